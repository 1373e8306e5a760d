/**
 * Tethered play (docs/protocol.md §10): the PC plays a motion on the robot in direct mode, frame by frame, one
 * synchronised move of servos 0..max per frame, at the times `playFrames` (src/motion/frames.ts) computes. It
 * needs no motion image, so it works on any firmware. See docs/tethered-play.md for the decisions:
 * - [decision] The sync move carries one speed/torque for all servos: the strongest (lowest number) of the
 *   frame's torques, so that no servo is driven weaker than its scene asks.
 * - [decision] Step 1 of §10 (runtime P/D and I gains) and the per-scene port values are not sent: §5 documents
 *   no parameter set for the gains, and the port writes' replies would share the servo bus's reply channel
 *   with the pose reads.
 * - Servos 0..max that the motion does not list hold the position read before playing (clamped to the safe
 *   range, as is every position sent). A servo of 0..max that does not answer that read stops play before it
 *   starts: its position would have to be guessed.
 * - Frame times are an absolute schedule on the client's clock (no drift); a frame the link is late for is
 *   sent at once and the lateness reported (`maxLateMs`).
 */
import type { Motion } from "../motion/index.ts";
import { clampPosition, MotionError, PLATFORM_PF2, playFrames } from "../motion/index.ts";
import { COMMANDS } from "../protocol/commands.ts";
import { WCK_MAX_POSITION, wckReadStatus, wckSyncMove } from "../protocol/wck.ts";
import { STANDARD_ZEROS } from "../protocol/zeros.ts";
import {
  RbcCancelledError,
  RbcDisconnectedError,
  RbcError,
  RbcNotConnectedError,
  RbcTimeoutError,
} from "./errors.ts";
import type { RbcConnection } from "./rbc-connection.ts";
import type { RbcSituation } from "./situation.ts";
import {
  byId,
  frameLabel,
  type TetheredPlayControl,
  TetheredPlayError,
  type TetheredPlayOptions,
  type TetheredPlayResult,
} from "./tethered-play-types.ts";

export {
  frameLabel,
  TetheredPlayControl,
  TetheredPlayError,
  type TetheredPlayHolds,
  type TetheredPlayOptions,
  type TetheredPlayProgress,
  type TetheredPlayResult,
} from "./tethered-play-types.ts";

/** What tethered play needs from the client, inside the client's one turn (`exclusive`). */
export interface TetheredPlayHost {
  readonly c: RbcConnection;
  /** The client's 0x10 (enter direct mode), within the turn. */
  enterDirect(): Promise<void>;
  /** The client's exit sequence (leave direct mode), within the turn. */
  exitDirect(): Promise<void>;
}

/**
 * Checks, before anything is sent, that the RBC would play the range (frames at least 20 ms apart, error 6) and
 * that the given zeros and platform have the right shape. Throws `TetheredPlayError("invalid-argument")`.
 */
export function checkTetheredPlay(doc: Motion, options: TetheredPlayOptions): void {
  const platform = options.platform;
  if (platform !== undefined && !(Number.isInteger(platform) && platform >= 0 && platform <= 255)) {
    throw refused({ kind: "play-platform", platform });
  }
  try {
    playFrames(doc, {
      range: options.range,
      robotZeros: options.robotZeros ?? STANDARD_ZEROS,
      platform: platform ?? PLATFORM_PF2,
    });
  } catch (e) {
    if (e instanceof MotionError) throw refused({ kind: "play-refused" }, e);
    throw e;
  }
}

function refused(situation: RbcSituation, cause?: unknown): TetheredPlayError {
  return new TetheredPlayError(
    "invalid-argument",
    undefined,
    0,
    0,
    undefined,
    "nothing-sent",
    cause,
    situation,
  );
}

/** Plays `doc` on the robot; runs inside the client's turn. See the module comment and `RbcClient.playTethered`. */
export async function runTetheredPlay(
  host: TetheredPlayHost,
  doc: Motion,
  options: TetheredPlayOptions,
  control: TetheredPlayControl,
): Promise<TetheredPlayResult> {
  const { c } = host;
  const signal = control.signal;
  const maxId = Math.max(...doc.servos.map((s) => s.id));
  const busIds = Array.from({ length: maxId + 1 }, (_, id) => id);
  const started = { at: c.clock.now(), late: 0 };
  let lastPositions: (number | undefined)[] = [];
  let transition = 0;
  let plannedMs = 0;
  const result = (outcome: TetheredPlayResult["outcome"]): TetheredPlayResult => ({
    outcome,
    framesSent: control.framesSent,
    totalFrames: control.totalFrames,
    transitionFrames: transition,
    lastFrame: control.lastFrame,
    lastPositions: byId(lastPositions, maxId),
    durationMs: control.framesSent > 0 ? c.clock.now() - started.at : 0,
    plannedMs,
    maxLateMs: started.late,
  });
  if (c.mode === "disconnected" || c.mode === "connecting") throw new RbcNotConnectedError();
  try {
    // Zeros and platform come from packet mode (the servo bus does not know them).
    let zeros = options.robotZeros;
    let platform = options.platform ?? c.state.platform;
    if (zeros === undefined || platform === undefined) {
      if (signal.aborted) return result("stopped");
      if (c.mode === "direct") await host.exitDirect();
      if (zeros === undefined) zeros = await c.request(COMMANDS.readZeros, undefined, { signal });
      if (platform === undefined) {
        await c.request(COMMANDS.readErrorCode, undefined, { signal });
        platform = c.state.platform ?? 0;
      }
    }
    if (signal.aborted) return result("stopped");
    let entered = false;
    if (c.mode !== "direct") {
      try {
        await host.enterDirect();
      } catch (e) {
        // Stop or Limp came while direct mode was being entered: the entry yielded to it (§3.6).
        if (signal.aborted) return result("stopped");
        throw e;
      }
      entered = true;
    }
    const read = await readPose(c, busIds, signal);
    if (signal.aborted) return result("stopped");
    if (read.silent.length > 0) {
      if (entered) await host.exitDirect().catch(() => {});
      throw new TetheredPlayError("timeout", undefined, 0, 0, undefined, "nothing-sent", undefined, {
        kind: "play-servos-silent",
        silent: read.silent,
        maxId,
      });
    }
    const plan = playFrames(doc, {
      range: options.range,
      robotZeros: zeros,
      platform,
      currentPose: read.pose,
    });
    control.totalFrames = plan.frames.length;
    transition = plan.transition.length;
    plannedMs = plan.durationMs;
    const held = busIds.map((id) => clampPosition(id, read.pose[id]!));
    const slot = new Map(plan.ids.map((id, i) => [id, i]));
    started.at = c.clock.now();
    c.setState({
      tethered: { startedAt: started.at, durationMs: plan.durationMs, totalFrames: control.totalFrames },
    });
    for (const [index, frame] of plan.frames.entries()) {
      const due = started.at + frame.atMs;
      await waitUntil(c, due, signal);
      if (signal.aborted) return result("stopped");
      // Direct mode ended under the play: bytes nobody asked for (the robot plays something), or the link.
      if (c.mode !== "direct") throw c.raw.servoFault ?? linkLost(control, undefined);
      started.late = Math.max(started.late, c.clock.now() - due);
      const positions = busIds.map((id) => {
        const k = slot.get(id);
        return clampPosition(id, k === undefined ? held[id]! : frame.positions[k]!);
      });
      const speed = Math.min(...frame.torques);
      await c
        .withTimeout(
          c.writeRaw(wckSyncMove(positions, speed), `tethered play, ${frameLabel(frame)}`),
          c.timeouts.quickMs,
          "tethered play frame",
        )
        .catch((e: unknown) => {
          throw linkLost(control, e);
        });
      control.framesSent++;
      control.lastFrame = { scene: frame.scene, frame: frame.frame };
      lastPositions = positions;
      options.onFrame?.({
        index,
        total: control.totalFrames,
        frame,
        scene: frame.scene,
        positions: byId(positions, maxId),
        elapsedMs: c.clock.now() - started.at,
        durationMs: plan.durationMs,
      });
    }
    const done = result("finished");
    // Sync moves have no reply: what the robot confirms is the pose read afterwards.
    const back = await readPose(c, busIds, undefined).catch((e: unknown) => {
      // Limp came during the read: the frames were all sent, only the confirmation is missing.
      if (e instanceof RbcCancelledError) return undefined;
      throw linkLost(control, e);
    });
    if (!back) return done;
    if (back.silent.length === busIds.length) {
      throw new TetheredPlayError(
        "timeout",
        undefined,
        control.framesSent,
        control.totalFrames,
        control.lastFrame,
        "last-frame",
        undefined,
        { kind: "play-unconfirmed", framesSent: control.framesSent, lastFrame: control.lastFrame! },
      );
    }
    const deviations = busIds
      .filter((id) => back.pose[id] !== undefined)
      .map((id) => Math.abs(back.pose[id]! - lastPositions[id]!));
    done.readBack = {
      positions: byId(back.pose, maxId),
      silent: back.silent,
      maxDeviation: Math.max(0, ...deviations),
    };
    return done;
  } catch (e) {
    if (signal.aborted && e instanceof RbcCancelledError) return result("stopped");
    if (e instanceof MotionError) throw refused({ kind: "play-refused" }, e);
    if (e instanceof RbcDisconnectedError) throw linkLost(control, e);
    throw e;
  } finally {
    if (c.state.tethered) c.setState({ tethered: undefined });
  }
}

/** The result of a play that Stop ended while it waited for its turn: nothing was sent. */
export function stoppedBeforeStart(doc: Motion): TetheredPlayResult {
  return {
    outcome: "stopped",
    framesSent: 0,
    totalFrames: 0,
    transitionFrames: 0,
    lastPositions: byId([], Math.max(...doc.servos.map((s) => s.id))),
    durationMs: 0,
    plannedMs: 0,
    maxLateMs: 0,
  };
}

/** A lost link or a write that never completed, mid-play. */
function linkLost(control: TetheredPlayControl, cause: unknown): TetheredPlayError {
  const timedOut = cause instanceof RbcTimeoutError;
  const { framesSent, totalFrames, lastFrame } = control;
  return new TetheredPlayError(
    timedOut ? "timeout" : "disconnected",
    undefined,
    framesSent,
    totalFrames,
    lastFrame,
    "unknown",
    cause,
    { kind: "play-link-lost", timedOut, framesSent, totalFrames, lastFrame },
  );
}

/** Resolves at `due` on the client's clock, at once on abort or when the link is lost. */
function waitUntil(c: RbcConnection, due: number, signal: AbortSignal): Promise<void> {
  const ms = due - c.clock.now();
  if (ms <= 0 || signal.aborted) return Promise.resolve();
  return new Promise((resolve) => {
    const done = () => {
      c.clock.clearTimeout(timer);
      signal.removeEventListener("abort", done);
      off();
      resolve();
    };
    const timer = c.clock.setTimeout(done, ms);
    signal.addEventListener("abort", done, { once: true });
    const off = c.stateChanges.on((s) => {
      if (s.mode === "disconnected") done();
    });
  });
}

/** Reads servos `ids` (status read, docs/protocol.md §5); a silent one is tried once more unless all were silent. */
async function readPose(
  c: RbcConnection,
  ids: readonly number[],
  signal: AbortSignal | undefined,
): Promise<{ pose: (number | undefined)[]; silent: number[] }> {
  const pose: (number | undefined)[] = [];
  const readOne = async (id: number): Promise<number | undefined> => {
    try {
      const reply = await c.raw.exchange(wckReadStatus(id), {
        need: 2,
        timeoutMs: c.timeouts.quickMs,
        note: `read servo ${id}`,
        signal,
      });
      // Servo replies carry no checksum; a position above 254 can only be noise on the line.
      return reply[1]! <= WCK_MAX_POSITION ? reply[1] : undefined;
    } catch (e) {
      // No answer: the servo's own timeout, or the robot's to the fence after a late reply (direct mode is then
      // over and every later read fails the same way, unsent).
      if (e instanceof RbcError && e.code === "timeout") return undefined;
      throw e;
    }
  };
  for (const id of ids) pose[id] = await readOne(id);
  let silent = ids.filter((id) => pose[id] === undefined);
  if (silent.length > 0 && silent.length < ids.length) {
    for (const id of silent) pose[id] = await readOne(id);
    silent = ids.filter((id) => pose[id] === undefined);
  }
  return { pose, silent };
}
