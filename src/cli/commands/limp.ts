import { noExtraArguments, parseCommand } from "../args.ts";
import type { CommandDef } from "../command.ts";
import { confirm } from "../confirm.ts";
import { connectRobot } from "../connect.ts";
import { CliError, EXIT } from "../errors.ts";

const OPTIONS = { yes: { type: "boolean", short: "y" } } as const;

const WARNING = "Hold the robot: every servo will go passive and it will fall if nobody holds it.";

export const limpCommand: CommandDef = {
  name: "limp",
  summary: "make every servo passive (the robot falls unless held); asks first",
  usage: "rbc limp [--yes] (--port PATH | --demo)",
  description: `
Makes servos 0-15 passive: they stop holding, and a standing robot falls unless someone holds it. rbc asks
first (y/N); --yes skips the question, and without a terminal --yes is required. A motion that plays is
ended with 7 first and a sound waited out, as the robot takes nothing else meanwhile. rbc reports how many
servos confirmed. To end a motion and keep the robot standing, use \`rbc stop\` instead.

The robot is left in its normal mode when rbc exits; the servos stay passive until they are moved again
(a motion, or the panel's Servos view).`,
  options: [["-y, --yes", "Make the servos passive without the question."]],
  examples: ["rbc limp --port /dev/ttyUSB0", "rbc limp --demo --yes"],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("limp", env.argv, OPTIONS);
    noExtraArguments("limp", positionals, 0);
    if (!values.yes && !env.stdin.isTTY) {
      throw new CliError(
        "confirmation-required",
        `${WARNING} Add --yes to make every servo passive (nothing was sent).`,
      );
    }
    const robot = await connectRobot("limp", values, env);
    if (!values.yes) {
      env.out.note(WARNING);
      const answer = await confirm(env, `Make every servo of ${robot.where} passive?`);
      if (answer === "interrupted") throw new CliError("interrupted", "Nothing was sent.", EXIT.interrupted);
      if (answer === "no") throw new CliError("not-confirmed", "Limp not confirmed; nothing was sent.");
    }
    const { confirmed, silent } = await robot.client.limp();
    if (silent.length === 0) {
      env.out.line(
        `All ${confirmed.length} servos confirmed passive. Hold the robot: it cannot stand on its own.`,
      );
    } else {
      env.out.line(
        `${confirmed.length} servos confirmed passive; servo ${silent.join(", ")} did not answer. If anything still moves, switch the robot off.`,
      );
    }
    env.out.result({ ok: silent.length === 0, confirmed, silent });
    return silent.length === 0 ? EXIT.ok : EXIT.failed;
  },
};
