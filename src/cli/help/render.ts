import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import type { CommandDef } from "../command.ts";
import { helpMessages } from "./messages.ts";

/** Help texts: `rbc --help` (overview) and `rbc COMMAND --help` (one command), in the language asked for. */

type Row = readonly [string, string];

function globalOptions(locale: Locale) {
  const t = translator(helpMessages, locale);
  const robot: Row[] = [
    ["-p, --port PATH", t("cliHelp.option.port")],
    ["--ports A,B,…", t("cliHelp.option.ports")],
    ["--demo", t("cliHelp.option.demo")],
  ];
  return {
    robot,
    json: ["--json", t("cliHelp.option.json")] as Row,
    log: ["--log", t("cliHelp.option.log")] as Row,
    lang: ["--lang en|ko", t("cliHelp.option.lang")] as Row,
    help: ["-h, --help", t("cliHelp.option.help")] as Row,
  };
}

/** Display columns of `text`: Hangul and other wide characters take two on a terminal. */
export function displayWidth(text: string): number {
  let width = 0;
  for (const ch of text) {
    const c = ch.codePointAt(0) ?? 0;
    const wide =
      (c >= 0x1100 && c <= 0x115f) ||
      (c >= 0x2e80 && c <= 0xa4cf) ||
      (c >= 0xac00 && c <= 0xd7a3) ||
      (c >= 0xf900 && c <= 0xfaff) ||
      (c >= 0xfe30 && c <= 0xfe4f) ||
      (c >= 0xff00 && c <= 0xff60) ||
      (c >= 0xffe0 && c <= 0xffe6);
    width += wide ? 2 : 1;
  }
  return width;
}

function table(rows: ReadonlyArray<Row>, indent = "  "): string {
  const width = Math.min(24, Math.max(...rows.map(([a]) => a.length)));
  return rows
    .map(([a, b]) =>
      a.length > width
        ? `${indent}${a}\n${indent}${" ".repeat(width + 2)}${b}`
        : `${indent}${a.padEnd(width)}  ${b}`,
    )
    .join("\n");
}

/** Wraps a paragraph at `width` columns (Hangul counts two), keeping `quoted commands` on one line. */
function wrap(text: string, width = 108): string {
  const KEEP = "\u0001";
  const kept = text.replace(/`[^`]*`/g, (q) => q.replaceAll(" ", KEEP));
  const lines: string[] = [];
  let line = "";
  for (const word of kept.split(/[ \n]+/).filter((w) => w !== "")) {
    if (line && displayWidth(line) + 1 + displayWidth(word) > width) {
      lines.push(line);
      line = word;
    } else {
      line = line ? `${line} ${word}` : word;
    }
  }
  if (line) lines.push(line);
  return lines.join("\n").replaceAll(KEEP, " ");
}

export function globalHelp(commands: readonly CommandDef[], locale: Locale = "en"): string {
  const t = translator(helpMessages, locale);
  const options = globalOptions(locale);
  const robotCommands = commands
    .filter((c) => c.talksToRobot)
    .map((c) => c.name)
    .join(", ");
  const examples = [
    ["rbc ports", t("cliHelp.example.ports")],
    ["rbc info --port /dev/ttyUSB0", t("cliHelp.example.info")],
    ["rbc info --demo", t("cliHelp.example.infoDemo")],
    ["rbc run 7 --demo", t("cliHelp.example.run")],
    ["rbc sim --pty", t("cliHelp.example.sim")],
    ...(locale === "en" ? [] : [["rbc info --demo --lang en", t("cliHelp.example.lang")]]),
  ]
    .map(([command, what]) => `  ${command!.padEnd(33)}  ${what}`)
    .join("\n");
  return `${t("cliHelp.title")}

${t("cliHelp.usage", { usage: "rbc COMMAND [options]" })}

${wrap(t("cliHelp.intro", { commands: robotCommands }))}

${t("cliHelp.commands")}
${table(commands.map((c) => [c.name, c.help(t).summary]))}

${t("cliHelp.robotOptions")}
${table([...options.robot, options.log])}

${t("cliHelp.everyOptions")}
${table([options.json, options.lang, options.help])}

${t("cliHelp.language")}

${t("cliHelp.developers")}

${t("cliHelp.exitCodes", { failure: '{"ok":false,"error":{"code":…,"message":…}}' })}

${t("cliHelp.examples")}
${examples}

${t("cliHelp.more")}
`;
}

export function commandHelp(command: CommandDef, locale: Locale = "en"): string {
  const t = translator(helpMessages, locale);
  const help = command.help(t);
  const global = globalOptions(locale);
  const options = command.talksToRobot
    ? [...help.options, ...global.robot, global.json, global.log, global.lang, global.help]
    : [...help.options, global.json, global.lang, global.help];
  const examples = command.examples.map((e) => `  ${e}`).join("\n");
  return `rbc ${command.name} — ${help.summary}

${t("cliHelp.usage", { usage: command.usage })}

${help.description.trim()}

${t("cliHelp.options")}
${table(options)}
${examples ? `\n${t("cliHelp.examples")}\n${examples}\n` : ""}`;
}
