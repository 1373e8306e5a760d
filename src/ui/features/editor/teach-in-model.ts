/**
 * Teach-in's pure part: which servos a limb is, the questions the panel asks, how positions read from the robot
 * become a scene's pose (the robot's zeros → the motion's), and the sentences that say what the robot confirmed
 * (in the language given; English unless given).
 */
import type { KeysWithoutParams } from "../../../i18n/catalogue.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { inEveryLanguage, type LocalText, type Said, said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import type { Motion } from "../../../motion/index.ts";
import { PLATFORM_PF2 } from "../../../motion/index.ts";
import { HUNO_SERVO_IDS } from "../../../protocol/servo-limits.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import type { Limb } from "./live-state.ts";
import { sceneNumber } from "./live-state.ts";
import { type EditorKey, type EditorTranslator, editorMessages } from "./messages.ts";

const english = translator(editorMessages, "en");

/**
 * The HUNO's limbs and their servo ids, named from the robot's own point of view (docs/protocol.md §4; names
 * as `jointName`): left leg 0-4, right leg 5-9 (hip roll, hip pitch, knee, ankle pitch, ankle roll), left arm
 * 10-12, right arm 13-15 (shoulder pitch, shoulder roll, elbow).
 */
interface LimbInfo {
  limb: Limb;
  /** Its name, in English ("Left leg"); `key` in the catalogue. */
  label: string;
  key: EditorKey;
  /** Its name inside a sentence: "the left leg". */
  inSentence: EditorKey;
  ids: readonly number[];
}

function limb(l: Omit<LimbInfo, "label">): LimbInfo {
  return { ...l, label: english(l.key) };
}

export const LIMBS: readonly LimbInfo[] = [
  limb({
    limb: "left-leg",
    key: "editor.limb.leftLeg",
    inSentence: "editor.limbIn.leftLeg",
    ids: [0, 1, 2, 3, 4],
  }),
  limb({
    limb: "right-leg",
    key: "editor.limb.rightLeg",
    inSentence: "editor.limbIn.rightLeg",
    ids: [5, 6, 7, 8, 9],
  }),
  limb({
    limb: "left-arm",
    key: "editor.limb.leftArm",
    inSentence: "editor.limbIn.leftArm",
    ids: [10, 11, 12],
  }),
  limb({
    limb: "right-arm",
    key: "editor.limb.rightArm",
    inSentence: "editor.limbIn.rightArm",
    ids: [13, 14, 15],
  }),
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

/** The question before teach-in starts, in English (the view asks it in the panel's language). */
export const TEACH_IN_QUESTION = english("editor.teach.question");

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

/** "servo 3", "servos 0–4, 10" (Korean: "서보 3", "서보 0–4, 10"). */
export function servosText(t: EditorTranslator, ids: readonly number[]): string {
  const list = { ids: idList(ids) };
  return ids.length === 1 ? t("editor.servosOne", list) : t("editor.servosMany", list);
}

/**
 * The servos as a fact of a message, in every language: "Servos 0–4" where it starts the sentence, "servos
 * 0–4" inside it.
 */
function servosFact(ids: readonly number[], atStart = true): LocalText {
  return inEveryLanguage((l) => {
    const text = servosText(translator(editorMessages, l), ids);
    return atStart ? text.charAt(0).toUpperCase() + text.slice(1) : text;
  });
}

const say = (key: KeysWithoutParams<typeof editorMessages>): Said => said(editorMessages, key);

/** The chosen limbs in words: "the left arm", "the left leg and the right arm", "every servo". */
export function limbsText(limbs: readonly Limb[], locale: Locale = "en"): string {
  const t = translator(editorMessages, locale);
  if (choosesAll(limbs)) return t("editor.limbs.every");
  const names = LIMBS.filter((l) => limbs.includes(l.limb)).map((l) => t(l.inSentence));
  if (names.length <= 1) return names[0] ?? t("editor.limbs.none");
  return t("editor.limbs.and", { list: names.slice(0, -1).join(", "), last: names.at(-1) ?? "" });
}

/** What "Make limp" did: the servos that confirmed, the ones that did not answer. */
export function limpNotice(
  confirmed: readonly number[],
  silent: readonly number[],
  stopped = false,
  locale: Locale = "en",
): Notice {
  const parts: Said[] = [];
  if (confirmed.length > 0) {
    const words = { servos: servosFact(confirmed) };
    const key = confirmed.length === 1 ? "editor.teach.limpOne" : "editor.teach.limpMany";
    parts.push(said(editorMessages, key, words));
  }
  if (silent.length > 0) {
    const words = { servos: servosFact(silent) };
    const key = silent.length === 1 ? "editor.teach.limpSilentOne" : "editor.teach.limpSilentMany";
    parts.push(said(editorMessages, key, words));
  }
  if (stopped) parts.push(say("editor.teach.limpStopped"));
  if (parts.length === 0) parts.push(say("editor.teach.noneMadeLimp"));
  return noticeOf(silent.length > 0 || stopped ? "warning" : "ok", locale, parts);
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
 * zeroDelta = the robot's zero − the motion's zero (docs/protocol.md §10, none on platform 4), so a pose read from
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
  locale: Locale = "en",
): Notice {
  const read = [...reading.pose.keys()];
  const n = String(sceneNumber(scene));
  const parts: Said[] = [];
  parts.push(
    read.length === 0
      ? said(editorMessages, "editor.teach.readNothing", { scene: n })
      : said(editorMessages, "editor.teach.readDone", { servos: servosFact(read, false), scene: n }),
  );
  if (silent.length > 0) {
    const words = { servos: servosFact(silent) };
    const key = silent.length === 1 ? "editor.teach.readSilentOne" : "editor.teach.readSilentMany";
    parts.push(said(editorMessages, key, words));
  }
  if (reading.converted.length > 0) {
    parts.push(
      said(editorMessages, "editor.teach.readConverted", { servos: servosFact(reading.converted, false) }),
    );
  }
  if (!zerosKnown) parts.push(say("editor.teach.readNoZeros"));
  if (reading.notInMotion.length > 0) {
    const words = { servos: servosFact(reading.notInMotion) };
    const key =
      reading.notInMotion.length === 1 ? "editor.teach.notInMotionOne" : "editor.teach.notInMotionMany";
    parts.push(said(editorMessages, key, words));
  }
  const tone = read.length === 0 ? "danger" : silent.length > 0 || !zerosKnown ? "warning" : "ok";
  return noticeOf(tone, locale, parts);
}

/** One servo that "Hold" moved: where it was read and where it was told to hold (its safe range). */
export interface HeldServo {
  id: number;
  read: number;
  held: number;
}

/** What "Hold" (or "End teach-in") did. */
export function holdNotice(
  held: readonly HeldServo[],
  silent: readonly number[],
  stopped = false,
  locale: Locale = "en",
): Notice {
  const parts: Said[] = [];
  const ids = held.map((h) => h.id);
  if (held.length > 0) {
    const words = { servos: servosFact(ids) };
    parts.push(
      said(editorMessages, held.length === 1 ? "editor.teach.heldOne" : "editor.teach.heldMany", words),
    );
  }
  for (const h of held) {
    if (h.held !== h.read) {
      const facts = { id: String(h.id), read: String(h.read), held: String(h.held) };
      parts.push(said(editorMessages, "editor.teach.heldClamped", facts));
    }
  }
  if (silent.length > 0) {
    const words = { servos: servosFact(silent) };
    const key = silent.length === 1 ? "editor.teach.holdSilentOne" : "editor.teach.holdSilentMany";
    parts.push(said(editorMessages, key, words));
  }
  if (stopped) parts.push(say("editor.teach.holdStopped"));
  if (parts.length === 0) parts.push(say("editor.teach.nothingToHold"));
  return noticeOf(silent.length > 0 || stopped ? "warning" : "ok", locale, parts);
}
