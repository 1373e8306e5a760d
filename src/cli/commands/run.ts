import { RbcError } from "../../device/errors.ts";
import type { StopActivityResult } from "../../device/rbc-client.ts";
import { isHazardousMotion, type RunReport } from "../../device/run-outcome.ts";
import { reconcile, shelfKey } from "../../device/shelf.ts";
import { errorSaid } from "../../i18n/error-said.ts";
import type { Locale } from "../../i18n/locale.ts";
import { motionHazardText, runCheckingText, runReportText } from "../../i18n/outcomes/run-words.ts";
import { said, saidBy, saidTogether } from "../../i18n/said.ts";
import { translator } from "../../i18n/translate.ts";
import { formatSeconds } from "../../i18n/units.ts";
import { BASIC_POSTURE_MOTION, downloadSlotOf, isOfferedMotionNumber } from "../../protocol/catalog.ts";
import { parseCommand } from "../args.ts";
import { type CommandDef, localeOf, type RunEnv } from "../command.ts";
import { connectRobot, type Robot } from "../connect.ts";
import { CliError, EXIT, SEE_LOG, UsageError } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { motionName } from "../motion-names.ts";
import { readShelves, shelfOf, shelfPath } from "../shelf-file.ts";
import { commandMessages } from "./messages.ts";
import { stoppedMotionSentence } from "./stop.ts";

export { motionName };

/** What rbc recorded uploading a downloaded motion (rbc shelf). */
interface Recorded {
  durationMs: number;
  name: string;
}

/**
 * What rbc recorded uploading the downloaded motions among `motions` (rbc shelf): the duration for the Run
 * check of docs/protocol.md §3.1 and the name to show — used only while the robot's free memory still allows
 * the record (`reconcile`); when it cannot be checked, or the shelf cannot be read, none (the check then says
 * what is known, and the motion is shown by its number and key).
 */
async function shelfRecords(
  robot: Robot,
  motions: readonly number[],
  env: RunEnv,
): Promise<Map<number, Recorded>> {
  const found = new Map<number, Recorded>();
  if (!motions.some((m) => downloadSlotOf(m) !== undefined)) return found;
  try {
    const file = await readShelves(shelfPath(env.env));
    if (file.robots.length === 0) return found;
    const { serialNumber } = await robot.client.identify();
    const free = await robot.client.readFreeMemory("motion");
    if (free === undefined) return found;
    const { shelf } = reconcile(shelfOf(file, shelfKey(serialNumber, robot.where)), free);
    for (const m of motions) {
      const slot = shelf.slots.find((s) => s.motionNumber === m);
      if (slot) found.set(m, { durationMs: slot.durationMs, name: slot.name });
    }
  } catch {
    // A shelf file that cannot be read changes nothing about the Run: its check says what is known.
  }
  return found;
}

const OPTIONS = { yes: { type: "boolean", short: "y" } } as const;

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
    const { values, positionals } = parseCommand("run", env.argv, OPTIONS);
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
    // Motions 20 and 21 carry a warning (docs/protocol.md §3.1): without --yes, nothing is sent.
    const hazardous = motions.find(isHazardousMotion);
    if (hazardous !== undefined && !values.yes) {
      throw new CliError(
        "confirmation-required",
        saidBy((l) =>
          translator(commandMessages, l)("cmd.run.needsYes", {
            hazard: motionHazardText(hazardous, l) ?? "",
            motion: String(hazardous),
          }),
        ),
      );
    }
    for (const n of new Set(motions.filter(isHazardousMotion))) {
      env.out.note(`rbc: ${t("cmd.run.hazardNote", { hazard: motionHazardText(n, locale) ?? "" })}`);
    }
    const robot = await connectRobot("run", values, env, { handlesInterrupt: true });
    const recorded = await shelfRecords(robot, motions, env);
    const results: Array<Record<string, unknown>> = [];
    for (const motion of motions) {
      const record = recorded.get(motion);
      const name = motionName(motion, "en", record?.name);
      const shown = motionName(motion, locale, record?.name);
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
      const started = robot.clock.now();
      // Ctrl-C: end the motion with 7 (Stop), never limp; the robot holds the pose it stopped in.
      let stopping: Promise<StopActivityResult | undefined> | undefined;
      const onInterrupt = () => {
        env.setExitNote(t("cmd.run.stoppingUnknown", { motion: shown }));
        stopping = robot.client.stopActivity().catch(() => undefined);
      };
      env.signal.addEventListener("abort", onInterrupt, { once: true });
      let failure: unknown;
      let report: RunReport | undefined;
      try {
        const expectedMs = record?.durationMs;
        // "Sent: checking" once the Run's checks are done and its packet is being written (never before: a Run
        // the busy probe refuses is not sent), then the verdict as the robot showed it (docs/protocol.md §3.1).
        const ready = () => {
          env.out.line(`${runCheckingText(shown, locale)}…`);
          return Promise.resolve();
        };
        report = await robot.client.runMotionReport(
          motion,
          expectedMs === undefined ? { ready } : { expectedMs, ready },
        );
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
        if (e instanceof RbcError && e.code === "busy") {
          throw new CliError(
            "busy",
            saidTogether([errorSaid(e, { detailHint: SEE_LOG }), said(commandMessages, "cmd.run.stopHint")]),
            EXIT.failed,
            {
              completed: results,
            },
          );
        }
        if (e instanceof RbcError && e.code === "motion-ignored") {
          const hint = robot.demo
            ? said(commandMessages, "cmd.run.ignoredDemo", { motion: String(motion) })
            : said(commandMessages, "cmd.run.ignored", {
                posture: String(BASIC_POSTURE_MOTION),
                motion: String(motion),
              });
          throw new CliError(
            "motion-ignored",
            saidTogether([errorSaid(e, { detailHint: SEE_LOG }), hint]),
            EXIT.failed,
            {
              completed: results,
            },
          );
        }
        throw e;
      }
      if (!report) throw new Error("unreachable: no report and no failure");
      const elapsedMs = Math.round(robot.clock.now() - started);
      const facts = {
        verdict: report.verdict,
        expectedMs: report.expectedMs ?? null,
        replyAfterMs: report.elapsedMs,
        before: report.before,
        busySeen: report.busySeen,
      };
      const what = (l: Locale) => runReportText(report, l) ?? "";
      // Exit 1 only for a Run known not to have played (docs/protocol.md §3.1 [decision, turn 4]); "not known"
      // is said as such and exits 0: the robot may well have played it.
      if (report.verdict === "ignored" || report.verdict === "after-busy") {
        throw new CliError("not-played", saidBy(what), EXIT.failed, {
          completed: results,
          motion,
          ...facts,
        });
      }
      results.push({ motion, name, elapsedMs, ...facts });
      if (report.verdict === "stopped-busy") env.out.line(t("cmd.run.stoppedBusy", { what: what(locale) }));
      else if (report.verdict === "not-known") {
        env.out.line(t("cmd.run.notKnown", { motion: shown, what: what(locale) }));
      } else {
        env.out.line(
          t("cmd.run.played", { motion: shown, duration: formatSeconds(report.elapsedMs / 1000, locale) }),
        );
      }
    }
    env.out.result({ ok: true, completed: results });
    return EXIT.ok;
  },
};
