import { RbcError } from "../../device/errors.ts";
import type { StopActivityResult } from "../../device/rbc-client.ts";
import {
  BASIC_POSTURE_MOTION,
  BUILT_IN_MOTIONS,
  downloadSlotOf,
  isOfferedMotionNumber,
} from "../../protocol/catalog.ts";
import { parseCommand } from "../args.ts";
import type { CommandDef } from "../command.ts";
import { connectRobot } from "../connect.ts";
import { CliError, EXIT, UsageError } from "../errors.ts";
import { stoppedMotionSentence } from "./stop.ts";

/** "7 (Basic posture)", "12 (downloaded motion 1)". */
export function motionName(n: number): string {
  const builtIn = BUILT_IN_MOTIONS.find((m) => m.number === n);
  if (builtIn) return `${n} (${builtIn.name})`;
  const slot = downloadSlotOf(n);
  return slot === undefined ? String(n) : `${n} (downloaded motion ${slot})`;
}

const MOTION_LIST = BUILT_IN_MOTIONS.map((m) => `  ${String(m.number).padStart(2)}  ${m.name}`).join("\n");

export const runCommand: CommandDef = {
  name: "run",
  summary: "run motions (7 = basic posture) and wait until they finish",
  usage: "rbc run N [N …] (--port PATH | --demo)",
  description: `
Runs motion N and waits for the robot to report that it finished (it answers only then). Several
numbers run one after the other. The built-in motions:

${MOTION_LIST}

Downloaded motions: 12-21 play downloads 1-10, 33-42 play downloads 11-20 (see \`rbc upload\`).
Other numbers are refused (some start battery charging or move to the raw zero pose).

After it is switched on, the RBC ignores every motion until 7 (basic posture) has run once; rbc says so
when that happens. The demo robot is switched on afresh by every rbc command, so put 7 first there:
\`rbc run 7 4 --demo\`.

Ctrl-C stops the motion as \`rbc stop\` does (exit code 130): rbc sends 7, the robot ends the motion at the
end of its current scene and keeps standing in that pose, and rbc says whether the robot confirmed (07).
No servo is made passive, and the motions after it are not started. A second Ctrl-C exits at once.`,
  options: [],
  examples: [
    "rbc run 7 --port /dev/ttyUSB0",
    "rbc run 7 4 4 --demo",
    "rbc run 12 --port /dev/ttyUSB0 --json",
  ],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("run", env.argv, {});
    if (positionals.length === 0) throw new UsageError("Give the motion number, e.g. rbc run 7.", "run");
    const motions = positionals.map((p) => {
      const n = Number(p);
      if (!/^\d+$/.test(p) || !isOfferedMotionNumber(n)) {
        throw new UsageError(
          `Motion "${p}" is not one rbc runs: use 1-11, 12-21 or 33-42 (see rbc run --help).`,
          "run",
        );
      }
      return n;
    });
    const robot = await connectRobot("run", values, env, { handlesInterrupt: true });
    const results: Array<{ motion: number; name: string; elapsedMs: number }> = [];
    for (const motion of motions) {
      const name = motionName(motion);
      if (results.length > 0) await env.out.settle();
      if (env.signal.aborted) {
        // Interrupted between two motions (or stdout was closed): do not start the next one.
        env.out.note(`rbc: stopped before motion ${name}; it was not started.`);
        env.out.result({
          ok: false,
          completed: results,
          error: { code: "interrupted", message: "Interrupted." },
        });
        return EXIT.interrupted;
      }
      env.out.line(`Running ${name}…`);
      const started = robot.clock.now();
      // Ctrl-C: end the motion with 7 (Stop), never limp; the robot keeps standing.
      let stopping: Promise<StopActivityResult | undefined> | undefined;
      const onInterrupt = () => {
        env.setExitNote(
          `motion ${name} was being stopped with 7; whether the robot confirmed is not known. If it still moves, hold it (rbc limp makes every servo passive).`,
        );
        stopping = robot.client.stopActivity().catch(() => undefined);
      };
      env.signal.addEventListener("abort", onInterrupt, { once: true });
      let failure: unknown;
      try {
        await robot.client.runMotion(motion);
      } catch (e) {
        failure = e;
      } finally {
        env.signal.removeEventListener("abort", onInterrupt);
      }
      if (stopping) {
        const result = await stopping;
        env.setExitNote(undefined);
        env.out.note(`rbc: interrupted: ${stoppedMotionSentence(result, name)}`);
        env.out.result({
          ok: false,
          completed: results,
          stopped: { motion, outcome: result?.motion?.outcome ?? "not-playing" },
          error: { code: "interrupted", message: "Interrupted." },
        });
        return EXIT.interrupted;
      }
      if (failure !== undefined) {
        const e = failure;
        if (e instanceof RbcError && e.code === "motion-ignored") {
          const hint = robot.demo
            ? ` The demo robot is switched on afresh by every rbc command: put 7 first, e.g. rbc run 7 ${motion} --demo.`
            : ` Run \`rbc run ${BASIC_POSTURE_MOTION}\` first (or \`rbc run 7 ${motion}\`).`;
          throw new CliError("motion-ignored", `${e.message}${hint}`, EXIT.failed, { completed: results });
        }
        throw e;
      }
      const elapsedMs = Math.round(robot.clock.now() - started);
      results.push({ motion, name, elapsedMs });
      env.out.line(`Done: ${name} in ${(elapsedMs / 1000).toFixed(1)} s.`);
    }
    env.out.result({ ok: true, completed: results });
    return EXIT.ok;
  },
};
