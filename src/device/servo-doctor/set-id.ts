import { WCK_MAX_ID } from "../../protocol/wck.ts";
import { RbcCancelledError, RbcInvalidArgumentError } from "../errors.ts";
import type { RbcClient } from "../rbc-client.ts";
import { leaveDirect, readingOf, stopCodeOf } from "./scan.ts";
import type { ServoReading, StopCode } from "./types.ts";

/** Why the guided id fix did not send the id set (nothing was sent to the servos but reads). */
export type SetIdRefusal =
  /** Nothing answers at FROM. */
  | "from-silent"
  /** Bytes that are not one pair answer at FROM: two servos share it; unplug the others of that chain. */
  | "from-garbled"
  /** A servo (or more) already answers at TO. */
  | "to-taken"
  /** The person did not confirm. */
  | "not-confirmed";

/** Why the fix, once sent, is not confirmed by the reads after it. */
export type SetIdFailure =
  /** Nothing answers at TO or at FROM: the servo answers nowhere (the hardware reset is the way back). */
  | "answers-nowhere"
  /** TO does not answer, FROM still does: the servo did not take the new id. */
  | "not-taken"
  /** TO answers but so does FROM (or either garbled): not one servo with a new id. */
  | "unclear";

export type SetIdResult =
  /** The servo answered at TO and FROM is silent: the new id is confirmed by reads. */
  | { outcome: "done"; from: number; to: number; after: { from: ServoReading; to: ServoReading } }
  | { outcome: "refused"; reason: SetIdRefusal; from: number; to: number; before: ServoReading[] }
  | {
      outcome: "failed";
      reason: SetIdFailure;
      from: number;
      to: number;
      after: { from: ServoReading; to: ServoReading };
    }
  /**
   * Stopped before the reads after the id set were done. `sent`: the id set's bytes were handed to the link
   * (false: nothing but reads reached the bus).
   */
  | { outcome: "stopped"; code: StopCode; from: number; to: number; sent: boolean };

export interface SetIdOptions {
  /** Asked once, after the checks passed and before the id set is sent; false refuses. */
  confirm?: (check: { from: number; to: number; position: number }) => Promise<boolean>;
  signal?: AbortSignal;
}

function checkId(id: number, which: "present" | "new"): void {
  if (!Number.isInteger(id) || id < 0 || id > WCK_MAX_ID) {
    throw new RbcInvalidArgumentError(undefined, { kind: "set-id-range", which, id, max: WCK_MAX_ID });
  }
}

/**
 * The guided id fix (docs/protocol.md §5 "Servo doctor" [decision]): exactly one servo answers at `from` (not
 * garbled), none at `to`, the person confirms; then `FF (E0|from) 0C to to cs`; then a read at `to` must
 * answer and a read at `from` must be silent. The outcome says what was read either way. The baud rate is
 * never touched. Direct mode through the client's guarded entry (only when idle), left at the end.
 */
export async function setServoId(
  client: RbcClient,
  from: number,
  to: number,
  options: SetIdOptions = {},
): Promise<SetIdResult> {
  checkId(from, "present");
  checkId(to, "new");
  if (from === to) {
    throw new RbcInvalidArgumentError(undefined, { kind: "set-id-same", id: from });
  }
  if (options.signal?.aborted) throw new RbcCancelledError();
  const read = async (id: number): Promise<ServoReading> => {
    const first = readingOf(id, await bus.readStatus(id, options.signal));
    return first.status === "garbled" ? readingOf(id, await bus.readStatus(id, options.signal)) : first;
  };
  let entered = false;
  // Stop counts from the moment the fix is asked for, not from when direct mode is entered (§3.6).
  const bus = client.servoBus.session();
  let sent = false;
  try {
    await client.enterDirectMode("servo-control");
    entered = true;
    const atFrom = await read(from);
    if (atFrom.status !== "answered") {
      const reason = atFrom.status === "silent" ? "from-silent" : "from-garbled";
      return { outcome: "refused", reason, from, to, before: [atFrom] };
    }
    const atTo = await read(to);
    if (atTo.status !== "silent") {
      return { outcome: "refused", reason: "to-taken", from, to, before: [atFrom, atTo] };
    }
    if (options.confirm && !(await options.confirm({ from, to, position: atFrom.position }))) {
      return { outcome: "refused", reason: "not-confirmed", from, to, before: [atFrom, atTo] };
    }
    // The reply (to, to) is not the proof: the reads below are. `sent` only once its bytes went to the link: Stop
    // during the question (or while the bus was fenced) ends it unsent (issue 32 item 5).
    await bus.setId(from, to, options.signal, () => {
      sent = true;
    });
    const after = { to: await read(to), from: await read(from) };
    if (after.to.status === "answered" && after.from.status === "silent") {
      return { outcome: "done", from, to, after };
    }
    const reason: SetIdFailure =
      after.to.status === "silent" && after.from.status === "silent"
        ? "answers-nowhere"
        : after.to.status === "silent" && after.from.status === "answered"
          ? "not-taken"
          : "unclear";
    return { outcome: "failed", reason, from, to, after };
  } catch (e) {
    // A refusal to enter (not idle, an upload under way) is the caller's to handle; Stop or Limp is an outcome.
    if (e instanceof RbcInvalidArgumentError || (!entered && !bus.stopped())) throw e;
    return { outcome: "stopped", code: stopCodeOf(e, client, bus), from, to, sent };
  } finally {
    await leaveDirect(client);
  }
}
