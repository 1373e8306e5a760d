import { HUNO_SERVO_COUNT } from "../../protocol/servo-limits.ts";
import { WCK_MAX_ID } from "../../protocol/wck.ts";
import { RbcCancelledError, RbcError, RbcInvalidArgumentError } from "../errors.ts";
import type { RbcClient } from "../rbc-client.ts";
import type { Heard } from "./collect-reply.ts";
import { scanFindings } from "./findings.ts";
import { cleanStatus, type ServoBusSession, ServoDoctorStoppedError } from "./servo-bus.ts";
import type { ScanResult, ServoReading, StopCode } from "./types.ts";

export interface ScanOptions {
  /** Ids to read, each 0-30, no repeats (default 0-15, a HUNO's). */
  ids?: readonly number[];
  signal?: AbortSignal;
  /** After each id: how many were read of how many, and the reading. */
  onProgress?: (progress: { done: number; total: number; reading: ServoReading }) => void;
}

/** Ids 0-15 (a HUNO's servos). */
export const HUNO_SCAN_IDS: readonly number[] = Array.from({ length: HUNO_SERVO_COUNT }, (_, i) => i);
/** Every id a servo can have, 0-30. */
export const ALL_SERVO_IDS: readonly number[] = Array.from({ length: WCK_MAX_ID + 1 }, (_, i) => i);

/** Checks a list of ids: integers 0-30, no repeats, at least one. Throws a typed error, nothing sent. */
export function checkServoIds(ids: readonly number[]): number[] {
  if (ids.length === 0) throw new RbcInvalidArgumentError(undefined, { kind: "scan-no-ids" });
  const seen = new Set<number>();
  for (const id of ids) {
    if (!Number.isInteger(id) || id < 0 || id > WCK_MAX_ID) {
      throw new RbcInvalidArgumentError(undefined, { kind: "servo-id-range", id, max: WCK_MAX_ID });
    }
    if (seen.has(id)) throw new RbcInvalidArgumentError(undefined, { kind: "scan-id-twice", id });
    seen.add(id);
  }
  return [...ids];
}

/** One id's reading from what the bus sent back after its mode-5 read. */
export function readingOf(id: number, heard: Heard): ServoReading {
  const status = cleanStatus(heard);
  if (status) return { id, status: "answered", ...status };
  const bytes = [...heard.early, ...heard.bytes];
  if (bytes.length === 0 && !heard.noisy) return { id, status: "silent" };
  return { id, status: "garbled", bytes };
}

/**
 * Why an operation stopped, from the error that stopped it; with its `session`, Stop or Limp pressed at any
 * moment since the operation was asked for (entering direct mode included) is "stop-pressed".
 */
export function stopCodeOf(e: unknown, client: RbcClient, session?: ServoBusSession): StopCode {
  if (client.mode === "disconnected") return "disconnected";
  if (e instanceof ServoDoctorStoppedError || session?.stopped()) return "stop-pressed";
  if (e instanceof RbcCancelledError) return "cancelled";
  if (e instanceof RbcError && e.code === "disconnected") return "disconnected";
  if (e instanceof RbcError && e.code === "wrong-mode") return "left-direct-mode";
  return "failed";
}

/**
 * Reads every id in `ids` once with a mode-5 read, one at a time (docs/protocol.md §5 "Servo doctor"). Direct
 * mode is entered through the client's guarded entry (only when idle: it throws `ActivityRefusedError`
 * otherwise, nothing sent) and left at the end, also after a cancel or an error. A scan that stops early
 * (cancel, Stop, a cable pull) resolves with the readings it has and `stopped` (why, and the ids not read).
 */
export async function scanServos(client: RbcClient, options: ScanOptions = {}): Promise<ScanResult> {
  const ids = checkServoIds(options.ids ?? HUNO_SCAN_IDS);
  const expected = ids.filter((id) => id < HUNO_SERVO_COUNT);
  if (options.signal?.aborted) throw new RbcCancelledError();
  let entered = false;
  // Stop counts from the moment the scan is asked for, not from when direct mode is entered (§3.6).
  const bus = client.servoBus.session();
  const servos: ServoReading[] = [];
  let stopped: ScanResult["stopped"];
  try {
    await client.enterDirectMode("servo-control");
    entered = true;
    for (const id of ids) {
      let reading = readingOf(id, await bus.readStatus(id, options.signal));
      // Bytes that are not one pair can be two servos at this id, or a late reply to the id before: read
      // again on a quiet line, and let the second reading decide (two servos garble it again).
      if (reading.status === "garbled") {
        reading = readingOf(id, await bus.readStatus(id, options.signal));
      }
      servos.push(reading);
      options.onProgress?.({ done: servos.length, total: ids.length, reading });
    }
  } catch (e) {
    // A refusal to enter (not idle, an upload under way) is the caller's to handle; Stop or Limp is an outcome.
    if (!entered && !bus.stopped()) throw e;
    stopped = { code: stopCodeOf(e, client, bus), unread: ids.slice(servos.length) };
  } finally {
    await leaveDirect(client);
  }
  const findings = scanFindings(servos, expected);
  return stopped ? { servos, findings, ids, expected, stopped } : { servos, findings, ids, expected };
}

/** Leaves direct mode if the client is still in it; a link already gone has nothing to leave. */
export async function leaveDirect(client: RbcClient): Promise<void> {
  if (client.mode !== "direct") return;
  await client.exitDirectMode().catch(() => {});
}
