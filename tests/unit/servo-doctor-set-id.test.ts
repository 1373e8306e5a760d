import { describe, expect, it } from "vitest";
import { scanServos, setServoId } from "../../src/device/servo-doctor/index.ts";
import { toHex } from "../../src/protocol/index.ts";
import { makeRig, type Rig } from "../support/rig.ts";

/**
 * The guided id fix (docs/protocol.md §5 "Servo doctor" [decision]) on the simulated servo bus, virtual clock,
 * 16 ms adapter latency. The id set's bytes are literal: the manual's example `FF E0 0C 1E 1E 6C` (0 → 30), and
 * 0 → 12 worked out by hand (E0 ^ 0C ^ 0C ^ 0C = EC, & 7F = 6C).
 */

const PORT = { latencyMs: 16 };

/** Every chunk the client wrote, as hex. */
function written(rig: Rig): string[] {
  const out: string[] = [];
  rig.client.log.on((e) => {
    if (e.direction === "out") out.push(toHex(e.bytes));
  });
  return out;
}

const isIdSet = (hex: string) => /^FF E[0-9A-F] 0C /.test(hex);

describe("setServoId", () => {
  it("servo 0 → 30: reads 0 (answers) and 30 (silent), asks, sends FF E0 0C 1E 1E 6C, then 30 answers and 0 is silent", async () => {
    const rig = await makeRig({ port: PORT });
    const out = written(rig);
    const asked: unknown[] = [];
    const result = await rig.run(
      setServoId(rig.client, 0, 30, {
        confirm: async (check) => {
          asked.push(check);
          return true;
        },
      }),
    );
    expect(asked).toEqual([{ from: 0, to: 30, position: 125 }]);
    expect(out.filter(isIdSet)).toEqual(["FF E0 0C 1E 1E 6C"]);
    expect(result).toEqual({
      outcome: "done",
      from: 0,
      to: 30,
      after: {
        to: { id: 30, status: "answered", load: 0, position: 125 },
        from: { id: 0, status: "silent" },
      },
    });
    // In order: read 0, read 30, the id set, read 30, read 0 (FF A0 00 20, FF BE 00 3E). The unanswered read
    // of 30 leaves the bus unsettled (docs/protocol.md §5): the id set is fenced first (leave, 0x12, enter).
    const servoBytes = out.filter((hex) => hex.startsWith("FF ") && !hex.startsWith("FF FF"));
    expect(servoBytes).toEqual([
      "FF A0 00 20",
      "FF BE 00 3E",
      "FF E0 FB 01 00 1A",
      "FF E0 0C 1E 1E 6C",
      "FF BE 00 3E",
      "FF A0 00 20",
      "FF E0 FB 01 00 1A",
    ]);
    expect(rig.client.mode).toBe("packet");
  });

  it("a replacement servo at id 0: refused while two servos answer at 0; once servo 0 is unplugged, 0 → 12 is done and the scan is clean", async () => {
    const rig = await makeRig({ port: PORT, sim: { servoFaults: { replacement: [12] } } });
    const out = written(rig);
    const refused = await rig.run(setServoId(rig.client, 0, 12));
    expect(refused).toMatchObject({ outcome: "refused", reason: "from-garbled", from: 0, to: 12 });
    expect(out.some(isIdSet)).toBe(false);
    rig.sim.connectServo(0, false);
    const done = await rig.run(setServoId(rig.client, 0, 12));
    expect(done.outcome).toBe("done");
    expect(out.filter(isIdSet)).toEqual(["FF E0 0C 0C 0C 6C"]);
    rig.sim.connectServo(0, true);
    const scan = await rig.run(scanServos(rig.client));
    expect(scan.findings).toEqual([]);
    expect(scan.servos[12]).toEqual({ id: 12, status: "answered", load: 0, position: 49 });
  });

  it("refused, with nothing but reads sent: nothing at FROM, a servo at TO, not confirmed", async () => {
    const rig = await makeRig({ port: PORT, sim: { servoFaults: { missing: [7] } } });
    const out = written(rig);
    expect(await rig.run(setServoId(rig.client, 7, 20))).toMatchObject({
      outcome: "refused",
      reason: "from-silent",
      before: [{ id: 7, status: "silent" }],
    });
    expect(await rig.run(setServoId(rig.client, 1, 2))).toMatchObject({
      outcome: "refused",
      reason: "to-taken",
      before: [
        { id: 1, status: "answered" },
        { id: 2, status: "answered" },
      ],
    });
    expect(await rig.run(setServoId(rig.client, 1, 20, { confirm: async () => false }))).toMatchObject({
      outcome: "refused",
      reason: "not-confirmed",
    });
    expect(out.some(isIdSet)).toBe(false);
    expect(rig.client.mode).toBe("packet");
  });

  it("bad ids: a typed error, nothing sent", async () => {
    const rig = await makeRig({ port: PORT });
    const out = written(rig);
    for (const [from, to] of [
      [1, 1],
      [31, 2],
      [2, -1],
      [1.5, 3],
    ] as const) {
      await expect(rig.run(setServoId(rig.client, from, to))).rejects.toMatchObject({
        code: "invalid-argument",
      });
    }
    expect(out).toEqual([]);
  });
});
