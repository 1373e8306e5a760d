import type {
  Finding,
  ScanResult,
  ServoReading,
  SetIdResult,
  StopCode,
  WiggleResult,
} from "../../../device/servo-doctor/index.ts";
import type { WckParameter, WckParameterValue } from "../../../protocol/wck.ts";
import { jointOf } from "../../joint-names/joint-name.ts";
import type { Locale } from "../../locale.ts";
import { translator } from "../../translate.ts";
import { errorText } from "../error-text.ts";
import { servoOutcomeMessages as messages } from "./messages.ts";

/**
 * The servo doctor's outcomes in words, from their codes and facts, in either language: `rbc servos` prints
 * them and the panel shows the same sentences. Types only from src/device (this folder stays pure).
 */

const t = (locale: Locale) => translator(messages, locale);

/** "Servo 7 (Right knee)", "Servo 20"; Korean "서보 7번(오른쪽 무릎)". The joint is the catalogue's (jointOf). */
export function servoText(id: number, locale: Locale): string {
  const joint = jointOf(id, locale);
  return joint === undefined
    ? t(locale)("outcome.servo.plain", { id: String(id) })
    : t(locale)("outcome.servo.withJoint", { id: String(id), joint });
}

/** "answered", "silent", "garbled". */
export function readingStatusText(status: ServoReading["status"], locale: Locale): string {
  return t(locale)(STATUS_KEY[status]);
}

const STATUS_KEY = {
  answered: "outcome.servo.status.answered",
  silent: "outcome.servo.status.silent",
  garbled: "outcome.servo.status.garbled",
} as const satisfies Record<ServoReading["status"], string>;

const PARAMETER_KEY = {
  gains: "outcome.servo.parameter.gains",
  speed: "outcome.servo.parameter.speed",
  overload: "outcome.servo.parameter.overload",
  bounds: "outcome.servo.parameter.bounds",
  iGain: "outcome.servo.parameter.iGain",
  io: "outcome.servo.parameter.io",
} as const satisfies Record<WckParameter, string>;

/** A parameter's name ("P and D gains", "bounds (lower, upper)"). */
export function parameterNameText(parameter: WckParameter, locale: Locale): string {
  return t(locale)(PARAMETER_KEY[parameter]);
}

/** A parameter's value as read, in the manual's order: "P 30, D 20", "1, 254" (the same in every language). */
export function parameterValueText(value: WckParameterValue): string {
  switch (value.parameter) {
    case "gains":
      return `P ${value.p}, D ${value.d}`;
    case "speed":
      return `${value.speed}, ${value.acceleration}`;
    case "overload":
      return String(value.code);
    case "bounds":
      return `${value.lower}, ${value.upper}`;
    case "iGain":
      return String(value.i);
    case "io":
      return String(value.outputs);
  }
}

/** A finding as one or two sentences. */
export function findingText(finding: Finding, locale: Locale): string {
  const tr = t(locale);
  const [first = 0] = finding.ids;
  switch (finding.code) {
    case "servo-missing":
      return tr("outcome.servo.finding.missing", { servo: servoText(first, locale) });
    case "servo-duplicate":
      return tr("outcome.servo.finding.duplicate", { id: String(first) });
    case "servo-replacement": {
      // Several silent joints: which one the new servo replaced is the owner's to say, not the scan's.
      const missing = finding.ids.slice(1);
      return missing.length > 1
        ? tr("outcome.servo.finding.replacementOneOf", {
            missing: missing.join(", "),
            choices: tr("outcome.servo.orList", {
              list: missing.slice(0, -1).join(", "),
              last: String(missing.at(-1)),
            }),
          })
        : tr("outcome.servo.finding.replacement", {
            missing: missing.join(", "),
            first: String(missing[0] ?? "?"),
          });
    }
    case "servo-high-load":
      return tr("outcome.servo.finding.highLoad", {
        servo: servoText(first, locale),
        load: String(finding.load ?? "?"),
      });
    case "bus-silent":
      return `${tr("outcome.servo.finding.busSilent")} ${hardwareResetText(locale)}`;
  }
}

/** The hardware reset (docs/protocol.md §5): for a servo that answers at no id. */
export function hardwareResetText(locale: Locale): string {
  return t(locale)("outcome.servo.hardwareReset");
}

const STOP_KEY = {
  cancelled: "outcome.servo.stopped.cancelled",
  "stop-pressed": "outcome.servo.stopped.stopPressed",
  disconnected: "outcome.servo.stopped.disconnected",
  "left-direct-mode": "outcome.servo.stopped.leftDirectMode",
  "firmware-sends-packets": "outcome.servo.stopped.firmwarePackets",
  failed: "outcome.servo.stopped.failed",
} as const satisfies Record<StopCode, string>;

/** Why an operation stopped, as a phrase. */
export function stopText(code: StopCode, locale: Locale): string {
  return t(locale)(STOP_KEY[code]);
}

/**
 * A scan that stopped early: why (the packets the firmware sent, or the error that stopped it, in a sentence of
 * its own), the ids read and those not read.
 */
export function scanStoppedText(result: ScanResult, locale: Locale): string | undefined {
  const stopped = result.stopped;
  if (!stopped) return undefined;
  const tr = t(locale);
  const none = tr("outcome.servo.none");
  const list = (ids: number[]) => (ids.length === 0 ? none : ids.join(", "));
  const ids = { read: list(result.servos.map((s) => s.id)), unread: list(stopped.unread) };
  const because = becauseText(stopped, locale);
  if (because) return tr("outcome.servo.stoppedBecause", { because: capitalised(because), ...ids });
  return tr("outcome.servo.stopped", { why: stopText(stopped.code, locale), ...ids });
}

/** The sentence that says why a scan stopped, when a phrase cannot: the firmware's packets, or the error. */
function becauseText(stopped: NonNullable<ScanResult["stopped"]>, locale: Locale): string | undefined {
  if (stopped.code === "firmware-sends-packets") {
    return stopped.type === undefined
      ? t(locale)("outcome.servo.firmwarePacketsUntyped")
      : t(locale)("outcome.servo.firmwarePackets", { type: hexByte(stopped.type) });
  }
  if (stopped.code === "failed" && stopped.error !== undefined) return errorText(stopped.error, locale);
  return undefined;
}

function hexByte(b: number): string {
  return `0x${b.toString(16).toUpperCase().padStart(2, "0")}`;
}

function capitalised(text: string): string {
  return text.charAt(0).toUpperCase() + text.slice(1);
}

/** The guided id fix's outcome, worded from what was read. */
export function setIdText(result: SetIdResult, locale: Locale): string {
  const tr = t(locale);
  const from = String(result.from);
  const to = String(result.to);
  switch (result.outcome) {
    case "done":
      return tr("outcome.servo.setId.done", {
        from,
        to,
        position: String(result.after.to.status === "answered" ? result.after.to.position : "?"),
      });
    case "refused": {
      const key = {
        "from-silent": "outcome.servo.setId.refused.fromSilent",
        "from-garbled": "outcome.servo.setId.refused.fromGarbled",
        "to-taken": "outcome.servo.setId.refused.toTaken",
        "not-confirmed": "outcome.servo.setId.refused.notConfirmed",
      } as const;
      return tr(key[result.reason], { from, to });
    }
    case "failed":
      if (result.reason === "answers-nowhere") {
        return `${tr("outcome.servo.setId.failed.answersNowhere", { from, to })} ${hardwareResetText(locale)}`;
      }
      if (result.reason === "not-taken") return tr("outcome.servo.setId.failed.notTaken", { from, to });
      return tr("outcome.servo.setId.failed.unclear", {
        from,
        to,
        toStatus: readingStatusText(result.after.to.status, locale),
        fromStatus: readingStatusText(result.after.from.status, locale),
      });
    case "stopped":
      return tr(result.sent ? "outcome.servo.setId.stopped" : "outcome.servo.setId.stoppedUnsent", {
        why: stopText(result.code, locale),
      });
  }
}

/** The wiggle test's outcome. */
export function wiggleText(result: WiggleResult, counts: number, locale: Locale): string {
  const tr = t(locale);
  const servo = servoText(result.id, locale);
  switch (result.outcome) {
    case "done":
      return tr(result.followed ? "outcome.servo.wiggle.followed" : "outcome.servo.wiggle.notFollowed", {
        servo,
        counts: String(counts),
        start: String(result.start),
        percent: String(result.followedPercent),
        load: String(result.maxLoad),
      });
    case "not-read":
      return tr("outcome.servo.wiggle.notRead", {
        servo,
        status: readingStatusText(result.reading.status, locale),
      });
    case "outside-safe-range":
      return tr("outcome.servo.wiggle.outsideSafeRange", {
        servo,
        start: String(result.start),
        min: String(result.min),
        max: String(result.max),
      });
    case "lost":
      return tr("outcome.servo.wiggle.lost", {
        servo,
        status: readingStatusText(result.reading.status, locale),
      });
    case "stopped":
      return tr("outcome.servo.wiggle.stopped", { why: stopText(result.code, locale) });
  }
}

/** Parameter reads that stopped early. */
export function infoStoppedText(code: StopCode, locale: Locale): string {
  return t(locale)("outcome.servo.info.stopped", { why: stopText(code, locale) });
}
