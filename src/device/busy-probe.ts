import { COMMANDS, type CommandSpec } from "../protocol/commands.ts";
import type { ClientCore } from "./client-core.ts";
import { RbcBadReplyError, RbcBusyError, RbcTimeoutError } from "./errors.ts";

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
 * The busy probe: a distance read (`readMainLoop`): answered, the main loop is free (`idle`); unanswered twice
 * while the firmware version is answered at once, `busy`. Rejects with a timeout when nothing answers: then
 * the link (or the robot) is gone, not busy.
 */
export async function probeBusy(core: ClientCore): Promise<ProbeResult> {
  try {
    await readMainLoop(core, COMMANDS.readDistance);
    return "idle";
  } catch (e) {
    if (e instanceof RbcBusyError) return "busy";
    throw e;
  }
}

/** Records a motion started elsewhere in the activity machine, when the client itself is doing nothing. */
export function noticeBusy(core: ClientCore): void {
  if (core.activity.doing.kind === "idle") core.activity.noticeBusy("probe");
}

/**
 * A read of a main-loop type (0x16) that says "busy" rather than blaming the link (`RbcBusyError`, docs/protocol.md
 * §3.6). A reply that came damaged (a garbled or partial frame) is retried as any idempotent read is. Silence is
 * told apart with 0x12, answered from the receive interrupt: unanswered too, the link is gone (the 0x16's
 * timeout); answered, the 0x16 is asked once more (a merely late reply is then paid off by count and the new
 * one read), and a second silence means busy. Each silent 0x16 owes the robot's late reply, which the
 * connection discards when it comes. Must run inside `exclusive`.
 */
export async function readMainLoop<R>(core: ClientCore, spec: CommandSpec<undefined, R>): Promise<R> {
  const { c } = core;
  let silences = 0;
  for (let attempt = 0; ; attempt++) {
    const sentAt = c.clock.now();
    try {
      return await c.request(spec, undefined, { retries: 0 });
    } catch (e) {
      const damaged =
        e instanceof RbcBadReplyError ||
        (e instanceof RbcTimeoutError && c.mainLoopAnsweredSince(spec.type, sentAt));
      if (!(e instanceof RbcTimeoutError) && !damaged) throw e;
      if (damaged) {
        if (attempt < c.retries) continue;
        throw e;
      }
      const waitedMs = (e as RbcTimeoutError).waitedMs;
      try {
        await c.request(COMMANDS.readFirmwareVersion, undefined, { retries: 0 });
      } catch (e2) {
        // Neither answered: the link or the robot is gone, and the first timeout says so.
        if (e2 instanceof RbcTimeoutError) throw e;
        throw e2;
      }
      silences++;
      if (silences >= 2) {
        noticeBusy(core);
        throw new RbcBusyError(spec.name, waitedMs);
      }
    }
  }
}
