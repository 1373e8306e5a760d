import { parseArgs } from "node:util";
import type { Locale } from "../i18n/locale.ts";
import { robotFactText } from "../i18n/outcomes/robot-facts.ts";
import { said } from "../i18n/said.ts";
import { translator } from "../i18n/translate.ts";
import { platformName } from "../protocol/catalog.ts";
import { commandName } from "../protocol/commands.ts";
import { formatFirmware } from "../shared/format.ts";
import type { ServoFaults } from "../sim/sim-servo-faults.ts";
import type { SimulatedRbcOptions } from "../sim/sim-types.ts";
import { parseFailure } from "./args.ts";
import { UsageError } from "./errors.ts";
import { cliMessages } from "./messages.ts";

/**
 * Firmware variants of the simulated RBC (docs/protocol.md §3.5), as command-line switches: `rbc sim` takes them as
 * options, and the demo robot of `--demo` takes the same switches from the RBC_DEMO_VARIANT environment
 * variable (e.g. `RBC_DEMO_VARIANT="--no-serial --firmware 9.99" rbc info --demo`). An environment variable
 * rather than more global options: the variants are for trying a client against odd firmware, not something
 * every command's help should list, and one variable reaches every command (info, zeros, upload, sensors, …).
 * The servo-bus faults of docs/protocol.md §5 (`--servo-missing N` …) are switches here too.
 */

export const VARIANT_OPTIONS = {
  "no-serial": { type: "boolean" },
  "no-status": { type: "boolean" },
  firmware: { type: "string" },
  platform: { type: "string" },
  "repeat-replies": { type: "boolean" },
  "repeat-type": { type: "string" },
  "repeat-distance": { type: "boolean" },
  "firmware-events": { type: "boolean" },
  "busy-motion": { type: "string" },
  "user-firmware": { type: "boolean" },
  "no-memory-read": { type: "boolean" },
  "servos-silent": { type: "boolean" },
  "sound-reply-at-once": { type: "boolean" },
  "quick-repeat-posture": { type: "boolean" },
  "no-zero-write": { type: "boolean" },
  // Servo-bus faults (docs/protocol.md §5): each takes a servo id 0-15 and may be given more than once.
  "servo-missing": { type: "string", multiple: true },
  "servo-duplicate": { type: "string", multiple: true },
  "servo-replacement": { type: "string", multiple: true },
  "servo-loaded": { type: "string", multiple: true },
  "servo-late": { type: "string", multiple: true },
  "in-bootloader": { type: "boolean" },
  // Old servo replies the controller relays as direct mode begins (docs/protocol.md §3.6): how many bytes.
  "stale-servo-bytes": { type: "string" },
} as const;

/** The demo robot's variant switches (same syntax as `rbc sim`'s). */
export const DEMO_VARIANT_VAR = "RBC_DEMO_VARIANT";

/** The reply the homebrew port repeats endlessly (docs/protocol.md §3.5): the distance sensor's. */
export const DEFAULT_REPEAT_TYPE = 0x16;
/**
 * Its pace: one 17-byte 0x16 reply about every 0.95 ms, 17.8 KB/s as measured on the homebrew port. Over a
 * paced wire (--baud-pacing) a reply cannot leave faster than its bytes take, so the interval grows to that.
 */
export const REPEAT_INTERVAL_MS = 0.955;

export type SimVariant = Pick<
  SimulatedRbcOptions,
  | "answersSerialNumber"
  | "answersExecutionStatus"
  | "firmware"
  | "platform"
  | "repeatReplies"
  | "firmwareEventPace"
  | "busyMotion"
  | "userFirmware"
  | "answersMemoryRead"
  | "servosSilent"
  | "soundReplyAtOnce"
  | "quickRepeatPosture"
  | "answersZeroWrite"
  | "servoFaults"
  | "staleServoBytes"
> & {
  /** The robot waits in its bootloader (docs/protocol.md §11): `^` again and again, no packet answered. */
  inBootloader?: boolean;
};

/** The simulator's own options of a variant, without the bootloader's. */
export function rbcOptionsOf(variant: SimVariant): Omit<SimVariant, "inBootloader"> {
  const { inBootloader: _, ...rbc } = variant;
  return rbc;
}

interface VariantValues {
  "no-serial"?: boolean;
  "no-status"?: boolean;
  firmware?: string;
  platform?: string;
  "repeat-replies"?: boolean;
  "repeat-type"?: string;
  "repeat-distance"?: boolean;
  "firmware-events"?: boolean;
  "busy-motion"?: string;
  "user-firmware"?: boolean;
  "no-memory-read"?: boolean;
  "servos-silent"?: boolean;
  "sound-reply-at-once"?: boolean;
  "quick-repeat-posture"?: boolean;
  "no-zero-write"?: boolean;
  "servo-missing"?: string[];
  "servo-duplicate"?: string[];
  "servo-replacement"?: string[];
  "servo-loaded"?: string[];
  "servo-late"?: string[];
  "in-bootloader"?: boolean;
  "stale-servo-bytes"?: string;
}

/** The servo-fault switches, the `ServoFaults` field each sets, and the lowest id it takes. */
const SERVO_FAULT_SWITCHES = [
  { option: "servo-missing", field: "missing", lowest: 0 },
  { option: "servo-duplicate", field: "duplicate", lowest: 0 },
  // Servo 0 answering at id 0 is no fault.
  { option: "servo-replacement", field: "replacement", lowest: 1 },
  { option: "servo-loaded", field: "loaded", lowest: 0 },
] as const satisfies readonly { option: keyof VariantValues; field: keyof ServoFaults; lowest: number }[];

function parseFirmware(text: string, command: string): { major: number; minor: number } {
  const m = /^(\d{1,3})\.(\d{1,3})$/.exec(text.trim());
  const major = m ? Number(m[1]) : Number.NaN;
  const minor = m ? Number(m[2]) : Number.NaN;
  if (!m || major > 255 || minor > 255) {
    throw new UsageError(said(cliMessages, "cli.variant.firmware", { value: text }), command);
  }
  return { major, minor };
}

function parsePlatform(text: string, command: string): number {
  const n = Number(text);
  if (!/^\d{1,3}$/.test(text.trim()) || n > 255) {
    throw new UsageError(said(cliMessages, "cli.variant.platform", { value: text }), command);
  }
  return n;
}

function parseBusyMotion(text: string, command: string): number {
  const n = Number(text);
  if (!/^\d{1,2}$/.test(text.trim()) || n < 1 || n > 11) {
    throw new UsageError(said(cliMessages, "cli.variant.busyMotion", { value: text }), command);
  }
  return n;
}

function parseStaleBytes(text: string, command: string): number {
  const n = Number(text);
  if (!/^\d{1,2}$/.test(text.trim()) || n > 64) {
    throw new UsageError(said(cliMessages, "cli.variant.staleServoBytes", { value: text }), command);
  }
  return n;
}

function parseServoId(text: string, option: string, lowest: number, command: string): number {
  const n = Number(text);
  if (!/^\d{1,2}$/.test(text.trim()) || n < lowest || n > 15) {
    throw new UsageError(
      said(cliMessages, "cli.variant.servoId", {
        option: `--${option}`,
        lowest: String(lowest),
        value: text,
      }),
      command,
    );
  }
  return n;
}

/** `--servo-late N:MS`: servo N (0-15) answers MS ms (0-5000) after each command. */
function parseLate(text: string, command: string): [number, number] {
  const m = /^(\d{1,2}):(\d{1,4})$/.exec(text.trim());
  const id = m ? Number(m[1]) : Number.NaN;
  const ms = m ? Number(m[2]) : Number.NaN;
  if (!m || id > 15 || ms > 5000) {
    throw new UsageError(said(cliMessages, "cli.variant.servoLate", { value: text }), command);
  }
  return [id, ms];
}

/** The servo faults the switches ask for, or undefined when none is given. */
function servoFaultsFromValues(values: VariantValues, command: string): ServoFaults | undefined {
  const faults: { -readonly [K in Exclude<keyof ServoFaults, "late">]?: number[] } & Pick<
    ServoFaults,
    "late"
  > = {};
  for (const { option, field, lowest } of SERVO_FAULT_SWITCHES) {
    const texts = values[option];
    if (texts === undefined || texts.length === 0) continue;
    faults[field] = [...new Set(texts.map((text) => parseServoId(text, option, lowest, command)))];
  }
  const late = values["servo-late"];
  if (late && late.length > 0) faults.late = Object.fromEntries(late.map((text) => parseLate(text, command)));
  const both = faults.replacement?.find((id) => faults.missing?.includes(id));
  if (both !== undefined) {
    throw new UsageError(
      said(cliMessages, "cli.variant.servoMissingAndReplaced", { id: String(both) }),
      command,
    );
  }
  return Object.keys(faults).length > 0 ? faults : undefined;
}

function parseType(text: string, command: string): number {
  const m = /^0x([0-9a-f]{1,2})$/i.exec(text.trim());
  if (!m) throw new UsageError(said(cliMessages, "cli.variant.repeatType", { value: text }), command);
  return Number.parseInt(m[1]!, 16);
}

/**
 * The simulator options the switches ask for (only those given: the rest keep the simulator's defaults).
 * `paced`: replies cross a wire modelled at 115200 baud, so repeats come no faster than it carries them.
 */
export function variantFromValues(values: VariantValues, command: string, paced = false): SimVariant {
  const variant: SimVariant = {};
  if (values["no-serial"]) variant.answersSerialNumber = false;
  if (values["no-status"]) variant.answersExecutionStatus = false;
  if (values["in-bootloader"]) variant.inBootloader = true;
  if (values.firmware !== undefined) variant.firmware = parseFirmware(values.firmware, command);
  if (values.platform !== undefined) variant.platform = parsePlatform(values.platform, command);
  if (values["firmware-events"]) variant.firmwareEventPace = true;
  if (values["busy-motion"] !== undefined)
    variant.busyMotion = parseBusyMotion(values["busy-motion"], command);
  if (values["user-firmware"]) variant.userFirmware = true;
  if (values["no-memory-read"]) variant.answersMemoryRead = false;
  if (values["servos-silent"]) variant.servosSilent = true;
  if (values["sound-reply-at-once"]) variant.soundReplyAtOnce = true;
  if (values["quick-repeat-posture"]) variant.quickRepeatPosture = true;
  if (values["no-zero-write"]) variant.answersZeroWrite = false;
  if (values["stale-servo-bytes"] !== undefined)
    variant.staleServoBytes = parseStaleBytes(values["stale-servo-bytes"], command);
  const servoFaults = servoFaultsFromValues(values, command);
  if (servoFaults) variant.servoFaults = servoFaults;
  // --repeat-distance names the homebrew port's own bug: the 0x16 reply, the default of --repeat-replies.
  if (values["repeat-replies"] || values["repeat-distance"] || values["repeat-type"] !== undefined) {
    const type =
      values["repeat-type"] === undefined ? DEFAULT_REPEAT_TYPE : parseType(values["repeat-type"], command);
    // A 0x16 reply is 17 bytes; 86.8 µs each at 115200 baud.
    variant.repeatReplies = {
      type,
      intervalMs: paced ? Math.max(REPEAT_INTERVAL_MS, 17 * 0.0868) : REPEAT_INTERVAL_MS,
    };
  }
  return variant;
}

/** RBC_DEMO_VARIANT, parsed with the switches of `rbc sim`; empty when unset. */
export function demoVariant(env: NodeJS.ProcessEnv, command?: string): SimVariant {
  const text = env[DEMO_VARIANT_VAR]?.trim();
  if (text === undefined || text === "") return {};
  const where = command ?? "sim";
  let values: VariantValues;
  try {
    ({ values } = parseArgs({
      args: text.split(/\s+/),
      options: VARIANT_OPTIONS,
      allowPositionals: false,
      strict: true,
    }));
  } catch (e) {
    const why = parseFailure(e);
    throw new UsageError(
      said(cliMessages, "cli.variant.demoVariant", { variable: DEMO_VARIANT_VAR, reason: why }),
      command,
    );
  }
  try {
    return variantFromValues(values, where);
  } catch (e) {
    if (e instanceof UsageError) {
      throw new UsageError(
        said(cliMessages, "cli.variant.inVariable", { variable: DEMO_VARIANT_VAR, reason: e.said }),
        command,
      );
    }
    throw e;
  }
}

/** The variant in words, for `rbc sim`'s ready line: empty for the standard robot. */
export function describeVariant(variant: SimVariant, locale: Locale = "en"): string[] {
  const t = translator(cliMessages, locale);
  const words: string[] = [];
  if (variant.answersSerialNumber === false) words.push(t("cli.variant.noSerial"));
  if (variant.answersExecutionStatus === false) words.push(t("cli.variant.noStatus"));
  if (variant.inBootloader) words.push(t("cli.variant.inBootloader"));
  if (variant.repeatReplies) {
    const type = variant.repeatReplies.type;
    const hex = `0x${type.toString(16).toUpperCase().padStart(2, "0")}`;
    words.push(t("cli.variant.repeats", { type: hex, name: commandName(type) }));
  }
  if (variant.firmwareEventPace) words.push(t("cli.variant.firmwareEvents"));
  if (variant.busyMotion !== undefined) {
    words.push(t("cli.variant.busyMotion.words", { number: String(variant.busyMotion) }));
  }
  if (variant.userFirmware) words.push(t("cli.variant.userFirmware"));
  if (variant.answersMemoryRead === false) words.push(t("cli.variant.noMemoryRead"));
  if (variant.servosSilent) words.push(t("cli.variant.servosSilent"));
  if (variant.soundReplyAtOnce) words.push(t("cli.variant.soundReplyAtOnce"));
  if (variant.quickRepeatPosture) words.push(t("cli.variant.quickRepeatPosture"));
  if (variant.answersZeroWrite === false) words.push(t("cli.variant.noZeroWrite"));
  if (variant.staleServoBytes) {
    words.push(t("cli.variant.staleServoBytes.words", { count: variant.staleServoBytes }));
  }
  const faults = variant.servoFaults;
  const ids = (list: readonly number[] | undefined) =>
    list && list.length > 0 ? list.join(", ") : undefined;
  const missing = ids(faults?.missing);
  if (missing) words.push(t("cli.variant.servoMissing", { ids: missing }));
  const duplicate = ids(faults?.duplicate);
  if (duplicate) words.push(t("cli.variant.servoDuplicate", { ids: duplicate }));
  const replacement = ids(faults?.replacement);
  if (replacement) words.push(t("cli.variant.servoReplacement", { ids: replacement }));
  const loaded = ids(faults?.loaded);
  if (loaded) words.push(t("cli.variant.servoLoaded", { ids: loaded }));
  for (const [id, ms] of Object.entries(faults?.late ?? {})) {
    words.push(t("cli.variant.servoLate.words", { id, ms: String(ms) }));
  }
  return words;
}

/** "firmware 9.99, serial not reported, platform 4 (PF2)": what the simulated robot says about itself. */
export function aboutRobot(
  firmware: { major: number; minor: number },
  serialNumber: string | undefined,
  platform: number,
  locale: Locale = "en",
): string {
  const t = translator(cliMessages, locale);
  return t("cli.variant.about", {
    firmware: formatFirmware(firmware),
    serial: serialNumber ?? robotFactText("notReported", locale),
    platform: String(platform),
    name: platformName(platform),
  });
}
