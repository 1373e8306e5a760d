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

/** Wraps a paragraph at `width` columns, keeping `quoted commands` on one line. */
function wrap(text: string, width = 108): string {
  const KEEP = "\u0001";
  const kept = text.replace(/`[^`]*`/g, (q) => q.replaceAll(" ", KEEP));
  const lines: string[] = [];
  let line = "";
  for (const word of kept.split(/[ \n]+/).filter((w) => w !== "")) {
    if (line && line.length + 1 + word.length > width) {
      lines.push(line);
      line = word;
    } else {
      line = line ? `${line} ${word}` : word;
    }
  }
  if (line) lines.push(line);
  return lines.join("\n").replaceAll(KEEP, " ");
}

export function globalHelp(commands: readonly CommandDef[]): string {
  const robotCommands = commands
    .filter((c) => c.talksToRobot)
    .map((c) => c.name)
    .join(", ");
  return `rbc — control a Robobuilder RBC robot controller from the command line

Usage: rbc COMMAND [options]

${wrap(`The commands that talk to a robot (${robotCommands}) need --port PATH (the robot's serial port) or
--demo (a simulated robot built into rbc, to try things without hardware). \`rbc ports\` takes neither;
\`rbc sim\` takes --port PATH (the device to serve the simulator on) or --pty, and refuses --demo.`)}

Commands:
${table(commands.map((c) => [c.name, c.summary]))}

Options of the commands that talk to a robot:
${table([...ROBOT_OPTIONS, LOG_OPTION])}

Options of every command:
${table([JSON_OPTION, HELP_OPTION])}

For tests and developers: RBC_DEMO_TIME_SCALE=N runs the demo robot N times faster (durations stay robot time);
RBC_DEMO_VARIANT="--no-serial --firmware 9.99 …" makes it one of the firmware variants of \`rbc sim\` (see its help).

Exit codes: 0 done, 1 failed (the reason is one line on stderr), 2 wrong command line, 130 interrupted (Ctrl-C),
143 stopped by SIGTERM (e.g. \`kill\`). With --json a failure is a JSON document on stdout too,
{"ok":false,"error":{"code":…,"message":…}}: one line for the commands that stream JSON lines (sensors, sim).

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
