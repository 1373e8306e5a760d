import type { StopActivityResult } from "../../device/rbc-client.ts";
import type { Locale } from "../../i18n/locale.ts";
import {
  motionNotPlayingText,
  stopFoundText,
  stoppedMotionDetailText,
  stoppedMotionText,
} from "../../i18n/outcomes/stop-words.ts";
import { said, saidBy, saidTogether } from "../../i18n/said.ts";
import { translator } from "../../i18n/translate.ts";
import { BASIC_POSTURE_MOTION } from "../../protocol/catalog.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { connectRobot, robotPlace } from "../connect.ts";
import { CliError, EXIT } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { commandMessages } from "./messages.ts";

/**
 * What Stop did to a motion, never more certain than the robot's reply, with what to do next and the 7/07
 * detail (used by `rbc run` on Ctrl-C). `name` is the motion's name in `locale`.
 */
export function stoppedMotionSentence(
  result: StopActivityResult | undefined,
  name: string,
  locale: Locale = "en",
): string {
  const motion = result?.motion;
  if (!motion) return motionNotPlayingText(name, locale);
  const t = translator(commandMessages, locale);
  const next =
    motion.outcome === "stopped"
      ? [t("cmd.stop.straighten")]
      : motion.outcome === "unconfirmed"
        ? [t("cmd.stop.holdHint")]
        : [];
  return [stoppedMotionText(motion, locale), ...next, stoppedMotionDetailText(motion, locale)].join(" ");
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
    env.out.line(t("cmd.stop.asking", { robot: robotPlace(robot, locale) }));
    // A fresh connection started nothing: Stop asks the robot with the busy probe and sends 7 only when it is
    // busy (docs/protocol.md §3.6; issue 21 item 4).
    const { found } = await robot.client.stopActivity();
    const words = (l: Locale) => (found ? stopFoundText(found, l) : "");
    switch (found?.kind) {
      case "idle":
        env.out.line(words(locale));
        env.out.result({ ok: true, found: "idle", sent: null, confirmed: false });
        return EXIT.ok;
      case "stopped":
        env.out.line(`${words(locale)} ${t("cmd.stop.noServoPassive")}`);
        env.out.result({
          ok: true,
          found: "busy",
          sent: BASIC_POSTURE_MOTION,
          confirmed: true,
          elapsedMs: found.elapsedMs,
        });
        return EXIT.ok;
      case "unconfirmed":
        throw new CliError(
          "not-confirmed",
          saidTogether([saidBy(words), said(commandMessages, "cmd.stop.holdHint")]),
          EXIT.failed,
          {
            found: "busy",
            sent: BASIC_POSTURE_MOTION,
            confirmed: false,
            cause: found.noReply.cause,
            errorCode: found.noReply.errorCode ?? null,
          },
        );
      default:
        // No answer at all (a fresh connection always probes, so `found` is there).
        throw new CliError("timeout", saidBy(words), EXIT.failed, {
          found: "unknown",
          sent: null,
          confirmed: false,
        });
    }
  },
};
