import { RbcCancelledError } from "../../device/errors.ts";
import { type SafeZeroWrite, ZeroBackupError, ZeroWriteFailedError } from "../../device/index.ts";
import type { ZeroWriteResult } from "../../device/types.ts";
import { HUNO_JOINT_NAMES } from "../../protocol/servo-limits.ts";
import {
  diffZeros,
  FACTORY_ZEROS,
  STANDARD_ZEROS,
  ZERO_COUNT,
  ZERO_TOLERANCE,
  zeroProblems,
  zeroRange,
} from "../../protocol/zeros.ts";
import { serialMismatchWarning } from "../../protocol/zeros-backup.ts";
import { formatFirmware } from "../../shared/format.ts";
import { type GlobalValues, noExtraArguments, parseCommand } from "../args.ts";
import type { CommandDef, RunEnv } from "../command.ts";
import { connectRobot, type Robot } from "../connect.ts";
import { CliError, EXIT, errorCode, errorLine, UsageError } from "../errors.ts";
import {
  readBackupFile,
  refuseExisting,
  saveAutomaticBackup,
  writeAutomaticBackup,
  writeBackupFile,
} from "../zeros-files.ts";

const OPTIONS = {
  "backup-dir": { type: "string" },
  force: { type: "boolean" },
} as const;

/** "125,202,162,…" or 16 separate words → numbers; a malformed list is a usage error. */
export function parseZeroList(words: readonly string[]): number[] {
  const parts = words.flatMap((w) => w.split(/[,\s]+/)).filter((p) => p !== "");
  if (parts.length === 0) throw new UsageError("Give the 16 zero values, e.g. 125,202,162,66,…", "zeros");
  return parts.map((p) => {
    if (!/^\d{1,3}$/.test(p)) throw new UsageError(`"${p}" is not a whole number from 0 to 254.`, "zeros");
    return Number(p);
  });
}

/** Headers, then one row per servo; each cell is text. */
type Column = { header: string; align: "left" | "right"; cells: string[] };

/** Lays columns out so that every cell lines up under its header, whatever the width of a value. */
export function alignColumns(columns: readonly Column[], indent = "  ", gap = "  "): string[] {
  const widths = columns.map((c) => Math.max(c.header.length, ...c.cells.map((t) => t.length)));
  const pad = (text: string, i: number) =>
    columns[i]!.align === "right" ? text.padStart(widths[i]!) : text.padEnd(widths[i]!);
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
export function zerosTable(zeros: readonly number[]): string[] {
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
    { header: "servo", align: "right", cells: ids.map(String) },
    { header: "joint", align: "left", cells: ids.map((id) => HUNO_JOINT_NAMES[id] ?? "") },
    { header: "zero", align: "right", cells: zeros.map(String) },
    { header: "reference", align: "right", cells: ids.map((id) => String(STANDARD_ZEROS[id])) },
    { header: "difference", align: "right", cells: ids.map(diff) },
    { header: "allowed", align: "right", cells: ids.map(range) },
    { header: "factory", align: "right", cells: ids.map((id) => String(FACTORY_ZEROS[id])) },
  ]);
  lines.push(
    "",
    `  reference: the table the RBC checks every write against; each zero must stay within ±${ZERO_TOLERANCE} of it`,
    "  (allowed), or the RBC refuses the whole table. factory: the zeros the firmware holds when new.",
  );
  return lines;
}

async function identify(robot: Robot) {
  // 0x0C is optional (PROTOCOL.md §3.5): a robot that does not answer it is "not reported".
  const { serialNumber } = await robot.client.identify();
  const zeros = await robot.client.readZeros();
  return { serialNumber, firmware: formatFirmware(robot.identity.firmware), zeros };
}

/** The robot by its serial number, or in words when its firmware does not report one. */
function robotName(serialNumber: string | undefined): string {
  return serialNumber ?? "(serial number not reported)";
}

/** Stops before anything is written when Ctrl-C came while reading or backing up. */
function stopIfInterrupted(env: RunEnv, backupFile?: string): void {
  if (!env.signal.aborted) return;
  throw new CliError(
    "interrupted",
    `Nothing was written to the robot${backupFile ? ` (the backup ${backupFile} was saved)` : ""}.`,
    EXIT.interrupted,
  );
}

/** How to find out what the robot holds after a write that may or may not have happened. */
function checkAdvice(backupFile: string): string {
  return `Check with \`rbc zeros read\`; the previous zeros are saved in ${backupFile} (to put them back: rbc zeros restore ${backupFile}).`;
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
  let backupFile: string | undefined;
  const onAbort = () =>
    env.out.note("rbc: finishing the zero write and its check (under a second), then stopping…");
  let outcome: SafeZeroWrite;
  try {
    outcome = await robot.client.writeZerosWithBackup(target, {
      robot: { serialNumber: current.serialNumber, firmware: current.firmware },
      signal: env.signal,
      saveBackup: async (backup) => {
        backupFile = await saveAutomaticBackup(values["backup-dir"] ?? env.cwd, backup);
        env.out.note(
          `Backed up the current zeros to ${backupFile} (restore with: rbc zeros restore ${backupFile}).`,
        );
        const changes = diffZeros(backup.zeros, target);
        env.out.line(
          `Changing ${changes.length} servo${changes.length > 1 ? "s" : ""}: ${changes.map((c) => `${c.id}: ${c.from} → ${c.to}`).join(", ")}`,
        );
        return backupFile;
      },
      onWrite: () => {
        env.signal.addEventListener("abort", onAbort, { once: true });
        // If rbc has to exit before the write has finished (a second Ctrl-C), the robot's zeros are unknown.
        if (backupFile) env.setExitNote(`The zeros may have been written. ${checkAdvice(backupFile)}`);
      },
    });
  } catch (e) {
    if (e instanceof ZeroBackupError && e.cause instanceof CliError) throw e.cause;
    if (e instanceof RbcCancelledError && env.signal.aborted) stopIfInterrupted(env, backupFile);
    if (e instanceof ZeroWriteFailedError) {
      throw new CliError(
        errorCode(e.reason),
        `${errorLine(e.reason)} ${checkAdvice(e.backupName)}`,
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
    env.out.line(`The robot already holds these zeros (${target.join(",")}); nothing was written.`);
    return { backupFile: undefined, result: undefined, interrupted: false };
  }
  const result: ZeroWriteResult = outcome;
  env.out.line(`Written and verified: the robot reads back ${result.readBack.join(",")}.`);
  const interrupted = env.signal.aborted;
  if (interrupted) {
    env.out.note(
      `rbc: interrupted after the write finished: the robot holds the new zeros (verified). The previous ones are in ${backupFile}.`,
    );
  }
  return { backupFile, result, interrupted };
}

export const zerosCommand: CommandDef = {
  name: "zeros",
  summary: "read, write, back up or restore the servo zero positions",
  usage: "rbc zeros (read | write V0,V1,…,V15 | backup [FILE] | restore FILE) (--port PATH | --demo)",
  description: `
The zero positions are 16 calibration values, one per servo 0-15, stored in the RBC. Every motion is
shifted by them, so wrong values make the robot stand crooked. Two fixed tables matter (the panel uses the
same names):

  reference zeros  125 202 162 66 108 124 48 88 184 142 90 40 125 161 210 127
                   The table the RBC checks every write against: each zero must lie within ±15 of it, or
                   the RBC refuses the whole table. rbc checks this first and sends nothing if a value is
                   out of range.
  factory zeros    124 202 162 65 108 125 46 88 184 142 90 40 125 161 210 126
                   What the firmware holds when the robot is new (a starting point, not a calibration).

  read             Prints the 16 values beside the reference zeros, the allowed range and the factory
                   zeros.
  write V0,…,V15   Writes 16 new values (comma separated, or 16 separate words), each within ±15 of the
                   reference zeros. Before writing it saves the current values to
                   rbc-zeros-<serial>-<date>.json (in --backup-dir, default the current folder), and after
                   writing it reads them back to verify.
  backup [FILE]    Saves the current values to FILE (default rbc-zeros-<serial>-<date>.json), in the same
                   format as the panel's backups ("Back up zeros" there).
  restore FILE     Writes the values of a backup file (checked first; a warning if it was saved from
                   another robot), with the same automatic backup and verification as write.

Ctrl-C during write or restore: before the write starts nothing is written; once it has started (it takes
under a second) rbc lets the write and its check finish, says what the robot holds, then exits with 130.`,
  options: [
    ["--backup-dir DIR", "Where write and restore save the automatic backup (default: the current folder)."],
    ["--force", "Let backup replace an existing FILE."],
  ],
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
        throw new UsageError(
          "Say what to do: zeros read, zeros write, zeros backup or zeros restore.",
          "zeros",
        );
      default:
        throw new UsageError(`Unknown zeros action "${action}" (read, write, backup, restore).`, "zeros");
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
  env.out.result({ serialNumber: current.serialNumber ?? null, zeros: current.zeros });
  env.out.line(`Zero positions of robot ${robotName(current.serialNumber)} (${robot.where}):`);
  for (const line of zerosTable(current.zeros)) env.out.line(line);
  env.out.line(`As a list: ${current.zeros.join(",")}`);
  return EXIT.ok;
}

async function write(env: RunEnv, values: Values, args: string[]): Promise<number> {
  const target = parseZeroList(args);
  const problems = zeroProblems(target);
  if (problems.length > 0) {
    throw new CliError(
      "zero-out-of-range",
      `Not written: ${problems.map((p) => p.message).join(" ")} Nothing was sent to the robot.`,
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
  if (file !== undefined) await refuseExisting(file, values.force === true);
  const robot = await connectRobot("zeros", values, env);
  const current = await identify(robot);
  const source = { ...current, serialNumber: current.serialNumber ?? "unknown" };
  const path = file ?? (await writeAutomaticBackup(env.cwd, source));
  const saved = file ? await writeBackupFile(file, source, values.force === true) : undefined;
  env.out.result({
    file: path,
    zeros: current.zeros,
    serialNumber: current.serialNumber ?? null,
    savedAt: saved?.savedAt,
  });
  env.out.line(
    `Backup saved as ${path}, ${current.zeros.length} zeros read from robot ${robotName(current.serialNumber)}: ${current.zeros.join(",")}`,
  );
  return EXIT.ok;
}

async function restore(env: RunEnv, values: Values, args: string[]): Promise<number> {
  noExtraArguments("zeros", args, 1);
  const file = args[0];
  if (file === undefined)
    throw new UsageError("Give the backup file to restore: rbc zeros restore FILE.", "zeros");
  const saved = await readBackupFile(file);
  if (saved.zeros.length !== ZERO_COUNT)
    throw new CliError("backup-wrong-count", `${file} does not hold 16 values.`);
  // Ctrl-C must not close the port in the middle of the write: backupAndWrite handles it.
  const robot = await connectRobot("zeros", values, env, { handlesInterrupt: true });
  const current = await identify(robot);
  const warning = serialMismatchWarning(saved, current.serialNumber);
  if (warning) env.out.note(`Warning: ${warning}`);
  env.out.line(`Restoring ${file} (saved ${saved.savedAt} from robot ${saved.serialNumber || "(unknown)"}).`);
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
