import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import type { RbmMotion } from "../../../protocol/rbm.ts";
import type { RbmIssue } from "../../../protocol/rbm-validate.ts";
import { type MotionsKey, type MotionsTranslator, motionsMessages } from "./messages.ts";

/**
 * A file's warnings grouped by kind (the validator's issue codes, docs/protocol.md §7), each kind with how much it
 * matters and what it means for the robot. Stock Motionbuilder files carry dozens of small warnings
 * (WalkJump.rbm: 27 "the servo will jump"): a flat list gives each the same weight, so the person cannot tell
 * a 1-step twitch from an arm driven into the body. Pure functions.
 */

/** How much a kind of warning matters: "serious" can hurt the robot, "check" deserves a look, "minor" does not change what the robot does. */
export type Weight = "serious" | "check" | "minor";

export interface WarningGroup {
  code: string;
  /** A short name of the kind: "Servo jumps between scenes". */
  title: string;
  weight: Weight;
  /** What it means for the robot, in one or two sentences. */
  meaning: string;
  issues: RbmIssue[];
}

/** A jump of at most this many position steps (of 0-254) is a twitch. */
export const SMALL_JUMP_STEPS = 3;

const WEIGHT_ORDER: Record<Weight, number> = { serious: 0, check: 1, minor: 2 };

const WEIGHT_KEYS: Readonly<Record<Weight, MotionsKey>> = {
  serious: "motions.weight.serious",
  check: "motions.weight.check",
  minor: "motions.weight.minor",
};

/** The weight of a kind of warning, in words (a badge beside its title): "Serious" / "심각". */
export function weightWord(weight: Weight, locale: Locale): string {
  return translator(motionsMessages, locale)(WEIGHT_KEYS[weight]);
}

/** The largest jump (position steps) among scene-jump warnings, from the motion itself; undefined if unknown. */
export function largestJump(motion: RbmMotion | undefined, issues: readonly RbmIssue[]): number | undefined {
  if (!motion) return undefined;
  let largest: number | undefined;
  for (const issue of issues) {
    if (issue.scene === undefined || issue.servo === undefined) continue;
    const scene = motion.scenes[issue.scene];
    const previous = motion.scenes[issue.scene - 1];
    const i = scene?.servos.findIndex((r) => r.id === issue.servo) ?? -1;
    const now = scene?.servos[i];
    const before = previous?.servos[i];
    if (!now || !before) continue;
    const steps = Math.abs(now.start - before.end);
    largest = largest === undefined ? steps : Math.max(largest, steps);
  }
  return largest;
}

interface Kind {
  /** Also what groups warnings: two codes with the same title are one kind for the person. */
  title: MotionsKey;
  weight: Weight;
  meaning: string;
}

function describe(
  t: MotionsTranslator,
  code: string,
  issues: RbmIssue[],
  motion: RbmMotion | undefined,
): Kind {
  switch (code) {
    case "rbm-unsafe-position":
      return {
        title: "motions.group.unsafeTitle",
        weight: "serious",
        meaning: t("motions.group.unsafeMeaning"),
      };
    case "rbm-scene-jump": {
      const jump = largestJump(motion, issues);
      const small = jump !== undefined && jump <= SMALL_JUMP_STEPS;
      const size =
        jump === undefined
          ? undefined
          : small
            ? t("motions.group.jumpLargestSmall", { count: jump })
            : t("motions.group.jumpLargest", { count: jump });
      return {
        title: "motions.group.jumpTitle",
        weight: small ? "minor" : "check",
        meaning: [t("motions.group.jumpMeaning"), size, t("motions.group.jumpRisk")]
          .filter((x) => x !== undefined)
          .join(" "),
      };
    }
    case "rbm-serial-mismatch":
      return {
        title: "motions.group.serialTitle",
        weight: "check",
        meaning: t("motions.group.serialMeaning"),
      };
    case "rbm-huno-servo-count":
      return { title: "motions.group.hunoTitle", weight: "check", meaning: t("motions.group.hunoMeaning") };
    case "rbm-many-frames":
    case "rbm-long-scene":
      return {
        title: "motions.group.limitsTitle",
        weight: "minor",
        meaning: t("motions.group.limitsMeaning"),
      };
    case "rbm-serial-format":
    case "rbm-header-constant":
      return {
        title: "motions.group.headerTitle",
        weight: "minor",
        meaning: t("motions.group.headerMeaning"),
      };
    default:
      return { title: "motions.group.otherTitle", weight: "check", meaning: t("motions.group.otherMeaning") };
  }
}

/**
 * Warnings grouped by kind: the most serious kind first, then in the order they first appear. Titles and
 * meanings in the panel's language (English unless given).
 */
export function groupWarnings(
  warnings: readonly RbmIssue[],
  motion?: RbmMotion,
  locale: Locale = "en",
): WarningGroup[] {
  const t = translator(motionsMessages, locale);
  const byTitle = new Map<MotionsKey, RbmIssue[]>();
  const codes = new Map<MotionsKey, string>();
  for (const w of warnings) {
    const title = describe(t, w.code, [w], undefined).title;
    const list = byTitle.get(title) ?? [];
    list.push(w);
    byTitle.set(title, list);
    if (!codes.has(title)) codes.set(title, w.code);
  }
  const groups = [...byTitle.entries()].map(([title, issues]): WarningGroup => {
    const code = codes.get(title) ?? "";
    const kind = describe(t, code, issues, motion);
    return { code, title: t(kind.title), weight: kind.weight, meaning: kind.meaning, issues };
  });
  return groups
    .map((g, order) => ({ g, order }))
    .sort((a, b) => WEIGHT_ORDER[a.g.weight] - WEIGHT_ORDER[b.g.weight] || a.order - b.order)
    .map(({ g }) => g);
}
