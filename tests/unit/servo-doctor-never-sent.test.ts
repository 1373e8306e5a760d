import { describe, expect, it } from "vitest";
import { scanServos, servoInfo, setServoId, wiggleServo } from "../../src/device/servo-doctor/index.ts";
import { toHex, WckDecoder } from "../../src/protocol/index.ts";
import { makeRig } from "../support/rig.ts";

/**
 * Issue 22 item 6: no code path of the servo doctor can send a wCK code that docs/protocol.md §5 marks "never
 * sent" (0x08 baud rate, 0x09 gains, 0x0B power-up gains, 0x0F overload, 0x11 bounds, 0x15 I gain, 0x17/0x18
 * power-up sets, 0x96 self-running motion), nor the 8-byte 10-bit move. Every public doctor operation runs, on
 * every simulated fault, and every byte written is decoded as the servos would.
 */

const NEVER_SENT = [0x08, 0x09, 0x0b, 0x0f, 0x11, 0x15, 0x17, 0x18, 0x96];
const HEADER = "FF FF AA 55 AA 55 37 BA";

describe("the servo doctor never sends a code §5 marks never sent", () => {
  const faults = [{}, { missing: [7] }, { duplicate: [3] }, { replacement: [12] }, { loaded: [4] }];
  for (const servoFaults of faults) {
    it(`scan 0-30, info, wiggle and set-id on ${JSON.stringify(servoFaults)}`, async () => {
      const { client, run } = await makeRig({ port: { latencyMs: 16 }, sim: { servoFaults } });
      const chunks: Uint8Array[] = [];
      client.log.on((e) => {
        if (e.direction === "out") chunks.push(e.bytes);
      });
      await run(scanServos(client, { ids: Array.from({ length: 31 }, (_, i) => i) }));
      for (const id of [0, 3, 4, 7, 12]) await run(servoInfo(client, id));
      for (const id of [3, 4, 7]) await run(wiggleServo(client, id));
      await run(setServoId(client, 0, 12, { confirm: async () => true }));
      await run(setServoId(client, 5, 20, { confirm: async () => true }));
      const parameterCodes = new Set<number>();
      let commands = 0;
      for (const chunk of chunks) {
        if (toHex(chunk).startsWith(HEADER)) continue;
        for (const command of new WckDecoder().push(chunk)) {
          commands++;
          expect(command.kind).not.toBe("move10");
          if (command.kind === "parameter") parameterCodes.add(command.data[0]);
        }
      }
      expect(commands).toBeGreaterThan(40);
      expect([...parameterCodes].filter((code) => NEVER_SENT.includes(code))).toEqual([]);
      // What was sent: the six reads and, at most, the id set.
      for (const code of parameterCodes) expect([0x0a, 0x0e, 0x10, 0x12, 0x16, 0x65, 0x0c]).toContain(code);
    });
  }
});
