import { describe, expect, it } from "vitest";
import { RbcTimeoutError } from "../../src/device/index.ts";
import { type ScanResult, scanServos } from "../../src/device/servo-doctor/index.ts";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import { scanStoppedText } from "../../src/i18n/outcomes/servos/servo-words.ts";
import { toHex } from "../../src/protocol/index.ts";
import { makeRig, type Rig } from "../support/rig.ts";

/**
 * Issue 32, items 3 and 8: the scan reports only what the bus showed (docs/protocol.md §5 "Servo doctor"), on the
 * simulated robot, virtual clock, a USB adapter's 16 ms latency. Reads are literal bytes: read id 7 is
 * `FF A7 00 27` (A7 ^ 00 = A7, & 7F = 27), id 8 `FF A8 00 28`, id 9 `FF A9 00 29`.
 */

const PORT = { latencyMs: 16 };
const ENTER_DIRECT = "FF FF AA 55 AA 55 37 BA 10 ";

/** Every chunk the client writes, as hex. */
function writes(rig: Rig): string[] {
  const out: string[] = [];
  rig.client.log.on((e) => {
    if (e.direction === "out") out.push(toHex(e.bytes));
  });
  return out;
}

describe("a firmware that sends RBC packets unasked", () => {
  it("repeating its 0x16 reply: the scan says so in both languages and never enters direct mode (no 0x10)", async () => {
    const rig = await makeRig({ port: PORT, sim: { repeatReplies: { type: 0x16 } } });
    const out = writes(rig);
    const result = await rig.run(scanServos(rig.client, { ids: [0, 1, 2] }));
    expect(result.stopped).toEqual({ code: "firmware-sends-packets", unread: [0, 1, 2], type: 0x16 });
    expect(result.servos).toEqual([]);
    expect(result.findings).toEqual([]);
    expect(out.some((hex) => hex.startsWith(ENTER_DIRECT))).toBe(false);
    expect(out.some((hex) => /^FF [AB][0-9A-F] 00 [0-9A-F]{2}$/.test(hex))).toBe(false);
    expect(rig.client.mode).toBe("packet");
    expect(rig.sim.directMode).toBe(false);
    expect(scanStoppedText(result, "en")).toBe(
      "The scan stopped: The robot's firmware keeps sending packets nobody asked for (type 0x16), as a build that repeats its reply endlessly does. Servo replies cannot be told from them, so the servos were not read. Read: none. Not read: 0, 1, 2.",
    );
    expect(scanStoppedText(result, "ko")).toContain("(종류 0x16)");
  });

  it("RBC packet bytes heard after a servo read are never a servo's reply: the scan stops and names them", async () => {
    const rig = await makeRig({ port: PORT });
    rig.client.log.on((e) => {
      // The whole 0x16 reply `FF FF AA 55 AA 55 37 BA 16 01 00 00 00 02 0A 00 0A` after read 1.
      if (e.direction === "out" && toHex(e.bytes) === "FF A1 00 21") {
        rig.port.injectToPc(
          [0xff, 0xff, 0xaa, 0x55, 0xaa, 0x55, 0x37, 0xba, 0x16, 1, 0, 0, 0, 2, 10, 0, 10],
          20,
        );
      }
    });
    const result = await rig.run(scanServos(rig.client, { ids: [0, 1, 2] }));
    expect(result.servos.map((s) => s.id)).toEqual([0]);
    expect(result.stopped).toEqual({ code: "firmware-sends-packets", unread: [1, 2], type: 0x16 });
    expect(result.findings.some((f) => f.code === "servo-duplicate")).toBe(false);
    expect(rig.client.mode).toBe("packet");
  });
});

describe("one servo's reply, late or copied, is that servo's", () => {
  it("two identical pairs one after the other at id 7: one servo, answered, no collision", async () => {
    const rig = await makeRig({ port: PORT, sim: { servoFaults: { missing: [7] } } });
    rig.client.log.on((e) => {
      if (e.direction === "out" && toHex(e.bytes) === "FF A7 00 27") {
        rig.port.injectToPc([0x00, 0x31], 20);
        rig.port.injectToPc([0x00, 0x31], 30);
      }
    });
    const result = await rig.run(scanServos(rig.client, { ids: [6, 7, 8] }));
    expect(result.servos[1]).toEqual({ id: 7, status: "answered", load: 0, position: 49 });
    expect(result.findings).toEqual([]);
  });

  it("a reply that comes after the first window (servo 7, 60 ms late): the second, longer read finds it", async () => {
    const rig = await makeRig({ port: PORT, sim: { servoFaults: { late: { 7: 60 } } } });
    const out = writes(rig);
    const result = await rig.run(scanServos(rig.client, { ids: [6, 7, 8] }));
    expect(result.servos).toEqual([
      { id: 6, status: "answered", load: 0, position: 72 },
      { id: 7, status: "answered", load: 0, position: 49 },
      { id: 8, status: "answered", load: 0, position: 163 },
    ]);
    expect(out.filter((hex) => hex === "FF A7 00 27")).toHaveLength(2);
    expect(result.findings).toEqual([]);
    expect(result.stopped).toBeUndefined();
  });

  for (const lateMs of [33, 60, 90, 110]) {
    it(`servo 7 ${lateMs} ms late, servos 8 and 9 unplugged: 7 answers its own 49, 8 and 9 are silent (fenced after every unanswered read)`, async () => {
      const rig = await makeRig({
        port: PORT,
        sim: { servoFaults: { late: { 7: lateMs }, missing: [8, 9] } },
      });
      const out = writes(rig);
      const result = await rig.run(scanServos(rig.client, { ids: [6, 7, 8, 9, 10] }));
      expect(result.stopped).toBeUndefined();
      expect(result.servos).toEqual([
        { id: 6, status: "answered", load: 0, position: 72 },
        { id: 7, status: "answered", load: 0, position: 49 },
        { id: 8, status: "silent" },
        { id: 9, status: "silent" },
        { id: 10, status: "answered", load: 0, position: 51 },
      ]);
      expect(result.findings).toEqual([
        { code: "servo-missing", ids: [8] },
        { code: "servo-missing", ids: [9] },
      ]);
      // Each read that heard nothing is followed by the leave sequence of a fence before the next read.
      const servoOut = out.filter((hex) => hex.startsWith("FF ") && !hex.startsWith("FF FF"));
      const after8 = servoOut.slice(servoOut.indexOf("FF A8 00 28"));
      expect(after8.slice(0, 6)).toEqual([
        "FF A8 00 28",
        "FF E0 FB 01 00 1A",
        "FF A8 00 28",
        "FF E0 FB 01 00 1A",
        "FF A9 00 29",
        "FF E0 FB 01 00 1A",
      ]);
    });
  }
});

describe("a 0-30 scan with servo 15 late", () => {
  it("servo 15 (60 ms late) answers its own 205; ids 16-30 are all silent, none takes its pair", async () => {
    const rig = await makeRig({ port: PORT, sim: { servoFaults: { late: { 15: 60 } } } });
    const ids = Array.from({ length: 31 }, (_, i) => i);
    const result = await rig.run(scanServos(rig.client, { ids }));
    expect(result.servos[15]).toEqual({ id: 15, status: "answered", load: 0, position: 205 });
    expect(result.servos.slice(16)).toEqual(ids.slice(16).map((id) => ({ id, status: "silent" })));
    expect(result.findings).toEqual([]);
  });
});

describe("a scan that stops names why", () => {
  const result: ScanResult = {
    servos: [{ id: 0, status: "answered", load: 0, position: 125 }],
    findings: [],
    ids: [0, 1],
    expected: [0, 1],
    stopped: { code: "failed", unread: [1], error: new RbcTimeoutError("read firmware version", 400) },
  };

  it("an error: its own sentence, in English and Korean, never just 'an error'", () => {
    for (const locale of ["en", "ko"] as const) {
      const text = scanStoppedText(result, locale) ?? "";
      const said = errorText(result.stopped?.error, locale);
      expect(text).toContain(said.slice(1));
      expect(text).not.toContain("(an error)");
      expect(text).not.toContain("(오류)");
    }
    expect(scanStoppedText(result, "en")).toMatch(/^The scan stopped: .+ Read: 0\. Not read: 1\.$/);
    expect(scanStoppedText(result, "ko")).toMatch(/^검사를 멈췄어요\. .+ 읽은 ID: 0\. 읽지 못한 ID: 1\.$/);
  });
});

describe("a late reply the client owes is not a packet nobody asked for", () => {
  it("a scan right after Stop ended a motion started elsewhere reads every servo: the busy probe's 0x16, answered when the motion ended, paid its own debt", async () => {
    const rig = await makeRig({ port: PORT, sim: { busyMotion: 2 } });
    // The busy probe's 0x16 goes unanswered while the motion plays (docs/protocol.md §3.6): one reply is owed.
    expect(await rig.run(rig.client.probeBusy())).toBe("busy");
    await rig.run(rig.client.stopActivity());
    expect(rig.sim.playingMotion).toBeUndefined();
    const result = await rig.run(scanServos(rig.client, { ids: [0, 1, 2] }));
    expect(result.stopped).toBeUndefined();
    expect(result.servos.map((s) => s.status)).toEqual(["answered", "answered", "answered"]);
  });
});
