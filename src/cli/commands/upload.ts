import { readFile } from "node:fs/promises";
import { basename } from "node:path";
import { RbcUploadError } from "../../device/errors.ts";
import { type FileUploadResult, UPLOAD_NOTICES } from "../../device/index.ts";
import { downloadedMotionNumber, MOTION_AREA_BYTES } from "../../protocol/catalog.ts";
import { motionImageSize } from "../../protocol/motion-image.ts";
import { parseRbm, RbmError, type RbmMotion, type RbmValidation, validateRbm } from "../../protocol/rbm.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import type { CommandDef, RunEnv } from "../command.ts";
import { confirm } from "../confirm.ts";
import { connectRobot } from "../connect.ts";
import { CliError, EXIT, UsageError } from "../errors.ts";
import { ProgressBar } from "../progress.ts";
import { issueLines, issuesJson, motionSummary, validationSummary } from "../upload-report.ts";
import { errorCodeWords } from "./info.ts";

const OPTIONS = {
  reset: { type: "boolean" },
  action: { type: "boolean" },
  yes: { type: "boolean", short: "y" },
} as const;

/** Warnings listed in words; --json has them all. */
const MAX_WARNINGS_SHOWN = 10;

/** PROTOCOL.md §6.3 [decision] Safety: one sentence, before the first byte, on a real robot (the device's words). */
export const EXPERIMENTAL_NOTICE = UPLOAD_NOTICES.experimental;
export const HOLD_ADVICE = UPLOAD_NOTICES.holdAdvice;

type Prepared =
  | { area: "motion"; motion: RbmMotion; imageBytes: number }
  | { area: "action"; bytes: Uint8Array; imageBytes: number };

/**
 * A file that does not parse, said once: one error is the failure's one-line reason itself; several are
 * listed on stdout (or in --json's `validation.errors`) and the reason only counts them. The reason never
 * quotes the file's contents beyond what the parser's message shows (one line, at most a few characters).
 */
export function rbmInvalid(env: Pick<RunEnv, "out">, file: string, e: RbmError): CliError {
  const validation: RbmValidation = { errors: [...e.issues], warnings: [] };
  const details = { file, validation: issuesJson(validation) };
  const name = basename(file);
  const first = e.issues[0]?.message ?? e.message;
  if (e.issues.length <= 1) {
    const reason = first.replace(/\s*\n\s*/g, " ").replace(/[.\s]+$/, "");
    return new CliError("rbm-invalid", `${name}: ${reason}. Nothing was sent.`, EXIT.failed, details);
  }
  env.out.line(`${file} cannot be uploaded:`);
  for (const line of issueLines("error", validation.errors)) env.out.line(line);
  const where = env.out.json ? "in validation.errors" : "listed above";
  return new CliError(
    "rbm-invalid",
    `${name} has ${e.issues.length} errors (${where}); nothing was sent.`,
    EXIT.failed,
    details,
  );
}

async function prepare(env: RunEnv, file: string, asAction: boolean): Promise<Prepared> {
  let bytes: Uint8Array;
  try {
    bytes = new Uint8Array(await readFile(file));
  } catch (e) {
    const why = (e as NodeJS.ErrnoException).code === "ENOENT" ? "no such file" : String(e);
    throw new CliError("file-unreadable", `Cannot read ${file}: ${why}.`);
  }
  if (asAction) {
    env.out.note(
      `${basename(file)}: uploaded as an action file, byte for byte (${bytes.length} bytes). No action file format is known, so its contents are not checked.`,
    );
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
  summary: "check a motion file (.rbm) and upload it to the robot's memory",
  usage: "rbc upload FILE.rbm [--reset] [--action] [--yes] (--port PATH | --demo)",
  description: `
Reads a Motionbuilder motion file (.rbm), checks it against the RBC's rules (errors stop the upload;
warnings are shown) and uploads it to the robot's motion memory, chunk by chunk, with a progress bar on
stderr. Afterwards it reports the free memory and the robot's error code in words. The robot keeps up to
20 downloaded motions: the first 10 play with \`rbc run 12\` … \`rbc run 21\`, the next ones with 33 … 42.

On a real robot (not --demo) uploading is experimental: the byte layout of the uploaded motion is the
project's reconstruction and has not been verified on real firmware. rbc says so and asks for
confirmation (--yes, or y at the prompt); run the motion first with the robot held or lying down.

Ctrl-C during the upload stops after the chunk in flight, makes the robot abandon the download, reports how
many bytes were acknowledged and what the robot's memory holds, and exits with code 130.`,
  options: [
    [
      "--reset",
      "First reset the memory pointer: forgets every downloaded motion (or action), frees the memory.",
    ],
    ["--action", "Upload FILE byte for byte as an action file (format unverified; not checked)."],
    ["-y, --yes", "Confirm an upload to a real robot without the prompt."],
  ],
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
    if (file === undefined)
      throw new UsageError("Give the motion file to upload, e.g. rbc upload examples/wave.rbm.", "upload");
    const prepared = await prepare(env, file, values.action === true);
    const real = !values.demo;
    if (real && !values.yes && !env.stdin.isTTY) {
      throw new CliError(
        "confirmation-required",
        `${EXPERIMENTAL_NOTICE} Add --yes to upload anyway (nothing was sent).`,
      );
    }

    const robot = await connectRobot("upload", values, env, { handlesInterrupt: true });
    const { client } = robot;
    let validation: RbmValidation = { errors: [], warnings: [] };
    if (prepared.area === "motion") {
      // 0x0C is optional (PROTOCOL.md §3.5): without a serial number the file's robot check is skipped.
      const { serialNumber } = await client.identify();
      if (serialNumber === undefined) {
        env.out.note("The robot does not report its serial number, so the file's robot check was skipped.");
      }
      validation = validateRbm(prepared.motion, { connectedSerialNumber: serialNumber });
      env.out.line(motionSummary(file, prepared.motion, prepared.imageBytes));
      env.out.line(validationSummary(validation));
      const shown = issueLines("warning", validation.warnings);
      for (const line of shown.slice(0, MAX_WARNINGS_SHOWN)) env.out.line(line);
      if (shown.length > MAX_WARNINGS_SHOWN) {
        env.out.line(`  … and ${shown.length - MAX_WARNINGS_SHOWN} more warnings (--json lists them all).`);
      }
    }

    if (real) {
      env.out.note(EXPERIMENTAL_NOTICE);
      env.out.note(HOLD_ADVICE);
      if (values.reset)
        env.out.note(`--reset will first forget every downloaded ${prepared.area} on the robot.`);
      const answer = values.yes
        ? "yes"
        : await confirm(env, `Upload ${basename(file)} to the robot on ${robot.where}?`);
      if (answer === "interrupted") {
        throw new CliError("interrupted", "Nothing was sent.", EXIT.interrupted);
      }
      if (answer === "no") throw new CliError("not-confirmed", "Upload not confirmed; nothing was sent.");
    }
    if (env.signal.aborted) throw new CliError("interrupted", "Nothing was sent.", EXIT.interrupted);

    const bar = new ProgressBar(env.out);
    let result: FileUploadResult;
    try {
      const options = {
        signal: env.signal,
        resetFirst: values.reset === true,
        onPhase: (phase: string) => {
          if (phase === "checking" && values.reset) {
            env.out.line(
              `Reset the ${prepared.area} memory pointer: the robot's downloaded ${prepared.area}s are forgotten.`,
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
        env.out.note(
          `rbc: upload interrupted: ${e.acknowledged} of ${e.total} bytes were acknowledged (outcome: ${e.outcome}). ${e.message}`,
        );
        env.out.result({
          ok: false,
          error: {
            code: "interrupted",
            message: e.message,
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

    const n = (v: number) => v.toLocaleString("en-US");
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
      `Uploaded ${n(result.total)} bytes in ${result.chunks} chunks in ${seconds.toFixed(1)} s (${n(rate)} bytes/s).`,
    );
    env.out.line(
      result.freeAfter === undefined
        ? `Free ${result.area} memory: not read (the robot did not answer); check with \`rbc info\`.`
        : `Free ${result.area} memory: ${n(result.freeAfter)} bytes (was ${n(result.freeBefore)}).`,
    );
    env.out.line(
      `Error code: ${result.errorCode === undefined ? "not read (the robot did not answer)" : errorCodeWords(result.errorCode)}.`,
    );
    const placed = uploadedSlot(result);
    if (placed.motionNumber !== undefined) {
      env.out.line(
        `It became motion ${placed.motionNumber} (downloaded motion ${placed.slot}): play it with \`rbc run ${placed.motionNumber}\`${real ? " — first with the robot held or lying down" : ""}.`,
      );
    } else if (result.area === "motion") {
      env.out.line(
        "The robot already held downloaded motions and does not say how many, so this one's number is not known: the first 10 uploads play with `rbc run 12` … `rbc run 21`, the next 10 with 33 … 42. Upload with --reset to make it motion 12 (the others are forgotten).",
      );
    }
    return EXIT.ok;
  },
};
