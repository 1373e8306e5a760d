import { SOUND_REPLY_DELAY_MS } from "../protocol/catalog.ts";
import { COMMANDS } from "../protocol/commands.ts";
import { sleep } from "../shared/clock.ts";
import type { ClientCore } from "./client-core.ts";
import { RbcCancelledError, RbcInvalidArgumentError } from "./errors.ts";

/** What a played sound's reply showed (docs/protocol.md §3.3, §9). */
export interface SoundReport {
  sound: number;
  /** From the request to the robot's reply, ms. */
  replyAfterMs: number;
  /** How long the sound keeps the robot busy: 200 ms + its length. */
  expectedMs: number;
  /**
   * The reply came before the sound can have played to its end: this firmware answers first and plays after
   * (docs/protocol.md §9, "a variant whose Run Sound reply comes at once"). The reply then proves only that the
   * request arrived; the client waited out the sound's length before sending anything else (the robot receives
   * nothing while a sound plays).
   */
  repliedAtOnce: boolean;
}

/**
 * `RbcClient.playSound`: plays sound 1-25 and resolves when it has ended — when the robot reports it finished
 * (200 ms + its length), or, on a firmware that answers at once, when its length has passed after that answer.
 * The activity machine holds the sound the whole time, for Stop and Limp to wait out (the RBC receives nothing
 * meanwhile, docs/protocol.md §3.6).
 */
export function playSound(
  core: ClientCore,
  sound: number,
  options: { signal?: AbortSignal },
): Promise<SoundReport> {
  const { c, activity } = core;
  const expectedMs = Number.isInteger(sound) ? COMMANDS.runSound.expectedMs?.(sound) : undefined;
  if (expectedMs === undefined) {
    return Promise.reject(new RbcInvalidArgumentError(undefined, { kind: "sound-number-range", sound }));
  }
  return c.exclusive(async () => {
    c.requirePacketMode(COMMANDS.runSound.name);
    const started = activity.startSound(sound, expectedMs);
    let echo: number | undefined;
    try {
      echo = await c.request(COMMANDS.runSound, sound, { signal: options.signal });
      const replyAfterMs = c.clock.now() - started.startedAt;
      // A reply sooner than the sound's own length cannot mark its end (docs/protocol.md §3.3).
      const repliedAtOnce = replyAfterMs < expectedMs - SOUND_REPLY_DELAY_MS;
      if (repliedAtOnce) {
        const left = started.startedAt + expectedMs - c.clock.now();
        await sleep(c.clock, left, options.signal, () => new RbcCancelledError());
      }
      return { sound, replyAfterMs, expectedMs, repliedAtOnce };
    } finally {
      if (activity.isCurrent(started)) activity.soundEnded(echo);
    }
  });
}

/** `RbcClient.runSound`: `playSound`, resolving with the robot's echo (the sound's number). */
export async function runSound(
  core: ClientCore,
  sound: number,
  options: { signal?: AbortSignal },
): Promise<number> {
  return (await playSound(core, sound, options)).sound;
}
