import {
  ALL_SERVO_IDS,
  HUNO_SCAN_IDS,
  INFO_PARAMETERS,
  type ParameterReading,
  type ScanResult,
  scanServos,
  servoInfo,
  setServoId,
  WIGGLE_COUNTS,
  wiggleServo,
} from "../../device/servo-doctor/index.ts";
import { jointOf } from "../../i18n/joint-names/joint-name.ts";
import type { Locale } from "../../i18n/locale.ts";
import {
  findingText,
  infoStoppedText,
  parameterNameText,
  parameterValueText,
  readingStatusText,
  scanStoppedText,
  setIdText,
  wiggleText,
} from "../../i18n/outcomes/servos/servo-words.ts";
import { said } from "../../i18n/said.ts";
import { translator } from "../../i18n/translate.ts";
import { type GlobalValues, intArgument, noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf, type RunEnv } from "../command.ts";
import { confirm } from "../confirm.ts";
import { connectRobot, robotPlace } from "../connect.ts";
import { CliError, EXIT, UsageError } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { servosMessages } from "./servos-messages.ts";
import { alignColumns } from "./zeros.ts";

const OPTIONS = { ids: { type: "string" }, yes: { type: "boolean", short: "y" } } as const;

/** "0-15", "0-30", "3,5,7" → ids; anything else is a usage error. */
export function parseIds(value: string | undefined): number[] {
  if (value === undefined) return [...HUNO_SCAN_IDS];
  if (value === "all") return [...ALL_SERVO_IDS];
  const bad = () => new UsageError(said(servosMessages, "cmd.servos.badIds", { value }), "servos");
  const range = /^(\d{1,2})-(\d{1,2})$/.exec(value.trim());
  const ids = range
    ? Array.from({ length: Number(range[2]) - Number(range[1]) + 1 }, (_, i) => Number(range[1]) + i)
    : value.split(",").map((p) => (/^\d{1,2}$/.test(p.trim()) ? Number(p) : Number.NaN));
  if (ids.length === 0 || ids.some((id) => !(id >= 0 && id <= 30)) || new Set(ids).size !== ids.length) {
    throw bad();
  }
  return ids;
}

/** The scan as JSON: {"servos":[…],"findings":[{"code","ids","message"}]} (issue 22 item 4). */
export function scanJson(result: ScanResult, locale: Locale) {
  return {
    servos: result.servos,
    findings: result.findings.map((f) => ({ ...f, message: findingText(f, locale) })),
    ...(result.stopped ? { stopped: result.stopped } : {}),
  };
}

/** Exit 0 when every expected servo answered (and the scan ran to its end). */
function scanOk(result: ScanResult): boolean {
  const answered = new Set(result.servos.filter((s) => s.status === "answered").map((s) => s.id));
  return !result.stopped && result.expected.every((id) => answered.has(id));
}

/** The scan as an aligned table. */
export function scanTable(result: ScanResult, locale: Locale): string[] {
  const t = translator(servosMessages, locale);
  const s = result.servos;
  return alignColumns([
    { header: t("cmd.servos.head.id"), align: "right", cells: s.map((r) => String(r.id)) },
    { header: t("cmd.servos.head.joint"), align: "left", cells: s.map((r) => jointOf(r.id, locale) ?? "") },
    {
      header: t("cmd.servos.head.status"),
      align: "left",
      cells: s.map((r) => {
        const word = readingStatusText(r.status, locale);
        return r.status === "garbled"
          ? `${word} (${r.bytes.map((b) => b.toString(16).toUpperCase().padStart(2, "0")).join(" ")})`
          : word;
      }),
    },
    {
      header: t("cmd.servos.head.position"),
      align: "right",
      cells: s.map((r) => (r.status === "answered" ? String(r.position) : "")),
    },
    {
      header: t("cmd.servos.head.load"),
      align: "right",
      cells: s.map((r) => (r.status === "answered" ? String(r.load) : "")),
    },
  ]);
}

async function scan(env: RunEnv, values: GlobalValues & { ids?: string }, args: string[]): Promise<number> {
  noExtraArguments("servos", args, 0);
  const ids = parseIds(values.ids);
  const locale = localeOf(env);
  const robot = await connectRobot("servos", values, env);
  const result = await scanServos(robot.client, { ids, signal: env.signal });
  env.out.result(scanJson(result, locale));
  for (const line of scanTable(result, locale)) env.out.line(line);
  env.out.line();
  const stopped = scanStoppedText(result, locale);
  if (stopped) env.out.line(stopped);
  for (const f of result.findings) env.out.line(findingText(f, locale));
  if (result.findings.length === 0 && scanOk(result)) {
    env.out.line(translator(servosMessages, locale)("cmd.servos.allAnswered"));
  }
  if (result.stopped?.code === "cancelled") return EXIT.interrupted;
  return scanOk(result) ? EXIT.ok : EXIT.failed;
}

function parameterText(reading: ParameterReading | undefined, locale: Locale): string {
  if (!reading) return "";
  return reading.status === "answered"
    ? parameterValueText(reading.value)
    : readingStatusText(reading.status, locale);
}

async function info(env: RunEnv, values: GlobalValues, args: string[]): Promise<number> {
  noExtraArguments("servos", args, 1);
  const id = intArgument("servos", said(servosMessages, "cmd.servos.id"), args[0], 0, 30);
  const locale = localeOf(env);
  const robot = await connectRobot("servos", values, env);
  const result = await servoInfo(robot.client, id, { signal: env.signal });
  env.out.result(result);
  for (const line of scanTable({ servos: [result.status], findings: [], ids: [id], expected: [] }, locale)) {
    env.out.line(line);
  }
  for (const parameter of INFO_PARAMETERS) {
    const reading = result.parameters[parameter];
    if (reading) env.out.line(`  ${parameterNameText(parameter, locale)}: ${parameterText(reading, locale)}`);
  }
  if (result.stopped) env.out.line(infoStoppedText(result.stopped.code, locale));
  return result.status.status === "answered" && !result.stopped ? EXIT.ok : EXIT.failed;
}

async function wiggle(
  env: RunEnv,
  values: GlobalValues & { yes?: boolean },
  args: string[],
): Promise<number> {
  noExtraArguments("servos", args, 1);
  const id = intArgument("servos", said(servosMessages, "cmd.servos.id"), args[0], 0, 15);
  const locale = localeOf(env);
  const t = translator(servosMessages, locale);
  if (!values.yes && !env.stdin.isTTY && !values.demo) {
    throw new CliError("confirmation-required", said(servosMessages, "cmd.servos.wiggle.needsYes"));
  }
  const robot = await connectRobot("servos", values, env);
  if (!values.yes && !robot.demo) {
    const answer = await confirm(
      env,
      t("cmd.servos.wiggle.question", { id: String(id), robot: robotPlace(robot, locale) }),
    );
    if (answer !== "yes")
      throw new CliError("not-confirmed", said(servosMessages, "cmd.servos.notConfirmed"));
  }
  const result = await wiggleServo(robot.client, id, { signal: env.signal });
  env.out.result(result);
  env.out.line(wiggleText(result, WIGGLE_COUNTS, locale));
  return result.outcome === "done" && result.followed ? EXIT.ok : EXIT.failed;
}

async function setId(env: RunEnv, values: GlobalValues & { yes?: boolean }, args: string[]): Promise<number> {
  noExtraArguments("servos", args, 2);
  const from = intArgument("servos", said(servosMessages, "cmd.servos.id"), args[0], 0, 30);
  const to = intArgument("servos", said(servosMessages, "cmd.servos.newId"), args[1], 0, 30);
  if (from === to)
    throw new UsageError(said(servosMessages, "cmd.servos.badIds", { value: `${from} ${to}` }), "servos");
  const locale = localeOf(env);
  const t = translator(servosMessages, locale);
  if (!values.yes && !env.stdin.isTTY) {
    throw new CliError(
      "confirmation-required",
      said(servosMessages, "cmd.servos.setId.needsYes", { from: String(from), to: String(to) }),
    );
  }
  const robot = await connectRobot("servos", values, env);
  const result = await setServoId(robot.client, from, to, {
    signal: env.signal,
    confirm: values.yes
      ? undefined
      : async ({ position }) =>
          (await confirm(
            env,
            t("cmd.servos.setId.question", {
              from: String(from),
              to: String(to),
              position: String(position),
            }),
          )) === "yes",
  });
  env.out.result(result);
  env.out.line(setIdText(result, locale));
  return result.outcome === "done" ? EXIT.ok : EXIT.failed;
}

export const servosCommand: CommandDef = {
  name: "servos",
  usage:
    "rbc servos (scan [--ids A-B] | info ID | wiggle ID [--yes] | set-id FROM TO [--yes]) (--port PATH | --demo)",
  help: COMMAND_HELP.servos,
  examples: [
    "rbc servos scan --demo",
    "rbc servos scan --ids 0-30 --port /dev/ttyUSB0 --json",
    "rbc servos info 7 --demo",
    "rbc servos wiggle 4 --port /dev/ttyUSB0",
    "rbc servos set-id 0 12 --port /dev/ttyUSB0",
  ],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("servos", env.argv, OPTIONS);
    const [action, ...args] = positionals;
    switch (action) {
      case "scan":
        return scan(env, values, args);
      case "info":
        return info(env, values, args);
      case "wiggle":
        return wiggle(env, values, args);
      case "set-id":
        return setId(env, values, args);
      case undefined:
        throw new UsageError(said(servosMessages, "cmd.servos.noAction"), "servos");
      default:
        throw new UsageError(said(servosMessages, "cmd.servos.unknownAction", { action }), "servos");
    }
  },
};
