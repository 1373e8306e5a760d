import { describe, expect, it } from "vitest";
import { type LogEntry, RbcError } from "../../src/device/index.ts";
import { setServoId } from "../../src/device/servo-doctor/index.ts";
import { errorText } from "../../src/i18n/index.ts";
import { toHex } from "../../src/protocol/index.ts";
import { makeRig } from "../support/rig.ts";

/**
 * Issue 32 items 4 and 5: say what was observed, never a cause nobody saw or a write that did not happen. The base
 * commit worded a zero write a firmware does not answer as "the robot refuses a table it considers out of range",
 * and reported the servo id fix as `sent: true` when Stop came during its question, before anything was written.
 */

function written(log: LogEntry[]): string[] {
  return log.filter((e) => e.direction === "out").map((e) => toHex(e.bytes));
}

describe("zero write on a firmware without 0x0E", () => {
  it("no answer, the read back unchanged: says exactly that, no guessed cause", async () => {
    const { client, run, fail } = await makeRig({ sim: { answersZeroWrite: false } });
    const before = await run(client.readZeros());
    const table = before.map((v, i) => (i === 3 ? v + 1 : v));
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    const e = await fail(client.writeZeros(table));
    expect(e).toBeInstanceOf(RbcError);
    expect(errorText(e, "en")).toBe(
      "The robot did not answer the zero write (0x0E), and reading the zeros back shows the new values were not stored.",
    );
    expect(errorText(e, "en")).not.toContain("out of range");
    // The write (type 0x0E), then the read back (type 0x0B); the robot's zeros are as before.
    expect(written(log).map((hex) => hex.split(" ")[8])).toEqual(["0E", "0B"]);
    expect(await run(client.readZeros())).toEqual(before);
  });
});

describe("servo id fix: Stop during its question", () => {
  it("stopped with sent: false, and no id set on the bus", async () => {
    const rig = await makeRig({ port: { latencyMs: 16 } });
    const log: LogEntry[] = [];
    rig.client.log.on((e) => log.push(e));
    const result = await rig.run(
      setServoId(rig.client, 0, 30, {
        confirm: async () => {
          await rig.client.stopActivity();
          return true;
        },
      }),
    );
    expect(result).toMatchObject({ outcome: "stopped", from: 0, to: 30, sent: false });
    expect(written(log).filter((hex) => /^FF E[0-9A-F] 0C /.test(hex))).toEqual([]);
  });
});
