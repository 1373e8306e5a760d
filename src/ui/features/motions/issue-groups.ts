import type { RbmMotion } from "../../../protocol/rbm.ts";
import type { RbmIssue } from "../../../protocol/rbm-validate.ts";

/**
 * A file's warnings grouped by kind (the validator's issue codes, PROTOCOL.md §7), each kind with how much it
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

export const WEIGHT_WORDS: Record<Weight, string> = {
  serious: "Serious",
  check: "Check",
  minor: "Minor",
};

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

function describe(
  code: string,
  issues: RbmIssue[],
  motion: RbmMotion | undefined,
): Omit<WarningGroup, "issues"> {
  switch (code) {
    case "rbm-unsafe-position":
      return {
        code,
        title: "Positions outside a joint's safe range",
        weight: "serious",
        meaning:
          "An uploaded motion drives the servo there as written: the limb can hit the body or another limb, strain the servo or tip the robot over. Check these positions before running the motion.",
      };
    case "rbm-scene-jump": {
      const jump = largestJump(motion, issues);
      const small = jump !== undefined && jump <= SMALL_JUMP_STEPS;
      const size =
        jump === undefined
          ? ""
          : ` The largest jump is ${jump} ${jump === 1 ? "step" : "steps"}${small ? ", a twitch you will hardly see" : ""}.`;
      return {
        code,
        title: "Servos jump between scenes",
        weight: small ? "minor" : "check",
        meaning: `A scene starts a servo somewhere other than where the scene before left it, so the servo moves there at full speed instead of smoothly.${size} Large jumps can shake the robot or make it fall.`,
      };
    }
    case "rbm-serial-mismatch":
      return {
        code,
        title: "Made for another robot",
        weight: "check",
        meaning:
          "The motion was saved for a robot with another serial number. Motionbuilder refuses it; the panel uploads it, so check that it suits this robot (its zeros and build may differ).",
      };
    case "rbm-huno-servo-count":
      return {
        code,
        title: "Not the HUNO's 16 servos",
        weight: "check",
        meaning: "The motion was probably made for another robot model: check which joints it moves.",
      };
    case "rbm-many-frames":
    case "rbm-long-scene":
      return {
        code,
        title: "Beyond Motionbuilder's limits",
        weight: "minor",
        meaning:
          "Motionbuilder would not write such a scene (more than 100 frames or longer than 10 s); the RBC plays it. Opening the file in Motionbuilder may change it.",
      };
    case "rbm-serial-format":
    case "rbm-header-constant":
      return {
        code,
        title: "Unusual header fields",
        weight: "minor",
        meaning:
          "The file's header differs from what Motionbuilder writes, so it was probably edited by hand or by another tool. The scenes are read and checked as usual.",
      };
    default:
      return { code, title: "Other warnings", weight: "check", meaning: "Read the details below." };
  }
}

/** Warnings grouped by kind: the most serious kind first, then in the order they first appear. */
export function groupWarnings(warnings: readonly RbmIssue[], motion?: RbmMotion): WarningGroup[] {
  const byTitle = new Map<string, RbmIssue[]>();
  const codes = new Map<string, string>();
  for (const w of warnings) {
    const title = describe(w.code, [w], undefined).title;
    const list = byTitle.get(title) ?? [];
    list.push(w);
    byTitle.set(title, list);
    if (!codes.has(title)) codes.set(title, w.code);
  }
  const groups = [...byTitle.entries()].map(([title, issues]) => ({
    ...describe(codes.get(title) ?? "", issues, motion),
    issues,
  }));
  return groups
    .map((g, order) => ({ g, order }))
    .sort((a, b) => WEIGHT_ORDER[a.g.weight] - WEIGHT_ORDER[b.g.weight] || a.order - b.order)
    .map(({ g }) => g);
}
