import { ZERO_COUNT } from "../../../protocol/zeros.ts";

/**
 * Unwritten zero changes are kept in this browser, so a reload or a closed tab loses nothing (issue 33 item 7).
 * The same place the Editor rescues its waiting change in when the page goes away: localStorage, written
 * synchronously with every change (the table is 16 short texts), so the record is there however the page ends.
 * One record per robot, under its serial number ("unknown" when the robot did not say it): a draft is offered
 * back only to the robot it was made for, and only as unwritten changes (never as what the robot holds).
 */

export const ZEROS_DRAFT_VERSION = 1;
export const ZEROS_DRAFT_PREFIX = "rbc-panel-zeros-draft:";

export interface KeptZerosDraft {
  version: typeof ZEROS_DRAFT_VERSION;
  /** The robot's serial number ("unknown" when it did not say). */
  robot: string;
  /** Epoch ms of the last change. */
  savedAt: number;
  /** The table's text per servo 0-15, as typed. */
  draft: string[];
}

/** Where records are kept: the page's localStorage, or a Map in tests. */
export interface DraftPlace {
  getItem(key: string): string | null;
  setItem(key: string, value: string): void;
  removeItem(key: string): void;
}

/** The page's localStorage, or undefined where the browser refuses it (then nothing is kept). */
export function pageDraftPlace(): DraftPlace | undefined {
  try {
    return typeof localStorage === "undefined" ? undefined : localStorage;
  } catch {
    return undefined;
  }
}

export function robotKey(serialNumber: string | undefined): string {
  return serialNumber && serialNumber.length > 0 ? serialNumber : "unknown";
}

/** The record kept for `robot`, if one is there and well formed (a damaged one is ignored, never trusted). */
export function readZerosDraft(place: DraftPlace | undefined, robot: string): KeptZerosDraft | undefined {
  let value: unknown;
  try {
    const text = place?.getItem(ZEROS_DRAFT_PREFIX + robot);
    if (!text) return undefined;
    value = JSON.parse(text);
  } catch {
    return undefined;
  }
  const r = value as Partial<KeptZerosDraft> | null;
  if (
    !r ||
    r.version !== ZEROS_DRAFT_VERSION ||
    r.robot !== robot ||
    typeof r.savedAt !== "number" ||
    !Number.isFinite(r.savedAt) ||
    !Array.isArray(r.draft) ||
    r.draft.length !== ZERO_COUNT ||
    !r.draft.every((v) => typeof v === "string" && v.length <= 12)
  ) {
    return undefined;
  }
  return { version: ZEROS_DRAFT_VERSION, robot, savedAt: r.savedAt, draft: [...r.draft] };
}

/** Keeps `draft` for `robot` (a full or refusing storage keeps nothing; the leave question still asks). */
export function keepZerosDraft(
  place: DraftPlace | undefined,
  robot: string,
  draft: readonly string[],
  savedAt: number,
): void {
  const record: KeptZerosDraft = { version: ZEROS_DRAFT_VERSION, robot, savedAt, draft: [...draft] };
  try {
    place?.setItem(ZEROS_DRAFT_PREFIX + robot, JSON.stringify(record));
  } catch {
    // Full or unavailable.
  }
}

export function forgetZerosDraft(place: DraftPlace | undefined, robot: string): void {
  try {
    place?.removeItem(ZEROS_DRAFT_PREFIX + robot);
  } catch {
    // Unavailable: nothing was kept either.
  }
}
