import { said } from "../../i18n/said.ts";
import type { CommandDef } from "../command.ts";
import { UsageError } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { commandMessages } from "./messages.ts";

export const logCommand: CommandDef = {
  name: "log",
  usage: "rbc log [COMMAND [ARGS …]] (--port PATH | --demo)",
  help: COMMAND_HELP.log,
  examples: [
    "rbc log info --demo",
    "rbc log zeros read --port /dev/ttyUSB0 2> trace.txt",
    "rbc upload Hi.rbm --demo --log",
  ],
  talksToRobot: true,
  async run(env) {
    const { findCommand } = await import("./index.ts");
    const { splitCommand } = await import("../args.ts");
    const { command, rest } = splitCommand(env.argv);
    const name = command ?? "info";
    const target = findCommand(name);
    if (!target || target.name === "log") {
      throw new UsageError(said(commandMessages, "cmd.log.unknown", { name }), "log");
    }
    if (target.name === "sim") throw new UsageError(said(commandMessages, "cmd.log.sim"), "log");
    if (target.streams) env.out.streaming();
    return target.run({ ...env, argv: [...rest, ...(rest.includes("--log") ? [] : ["--log"])] });
  },
};
