import { limpStoppedMotionFirstText, nothingSentText } from "../../i18n/outcomes/device.ts";
import { limpResultText, limpWarningText } from "../../i18n/outcomes/limp-words.ts";
import { said, saidBy } from "../../i18n/said.ts";
import { translator } from "../../i18n/translate.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { confirm } from "../confirm.ts";
import { connectRobot, robotPlace } from "../connect.ts";
import { CliError, EXIT } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { commandMessages } from "./messages.ts";

const OPTIONS = { yes: { type: "boolean", short: "y" } } as const;

export const limpCommand: CommandDef = {
  name: "limp",
  usage: "rbc limp [--yes] (--port PATH | --demo)",
  help: COMMAND_HELP.limp,
  examples: ["rbc limp --port /dev/ttyUSB0", "rbc limp --demo --yes"],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("limp", env.argv, OPTIONS);
    noExtraArguments("limp", positionals, 0);
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    if (!values.yes && !env.stdin.isTTY) {
      throw new CliError(
        "confirmation-required",
        said(commandMessages, "cmd.limp.needsYes", { warning: saidBy(limpWarningText) }),
      );
    }
    const robot = await connectRobot("limp", values, env);
    if (!values.yes) {
      env.out.note(limpWarningText(locale));
      const answer = await confirm(env, t("cmd.limp.question", { robot: robotPlace(robot, locale) }));
      if (answer === "interrupted") {
        throw new CliError("interrupted", saidBy(nothingSentText), EXIT.interrupted);
      }
      if (answer === "no")
        throw new CliError("not-confirmed", said(commandMessages, "cmd.limp.notConfirmed"));
    }
    const { confirmed, silent, stoppedMotionFirst } = await robot.client.limp();
    if (stoppedMotionFirst) env.out.line(limpStoppedMotionFirstText(locale));
    env.out.line(limpResultText({ confirmed, silent }, locale));
    env.out.result({
      ok: silent.length === 0,
      confirmed,
      silent,
      stoppedMotionFirst: stoppedMotionFirst === true,
    });
    return silent.length === 0 ? EXIT.ok : EXIT.failed;
  },
};
