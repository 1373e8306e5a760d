import { describe, expect, it } from "vitest";
import { scanServos } from "../../src/device/servo-doctor/index.ts";
import { parseRbm, toHex } from "../../src/protocol/index.ts";
import { exampleText } from "../data/project-data.ts";
import { makeRig } from "../support/rig.ts";

/**
 * The servo doctor's scan (docs/protocol.md §5 "Servo doctor") against the simulated servo bus and its faults,
 * on a virtual clock, through the whole stack (client → Web Serial transport → mock port → simulated RBC) with a
 * USB adapter's 16 ms latency.
 */

const PORT = { latencyMs: 16 };

describe("scanServos on the simulated bus", () => {
  it("a healthy HUNO: ids 0-15 answer with the basic posture, no findings, direct mode left", async () => {
    const { client, run, sim } = await makeRig({ port: PORT });
    const result = await run(scanServos(client));
    expect(result.servos.map((s) => s.status)).toEqual(Array(16).fill("answered"));
    expect(result.servos.map((s) => (s.status === "answered" ? s.position : -1))).toEqual([
      125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205,
    ]);
    expect(result.findings).toEqual([]);
    expect(result.stopped).toBeUndefined();
    expect(client.mode).toBe("packet");
    expect(sim.directMode).toBe(false);
  });
});

describe("scanServos on each simulated fault", () => {
  it("a missing servo 7: silent, one finding servo-missing [7], every other id answered", async () => {
    const { client, run } = await makeRig({ port: PORT, sim: { servoFaults: { missing: [7] } } });
    const result = await run(scanServos(client));
    expect(result.servos[7]).toEqual({ id: 7, status: "silent" });
    expect(result.servos.filter((s) => s.status === "answered")).toHaveLength(15);
    expect(result.findings).toEqual([{ code: "servo-missing", ids: [7] }]);
  });

  it("two servos at id 3: garbled (3 bytes, the AND of both replies), servo-duplicate [3]; id 4 keeps its own answer", async () => {
    const { client, run } = await makeRig({ port: PORT, sim: { servoFaults: { duplicate: [3] } } });
    const result = await run(scanServos(client));
    // Both answer 00 58 (load 0, position 88), one a byte after the other: 00, 58 & 00, 58.
    expect(result.servos[3]).toEqual({ id: 3, status: "garbled", bytes: [0x00, 0x00, 0x58] });
    expect(result.servos[4]).toEqual({ id: 4, status: "answered", load: 0, position: 108 });
    expect(result.findings).toEqual([{ code: "servo-duplicate", ids: [3] }]);
  });

  it("a replacement servo for 12 still at id 0: id 0 garbled, id 12 silent, one finding servo-replacement [0, 12]", async () => {
    const { client, run } = await makeRig({ port: PORT, sim: { servoFaults: { replacement: [12] } } });
    const result = await run(scanServos(client));
    expect(result.servos[0]?.status).toBe("garbled");
    expect(result.servos[12]).toEqual({ id: 12, status: "silent" });
    expect(result.findings).toEqual([{ code: "servo-replacement", ids: [0, 12] }]);
  });

  it("a loaded servo 4: answered with load 180, servo-high-load [4]", async () => {
    const { client, run } = await makeRig({ port: PORT, sim: { servoFaults: { loaded: [4] } } });
    const result = await run(scanServos(client));
    expect(result.servos[4]).toEqual({ id: 4, status: "answered", load: 180, position: 108 });
    expect(result.findings).toEqual([{ code: "servo-high-load", ids: [4], load: 180 }]);
  });

  it("ids 0-30: ids 16-30 are silent and expected by no one, so no finding", async () => {
    const { client, run } = await makeRig({ port: PORT });
    const ids = Array.from({ length: 31 }, (_, i) => i);
    const result = await run(scanServos(client, { ids }));
    expect(result.servos.slice(16).every((s) => s.status === "silent")).toBe(true);
    expect(result.expected).toEqual(ids.slice(0, 16));
    expect(result.findings).toEqual([]);
  });
});

describe("a late or garbled reply is never attributed to the next id", () => {
  it("a pair arriving 60 ms after id 7's first read (id 7 missing) is fenced off: id 7 silent after its second read, id 8 read once with its own 163", async () => {
    const { client, run, port, clock } = await makeRig({
      port: PORT,
      sim: { servoFaults: { missing: [7] } },
    });
    const written: string[] = [];
    client.log.on((e) => {
      if (e.direction !== "out") return;
      written.push(toHex(e.bytes));
      // The first read of id 7 is FF A7 00 27: a stray pair (load 0, position 49) follows 60 ms later, after
      // its window; the fence that follows an unanswered read takes it (docs/protocol.md §5).
      if (toHex(e.bytes) === "FF A7 00 27" && written.filter((w) => w === "FF A7 00 27").length === 1) {
        port.injectToPc([0x00, 0x31], 60);
      }
    });
    const result = await run(scanServos(client, { ids: [6, 7, 8, 9] }));
    expect(result.servos).toEqual([
      { id: 6, status: "answered", load: 0, position: 72 },
      { id: 7, status: "silent" },
      { id: 8, status: "answered", load: 0, position: 163 },
      { id: 9, status: "answered", load: 0, position: 141 },
    ]);
    // Id 7 was read twice (the second time with the longer window), id 8 (FF A8 00 28) once.
    expect(written.filter((w) => w === "FF A7 00 27")).toHaveLength(2);
    expect(written.filter((w) => w === "FF A8 00 28")).toHaveLength(1);
    expect(result.findings).toEqual([{ code: "servo-missing", ids: [7] }]);
    expect(clock.now()).toBeGreaterThan(0);
  });

  it("a pair arriving inside id 7's own window (40 ms) stays id 7's", async () => {
    const { client, run, port } = await makeRig({ port: PORT, sim: { servoFaults: { missing: [7] } } });
    client.log.on((e) => {
      if (e.direction === "out" && toHex(e.bytes) === "FF A7 00 27") port.injectToPc([0x00, 0x31], 40 - 16);
    });
    const result = await run(scanServos(client, { ids: [7, 8] }));
    expect(result.servos[1]).toEqual({ id: 8, status: "answered", load: 0, position: 163 });
    // Inside id 7's window a pair is id 7's answer (no timing can tell it from one): never id 8's.
    expect(result.servos[0]).toEqual({ id: 7, status: "answered", load: 0, position: 49 });
  });
});

describe("a scan that stops says which ids were read", () => {
  it("cancelled after id 2: ids 0-2 read, 3-15 unread, direct mode left", async () => {
    const { client, run } = await makeRig({ port: PORT });
    const abort = new AbortController();
    const result = await run(
      scanServos(client, {
        signal: abort.signal,
        onProgress: ({ done }) => {
          if (done === 3) abort.abort();
        },
      }),
    );
    expect(result.servos.map((s) => s.id)).toEqual([0, 1, 2]);
    expect(result.stopped).toEqual({
      code: "cancelled",
      unread: Array.from({ length: 13 }, (_, i) => i + 3),
    });
    expect(client.mode).toBe("packet");
  });

  it("a cable pull after id 4: stopped as disconnected with the ids read", async () => {
    const { client, run, port } = await makeRig({ port: PORT });
    const result = await run(
      scanServos(client, {
        onProgress: ({ done }) => {
          if (done === 5) port.unplug();
        },
      }),
    );
    expect(result.servos.map((s) => s.id)).toEqual([0, 1, 2, 3, 4]);
    expect(result.stopped?.code).toBe("disconnected");
    expect(result.stopped?.unread[0]).toBe(5);
  });

  it("refused while an upload is under way: typed, nothing sent to the servo bus", async () => {
    const { client, run, clock } = await makeRig({ port: PORT });
    const written: string[] = [];
    client.log.on((e) => {
      if (e.direction === "out") written.push(toHex(e.bytes));
    });
    const upload = client.uploadMotion(parseRbm(exampleText("wave.rbm")), { resetFirst: true });
    const scan = scanServos(client);
    await clock.advance(1);
    await expect(run(scan)).rejects.toMatchObject({ name: "ActivityRefusedError", from: "upload" });
    await run(upload);
    // No 0x10 (enter direct mode) and no servo read (FF A0..BE) went out.
    expect(written.some((hex) => hex.startsWith("FF FF AA 55 AA 55 37 BA 10 "))).toBe(false);
    expect(written.some((hex) => /^FF [AB][0-9A-F] 00 [0-9A-F]{2}$/.test(hex))).toBe(false);
  });

  it("bad ids are refused with a typed error before anything is sent", async () => {
    const { client, fail } = await makeRig({ port: PORT });
    for (const ids of [[], [31], [1, 1], [2.5]]) {
      const e = await fail(scanServos(client, { ids }));
      expect((e as Error & { code: string }).code).toBe("invalid-argument");
    }
    expect(client.mode).toBe("packet");
  });
});
