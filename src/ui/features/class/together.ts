import type { RunReport } from "../../../device/run-outcome.ts";
import { COMMANDS } from "../../../protocol/commands.ts";
import type { Notice, RobotStop } from "../../app-state.ts";
import { stopOutcome } from "../../stop-outcome.ts";
import type { ClassRoom, RobotLink } from "./class-room.ts";
import { robotNamed } from "./names.ts";
import { failedNotice, limpResultNotice, runResultNotice } from "./result-words.ts";
import { classOf, patchClass, patchRobot } from "./state.ts";

/**
 * What the class does together: Run on all, Stop all, Limp all. Each robot is driven on its own connection and
 * awaited on its own (`Promise.allSettled`), so a robot that fails, is busy or is gone gets its own result and
 * never holds up or colours the others'.
 */

const RUN_MOTION = COMMANDS.runMotion.type;

/**
 * A gate that opens when each of `count` runners has arrived or dropped out (failed before it got there), so
 * that none waits for a robot that will never come.
 */
export function startingGate(count: number): { arrive(): Promise<void>; dropOut(): void } {
  let waiting = count;
  let open!: () => void;
  const opened = new Promise<void>((resolve) => {
    open = resolve;
  });
  const one = () => {
    waiting--;
    if (waiting <= 0) open();
  };
  return {
    arrive() {
      one();
      return opened;
    },
    dropOut: one,
  };
}

/**
 * Sends motion `number` to every robot of `links`, written in the same tick: each client first makes sure
 * nothing else is playing (the busy probe of docs/protocol.md §3.6, which the device's verdict needs) and then
 * waits at a starting gate (`RunMotionOptions.ready`) until every robot has got that far or dropped out; then
 * every Run packet is written. The skew is measured where the Run packets are written (the clients' packet
 * logs), first to last, in `now()` time (performance.now in the page). Each robot's result is the device's
 * verdict (`runMotionReport`): a `14 nn` reply alone never proves motion nn played.
 */
export async function runOnEach(
  room: ClassRoom,
  links: readonly RobotLink[],
  number: number,
  now: () => number,
): Promise<void> {
  const { store } = room;
  if (links.length === 0) return;
  const written = new Map<number, number>();
  const listening = links.map((link) =>
    link.client.log.on((entry) => {
      if (entry.direction !== "out" || entry.kind !== "packet" || entry.type !== RUN_MOTION) return;
      if (!written.has(link.id)) written.set(link.id, now());
    }),
  );
  for (const link of links) patchRobot(store, link.id, { task: "run", result: undefined });
  const gate = startingGate(links.length);
  const runs: Promise<RunReport>[] = links.map(async (link) => {
    let arrived = false;
    try {
      if (link.client.mode === "direct") await link.client.exitDirectMode();
      return await link.client.runMotionReport(number, {
        ready: () => {
          arrived = true;
          return gate.arrive();
        },
      });
    } finally {
      if (!arrived) gate.dropOut();
    }
  });
  const settled = await Promise.allSettled(runs);
  for (const stop of listening) stop();
  const times = [...written.values()];
  const skewMs = times.length > 0 ? Math.max(...times) - Math.min(...times) : 0;
  const { locale } = store.get();
  links.forEach((link, i) => {
    const outcome = settled[i]!;
    patchRobot(store, link.id, (r) => ({
      task: r.task === "run" ? undefined : r.task,
      result: runResultNotice(outcome, locale),
    }));
  });
  patchClass(store, { lastRun: { number, robots: times.length, skewMs } });
}

/**
 * Stop on every robot (7 to each one playing a motion, an upload cancelled); each says what it confirmed, in
 * its row and in what this returns (the top bar says it too: `stopAll`, src/ui/stop-all.ts).
 */
export async function stopEach(room: ClassRoom, links: readonly RobotLink[]): Promise<RobotStop[]> {
  const { store } = room;
  return Promise.all(
    links.map(async (link) => {
      link.abort?.abort();
      let result: Notice;
      try {
        result = stopOutcome(await link.client.stopActivity(), false, store.get().locale);
      } catch (e) {
        result = failedNotice("stop", e, store.get().locale);
      }
      patchRobot(store, link.id, { result });
      return { robot: robotNamed(classOf(store.get()), link.id), notice: result };
    }),
  );
}

/** Limp on every robot: every servo passive (the view asked once, naming how many robots will fall). */
export async function limpEach(room: ClassRoom, links: readonly RobotLink[]): Promise<void> {
  const { store } = room;
  await Promise.all(
    links.map(async (link) => {
      link.abort?.abort();
      try {
        const result = await link.client.limp();
        patchRobot(store, link.id, { result: limpResultNotice(result, store.get().locale) });
      } catch (e) {
        patchRobot(store, link.id, { result: failedNotice("limp", e, store.get().locale) });
      }
    }),
  );
}
