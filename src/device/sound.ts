import { COMMANDS } from "../protocol/commands.ts";
import type { ClientCore } from "./client-core.ts";
import { RbcInvalidArgumentError } from "./errors.ts";

/**
 * `RbcClient.runSound`: plays sound 1-25 and resolves when the robot reports it finished (200 ms + its length).
 * The activity machine holds the sound while it plays, for Stop and Limp to wait out (the RBC receives nothing
 * meanwhile, docs/protocol.md §3.6).
 */
export function runSound(
  core: ClientCore,
  sound: number,
  options: { signal?: AbortSignal },
): Promise<number> {
  const { c, activity } = core;
  const expectedMs = Number.isInteger(sound) ? COMMANDS.runSound.expectedMs?.(sound) : undefined;
  if (expectedMs === undefined) {
    return Promise.reject(
      new RbcInvalidArgumentError(`Sound number must be 1-25, got ${sound}. Nothing was sent.`),
    );
  }
  return c.exclusive(async () => {
    c.requirePacketMode(COMMANDS.runSound.name);
    const started = activity.startSound(sound, expectedMs);
    let echo: number | undefined;
    try {
      echo = await c.request(COMMANDS.runSound, sound, { signal: options.signal });
      return echo;
    } finally {
      if (activity.isCurrent(started)) activity.soundEnded(echo);
    }
  });
}
