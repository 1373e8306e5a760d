import { describe, expect, it } from "vitest";
import type { LogEntry } from "../../src/device/index.ts";
import { FACTORY_ZEROS, fromHex } from "../../src/protocol/index.ts";
import { formatFirmware, formatLocalDate } from "../../src/shared/format.ts";
import { formatLogLine, logAsText, PacketLog } from "../../src/ui/features/log/packet-log.ts";
import {
  checkDraft,
  clampZero,
  draftTable,
  factoryDraft,
  pendingChanges,
  toDraft,
} from "../../src/ui/features/zeros/editor.ts";
import { formatCount, formatDelta } from "../../src/ui/format.ts";
import { routeFromHash } from "../../src/ui/router.ts";
import { describePort, PORT_FILTERS } from "../../src/ui/serial-ports.ts";
import { createStore, frameScheduler } from "../../src/ui/store.ts";

function entry(n: number, direction: "in" | "out" = "out"): LogEntry {
  return {
    time: n,
    direction,
    kind: "packet",
    type: 0x12,
    name: `packet ${n}`,
    bytes: Uint8Array.of(n & 0xff, 0x0a),
  };
}

describe("format", () => {
  it("shows the firmware minor as two decimal digits", () => {
    expect(formatFirmware({ major: 2, minor: 0x17 })).toBe("2.23");
    expect(formatFirmware({ major: 2, minor: 0x0f })).toBe("2.15");
    expect(formatFirmware({ major: 3, minor: 5 })).toBe("3.05");
  });
  it("formats counts, deltas and dates", () => {
    expect(formatCount(24576)).toBe("24,576");
    expect(formatDelta(5)).toBe("+5");
    expect(formatDelta(-2)).toBe("\u22122");
    expect(formatDelta(0)).toBe("");
    expect(formatLocalDate(new Date(2026, 0, 5))).toBe("2026-01-05");
  });
});

describe("packet log ring buffer", () => {
  it("keeps the newest entries up to its capacity", () => {
    const log = new PacketLog(3);
    for (let i = 1; i <= 5; i++) log.push(entry(i));
    expect(log.size).toBe(3);
    expect(log.dropped).toBe(2);
    expect(log.lines().map((l) => l.name)).toEqual(["packet 3", "packet 4", "packet 5"]);
    expect(log.newest(2).map((l) => l.name)).toEqual(["packet 5", "packet 4"]);
    expect(log.lines()[0]?.hex).toBe("03 0A");
  });
  it("clears, and counts revisions", () => {
    const log = new PacketLog(5);
    log.push(entry(1));
    const revision = log.revision;
    log.clear();
    expect(log.size).toBe(0);
    expect(log.lines()).toEqual([]);
    expect(log.revision).toBeGreaterThan(revision);
  });
  it("writes lines people can read", () => {
    const log = new PacketLog(5, (ms) => new Date(2026, 10, 21, 14, 2, 11).getTime() + ms);
    log.push({
      time: 45,
      direction: "in",
      kind: "packet",
      name: "Read firmware version",
      bytes: fromHex("02 17"),
    });
    const [line] = log.lines();
    if (!line) throw new Error("no line");
    expect(formatLogLine(line)).toBe("14:02:11.045  RBC → PC  Read firmware version (2 bytes)  02 17");
    expect(logAsText([line], "header")).toBe(`header\n${formatLogLine(line)}\n`);
  });
  it("refuses a capacity that is not a positive integer", () => {
    expect(() => new PacketLog(0)).toThrow(RangeError);
  });
});

describe("zeros editor rules", () => {
  it("accepts the factory table", () => {
    const check = checkDraft(factoryDraft());
    expect(check.problems.size).toBe(0);
    expect(draftTable(check)).toEqual([...FACTORY_ZEROS]);
    expect(pendingChanges(FACTORY_ZEROS, check)).toEqual([]);
  });
  it("marks empty, non-numeric and out-of-range fields, and writes nothing", () => {
    const draft = toDraft(FACTORY_ZEROS);
    draft[0] = "";
    draft[1] = "2x";
    draft[3] = "82";
    const check = checkDraft(draft);
    expect([...check.problems.keys()]).toEqual([0, 1, 3]);
    expect(check.problems.get(3)).toMatch(/Servo 3 \(Left ankle pitch\): 82 is outside 51–81/);
    expect(draftTable(check)).toBeUndefined();
  });
  it("lists what would change", () => {
    const draft = toDraft(FACTORY_ZEROS);
    draft[3] = "70";
    expect(pendingChanges(FACTORY_ZEROS, checkDraft(draft))).toEqual([{ id: 3, from: 65, to: 70 }]);
  });
  it("clamps into the accepted window", () => {
    expect(clampZero(3, 200)).toBe(81);
    expect(clampZero(3, 0)).toBe(51);
    expect(clampZero(3, 70.4)).toBe(70);
  });
});

describe("store, router, ports", () => {
  it("merges patches and batches renders per frame", () => {
    const store = createStore({ a: 1, b: "x" });
    const seen: number[] = [];
    store.subscribe((s) => seen.push(s.a));
    store.update({ a: 2 });
    store.update((s) => ({ a: s.a + 1 }));
    expect(store.get()).toEqual({ a: 3, b: "x" });
    expect(seen).toEqual([2, 3]);

    const frames: Array<() => void> = [];
    let renders = 0;
    const schedule = frameScheduler(
      () => renders++,
      (cb) => frames.push(cb),
    );
    schedule();
    schedule();
    schedule();
    expect(frames.length).toBe(1);
    frames[0]?.();
    expect(renders).toBe(1);
    schedule();
    expect(frames.length).toBe(2);
  });
  it("reads routes from the hash", () => {
    const views = [
      {
        id: "robot",
        label: "Robot",
        load: async () => ({
          default: {
            needsRobot: false,
            render: () => {
              throw new Error();
            },
          },
        }),
      },
      {
        id: "zeros",
        label: "Zeros",
        load: async () => ({
          default: {
            needsRobot: false,
            render: () => {
              throw new Error();
            },
          },
        }),
      },
    ];
    expect(routeFromHash("#/zeros", views)).toBe("zeros");
    expect(routeFromHash("#/nope", views)).toBeUndefined();
    expect(routeFromHash("#main", views)).toBeUndefined();
    expect(routeFromHash("", views)).toBeUndefined();
  });
  it("filters the chooser to the four USB serial vendors and names ports", () => {
    expect(PORT_FILTERS).toEqual([
      { usbVendorId: 0x0403 },
      { usbVendorId: 0x067b },
      { usbVendorId: 0x10c4 },
      { usbVendorId: 0x1a86 },
    ]);
    expect(describePort({ usbVendorId: 0x0403, usbProductId: 0x6001 })).toBe(
      "FTDI USB serial adapter (0403:6001)",
    );
    expect(describePort({ usbVendorId: 0x1a86, usbProductId: 0x7523 })).toBe(
      "WCH (CH340) USB serial adapter (1A86:7523)",
    );
    expect(describePort({ usbVendorId: 0x2341, usbProductId: 0x0043 })).toBe("USB serial device (2341:0043)");
    expect(describePort({})).toBe("Serial port (Bluetooth or built in)");
  });
});
