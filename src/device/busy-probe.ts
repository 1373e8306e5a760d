import { COMMANDS, type CommandSpec } from "../protocol/commands.ts";
import type { ClientCore } from "./client-core.ts";
import { RbcBadReplyError, RbcBusyError, RbcTimeoutError } from "./errors.ts";
import type { BusySeen } from "./run-outcome.ts";

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

/**
 * [decision] How long after the 0x12's reply the 0x16's may still come from an idle robot: the 0x16 was sent first,
 * both replies travel the same link in order, and an idle main loop answers within a pass (about 3.5 ms,
 * docs/protocol.md §3.6). Later than this (plus a slow link's extra time), the main loop is busy.
 */
export const MAIN_LOOP_GRACE_MS = 50;

/**
 * The busy check asked while a Run is under way (docs/protocol.md §3.1 [decision, turn 4], §3.6): 0x16 (answered by
 * the main loop) then 0x12 (answered from the receive interrupt). `busy` when 0x12 is answered and 0x16 is not,
 * `MAIN_LOOP_GRACE_MS` after it, or before the Run's reply (`runAnswered`: the main loop
 * answered the 0x16 only after it had sent the motion's end); `idle` when the main loop answered 0x16 first;
 * `no-answer` when neither told anything. `onBusy` hears "busy" as soon as it is known; the promise settles once
 * the 0x16 has (its late reply is matched by count, `RbcConnection`). Must run inside `exclusive`, beside the
 * Run's own wait.
 */
export async function checkBusyDuringRun(
  core: ClientCore,
  runAnswered: () => boolean,
  onBusy: () => void,
  runWaitMs: number,
): Promise<BusySeen> {
  const { c } = core;
  let seen: BusySeen | undefined;
  const decide = (what: BusySeen) => {
    if (seen !== undefined) return;
    seen = what;
    if (what === "busy") onBusy();
  };
  let versionAnswered = false;
  let distanceSettled = false;
  let afterRun = false;
  const distance = c
    .request(COMMANDS.readDistance, undefined, {
      retries: 0,
      // A busy main loop answers when the motion ends: waited for as long as the Run is, so that it is not owed.
      timeoutMs: runWaitMs,
      measure: false,
      accept: () => {
        afterRun = runAnswered();
        return true;
      },
    })
    .then(
      () => decide(!afterRun ? "idle" : versionAnswered ? "busy" : "no-answer"),
      (e: unknown) => decide(versionAnswered && e instanceof RbcTimeoutError ? "busy" : "no-answer"),
    )
    .finally(() => {
      distanceSettled = true;
    });
  const version = c.request(COMMANDS.readFirmwareVersion, undefined, { retries: 0 }).then(
    async () => {
      versionAnswered = true;
      // A slow link (Bluetooth) may deliver two replies sent together further apart: its extra time is added.
      await c.sleep(MAIN_LOOP_GRACE_MS + c.roundTrip.extraMs);
      if (!distanceSettled) decide("busy");
    },
    () => {},
  );
  await Promise.all([distance, version]);
  return seen ?? "no-answer";
}
