import type { VirtualClock } from "../../src/shared/clock.ts";

/**
 * Runs a virtual clock's timers until `done` settles, like `VirtualClock.run`, but also waits for work that
 * is not on the clock (a dynamic `import()`, a file read): when no timer is set, it waits for the host's next
 * task instead of giving up, for up to `idleLimitMs` of real time in a row. Robot time still moves only from
 * timer to timer, so what a test sees never depends on how busy the machine is.
 */
export async function driveClock<T>(
  clock: VirtualClock,
  done: Promise<T>,
  { limitMs = 600_000, idleLimitMs = 10_000 } = {},
): Promise<T> {
  let finished = false;
  const tracked = done.finally(() => {
    finished = true;
  });
  tracked.catch(() => {});
  const limit = clock.now() + limitMs;
  let idleSince: number | undefined;
  await clock.advance(0);
  while (!finished) {
    const due = clock.nextDue;
    if (due !== undefined && due <= limit) {
      idleSince = undefined;
      await clock.advanceTo(due);
      continue;
    }
    if (due !== undefined) throw new Error(`driveClock: still pending after ${limitMs} ms of robot time`);
    idleSince ??= Date.now();
    if (Date.now() - idleSince > idleLimitMs) {
      throw new Error(`driveClock: no timer set and still pending after ${idleLimitMs} ms of real time`);
    }
    await new Promise((resolve) => setTimeout(resolve, 1));
  }
  return tracked;
}
