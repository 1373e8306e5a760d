import { readFile } from "node:fs/promises";
import { basename, resolve } from "node:path";
import { RbcUploadError } from "../../device/errors.ts";
import type { FileUploadResult } from "../../device/index.ts";
import type { Locale } from "../../i18n/locale.ts";
import { nothingSentText, uploadNoticeText, uploadOutcomeText } from "../../i18n/outcomes/device.ts";
import { errorText } from "../../i18n/outcomes/error-text.ts";
import { remoteKeyWords } from "../../i18n/outcomes/remote-key.ts";
import { uploadAfterText } from "../../i18n/outcomes/upload-words.ts";
import { inEveryLanguage, type Said, said, saidBy } from "../../i18n/said.ts";
import { translator } from "../../i18n/translate.ts";
import { formatSeconds } from "../../i18n/units.ts";
import { downloadedMotionNumber, MOTION_AREA_BYTES } from "../../protocol/catalog.ts";
import { motionImage, motionImageSize } from "../../protocol/motion-image.ts";
import {
  motionDurationMs,
  parseRbm,
  RbmError,
  type RbmMotion,
  type RbmValidation,
  validateRbm,
} from "../../protocol/rbm.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf, type RunEnv } from "../command.ts";
import { confirm } from "../confirm.ts";
import { connectRobot, robotPlace } from "../connect.ts";
import { CliError, EXIT, UsageError } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { ProgressBar } from "../progress.ts";
import { errorCodeWords } from "../robot-words.ts";
import { recordOnShelf } from "../shelf-record.ts";
import {
  type IssueWords,
  issueLines,
  issuesJson,
  issueText,
  motionSummary,
  validationSummary,
} from "../upload-report.ts";
import { unreadable } from "../zeros-files.ts";
import { commandMessages } from "./messages.ts";

const OPTIONS = {
  reset: { type: "boolean" },
  action: { type: "boolean" },
  yes: { type: "boolean", short: "y" },
} as const;

/** Warnings listed in words; --json has them all. */
const MAX_WARNINGS_SHOWN = 10;

const notice = uploadNoticeText;

/** How `env` tells a motion file's problems: in its language, with the English after `--log`. */
export function issueWords(env: Pick<RunEnv, "argv" | "locale">): IssueWords {
  return { locale: localeOf(env), withEnglish: env.argv.includes("--log") };
}

type Prepared =
  | { area: "motion"; motion: RbmMotion; imageBytes: number }
  | { area: "action"; bytes: Uint8Array; imageBytes: number };

/**
 * A file that does not parse, said once: one error is the failure's one-line reason itself; several are
 * listed on stdout (or in --json's `validation.errors`) and the reason only counts them. The reason never
 * quotes the file's contents beyond what the parser's message shows (one line, at most a few characters).
 */
export function rbmInvalid(
  env: Pick<RunEnv, "out" | "argv" | "locale">,
  file: string,
  e: RbmError,
): CliError {
  const validation: RbmValidation = { errors: [...e.issues], warnings: [] };
  const details = { file, validation: issuesJson(validation) };
  const name = basename(file);
  const first = e.issues[0] ?? { code: e.code, message: e.message };
  if (e.issues.length <= 1) {
    const reason = (l: Locale) =>
      issueText(first, { locale: l })
        .replace(/\s*\n\s*/g, " ")
        .replace(/[.\s]+$/, "");
    const words = said(commandMessages, "cmd.upload.fileRefused", {
      file: name,
      reason: inEveryLanguage(reason),
    });
    return new CliError("rbm-invalid", words, EXIT.failed, details);
  }
  const t = translator(commandMessages, localeOf(env));
  env.out.line(t("cmd.upload.cannotUpload", { file }));
  for (const line of issueLines("error", validation.errors, issueWords(env))) env.out.line(line);
  const count = String(e.issues.length);
  const words: Said = env.out.json
    ? said(commandMessages, "cmd.upload.errorsInJson", { file: name, errors: count })
    : said(commandMessages, "cmd.upload.errorsAbove", { file: name, errors: count });
  return new CliError("rbm-invalid", words, EXIT.failed, details);
}

async function prepare(env: RunEnv, file: string, asAction: boolean): Promise<Prepared> {
  let bytes: Uint8Array;
  try {
    bytes = new Uint8Array(await readFile(resolve(env.cwd, file)));
  } catch (e) {
    throw unreadable(file, e);
  }
  if (asAction) {
    const t = translator(commandMessages, localeOf(env));
    env.out.note(t("cmd.upload.asAction", { file: basename(file), bytes: String(bytes.length) }));
    return { area: "action", bytes, imageBytes: bytes.length };
  }
  try {
    const motion = parseRbm(new TextDecoder().decode(bytes));
    return {
      area: "motion",
      motion,
      imageBytes: motionImageSize(motion.servos.length, motion.scenes.length),
    };
  } catch (e) {
    if (!(e instanceof RbmError)) throw e;
    throw rbmInvalid(env, file, e);
  }
}

/**
 * Which slot, and so which Run Motion number, the file became. After --reset it is the first (12); when the
 * robot's motion memory was empty before the upload (free memory = the whole area, so no file was stored),
 * it is the first as well. Otherwise the robot does not say how many files it holds, so it is not known.
 */
export function uploadedSlot(result: FileUploadResult): {
  slot: number | undefined;
  motionNumber: number | undefined;
} {
  if (result.slot !== undefined) return { slot: result.slot, motionNumber: result.motionNumber };
  if (result.area === "motion" && result.freeBefore === MOTION_AREA_BYTES) {
    return { slot: 1, motionNumber: downloadedMotionNumber(1) };
  }
  return { slot: undefined, motionNumber: undefined };
}

export const uploadCommand: CommandDef = {
  name: "upload",
  usage: "rbc upload FILE.rbm [--reset] [--action] [--yes] (--port PATH | --demo)",
  help: COMMAND_HELP.upload,
  examples: [
    "rbc upload examples/wave.rbm --demo",
    "rbc upload wave.rbm --reset --port /dev/ttyUSB0",
    "rbc upload wave.rbm --port /dev/ttyUSB0 --yes --json",
  ],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("upload", env.argv, OPTIONS);
    noExtraArguments("upload", positionals, 1);
    const file = positionals[0];
    if (file === undefined) throw new UsageError(said(commandMessages, "cmd.upload.noFile"), "upload");
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    const prepared = await prepare(env, file, values.action === true);
    const real = !values.demo;
    if (real && !values.yes && !env.stdin.isTTY) {
      throw new CliError(
        "confirmation-required",
        said(commandMessages, "cmd.upload.needsYes", {
          notice: inEveryLanguage((l) => notice("experimental", l)),
        }),
      );
    }

    const robot = await connectRobot("upload", values, env, { handlesInterrupt: true });
    const { client } = robot;
    let validation: RbmValidation = { errors: [], warnings: [] };
    let serialNumber: string | undefined;
    if (prepared.area === "motion") {
      // 0x0C is optional (docs/protocol.md §3.5): without a serial number the file's robot check is skipped.
      serialNumber = (await client.identify()).serialNumber;
      if (serialNumber === undefined) env.out.note(t("cmd.upload.noSerial"));
      validation = validateRbm(prepared.motion, { connectedSerialNumber: serialNumber });
      env.out.line(motionSummary(file, prepared.motion, prepared.imageBytes, locale));
      env.out.line(validationSummary(validation, locale));
      const shown = issueLines("warning", validation.warnings, issueWords(env));
      for (const line of shown.slice(0, MAX_WARNINGS_SHOWN)) env.out.line(line);
      if (shown.length > MAX_WARNINGS_SHOWN) {
        env.out.line(`  ${t("cmd.moreWarnings", { more: String(shown.length - MAX_WARNINGS_SHOWN) })}`);
      }
    }

    if (real) {
      env.out.note(notice("experimental", locale));
      env.out.note(notice("holdAdvice", locale));
      if (values.reset) {
        env.out.note(
          prepared.area === "motion" ? t("cmd.upload.resetWarnMotion") : t("cmd.upload.resetWarnAction"),
        );
      }
      const answer = values.yes
        ? "yes"
        : await confirm(
            env,
            t("cmd.upload.question", { file: basename(file), robot: robotPlace(robot, locale) }),
          );
      if (answer === "interrupted") {
        throw new CliError("interrupted", saidBy(nothingSentText), EXIT.interrupted);
      }
      if (answer === "no")
        throw new CliError("not-confirmed", said(commandMessages, "cmd.upload.notConfirmed"));
    }
    if (env.signal.aborted) throw new CliError("interrupted", saidBy(nothingSentText), EXIT.interrupted);

    const bar = new ProgressBar(env.out, undefined, locale);
    let result: FileUploadResult;
    try {
      const options = {
        signal: env.signal,
        resetFirst: values.reset === true,
        onPhase: (phase: string) => {
          if (phase === "checking" && values.reset) {
            env.out.line(
              prepared.area === "motion" ? t("cmd.upload.resetMotion") : t("cmd.upload.resetAction"),
            );
          }
        },
        onProgress: (p: { acknowledged: number; total: number }) => bar.update(p.acknowledged, p.total),
      };
      result =
        prepared.area === "motion"
          ? await client.uploadMotion(prepared.motion, options)
          : await client.uploadAction(prepared.bytes, options);
    } catch (e) {
      bar.finish();
      if (e instanceof RbcUploadError && e.code === "cancelled") {
        // What the robot's memory shows and what to do, from the outcome catalogue in every language.
        const what = e.facts ? uploadAfterText(e.facts, locale) : uploadOutcomeText(e.outcome, locale);
        const counts = { acknowledged: String(e.acknowledged), total: String(e.total) };
        env.out.note(`rbc: ${t("cmd.upload.interrupted", { ...counts, outcome: e.outcome, what })}`);
        env.out.result({
          ok: false,
          error: {
            code: "interrupted",
            message: errorText(e, "en"),
            acknowledged: e.acknowledged,
            total: e.total,
            outcome: e.outcome,
          },
        });
        return EXIT.interrupted;
      }
      throw e;
    }
    bar.finish();

    const seconds = result.elapsedMs / 1000;
    const rate = seconds > 0 ? Math.round(result.total / seconds) : 0;
    env.out.result({
      ok: true,
      file,
      demo: robot.demo,
      validation: issuesJson(validation),
      ...result,
      ...uploadedSlot(result),
      bytesPerSecond: rate,
      error: result.errorCode === undefined ? "not read" : errorCodeWords(result.errorCode),
    });
    env.out.line(
      t("cmd.upload.uploaded", {
        bytes: result.total,
        chunks: String(result.chunks),
        duration: formatSeconds(seconds, locale),
        rate,
      }),
    );
    const motionArea = result.area === "motion";
    if (result.freeAfter === undefined) {
      env.out.line(motionArea ? t("cmd.upload.freeMotionUnread") : t("cmd.upload.freeActionUnread"));
    } else {
      const free = { free: result.freeAfter, before: result.freeBefore };
      env.out.line(motionArea ? t("cmd.upload.freeMotion", free) : t("cmd.upload.freeAction", free));
    }
    env.out.line(
      result.errorCode === undefined
        ? t("cmd.upload.errorCodeUnread")
        : t("cmd.upload.errorCode", { words: errorCodeWords(result.errorCode, locale) }),
    );
    const placed = uploadedSlot(result);
    if (placed.motionNumber !== undefined) {
      const became = {
        motion: String(placed.motionNumber),
        key: remoteKeyWords(placed.motionNumber, locale),
      };
      env.out.line(real ? t("cmd.upload.becameHeld", became) : t("cmd.upload.became", became));
    } else if (result.area === "motion") {
      env.out.line(t("cmd.upload.numberUnknown"));
    }
    if (prepared.area === "motion" && placed.slot !== undefined && result.footprint !== undefined) {
      await recordOnShelf(env, {
        robot: { serialNumber, port: robot.where },
        slot: placed.slot,
        name: prepared.motion.name,
        image: motionImage(prepared.motion),
        durationMs: motionDurationMs(prepared.motion),
        footprint: result.footprint,
      });
    }
    return EXIT.ok;
  },
};
