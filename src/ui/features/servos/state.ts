import type { Locale } from "../../../i18n/locale.ts";
import { type Said, said, wordOf } from "../../../i18n/said.ts";
import { HUNO_BASIC_POSTURE, HUNO_SERVO_IDS, safeRange } from "../../../protocol/servo-limits.ts";
import type { Notice } from "../../notices.ts";
import type { Store } from "../../store.ts";
import { servosMessages } from "./messages.ts";

/**
 * The Servos view's part of the app state, one per connection (the session resets it to undefined, which
 * `servosOf` reads as the initial value).
 */
export interface ServosState {
  /** Last known position per servo id 0-15 (from a read or a move's reply). */
  positions: (number | undefined)[];
  /** Where each slider points. */
  targets: number[];
  /** Text being typed into a servo's number box, not applied yet (so redraws do not reset it). */
  drafts?: Partial<Record<number, string>>;
  /** Why a typed target was refused, by servo id (nothing was sent for it). */
  refused?: Partial<Record<number, Said>>;
  /** Torque per servo for moves: 0 (strong) .. 4 (weak). */
  torques: number[];
  /** Servos that did not answer the last read. */
  silent: number[];
  /** Wall-clock ms of the last "Read all positions". */
  readAt?: number;
  /** Wall-clock ms of the last position the robot reported (a read or a move's reply). */
  positionsAt?: number;
  /** The view shows the robot in 3D ("Show the robot in 3D"; kept for the connection). */
  robot3dShown?: boolean;
  busy?: "entering" | "leaving" | "reading" | "posture";
  confirmingPosture: boolean;
  /** Speed of "All to basic posture": 0 (fast) .. 4 (slow). */
  speed: number;
  notice?: Notice;
}

export const SERVO_IDS: readonly number[] = HUNO_SERVO_IDS;
export const DEFAULT_TORQUE = 2;

/** The safe range of servo `id` (docs/protocol.md §5 for 0-15; other ids get the full 0-254). */
export function servoRange(id: number): { min: number; max: number } {
  return safeRange(id) ?? { min: 0, max: 254 };
}

/**
 * A target typed into servo `id`'s number box: a whole number within its safe range, or the sentence that says
 * why it is refused (in `locale`, English by default). Like the zeros editor, a value outside the range is
 * refused, never clamped: 300 typed for a servo whose range is 1-198 must not move it to 198.
 */
export function checkTypedTarget(
  id: number,
  text: string,
  locale: Locale = "en",
): { position: number } | { problem: string } {
  const checked = checkTyped(id, text);
  return "position" in checked ? checked : { problem: wordOf(checked.problem, locale) };
}

/** `checkTypedTarget`, the refusal kept as a message (worded when drawn, in the language of that moment). */
export function checkTyped(id: number, text: string): { position: number } | { problem: Said } {
  const range = servoRange(id);
  const [min, max] = [String(range.min), String(range.max)];
  const trimmed = text.trim();
  const who = String(id);
  if (trimmed === "") return { problem: said(servosMessages, "servos.typed.empty", { id: who, min, max }) };
  if (!/^-?\d+$/.test(trimmed)) {
    return { problem: said(servosMessages, "servos.typed.notWhole", { id: who, text: trimmed, min, max }) };
  }
  const position = Number(trimmed);
  if (position < range.min || position > range.max) {
    const facts = { id: who, position: String(position), min, max };
    return { problem: said(servosMessages, "servos.typed.outside", facts) };
  }
  return { position };
}

export function clampToSafe(id: number, position: number): number {
  const { min, max } = servoRange(id);
  return Math.max(min, Math.min(max, Math.round(position)));
}

/** Every slider at the basic posture. */
export function basicPostureTargets(): number[] {
  return SERVO_IDS.map((id) => clampToSafe(id, HUNO_BASIC_POSTURE[id] ?? 127));
}

export function initialServos(): ServosState {
  return {
    positions: SERVO_IDS.map(() => undefined),
    targets: basicPostureTargets(),
    torques: SERVO_IDS.map(() => DEFAULT_TORQUE),
    silent: [],
    confirmingPosture: false,
    speed: 4,
  };
}

/** The part of the app state this feature owns (src/ui/app-state.ts composes the parts). */
export interface ServosSlice {
  servos?: ServosState;
}

export function servosOf(s: ServosSlice): ServosState {
  return s.servos ?? initialServos();
}

export function patchServos(
  store: Store<ServosSlice>,
  p: Partial<ServosState> | ((x: ServosState) => Partial<ServosState>),
): void {
  store.update((s) => {
    const cur = servosOf(s);
    return { servos: { ...cur, ...(typeof p === "function" ? p(cur) : p) } };
  });
}
