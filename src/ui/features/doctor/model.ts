import type { Finding, FindingCode, ScanResult, ServoReading } from "../../../device/servo-doctor/index.ts";
import { HUNO_SERVO_COUNT, HUNO_SERVO_IDS } from "../../../protocol/servo-limits.ts";

export { HUNO_SERVO_IDS };

/**
 * Every id a wCK servo can have, 0-30 (docs/protocol.md §5): the device's `ALL_SERVO_IDS`, listed here so that
 * drawing the view does not load the device's servo code (tests/unit/servo-check-model.test.ts checks they agree).
 */
export const ALL_SERVO_IDS: readonly number[] = Array.from({ length: 31 }, (_, i) => i);
const WCK_MAX_ID = ALL_SERVO_IDS.length - 1;

import type { DoctorFix, DoctorState } from "./state.ts";

/**
 * The Servo check's pure logic: where each servo sits on the flat HUNO figure, what mark a reading gives it, the
 * order findings are said in, the id fix a scan suggests, and the checks of the typed ids. No DOM, no words.
 */

/** The figure's drawing area (SVG user units). */
export const FIGURE_WIDTH = 240;
export const FIGURE_HEIGHT = 300;
/** The figure's middle line: the robot faces the viewer, so its left side (ids 0-4, 10-12) is right of it. */
export const FIGURE_MIDDLE = FIGURE_WIDTH / 2;

/** Distance from the middle line to a leg's servos and to the three servos of an arm, outwards. */
const LEG_X = 24;
const ARM_X = [44, 66, 78] as const;
const LEG_Y = [150, 172, 210, 246, 268] as const;
const ARM_Y = [80, 104, 140] as const;

export interface FigurePoint {
  id: number;
  x: number;
  y: number;
  /** The robot's own side: "left" is drawn on the viewer's right. */
  side: "left" | "right";
}

/**
 * Each HUNO servo 0-15 on the figure (docs/protocol.md §4): 0-4 left leg and 5-9 right leg (hip roll, hip pitch,
 * knee, ankle pitch, ankle roll, top to bottom), 10-12 left arm and 13-15 right arm (shoulder pitch, shoulder
 * roll, elbow, inside out). The robot faces the viewer: its left side is on the viewer's right (x > middle).
 */
export function figurePoints(): FigurePoint[] {
  const points: FigurePoint[] = [];
  for (let id = 0; id < HUNO_SERVO_COUNT; id++) {
    const left = id <= 4 || (id >= 10 && id <= 12);
    const sign = left ? 1 : -1;
    const side = left ? "left" : "right";
    if (id <= 9) {
      const k = id % 5;
      points.push({ id, x: FIGURE_MIDDLE + sign * LEG_X, y: LEG_Y[k] ?? 0, side });
    } else {
      const k = (id - 10) % 3;
      points.push({ id, x: FIGURE_MIDDLE + sign * (ARM_X[k] ?? 0), y: ARM_Y[k] ?? 0, side });
    }
  }
  return points;
}

/** What a servo's mark on the figure and in the table says. */
export type ServoMark = "answered" | "high-load" | "silent" | "garbled" | "unread";

/**
 * The mark of one reading (none yet: "unread"). A clean answer is "high-load" when the scan's findings say so
 * (the device judges the load, `servo-high-load`; during a scan, before its findings, it is "answered").
 */
export function markOf(reading: ServoReading | undefined, highLoad: readonly number[] = []): ServoMark {
  if (!reading) return "unread";
  if (reading.status === "answered") return highLoad.includes(reading.id) ? "high-load" : "answered";
  return reading.status;
}

/** The ids the scan found carrying a high load at rest. */
export function highLoadIds(d: DoctorState): number[] {
  if (d.scanning || !d.scan) return [];
  return d.scan.findings.filter((f) => f.code === "servo-high-load").flatMap((f) => f.ids);
}

/** The readings to show: the scan under way, else the last scan's. */
export function shownReadings(d: DoctorState): readonly ServoReading[] {
  return d.scanning?.readings ?? d.scan?.servos ?? [];
}

/** The order findings are said in: nothing answers, a replacement servo, two at one id, silent, loaded. */
const FINDING_ORDER: Record<FindingCode, number> = {
  "bus-silent": 0,
  "servo-replacement": 1,
  "servo-duplicate": 2,
  "servo-missing": 3,
  "servo-high-load": 4,
};

/** The findings, most basic first (a bus that is silent explains every silent id), then by id. */
export function orderedFindings(findings: readonly Finding[]): Finding[] {
  return [...findings].sort(
    (a, b) => FINDING_ORDER[a.code] - FINDING_ORDER[b.code] || (a.ids[0] ?? 0) - (b.ids[0] ?? 0),
  );
}

/**
 * The id fix a scan suggests, to fill in the guided fix (the person still checks and confirms it): a replacement
 * servo at the factory id 0 should take the silent joint's id when exactly one joint is silent (with several, which
 * one it replaced is the owner's to say: nothing is suggested); else one servo answering at an id no HUNO joint has
 * (16-30) while exactly one joint is silent should take that joint's id. Otherwise none.
 */
export function suggestedFix(result: ScanResult | undefined): { from: number; to: number } | undefined {
  if (!result || result.stopped) return undefined;
  const replacement = result.findings.find((f) => f.code === "servo-replacement");
  if (replacement) {
    const [, to, other] = replacement.ids;
    return to !== undefined && other === undefined ? { from: 0, to } : undefined;
  }
  const missing = result.findings.filter((f) => f.code === "servo-missing").map((f) => f.ids[0] ?? 0);
  const strays = result.servos.filter((r) => r.status === "answered" && r.id >= HUNO_SERVO_COUNT);
  const [stray] = strays;
  const [only] = missing;
  return stray && only !== undefined && strays.length === 1 && missing.length === 1
    ? { from: stray.id, to: only }
    : undefined;
}

/** The typed ids of the guided fix, checked: whole numbers 0-30, different. Nothing is sent otherwise. */
export function checkFixIds(
  fix: Pick<DoctorFix, "from" | "to">,
): { from: number; to: number } | { problem: NonNullable<DoctorFix["problem"]> } {
  const parse = (text: string) => (/^\s*\d{1,2}\s*$/.test(text) ? Number(text) : Number.NaN);
  const from = parse(fix.from);
  const to = parse(fix.to);
  if (!(from >= 0 && from <= WCK_MAX_ID)) return { problem: "bad-from" };
  if (!(to >= 0 && to <= WCK_MAX_ID)) return { problem: "bad-to" };
  if (from === to) return { problem: "same" };
  return { from, to };
}
