import { COMMANDS } from "../protocol/commands.ts";
import { RbcTimeoutError } from "./errors.ts";
import type { RbcConnection } from "./rbc-connection.ts";

/**
 * The busy probe of docs/protocol.md §3.6 [decision]: 0x12 (answered from the firmware's receive interrupt, at
 * once even while a motion plays), then 0x16 (answered from its main loop, which a playing motion keeps busy).
 * `idle`: both answered in their quick time. `busy`: 0x12 answered, 0x16 not within its quick time: the main
 * loop is busy (a motion started elsewhere, or an endless user function); the 0x16 reply that may come later is
 * the connection's to discard. An unanswered 0x12 rejects with its `RbcTimeoutError`: the robot did not
 * answer at all, which is not "busy".
 *
 * Runs inside the caller's turn of the queue (`RbcConnection.exclusive`). Sends packets: packet mode only.
 */
export type BusyProbeResult = { busy: false } | { busy: true; waitedMs: number };

export async function probeBusy(c: RbcConnection): Promise<BusyProbeResult> {
  const quickMs = c.timeouts.quickMs;
  await c.request(COMMANDS.readFirmwareVersion, undefined, { retries: 0, timeoutMs: quickMs });
  try {
    await c.request(COMMANDS.readDistance, undefined, { retries: 0, timeoutMs: quickMs });
    return { busy: false };
  } catch (e) {
    if (e instanceof RbcTimeoutError) return { busy: true, waitedMs: e.waitedMs };
    throw e;
  }
}
