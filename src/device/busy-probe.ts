import { COMMANDS, type CommandSpec } from "../protocol/commands.ts";
import type { ClientCore } from "./client-core.ts";
import { RbcBusyError, RbcTimeoutError } from "./errors.ts";

/**
 * Busy, not gone (docs/protocol.md §3.6 [decision]): the RBC answers 0x11/0x12 from its receive interrupt, at
 * once even while a motion plays, and 0x16 from its main loop, which is busy for the whole motion. So a 0x12
 * answered at once together with a 0x16 unanswered within its quick time means the main loop is busy: a motion
 * plays (perhaps started by the remote, the PF buttons or another program), or an endless user function runs.
 * The unanswered 0x16 owes one reply (`RbcConnection` matches main-loop replies by count).
 */

/** `idle`: the main loop answered 0x16. `busy`: 0x12 answered, 0x16 not. Must run inside `exclusive`. */
export type ProbeResult = "idle" | "busy";

/**
 * The busy probe: 0x16 within the quick time (idle), else 0x12 (busy when it is answered). Rejects with the
 * 0x12's `RbcTimeoutError` when neither is answered: then the link (or the robot) is gone, not busy.
 */
export async function probeBusy(core: ClientCore): Promise<ProbeResult> {
  const { c } = core;
  const type = COMMANDS.readDistance.type;
  const sentAt = c.clock.now();
  try {
    await c.request(COMMANDS.readDistance, undefined, { retries: 0 });
    return "idle";
  } catch (e) {
    if (!(e instanceof RbcTimeoutError)) throw e;
  }
  // Its main loop answered after the 0x16 was written, so it is free: that reply alone was lost.
  if (c.mainLoopAnsweredSince(type, sentAt)) return "idle";
  await c.request(COMMANDS.readFirmwareVersion, undefined, { retries: 0 });
  noticeBusy(core);
  return "busy";
}

/** Records a motion started elsewhere in the activity machine, when the client itself is doing nothing. */
export function noticeBusy(core: ClientCore): void {
  if (core.activity.doing.kind === "idle") core.activity.noticeBusy("probe");
}

/**
 * A read of a main-loop type (0x16) that says "busy" rather than blaming the link when it goes unanswered
 * while 0x12 is answered (`RbcBusyError`). No retries: each unanswered 0x16 would owe one more reply. Must run
 * inside `exclusive`.
 */
export async function readMainLoop<R>(core: ClientCore, spec: CommandSpec<undefined, R>): Promise<R> {
  const { c } = core;
  const sentAt = c.clock.now();
  try {
    return await c.request(spec, undefined, { retries: 0 });
  } catch (e) {
    if (!(e instanceof RbcTimeoutError)) throw e;
    if (c.mainLoopAnsweredSince(spec.type, sentAt)) throw e;
    try {
      await c.request(COMMANDS.readFirmwareVersion, undefined, { retries: 0 });
    } catch (e2) {
      // Neither answered: the link or the robot is gone, and the first timeout says so.
      if (e2 instanceof RbcTimeoutError) throw e;
      throw e2;
    }
    noticeBusy(core);
    throw new RbcBusyError(spec.name, e.waitedMs);
  }
}
