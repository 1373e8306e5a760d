import { resolve } from "node:path";
import { RbcCancelledError } from "../../device/errors.ts";
import { type SafeZeroWrite, ZeroBackupError, ZeroWriteFailedError } from "../../device/index.ts";
import type { ZeroWriteResult } from "../../device/types.ts";
import { errorSaid } from "../../i18n/error-said.ts";
import { jointOf } from "../../i18n/joint-names/joint-name.ts";
import type { Locale } from "../../i18n/locale.ts";
import { serialMismatchWarning, zerosNotWrittenText } from "../../i18n/outcomes/zero-words.ts";
import { type Said, said, saidBy, saidTogether, wordOf } from "../../i18n/said.ts";
import { translator } from "../../i18n/translate.ts";
import { formatDateTime } from "../../i18n/units.ts";
import {
  diffZeros,
  FACTORY_ZEROS,
  STANDARD_ZEROS,
  ZERO_COUNT,
  ZERO_TOLERANCE,
  zeroProblems,
  zeroRange,
} from "../../protocol/zeros.ts";
import { formatFirmware } from "../../shared/format.ts";
import { type GlobalValues, noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf, type RunEnv } from "../command.ts";
import { connectRobot, type Robot, robotPlace } from "../connect.ts";
import { CliError, EXIT, errorCode, SEE_LOG, UsageError } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { displayWidth } from "../help/render.ts";
import {
  readBackupFile,
  refuseExisting,
  saveAutomaticBackup,
  writeAutomaticBackup,
  writeBackupFile,
} from "../zeros-files.ts";
import { commandMessages } from "./messages.ts";

const OPTIONS = {
  "backup-dir": { type: "string" },
  force: { type: "boolean" },
} as const;

/** "125,202,162,…" or 16 separate words → numbers; a malformed list is a usage error. */
export function parseZeroList(words: readonly string[]): number[] {
  const parts = words.flatMap((w) => w.split(/[,\s]+/)).filter((p) => p !== "");
  if (parts.length === 0) throw new UsageError(said(commandMessages, "cmd.zeros.noValues"), "zeros");
  return parts.map((p) => {
    if (!/^\d{1,3}$/.test(p))
      throw new UsageError(said(commandMessages, "cmd.zeros.notANumber", { value: p }), "zeros");
    return Number(p);
  });
}

/** Headers, then one row per servo; each cell is text. */
type Column = { header: string; align: "left" | "right"; cells: string[] };

/**
 * Lays columns out so that every cell lines up under its header, whatever the width of a value (a Hangul
 * header takes two columns a syllable on a terminal).
 */
export function alignColumns(columns: readonly Column[], indent = "  ", gap = "  "): string[] {
  const widths = columns.map((c) => Math.max(displayWidth(c.header), ...c.cells.map((t) => displayWidth(t))));
  const fill = (text: string, i: number) => " ".repeat(Math.max(0, widths[i]! - displayWidth(text)));
  const pad = (text: string, i: number) =>
    columns[i]!.align === "right" ? `${fill(text, i)}${text}` : `${text}${fill(text, i)}`;
  const rows = Math.max(0, ...columns.map((c) => c.cells.length));
  const line = (cell: (c: Column) => string) =>
    `${indent}${columns.map((c, i) => pad(cell(c), i)).join(gap)}`.trimEnd();
  const lines = [line((c) => c.header)];
  for (let r = 0; r < rows; r++) lines.push(line((c) => c.cells[r] ?? ""));
  return lines;
}

/**
 * The robot's zeros beside the two tables people mix up, named as in the panel: the reference zeros (what the
 * RBC checks every write against, ±15) and the factory zeros (what the firmware holds when new).
 */
export function zerosTable(zeros: readonly number[], locale: Locale = "en"): string[] {
  const t = translator(commandMessages, locale);
  const ids = zeros.map((_, id) => id);
  const diff = (id: number) => {
    const d = zeros[id]! - STANDARD_ZEROS[id]!;
    return d === 0 ? "0" : d > 0 ? `+${d}` : String(d);
  };
  const range = (id: number) => {
    const { min, max } = zeroRange(id);
    return `${min}-${max}`;
  };
  const lines = alignColumns([
    { header: t("cmd.zeros.column.servo"), align: "right", cells: ids.map(String) },
    { header: t("cmd.zeros.column.joint"), align: "left", cells: ids.map((id) => jointOf(id, locale) ?? "") },
    { header: t("cmd.zeros.column.zero"), align: "right", cells: zeros.map(String) },
    {
      header: t("cmd.zeros.column.reference"),
      align: "right",
      cells: ids.map((id) => String(STANDARD_ZEROS[id])),
    },
    { header: t("cmd.zeros.column.difference"), align: "right", cells: ids.map(diff) },
    { header: t("cmd.zeros.column.allowed"), align: "right", cells: ids.map(range) },
    {
      header: t("cmd.zeros.column.factory"),
      align: "right",
      cells: ids.map((id) => String(FACTORY_ZEROS[id])),
    },
  ]);
  lines.push(
    "",
    ...t("cmd.zeros.legend", { tolerance: String(ZERO_TOLERANCE) })
      .split("\n")
      .map((l) => `  ${l}`),
  );
  return lines;
}

async function identify(robot: Robot) {
  // 0x0C is optional (docs/protocol.md §3.5): a robot that does not answer it is "not reported".
  const { serialNumber } = await robot.client.identify();
  const zeros = await robot.client.readZeros();
  return { serialNumber, firmware: formatFirmware(robot.identity.firmware), zeros };
}

/** The robot by its serial number, or in words when its firmware does not report one. */
function robotName(serialNumber: string | undefined, locale: Locale): string {
  return serialNumber ?? translator(commandMessages, locale)("cmd.zeros.serialNotReported");
}

/** Stops before anything is written when Ctrl-C came while reading or backing up. */
function stopIfInterrupted(env: RunEnv, backupFile?: string): void {
  if (!env.signal.aborted) return;
  const words = backupFile
    ? said(commandMessages, "cmd.zeros.nothingWrittenBackup", { file: backupFile })
    : said(commandMessages, "cmd.zeros.nothingWritten");
  throw new CliError("interrupted", words, EXIT.interrupted);
}

/** How to find out what the robot holds after a write that may or may not have happened. */
function checkAdvice(backupFile: string): Said {
  return said(commandMessages, "cmd.zeros.checkAdvice", { file: backupFile });
}

/**
 * The device's zero-write policy (backup first, then write and verify; `writeZerosWithBackup`), with the CLI's
 * file for the backup and its words. Shared by `write` and `restore`. The write and its verification take well
 * under a second, so Ctrl-C during them lets them finish (the robot's zeros are then known) and the command
 * exits 130 afterwards; Ctrl-C before the write stops without writing.
 */
async function backupAndWrite(
  env: RunEnv,
  robot: Robot,
  values: { "backup-dir"?: string },
  target: readonly number[],
  current: { serialNumber: string | undefined; firmware: string; zeros: number[] },
): Promise<{ backupFile: string | undefined; result: ZeroWriteResult | undefined; interrupted: boolean }> {
  stopIfInterrupted(env);
  const locale = localeOf(env);
  const t = translator(commandMessages, locale);
  let backupFile: string | undefined;
  const onAbort = () => env.out.note(`rbc: ${t("cmd.zeros.finishing")}`);
  let outcome: SafeZeroWrite;
  try {
    outcome = await robot.client.writeZerosWithBackup(target, {
      robot: { serialNumber: current.serialNumber, firmware: current.firmware },
      signal: env.signal,
      saveBackup: async (backup) => {
        backupFile = await saveAutomaticBackup(resolve(env.cwd, values["backup-dir"] ?? "."), backup);
        env.out.note(t("cmd.zeros.backedUp", { file: backupFile }));
        const changes = diffZeros(backup.zeros, target);
        const list = changes.map((c) => `${c.id}: ${c.from} → ${c.to}`).join(", ");
        env.out.line(t("cmd.zeros.changing", { count: changes.length, changes: list }));
        return backupFile;
      },
      onWrite: () => {
        env.signal.addEventListener("abort", onAbort, { once: true });
        // If rbc has to exit before the write has finished (a second Ctrl-C), the robot's zeros are unknown.
        if (backupFile)
          env.setExitNote(t("cmd.zeros.mayBeWritten", { advice: wordOf(checkAdvice(backupFile), locale) }));
      },
    });
  } catch (e) {
    if (e instanceof ZeroBackupError && e.cause instanceof CliError) throw e.cause;
    if (e instanceof RbcCancelledError && env.signal.aborted) stopIfInterrupted(env, backupFile);
    if (e instanceof ZeroWriteFailedError) {
      throw new CliError(
        errorCode(e.reason),
        saidTogether([errorSaid(e.reason, { detailHint: SEE_LOG }), checkAdvice(e.backupName)]),
        EXIT.failed,
        {
          backupFile: e.backupName,
        },
      );
    }
    throw e;
  } finally {
    env.signal.removeEventListener("abort", onAbort);
    env.setExitNote(undefined);
  }
  if (!outcome.changed) {
    env.out.line(t("cmd.zeros.unchanged", { zeros: target.join(",") }));
    return { backupFile: undefined, result: undefined, interrupted: false };
  }
  const result: ZeroWriteResult = outcome;
  env.out.line(t("cmd.zeros.written", { zeros: result.readBack.join(",") }));
  const interrupted = env.signal.aborted;
  if (interrupted) env.out.note(`rbc: ${t("cmd.zeros.interruptedAfterWrite", { file: backupFile ?? "" })}`);
  return { backupFile, result, interrupted };
}

export const zerosCommand: CommandDef = {
  name: "zeros",
  usage: "rbc zeros (read | write V0,V1,…,V15 | backup [FILE] | restore FILE) (--port PATH | --demo)",
  help: COMMAND_HELP.zeros,
  examples: [
    "rbc zeros read --demo",
    "rbc zeros write 125,202,162,66,108,124,48,88,184,142,90,40,125,161,210,127 --demo",
    "rbc zeros backup my-robot.json --port /dev/ttyUSB0",
    "rbc zeros restore my-robot.json --port /dev/ttyUSB0",
  ],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("zeros", env.argv, OPTIONS);
    const [action, ...args] = positionals;
    switch (action) {
      case "read":
        return read(env, values, args);
      case "write":
        return write(env, values, args);
      case "backup":
        return backup(env, values, args);
      case "restore":
        return restore(env, values, args);
      case undefined:
        throw new UsageError(said(commandMessages, "cmd.zeros.noAction"), "zeros");
      default:
        throw new UsageError(said(commandMessages, "cmd.zeros.unknownAction", { action }), "zeros");
    }
  },
};

/** Leads the `--json` result when Ctrl-C came during the write, which was allowed to finish. */
const INTERRUPTED_AFTER_WRITE = {
  ok: false,
  error: {
    code: "interrupted",
    message: "Interrupted after the write finished; the new zeros are verified.",
  },
} as const;

type Values = GlobalValues & { "backup-dir"?: string; force?: boolean };

async function read(env: RunEnv, values: Values, args: string[]): Promise<number> {
  noExtraArguments("zeros", args, 0);
  const robot = await connectRobot("zeros", values, env);
  const current = await identify(robot);
  const locale = localeOf(env);
  const t = translator(commandMessages, locale);
  env.out.result({ serialNumber: current.serialNumber ?? null, zeros: current.zeros });
  const robotWords = { robot: robotName(current.serialNumber, locale), where: robotPlace(robot, locale) };
  env.out.line(t("cmd.zeros.readTitle", robotWords));
  for (const line of zerosTable(current.zeros, locale)) env.out.line(line);
  env.out.line(t("cmd.zeros.asList", { zeros: current.zeros.join(",") }));
  return EXIT.ok;
}

async function write(env: RunEnv, values: Values, args: string[]): Promise<number> {
  const target = parseZeroList(args);
  const problems = zeroProblems(target);
  if (problems.length > 0) {
    throw new CliError(
      "zero-out-of-range",
      saidBy((l) => zerosNotWrittenText(problems, l)),
    );
  }
  // Ctrl-C must not close the port in the middle of the write: backupAndWrite handles it.
  const robot = await connectRobot("zeros", values, env, { handlesInterrupt: true });
  const current = await identify(robot);
  const { backupFile, result, interrupted } = await backupAndWrite(env, robot, values, target, current);
  env.out.result({
    ...(interrupted ? INTERRUPTED_AFTER_WRITE : {}),
    previous: current.zeros,
    written: target,
    readBack: result?.readBack ?? current.zeros,
    backupFile: backupFile ?? null,
    changed: result !== undefined,
  });
  return interrupted ? EXIT.interrupted : EXIT.ok;
}

async function backup(env: RunEnv, values: Values, args: string[]): Promise<number> {
  noExtraArguments("zeros", args, 1);
  const file = args[0];
  if (file !== undefined) await refuseExisting(resolve(env.cwd, file), values.force === true);
  const robot = await connectRobot("zeros", values, env);
  const current = await identify(robot);
  const source = { ...current, serialNumber: current.serialNumber ?? "unknown" };
  const path = file ?? (await writeAutomaticBackup(env.cwd, source));
  const saved = file
    ? await writeBackupFile(resolve(env.cwd, file), source, values.force === true)
    : undefined;
  env.out.result({
    file: path,
    zeros: current.zeros,
    serialNumber: current.serialNumber ?? null,
    savedAt: saved?.savedAt,
  });
  const locale = localeOf(env);
  env.out.line(
    translator(commandMessages, locale)("cmd.zeros.backupSaved", {
      file: path,
      number: String(current.zeros.length),
      robot: robotName(current.serialNumber, locale),
      zeros: current.zeros.join(","),
    }),
  );
  return EXIT.ok;
}

async function restore(env: RunEnv, values: Values, args: string[]): Promise<number> {
  noExtraArguments("zeros", args, 1);
  const file = args[0];
  if (file === undefined) throw new UsageError(said(commandMessages, "cmd.zeros.noBackupFile"), "zeros");
  const saved = await readBackupFile(resolve(env.cwd, file));
  if (saved.zeros.length !== ZERO_COUNT) {
    throw new CliError("backup-wrong-count", said(commandMessages, "cmd.zeros.not16", { file }));
  }
  // Ctrl-C must not close the port in the middle of the write: backupAndWrite handles it.
  const robot = await connectRobot("zeros", values, env, { handlesInterrupt: true });
  const current = await identify(robot);
  const locale = localeOf(env);
  const t = translator(commandMessages, locale);
  const warning = serialMismatchWarning(saved, current.serialNumber, locale);
  const savedFrom = saved.serialNumber || t("cmd.zeros.unknownRobot");
  if (warning) env.out.note(t("cmd.warning", { warning }));
  // English shows the file's own timestamp, as it always did; other languages a date and time of theirs.
  const savedAt = locale === "en" ? saved.savedAt : formatDateTime(new Date(saved.savedAt), locale);
  env.out.line(t("cmd.zeros.restoring", { file, savedAt, robot: savedFrom }));
  const { backupFile, result, interrupted } = await backupAndWrite(env, robot, values, saved.zeros, current);
  env.out.result({
    ...(interrupted ? INTERRUPTED_AFTER_WRITE : {}),
    file,
    previous: current.zeros,
    written: saved.zeros,
    readBack: result?.readBack ?? current.zeros,
    backupFile: backupFile ?? null,
    changed: result !== undefined,
    warning: warning ?? null,
  });
  return interrupted ? EXIT.interrupted : EXIT.ok;
}
