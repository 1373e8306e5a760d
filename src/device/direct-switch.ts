import { COMMANDS } from "../protocol/commands.ts";
import { EXIT_DIRECT_MODE } from "../protocol/wck.ts";
import type { DirectUse } from "./activity.ts";
import { probeBusy } from "./busy-probe.ts";
import type { ClientCore } from "./client-core.ts";
import { RbcNotIdleError } from "./direct-mode-errors.ts";
import { RbcBadReplyError, RbcCancelledError, RbcError, RbcTimeoutError } from "./errors.ts";
import { WIRE_BYTE_MS } from "./raw-channel.ts";

/** The log's note for 0xFF sent to leave direct mode when the RBC did not answer (it may have switched). */
const BLIND_EXIT_NOTE = "leave direct mode (blind, after no reply)";

/**
 * The 0x10 request and its reply on the wire (15 + 1 bytes each way): a paced link takes at least this (less a
 * tenth of a millisecond for the clock's grain).
 */
const ENTER_WIRE_MS = 32 * WIRE_BYTE_MS - 0.1;

/**
 * Enters direct mode (0x10, docs/protocol.md §5) for `use`, within the caller's turn. Only when the robot is
 * idle (§3.6 [decision], `requireIdleRobot`): refused before anything reaches the servo bus otherwise.
 * Already in direct mode, `use` takes it over. Stop or Limp pressed while it switches (§3.6 [decision, turn 4])
 * wins at its next step: nothing more is sent and it rejects with `RbcCancelledError` (by which of them); their
 * own turn, next in the queue, finds the mode the robot is in (Stop leaves direct mode, Limp uses it).
 */
export async function enterDirect(core: ClientCore, use: DirectUse): Promise<void> {
  const { c, activity } = core;
  if (c.mode === "direct") {
    activity.handDirect(use);
    return;
  }
  const epoch = c.epoch;
  await requireIdleRobot(core, use);
  if (c.epoch !== epoch) throw c.cancelledSince(epoch);
  const sentAt = c.clock.now();
  try {
    await c.request(COMMANDS.enterDirectMode, undefined);
  } catch (e) {
    // The RBC may have switched even though its `01` was lost, garbled or no longer waited for (Limp ends the
    // wait); it would then relay every later packet to the servo bus. The exit sequence is harmless garbage in
    // packet mode, so send it blindly.
    if (e instanceof RbcTimeoutError || e instanceof RbcBadReplyError || e instanceof RbcCancelledError) {
      await c.writeRaw(EXIT_DIRECT_MODE, BLIND_EXIT_NOTE).catch(() => {});
      c.parser.reset();
    }
    throw e;
  }
  startDirect(core, use, c.clock.now() - sentAt);
  // The RBC has switched: Stop or Limp, pressed meanwhile, finds direct mode in its own turn (Stop leaves it).
  if (c.epoch !== epoch) throw c.cancelledSince(epoch);
  await drainStale(core);
}

/**
 * Waits out the settle time after entering direct mode (docs/protocol.md §3.6 [decision, turn 4]): the old servo
 * replies the controller's servo-side buffer relays as direct mode begins come meanwhile, and are drained and
 * logged, not judged (`RawChannel.guardServoBus`). The first servo command is written after it.
 */
export function drainStale(core: ClientCore): Promise<void> {
  const left = core.c.raw.settleLeftMs;
  return left > 0 ? core.c.sleep(left) : Promise.resolve();
}

/**
 * Direct mode only when the robot is idle (docs/protocol.md §3.6 [decision]): nothing this client started is
 * under way (the activity machine refuses otherwise, `ActivityRefusedError`, nothing sent), and the busy probe
 * is clean (0x16 answered within its quick time; only after a silence is 0x12 asked, then 0x16 once more). A
 * busy main loop (a motion started elsewhere) is recorded in the activity machine and refused with
 * `RbcNotIdleError`; a clean probe ends an earlier `busy`.
 */
export async function requireIdleRobot(core: ClientCore, use: DirectUse): Promise<void> {
  const { c, activity } = core;
  if (activity.doing.kind !== "busy") activity.requireIdle("enterDirect");
  // A busy main loop is recorded in the activity machine by the probe itself. Each of its two 0x16 went
  // unanswered for the quick time: that is the wait the error reports.
  if ((await probeBusy(core)) === "busy") throw new RbcNotIdleError(use, c.timeouts.quickMs);
  if (activity.doing.kind === "busy") activity.busyEnded();
}

/**
 * The robot has switched to direct mode (its `01` came after `enterMs`, or is assumed): the client and the
 * activity machine say so, and the servo bus's rules start (`RawChannel.guardServoBus`).
 */
export function startDirect(core: ClientCore, use: DirectUse, enterMs: number | undefined): void {
  const { c, activity } = core;
  c.subscription = undefined;
  activity.enterDirect(use);
  c.setState({ mode: "direct", subscription: undefined });
  c.raw.guardServoBus({
    // A link known to take no wire time (a pseudo terminal) is never paced, however slowly a loaded machine
    // answered the switch: its replies can come sooner than their bytes' wire time, and must not count as early.
    paced: c.transport.unpaced !== true && enterMs !== undefined && enterMs >= ENTER_WIRE_MS,
    leave: () => leaveStillPlaying(core),
    fence: () => fenceServoBus(core),
    settleMs: c.timeouts.settleMs,
  });
}

/** Leaves direct mode with the 6-byte exit sequence (no reply), within the caller's turn. */
export async function exitDirect(core: ClientCore): Promise<void> {
  const { c, activity } = core;
  if (c.mode !== "direct") return;
  c.raw.endServoBus();
  await c.writeRaw(EXIT_DIRECT_MODE, "leave direct mode");
  c.parser.reset();
  if (activity.direct) activity.exitDirect();
  c.setState({ mode: "packet" });
}

/** Bytes nobody asked for came from the servo bus: leave direct mode at once (the operation fails with them). */
function leaveStillPlaying(core: ClientCore): void {
  const { c, activity } = core;
  c.writeRaw(EXIT_DIRECT_MODE, "leave direct mode: the robot is still playing something").catch(() => {});
  c.parser.reset();
  if (activity.direct) activity.exitDirect();
  c.setState({ mode: "packet" });
}

/**
 * Makes sure a late servo reply has arrived or never will before the next servo command (see
 * `RawChannel.guardServoBus`): leaves direct mode, waits for a 0x12 reply (the link keeps order, so every servo
 * byte sent before it has come, and the packet parser discarded it), and enters direct mode again. If the
 * robot does not answer, direct mode is over and the next command is not sent.
 */
async function fenceServoBus(core: ClientCore): Promise<void> {
  const { c, activity } = core;
  await c.writeRaw(EXIT_DIRECT_MODE, "leave direct mode (a late servo reply may still come)");
  c.parser.reset();
  c.setState({ mode: "packet" });
  try {
    await c.request(COMMANDS.readFirmwareVersion, undefined);
    await c.request(COMMANDS.enterDirectMode, undefined, { retries: 0 });
  } catch (e) {
    await c.writeRaw(EXIT_DIRECT_MODE, BLIND_EXIT_NOTE).catch(() => {});
    c.parser.reset();
    if (activity.direct) activity.exitDirect();
    // Not the servo's timeout (callers take that for a silent servo): the robot itself did not answer.
    throw e instanceof RbcTimeoutError ? new RbcError("timeout", undefined, { cause: e }) : e;
  }
  c.setState({ mode: "direct" });
}
