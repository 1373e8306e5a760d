import { HUNO_SERVO_COUNT } from "../../protocol/servo-limits.ts";
import { WCK_MAX_ID } from "../../protocol/wck.ts";
import { sleep } from "../../shared/clock.ts";
import { RbcCancelledError, RbcError, RbcInvalidArgumentError } from "../errors.ts";
import type { RbcClient } from "../rbc-client.ts";
import { scanFindings } from "./findings.ts";
import { FirmwarePacketsSeen, readId } from "./read-id.ts";
import { SERVO_REPLY_WINDOW_MS, type ServoBusSession, ServoDoctorStoppedError } from "./servo-bus.ts";
import type { ScanResult, ServoReading, StopCode } from "./types.ts";

export { readingOf } from "./read-id.ts";

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

/**
 * Why an operation stopped, from the error that stopped it; with its `session`, Stop or Limp pressed at any
 * moment since the operation was asked for (entering direct mode included) is "stop-pressed".
 */
export function stopCodeOf(e: unknown, client: RbcClient, session?: ServoBusSession): StopCode {
  if (client.mode === "disconnected") return "disconnected";
  if (e instanceof ServoDoctorStoppedError || session?.stopped()) return "stop-pressed";
  if (e instanceof FirmwarePacketsSeen) return "firmware-sends-packets";
  if (e instanceof RbcCancelledError) return "cancelled";
  if (e instanceof RbcError && e.code === "disconnected") return "disconnected";
  if (e instanceof RbcError && e.code === "wrong-mode") return "left-direct-mode";
  return "failed";
}

/**
 * Reads every id in `ids`, one at a time, with mode-5 reads (docs/protocol.md §5 "Servo doctor"; `readId`: a
 * garbled id is read again, a silent one again with a longer window, and every unanswered read is fenced before
 * the next). First the busy probe, and a watch of the line: a firmware that sends RBC packets nobody asked for
 * (a build that repeats its 0x16 reply) stops the scan before direct mode, as such packets would be taken for
 * servo replies. Direct mode is entered through the client's guarded entry (only when idle: it throws
 * `ActivityRefusedError` otherwise, nothing sent) and left at the end, also after a cancel or an error. A scan
 * that stops early resolves with the readings it has and `stopped` (why, its facts, and the ids not read).
 */
export async function scanServos(client: RbcClient, options: ScanOptions = {}): Promise<ScanResult> {
  const ids = checkServoIds(options.ids ?? HUNO_SCAN_IDS);
  const expected = ids.filter((id) => id < HUNO_SERVO_COUNT);
  if (options.signal?.aborted) throw new RbcCancelledError();
  // Stop counts from the moment the scan is asked for, not from when direct mode is entered (§3.6).
  const bus = client.servoBus.session();
  let entered = false;
  const servos: ServoReading[] = [];
  let stopped: ScanResult["stopped"];
  try {
    const unasked = await unaskedPacketType(client, options.signal);
    if (unasked !== undefined) {
      stopped = { code: "firmware-sends-packets", unread: ids, type: unasked ?? undefined };
      return { servos, findings: [], ids, expected, stopped };
    }
    // Stop pressed while the line was watched: nothing enters direct mode.
    if (bus.stopped()) throw new RbcCancelledError();
    await client.enterDirectMode("servo-control");
    entered = true;
    for (const id of ids) {
      const reading = await readId(bus, id, options.signal);
      servos.push(reading);
      options.onProgress?.({ done: servos.length, total: ids.length, reading });
    }
  } catch (e) {
    // A refusal to enter (not idle, an upload under way) is the caller's to handle; Stop or Limp is an outcome.
    if (!entered && !bus.stopped()) throw e;
    stopped = { code: stopCodeOf(e, client, bus), unread: ids.slice(servos.length) };
    if (e instanceof FirmwarePacketsSeen && e.type !== undefined) stopped.type = e.type;
    if (stopped.code === "failed") stopped.error = e;
  } finally {
    await leaveDirect(client);
  }
  const findings = scanFindings(servos, expected);
  return stopped ? { servos, findings, ids, expected, stopped } : { servos, findings, ids, expected };
}

/**
 * The direct-mode entry's own checks (refused while an operation is under way, nothing sent; the busy probe,
 * 0x16, docs/protocol.md §3.6), then a quick time's watch of the line: the type of an RBC packet nobody asked for
 * that came meanwhile (null when its type is not known), or undefined for a quiet line.
 */
async function unaskedPacketType(
  client: RbcClient,
  signal?: AbortSignal,
): Promise<number | null | undefined> {
  const before = client.stats.unaskedReplies;
  const types: number[] = [];
  const off = client.log.on((e) => {
    if (e.direction === "in" && e.kind === "packet" && e.type !== undefined) types.push(e.type);
  });
  try {
    await client.checkIdleForDirect("servo-control");
    types.length = 0;
    await sleep(
      client.clock,
      SERVO_REPLY_WINDOW_MS + client.link.extraMs,
      signal,
      () => new RbcCancelledError(),
    );
  } finally {
    off();
  }
  if (client.stats.unaskedReplies === before) return undefined;
  return types[0] ?? null;
}

/** Leaves direct mode if the client is still in it; a link already gone has nothing to leave. */
export async function leaveDirect(client: RbcClient): Promise<void> {
  if (client.mode !== "direct") return;
  await client.exitDirectMode().catch(() => {});
}
