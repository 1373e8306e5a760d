import { ProtocolError } from "../../protocol/errors.ts";
import {
  decodeWckParameter,
  WCK_MAX_ID,
  WCK_PARAMETER_READS,
  type WckParameter,
  type WckParameterValue,
} from "../../protocol/wck.ts";
import { RbcCancelledError, RbcInvalidArgumentError } from "../errors.ts";
import type { RbcClient } from "../rbc-client.ts";
import type { Heard } from "./collect-reply.ts";
import { leaveDirect, readingOf, stopCodeOf } from "./scan.ts";
import { oneClean } from "./servo-bus.ts";
import type { ServoReading, StopCode } from "./types.ts";

/** One parameter read: its value in the manual's byte order, or what came instead. */
export type ParameterReading =
  | { status: "answered"; value: WckParameterValue }
  | { status: "silent" }
  | { status: "garbled"; bytes: number[] };

export interface ServoInfo {
  id: number;
  /** The mode-5 read first: a servo that does not answer it is not asked for more. */
  status: ServoReading;
  /** Each parameter read of §5, when the status read answered. */
  parameters: Partial<Record<WckParameter, ParameterReading>>;
  stopped?: { code: StopCode };
}

/** The parameters read, in the order read. */
export const INFO_PARAMETERS = Object.keys(WCK_PARAMETER_READS) as WckParameter[];

function parameterReading(parameter: WckParameter, heard: Heard): ParameterReading {
  if (oneClean(heard)) {
    try {
      return { status: "answered", value: decodeWckParameter(parameter, heard.bytes) };
    } catch (e) {
      if (!(e instanceof ProtocolError)) throw e;
    }
  }
  const bytes = [...heard.early, ...heard.bytes];
  return bytes.length === 0 && !heard.noisy ? { status: "silent" } : { status: "garbled", bytes };
}

/**
 * Reads servo `id`'s status and its parameters (docs/protocol.md §5: P/D gains 0x0A, speed and acceleration
 * 0x0E, overload limit 0x10, bounds 0x12 (lower, upper), I gain 0x16, I/O 0x65), reads only. Direct mode through
 * the client's guarded entry, left at the end.
 */
export async function servoInfo(
  client: RbcClient,
  id: number,
  options: { signal?: AbortSignal } = {},
): Promise<ServoInfo> {
  if (!Number.isInteger(id) || id < 0 || id > WCK_MAX_ID) {
    throw new RbcInvalidArgumentError(undefined, { kind: "servo-id-range", id, max: WCK_MAX_ID });
  }
  if (options.signal?.aborted) throw new RbcCancelledError();
  let entered = false;
  // Stop counts from the moment the read is asked for, not from when direct mode is entered (§3.6).
  const bus = client.servoBus.session();
  const info: ServoInfo = { id, status: { id, status: "silent" }, parameters: {} };
  try {
    await client.enterDirectMode("servo-control");
    entered = true;
    info.status = readingOf(id, await bus.readStatus(id, options.signal));
    if (info.status.status !== "answered") return info;
    for (const parameter of INFO_PARAMETERS) {
      info.parameters[parameter] = parameterReading(
        parameter,
        await bus.readParameter(id, parameter, options.signal),
      );
    }
  } catch (e) {
    // A refusal to enter (not idle, an upload under way) is the caller's to handle; Stop or Limp is an outcome.
    if (!entered && !bus.stopped()) throw e;
    info.stopped = { code: stopCodeOf(e, client, bus) };
  } finally {
    await leaveDirect(client);
  }
  return info;
}
