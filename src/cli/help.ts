import type { CommandDef } from "./command.ts";

/** Help texts: `rbc --help` (overview) and `rbc COMMAND --help` (one command). */

const ROBOT_OPTIONS: ReadonlyArray<readonly [string, string]> = [
  [
    "-p, --port PATH",
    "Serial port of the robot, e.g. /dev/ttyUSB0 or COM3 (see `rbc ports`). Default: $RBC_PORT.",
  ],
  ["--demo", "Use the built-in simulated robot instead (firmware 2.23, HUNO, just switched on)."],
];

const JSON_OPTION = [
  "--json",
  "Print the result as JSON on stdout (messages and progress stay on stderr).",
] as const;
const LOG_OPTION = [
  "--log",
  "Print the packet trace (every packet in hex, with its command name) on stderr.",
] as const;
const HELP_OPTION = ["-h, --help", "Show help."] as const;
const COMMON_OPTIONS: ReadonlyArray<readonly [string, string]> = [JSON_OPTION, LOG_OPTION, HELP_OPTION];

function table(rows: ReadonlyArray<readonly [string, string]>, indent = "  "): string {
  const width = Math.min(24, Math.max(...rows.map(([a]) => a.length)));
  return rows
    .map(([a, b]) =>
      a.length > width
        ? `${indent}${a}\n${indent}${" ".repeat(width + 2)}${b}`
        : `${indent}${a.padEnd(width)}  ${b}`,
    )
    .join("\n");
}

export function globalHelp(commands: readonly CommandDef[]): string {
  return `rbc — control a Robobuilder RBC robot controller from the command line

Usage: rbc COMMAND [options]

Every command that talks to a robot needs --port PATH (the robot's serial port) or --demo (a simulated
robot built into rbc, to try things without hardware).

Commands:
${table(commands.map((c) => [c.name, c.summary]))}

Options for every command:
${table([...ROBOT_OPTIONS, ...COMMON_OPTIONS])}

Exit codes: 0 done, 1 failed (the reason is one line on stderr), 2 wrong command line, 130 interrupted (Ctrl-C).

Examples:
  rbc ports                          find the robot's serial port
  rbc info --port /dev/ttyUSB0       firmware, serial number, error code, free memory
  rbc info --demo                    the same against the simulated robot
  rbc run 7 --demo                   basic posture (needed once after switching on)
  rbc sim --pty                      serve a simulated robot on a pseudo serial port

Run \`rbc COMMAND --help\` for details of one command.
`;
}

export function commandHelp(command: CommandDef): string {
  const options = command.talksToRobot
    ? [...command.options, ...ROBOT_OPTIONS, ...COMMON_OPTIONS]
    : [...command.options, JSON_OPTION, HELP_OPTION];
  const examples = command.examples.map((e) => `  ${e}`).join("\n");
  return `rbc ${command.name} — ${command.summary}

Usage: ${command.usage}

${command.description.trim()}

Options:
${table(options)}
${examples ? `\nExamples:\n${examples}\n` : ""}`;
}
