import { RbcError, RbcRunNoReplyError } from "../../device/errors.ts";
import type { StopActivityResult } from "../../device/rbc-client.ts";
import type { Locale } from "../../i18n/locale.ts";
import { noReplyCauseText } from "../../i18n/outcomes/run-words.ts";
import { translator } from "../../i18n/translate.ts";
import { formatSeconds } from "../../i18n/units.ts";
import { BASIC_POSTURE_MOTION } from "../../protocol/catalog.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { connectRobot, robotPlace } from "../connect.ts";
import { CliError, EXIT } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { joinSaid, said, saidBy } from "../said.ts";
import { commandMessages } from "./messages.ts";

/**
 * What Stop did to a motion, in one sentence, never more certain than the robot's reply (used by `rbc run` on
 * Ctrl-C). `name` is the motion's name in `locale`.
 */
export function stoppedMotionSentence(
  result: StopActivityResult | undefined,
  name: string,
  locale: Locale = "en",
): string {
  const t = translator(commandMessages, locale);
  switch (result?.motion?.outcome) {
    case "stopped":
      return t("cmd.stop.stopped", { motion: name });
    case "ended-then-posture":
      return t("cmd.stop.endedThenPosture", { motion: name });
    case "posture":
      return t("cmd.stop.posture");
    case "unconfirmed":
      return t("cmd.stop.unconfirmed", { motion: name });
    default:
      return t("cmd.stop.notPlaying", { motion: name });
  }
}

export const stopCommand: CommandDef = {
  name: "stop",
  usage: "rbc stop (--port PATH | --demo)",
  help: COMMAND_HELP.stop,
  examples: ["rbc stop --port /dev/ttyUSB0", "rbc stop --demo --json"],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("stop", env.argv, {});
    noExtraArguments("stop", positionals, 0);
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    const robot = await connectRobot("stop", values, env);
    const started = robot.clock.now();
    env.out.line(t("cmd.stop.sending", { robot: robotPlace(robot, locale) }));
    try {
      await robot.client.stopMotion();
    } catch (e) {
      // Unanswered: what the error code (0x11) and the busy probe showed (docs/protocol.md §3.1 [decision]).
      if (e instanceof RbcRunNoReplyError && e.facts.cause !== "unknown" && e.facts.cause !== "power-up") {
        const { facts } = e;
        throw new CliError(
          "not-confirmed",
          joinSaid([
            said(commandMessages, "cmd.stop.notConfirmed"),
            saidBy((l) => noReplyCauseText(facts, l)),
          ]),
          EXIT.failed,
          {
            sent: BASIC_POSTURE_MOTION,
            confirmed: false,
            cause: facts.cause,
            errorCode: facts.errorCode ?? null,
          },
        );
      }
      if (e instanceof RbcError && (e.code === "timeout" || e.code === "motion-ignored")) {
        throw new CliError("not-confirmed", said(commandMessages, "cmd.stop.notConfirmed"), EXIT.failed, {
          sent: BASIC_POSTURE_MOTION,
          confirmed: false,
        });
      }
      throw e;
    }
    const elapsedMs = Math.round(robot.clock.now() - started);
    env.out.line(t("cmd.stop.confirmed", { duration: formatSeconds(elapsedMs / 1000, locale) }));
    env.out.result({ ok: true, sent: BASIC_POSTURE_MOTION, confirmed: true, elapsedMs });
    return EXIT.ok;
  },
};
