import type { CommandDef } from "../command.ts";
import { UsageError } from "../errors.ts";

export const logCommand: CommandDef = {
  name: "log",
  summary: "run a command and show its packet trace (same as adding --log)",
  usage: "rbc log [COMMAND [ARGS …]] (--port PATH | --demo)",
  description: `
Runs COMMAND (default: info) and prints every packet that goes over the link, in hex with the command's
name and a time in seconds, on stderr, while the command's own output stays on stdout:

     0.001  PC→RBC  leave direct mode (blind)       FF E0 FB 01 00 1A
     0.052  PC→RBC  0x12 Read firmware version      FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01
     0.055  RBC→PC  0x12 Read firmware version      FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 15

\`rbc log info --demo\` is the same as \`rbc info --demo --log\`; --log works with every command. With --json
the trace lines are JSON objects (one per line, on stderr). To keep a trace: rbc log info --port … 2> trace.txt`,
  options: [],
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
    if (!target || target.name === "log") throw new UsageError(`Unknown command "${name}" to log.`, "log");
    if (target.name === "sim") throw new UsageError("rbc sim prints its own packet trace.", "log");
    if (target.streams) env.out.streaming();
    return target.run({ ...env, argv: [...rest, ...(rest.includes("--log") ? [] : ["--log"])] });
  },
};
