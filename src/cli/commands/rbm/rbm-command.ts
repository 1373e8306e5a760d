import { readFile, writeFile } from "node:fs/promises";
import { basename, dirname, join, resolve } from "node:path";
import {
  noRobotSerialText,
  restampChangeText,
  restampRefusalText,
} from "../../../i18n/outcomes/restamp/restamp-words.ts";
import { inEveryLanguage, said, saidBy } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import {
  RBM_ZERO_SERIAL,
  RestampError,
  restampedFileName,
  restampRbmBytes,
} from "../../../motion/restamp.ts";
import { RbmError } from "../../../protocol/rbm.ts";
import { type GlobalValues, noExtraArguments, parseCommand } from "../../args.ts";
import { type CommandDef, localeOf, type RunEnv } from "../../command.ts";
import { connectRobot, robotPlace } from "../../connect.ts";
import { CliError, EXIT, UsageError } from "../../errors.ts";
import { COMMAND_HELP } from "../../help/command-help.ts";
import { issueText } from "../../upload-report.ts";
import { unreadable } from "../../zeros-files.ts";
import { rbmCommandMessages } from "./messages.ts";

/**
 * `rbc rbm restamp FILE [--serial N | --zeros] [-o OUT]` (issue 23 item 4): writes a serial number, or zeros,
 * into field 2 of a Motionbuilder file (docs/protocol.md §7), so that Motionbuilder takes a motion made for
 * another robot; every other byte stays (src/motion/restamp.ts). Without --serial or --zeros, --port/--demo
 * gives the connected robot's serial number. FILE is never overwritten unless -o names it; without -o the copy
 * is FILE's name with the serial number (or "zeros") added, beside it, and an existing file of that name is
 * left alone.
 */

const OPTIONS = {
  serial: { type: "string" },
  zeros: { type: "boolean" },
  output: { type: "string", short: "o" },
} as const;

type Values = GlobalValues & { serial?: string; zeros?: boolean; output?: string };

/** `wave.rbm` → `wave-zeros.rbm` / `wave-8958899989309.rbm`, beside FILE. */
export function restampedName(file: string, serial: string): string {
  return join(dirname(file), restampedFileName(basename(file), serial));
}

/** The serial number to write: --serial, --zeros, or the connected robot's (which --port/--demo name). */
async function targetSerial(
  env: RunEnv,
  values: Values,
): Promise<{ serial: string; source: "option" | "zeros" | "robot" }> {
  if (values.serial !== undefined && values.zeros) {
    throw new UsageError(said(rbmCommandMessages, "cmd.rbm.serialOrZeros"), "rbm");
  }
  if (values.zeros) return { serial: RBM_ZERO_SERIAL, source: "zeros" };
  if (values.serial !== undefined) return { serial: values.serial.trim(), source: "option" };
  if (!values.demo && values.port === undefined && !env.env.RBC_PORT) {
    throw new UsageError(said(rbmCommandMessages, "cmd.rbm.whichSerial"), "rbm");
  }
  const robot = await connectRobot("rbm", values, env);
  const { serialNumber } = await robot.client.identify();
  const locale = localeOf(env);
  const place = robotPlace(robot, locale);
  if (serialNumber === undefined) {
    throw new CliError("no-robot-serial", saidBy(noRobotSerialText));
  }
  env.out.note(
    translator(rbmCommandMessages, locale)("cmd.rbm.fromRobot", { robot: place, serial: serialNumber }),
  );
  return { serial: serialNumber, source: "robot" };
}

async function restamp(env: RunEnv, values: Values, args: string[]): Promise<number> {
  if (args.length === 0) throw new UsageError(said(rbmCommandMessages, "cmd.rbm.noFile"), "rbm");
  noExtraArguments("rbm", args, 1);
  const file = args[0]!;
  const locale = localeOf(env);
  const t = translator(rbmCommandMessages, locale);
  const path = resolve(env.cwd, file);
  let bytes: Uint8Array;
  try {
    bytes = new Uint8Array(await readFile(path));
  } catch (e) {
    throw unreadable(file, e);
  }
  const { serial, source } = await targetSerial(env, values);
  let result: ReturnType<typeof restampRbmBytes>;
  try {
    result = restampRbmBytes(bytes, serial);
  } catch (e) {
    if (e instanceof RbmError) {
      const first = e.issues[0] ?? { code: e.code, message: e.message };
      const reason = (l: typeof locale) => issueText(first, { locale: l }).replace(/[.\s]+$/, "");
      throw new CliError(
        e.code,
        said(rbmCommandMessages, "cmd.rbm.notMotion", {
          file: basename(file),
          reason: inEveryLanguage(reason),
        }),
        EXIT.failed,
        { file },
      );
    }
    if (e instanceof RestampError) {
      throw new CliError(
        e.code,
        said(rbmCommandMessages, "cmd.rbm.refused", {
          reason: inEveryLanguage((l) => restampRefusalText(e, l)),
        }),
        EXIT.failed,
        { file, ...e.facts },
      );
    }
    throw e;
  }
  const json = { file, before: result.before, after: result.after, changed: result.changed, source };
  if (!result.changed) {
    env.out.line(restampChangeText(result, locale));
    env.out.line(t("cmd.rbm.nothingWritten"));
    env.out.result({ ok: true, ...json, output: null });
    return EXIT.ok;
  }
  const output = values.output ?? restampedName(file, serial);
  const outPath = resolve(env.cwd, output);
  try {
    // -o names the file to write, so it may replace it; the default name never replaces anything.
    await writeFile(outPath, result.output, { flag: values.output === undefined ? "wx" : "w" });
  } catch (e) {
    if ((e as NodeJS.ErrnoException).code === "EEXIST") {
      throw new CliError("output-exists", said(rbmCommandMessages, "cmd.rbm.outputExists", { path: output }));
    }
    throw new CliError(
      "file-unwritable",
      said(rbmCommandMessages, "cmd.rbm.cannotWrite", { path: output, why: String(e) }),
    );
  }
  env.out.line(t("cmd.rbm.written", { output, file }));
  env.out.line(restampChangeText(result, locale));
  env.out.result({ ok: true, ...json, output });
  return EXIT.ok;
}

export const rbmCommand: CommandDef = {
  name: "rbm",
  usage: "rbc rbm restamp FILE [--serial N | --zeros] [-o OUT] [--port PATH | --demo]",
  help: COMMAND_HELP.rbm,
  examples: [
    "rbc rbm restamp shared-dance.rbm --zeros",
    "rbc rbm restamp shared-dance.rbm --serial 8958899989309 -o dance.rbm",
    "rbc rbm restamp shared-dance.rbm --port /dev/ttyUSB0",
  ],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("rbm", env.argv, OPTIONS);
    const [action, ...args] = positionals;
    switch (action) {
      case "restamp":
        return restamp(env, values, args);
      case undefined:
        throw new UsageError(said(rbmCommandMessages, "cmd.rbm.noAction"), "rbm");
      default:
        throw new UsageError(said(rbmCommandMessages, "cmd.rbm.unknownAction", { action }), "rbm");
    }
  },
};
