import { motionImage, parseRbm, RbmError, serializeRbm, validateRbm } from "../../src/protocol/index.ts";
import { isAcceptedZeroTable } from "../../src/protocol/zeros.ts";
import { parseZerosBackup, zerosBackupSchema } from "../../src/protocol/zeros-backup.ts";

/**
 * Functions the fuzz tests run inside a time-boxed worker (tests/support/time-box.ts). Each takes one input
 * and returns a plain, structured-clonable verdict; they never throw (an unexpected exception is a verdict).
 */

export type Verdict =
  | { kind: "ok"; detail?: string }
  | { kind: "typed-error"; code: string }
  | { kind: "violation"; detail: string };

function unexpected(e: unknown): Verdict {
  const name = e instanceof Error ? e.name : typeof e;
  const message = e instanceof Error ? e.message : String(e);
  return { kind: "violation", detail: `threw ${name}: ${message}` };
}

/** parseRbm: a motion that validates, serializes back to the same text and encodes as an image; or RbmError. */
export function checkRbm(text: string): Verdict {
  let motion: ReturnType<typeof parseRbm>;
  try {
    motion = parseRbm(text);
  } catch (e) {
    if (
      e instanceof RbmError &&
      typeof e.code === "string" &&
      e.code.startsWith("rbm-") &&
      e.message.length > 0
    ) {
      return { kind: "typed-error", code: e.code };
    }
    return unexpected(e);
  }
  try {
    const errors = validateRbm(motion).errors;
    if (errors.length > 0) return { kind: "violation", detail: `accepted with errors: ${errors[0]!.code}` };
    if (serializeRbm(motion) !== text)
      return { kind: "violation", detail: "serializeRbm(parseRbm(text)) !== text" };
    try {
      motionImage(motion);
    } catch (e) {
      if (!(e instanceof RbmError)) return unexpected(e);
    }
    return { kind: "ok" };
  } catch (e) {
    return unexpected(e);
  }
}

/** parseZerosBackup: a refusal with a known problem and a message, or a backup the schema and the RBC accept. */
export function checkZerosBackup(text: string): Verdict {
  let parsed: ReturnType<typeof parseZerosBackup>;
  try {
    parsed = parseZerosBackup(text);
  } catch (e) {
    return unexpected(e);
  }
  if (!parsed.ok) {
    const problems = ["not-json", "wrong-format", "wrong-version", "wrong-count", "out-of-range", "invalid"];
    if (!problems.includes(parsed.problem))
      return { kind: "violation", detail: `unknown problem ${parsed.problem}` };
    if (typeof parsed.message !== "string" || parsed.message.length < 10) {
      return { kind: "violation", detail: "refusal without a message" };
    }
    return { kind: "typed-error", code: parsed.problem };
  }
  if (!zerosBackupSchema.safeParse(parsed.backup).success)
    return { kind: "violation", detail: "schema rejects it" };
  if (!isAcceptedZeroTable(parsed.backup.zeros))
    return { kind: "violation", detail: "zeros the RBC refuses" };
  return { kind: "ok", detail: parsed.backup.zeros.join(",") };
}

/** For the time box's own test: busy-waits `input` milliseconds (a stand-in for a hang). */
export function spin(input: string): Verdict {
  const until = performance.now() + Number(input);
  while (performance.now() < until) {
    // spinning
  }
  return { kind: "ok" };
}

export const FUZZ_TARGETS = { checkRbm, checkZerosBackup, spin } as const;
export type FuzzTarget = keyof typeof FUZZ_TARGETS;
