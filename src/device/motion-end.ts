import { BASIC_POSTURE_MOTION } from "../protocol/catalog.ts";
import { COMMANDS } from "../protocol/commands.ts";
import { encodePacket } from "../protocol/packet.ts";
import type { Clock } from "../shared/clock.ts";
import { Waitress } from "../shared/waitress.ts";
import type { Stop7Sender } from "./activity.ts";
import type { ClientCore } from "./client-core.ts";

/**
 * The longest the RBC may take to reach the end of the current scene after a 7 (a scene is at most ~10 s in
 * Motionbuilder, but the built-in motions' scenes are well under 1 s).
 */
export const SCENE_END_MS = 1000;

/** How long Basic posture (motion 7) takes. */
export function postureDurationMs(): number {
  return COMMANDS.runMotion.expectedMs?.(BASIC_POSTURE_MOTION) ?? 0;
}

/**
 * How a playing motion ended when 7 was sent to end it, no more certain than the robot confirmed:
 * `stopped`: the robot answered `07` (it ends at the end of the current scene and holds that pose).
 * `ended-then-posture`: the motion had just ended on its own, so the robot took the 7 as Basic posture and
 * confirmed that. `posture`: Basic posture itself was playing (it cannot be stopped) and the robot confirmed
 * its end. `unconfirmed`: no `07` came in time (or the 7 could not be sent).
 */
export type MotionEndOutcome = "stopped" | "ended-then-posture" | "posture" | "unconfirmed";

/** What `endPlayingMotion` found: `endedFirst` when the motion's own end came back (it ended before the 7). */
export interface MotionEnd {
  motion: number;
  outcome: MotionEndOutcome;
  endedFirst?: boolean;
}

/**
 * Ends the motion this client plays the only way the RBC allows: motion 7, which it takes even while playing
 * (docs/protocol.md §3.6). The 7 is sent once, whoever asks (the activity machine remembers it), ahead of the
 * queue: the motion's own Run is still waiting for its reply. The robot stops at the end of the current scene
 * and answers once, `07`, which the waiting Run takes; basic posture is not played. If the motion ended on its
 * own just before the 7 arrived, its own number comes back and the robot plays basic posture, which the Run
 * waits out (`awaitPostureAfterEnd`). Waits at most `waitMs` for the motion's end (undefined: as long as the
 * Run waits). Undefined when no motion of this client plays.
 */
export async function endPlayingMotion(
  core: ClientCore,
  by: Stop7Sender,
  waitMs?: number,
): Promise<MotionEnd | undefined> {
  const { c, activity } = core;
  const playing = activity.motion;
  if (!playing) return undefined;
  const { motion } = playing;
  if (motion === BASIC_POSTURE_MOTION) {
    // Basic posture cannot be stopped: it is waited out, and whether a 7 started it does not matter here.
    const n = await playing.ended;
    const outcome =
      n !== BASIC_POSTURE_MOTION ? "unconfirmed" : playing.endedMotion ? "ended-then-posture" : "posture";
    return { motion: playing.endedMotion ?? motion, outcome };
  }
  if (by === "caller") c.requirePacketMode(COMMANDS.runMotion.name);
  if (activity.sendStop7(by)) {
    const sent = await c
      .writePacket(
        encodePacket(COMMANDS.runMotion.type, COMMANDS.runMotion.request(BASIC_POSTURE_MOTION)),
        COMMANDS.runMotion.type,
      )
      .then(
        () => true,
        () => false,
      );
    if (!sent) return { motion, outcome: "unconfirmed" };
  }
  const n = await within(c.clock, playing.ended, waitMs);
  if (n === BASIC_POSTURE_MOTION) return { motion, outcome: "stopped" };
  if (n !== motion) return { motion, outcome: "unconfirmed" };
  // It ended on its own just before the 7 arrived: the robot took the 7 as Run Motion 7 (basic posture).
  const posture = activity.motion;
  const confirmed = posture?.endedMotion === motion ? await posture.ended : undefined;
  const outcome = confirmed === BASIC_POSTURE_MOTION ? "ended-then-posture" : "unconfirmed";
  return { motion, outcome, endedFirst: true };
}

/**
 * The Run's reply showed that its motion ended just before the 7 (the activity machine now says Basic posture
 * plays): waits, in the next turn, for the posture's own `07`, and tells the machine how it ended.
 */
export function awaitPostureAfterEnd(core: ClientCore): void {
  const { c, activity } = core;
  const posture = activity.motion;
  if (!posture) return;
  c.exclusive(() =>
    c.transact(
      COMMANDS.runMotion.type,
      COMMANDS.runMotion.request(BASIC_POSTURE_MOTION),
      "Basic posture",
      postureDurationMs() + c.timeouts.marginMs,
      { accept: (p) => p.contents[0] === BASIC_POSTURE_MOTION, send: false },
    ),
  ).then(
    () => {
      c.setState({ basicPostureConfirmed: true });
      if (activity.isCurrent(posture)) activity.motionReplied(BASIC_POSTURE_MOTION);
    },
    () => {
      if (activity.isCurrent(posture)) activity.motionFailed();
    },
  );
}

/** `p`'s value, or undefined when it rejects or `ms` passes first (undefined `ms`: no limit). */
function within<T>(clock: Clock, p: Promise<T>, ms: number | undefined): Promise<T | undefined> {
  const wait = new Waitress<T | undefined>(clock).wait(
    undefined,
    ms === undefined ? {} : { deadline: { ms, value: () => undefined } },
  );
  p.then(wait.resolve, () => wait.resolve(undefined));
  return wait.promise;
}
