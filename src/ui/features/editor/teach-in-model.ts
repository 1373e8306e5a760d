/**
 * Teach-in's pure part: which servos a limb is, the questions the panel asks, how positions read from the robot
 * become a scene's pose (the robot's zeros → the motion's), and the sentences that say what the robot confirmed.
 */
import type { Motion } from "../../../motion/index.ts";
import { PLATFORM_PF2 } from "../../../motion/index.ts";
import { HUNO_SERVO_IDS } from "../../../protocol/servo-limits.ts";
import type { Notice } from "../../app-state.ts";
import type { Limb } from "./live-state.ts";
import { sceneNumber } from "./live-state.ts";

/**
 * The HUNO's limbs and their servo ids (docs/motion-document.md, Mirror; names as `jointName`): legs 0-4 and
 * 5-9 (hip roll, hip pitch, knee, ankle pitch, ankle roll), arms 10-12 and 13-15 (shoulder pitch, shoulder
 * roll, elbow).
 */
export const LIMBS: readonly { limb: Limb; label: string; ids: readonly number[] }[] = [
  { limb: "right-leg", label: "Right leg", ids: [0, 1, 2, 3, 4] },
  { limb: "left-leg", label: "Left leg", ids: [5, 6, 7, 8, 9] },
  { limb: "right-arm", label: "Right arm", ids: [10, 11, 12] },
  { limb: "left-arm", label: "Left arm", ids: [13, 14, 15] },
];

export const ALL_LIMBS: readonly Limb[] = LIMBS.map((l) => l.limb);

export function limbIds(limb: Limb): readonly number[] {
  return LIMBS.find((l) => l.limb === limb)?.ids ?? [];
}

/** The servo ids of the chosen limbs, ascending, each once. */
export function chosenIds(limbs: readonly Limb[]): number[] {
  const ids = new Set<number>();
  for (const limb of limbs) for (const id of limbIds(limb)) ids.add(id);
  return [...ids].sort((a, b) => a - b);
}

/** Every servo of the robot is chosen: it cannot stand, so the panel asks again. */
export function choosesAll(limbs: readonly Limb[]): boolean {
  const ids = new Set(chosenIds(limbs));
  return HUNO_SERVO_IDS.every((id) => ids.has(id));
}

export const TEACH_IN_QUESTION = "Hold the robot: the servos you choose go limp.";
export const LIMP_ALL_QUESTION =
  "All 16 servos go limp: the robot cannot stand on its own. Hold it with both hands, or lay it down.";

/** "0–4, 10" — runs of consecutive ids joined with a dash. */
export function idList(ids: readonly number[]): string {
  const sorted = [...ids].sort((a, b) => a - b);
  const parts: string[] = [];
  for (let i = 0; i < sorted.length; ) {
    let j = i;
    while (j + 1 < sorted.length && sorted[j + 1] === sorted[j]! + 1) j++;
    parts.push(j - i >= 2 ? `${sorted[i]}–${sorted[j]}` : sorted.slice(i, j + 1).join(", "));
    i = j + 1;
  }
  return parts.join(", ");
}

/** Joins sentences, each starting with a capital letter. */
function sentences(parts: readonly string[]): string {
  return parts.map((p) => p.charAt(0).toUpperCase() + p.slice(1)).join(" ");
}

function servos(ids: readonly number[]): string {
  return `${ids.length === 1 ? "servo" : "servos"} ${idList(ids)}`;
}

/** The chosen limbs in words: "the right arm", "the right leg and the left arm", "every servo". */
export function limbsText(limbs: readonly Limb[]): string {
  if (choosesAll(limbs)) return "every servo";
  const names = LIMBS.filter((l) => limbs.includes(l.limb)).map((l) => `the ${l.label.toLowerCase()}`);
  if (names.length <= 1) return names[0] ?? "no servo";
  return `${names.slice(0, -1).join(", ")} and ${names.at(-1)}`;
}

/** What "Make limp" did: the servos that confirmed, the ones that did not answer. */
export function limpNotice(confirmed: readonly number[], silent: readonly number[], stopped = false): Notice {
  const parts: string[] = [];
  if (confirmed.length > 0) {
    parts.push(
      `${servos(confirmed)} ${confirmed.length === 1 ? "is" : "are"} limp (confirmed): pose ${confirmed.length === 1 ? "it" : "them"} by hand.`,
    );
  }
  if (silent.length > 0) {
    parts.push(
      `${servos(silent)} did not answer and may still hold; check ${silent.length === 1 ? "its cable" : "their cables"}.`,
    );
  }
  if (stopped) parts.push("Stop ended the rest: no other servo was made limp.");
  if (parts.length === 0) parts.push("No servo was made limp.");
  return { tone: silent.length > 0 || stopped ? "warning" : "ok", text: sentences(parts) };
}

/** A position read from the robot, by servo id. */
export interface ReadServo {
  id: number;
  position: number;
}

export interface SceneReading {
  /** Positions for the scene's end pose (the motion's zeros), by servo id. */
  pose: Map<number, number>;
  /** Servos whose position was converted because the robot's zero differs from the motion's. */
  converted: number[];
  /** Servos read that the motion does not list (not used). */
  notInMotion: number[];
}

/**
 * The positions read from the robot as a pose of the motion. Tethered play sends `position + zeroDelta` with
 * zeroDelta = the robot's zero − the motion's zero (PROTOCOL.md §10, none on platform 4), so a pose read from
 * this robot is stored as `position − zeroDelta` and plays back to where it was read. Without the robot's
 * zeros the positions are stored as read. Results outside 0-254 are clamped (an .rbm position is 0-254).
 */
export function sceneReading(
  doc: Motion,
  reads: readonly ReadServo[],
  robotZeros: readonly number[] | undefined,
  platform: number | undefined,
): SceneReading {
  const pose = new Map<number, number>();
  const converted: number[] = [];
  const notInMotion: number[] = [];
  for (const { id, position } of reads) {
    const servo = doc.servos.find((s) => s.id === id);
    if (!servo) {
      notInMotion.push(id);
      continue;
    }
    const robotZero = robotZeros?.[id];
    const delta = platform === PLATFORM_PF2 || robotZero === undefined ? 0 : robotZero - servo.zero;
    if (delta !== 0) converted.push(id);
    pose.set(id, Math.max(0, Math.min(254, position - delta)));
  }
  return { pose, converted, notInMotion };
}

/** What "Read pose into scene N" did, no more certain than the robot answered. */
export function readNotice(
  scene: number,
  reading: SceneReading,
  silent: readonly number[],
  zerosKnown: boolean,
): Notice {
  const read = [...reading.pose.keys()];
  const n = sceneNumber(scene);
  const parts: string[] = [];
  parts.push(
    read.length === 0
      ? `Nothing was read into scene ${n}: no servo of this motion answered.`
      : `Read ${servos(read)} into scene ${n} (its end pose; one undo step).`,
  );
  if (silent.length > 0) {
    parts.push(
      `${servos(silent)} did not answer: ${silent.length === 1 ? "its position" : "their positions"} in the scene did not change; check ${silent.length === 1 ? "its cable" : "their cables"}.`,
    );
  }
  if (reading.converted.length > 0) {
    parts.push(
      `The robot's zeros differ from the motion's for ${servos(reading.converted)}: those positions were converted to the motion's zeros, so they play back where they were read.`,
    );
  }
  if (!zerosKnown) parts.push("The robot's zeros could not be read, so the positions are stored as read.");
  if (reading.notInMotion.length > 0) {
    parts.push(
      `${servos(reading.notInMotion)} ${reading.notInMotion.length === 1 ? "is" : "are"} not in this motion.`,
    );
  }
  return {
    tone: read.length === 0 ? "danger" : silent.length > 0 || !zerosKnown ? "warning" : "ok",
    text: sentences(parts),
  };
}

/** One servo that "Hold" moved: where it was read and where it was told to hold (its safe range). */
export interface HeldServo {
  id: number;
  read: number;
  held: number;
}

/** What "Hold" (or "End teach-in") did. */
export function holdNotice(held: readonly HeldServo[], silent: readonly number[], stopped = false): Notice {
  const parts: string[] = [];
  const ids = held.map((h) => h.id);
  if (held.length > 0) {
    parts.push(
      `${servos(ids)} ${held.length === 1 ? "holds" : "hold"} where ${held.length === 1 ? "it was" : "they were"} posed (torque on, confirmed).`,
    );
  }
  for (const h of held) {
    if (h.held !== h.read) {
      parts.push(`Servo ${h.id} was at ${h.read}, outside its safe range: it holds at ${h.held}.`);
    }
  }
  if (silent.length > 0) {
    parts.push(
      `${servos(silent)} did not answer and may still be limp: hold the robot and check ${silent.length === 1 ? "its cable" : "their cables"}.`,
    );
  }
  if (stopped) parts.push("Stop ended the rest: the servos not listed may still be limp.");
  if (parts.length === 0) parts.push("No servo was limp: nothing to hold.");
  return { tone: silent.length > 0 || stopped ? "warning" : "ok", text: sentences(parts) };
}
