import { RbcError } from "../../device/errors.ts";
import type { StopActivityResult } from "../../device/rbc-client.ts";
import { translator } from "../../i18n/translate.ts";
import { formatSeconds } from "../../i18n/units.ts";
import { BASIC_POSTURE_MOTION, isOfferedMotionNumber } from "../../protocol/catalog.ts";
import { parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { connectRobot } from "../connect.ts";
import { CliError, EXIT, errorSaid, UsageError } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { motionName } from "../motion-names.ts";
import { joinSaid, said } from "../said.ts";
import { commandMessages } from "./messages.ts";
import { stoppedMotionSentence } from "./stop.ts";

export { motionName };

export const runCommand: CommandDef = {
  name: "run",
  usage: "rbc run N [N …] (--port PATH | --demo)",
  help: COMMAND_HELP.run,
  examples: [
    "rbc run 7 --port /dev/ttyUSB0",
    "rbc run 7 4 4 --demo",
    "rbc run 12 --port /dev/ttyUSB0 --json",
  ],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("run", env.argv, {});
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    if (positionals.length === 0) throw new UsageError(said(commandMessages, "cmd.run.noMotion"), "run");
    const motions = positionals.map((p) => {
      const n = Number(p);
      if (!/^\d+$/.test(p) || !isOfferedMotionNumber(n)) {
        throw new UsageError(said(commandMessages, "cmd.run.notOffered", { motion: p }), "run");
      }
      return n;
    });
    const robot = await connectRobot("run", values, env, { handlesInterrupt: true });
    const results: Array<{ motion: number; name: string; elapsedMs: number }> = [];
    for (const motion of motions) {
      const name = motionName(motion);
      const shown = motionName(motion, locale);
      if (results.length > 0) await env.out.settle();
      if (env.signal.aborted) {
        // Interrupted between two motions (or stdout was closed): do not start the next one.
        env.out.note(`rbc: ${t("cmd.run.notStarted", { motion: shown })}`);
        env.out.result({
          ok: false,
          completed: results,
          error: { code: "interrupted", message: "Interrupted." },
        });
        return EXIT.interrupted;
      }
      env.out.line(t("cmd.run.running", { motion: shown }));
      const started = robot.clock.now();
      // Ctrl-C: end the motion with 7 (Stop), never limp; the robot keeps standing.
      let stopping: Promise<StopActivityResult | undefined> | undefined;
      const onInterrupt = () => {
        env.setExitNote(t("cmd.run.stoppingUnknown", { motion: shown }));
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
        env.out.note(
          `rbc: ${t("cmd.interruptedBecause", { what: stoppedMotionSentence(result, shown, locale) })}`,
        );
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
            ? said(commandMessages, "cmd.run.ignoredDemo", { motion: String(motion) })
            : said(commandMessages, "cmd.run.ignored", {
                posture: String(BASIC_POSTURE_MOTION),
                motion: String(motion),
              });
          throw new CliError("motion-ignored", joinSaid([errorSaid(e), hint]), EXIT.failed, {
            completed: results,
          });
        }
        throw e;
      }
      const elapsedMs = Math.round(robot.clock.now() - started);
      results.push({ motion, name, elapsedMs });
      env.out.line(t("cmd.run.done", { motion: shown, duration: formatSeconds(elapsedMs / 1000, locale) }));
    }
    env.out.result({ ok: true, completed: results });
    return EXIT.ok;
  },
};
