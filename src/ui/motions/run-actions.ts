import { RbcError } from "../../device/errors.ts";
import {
  BASIC_POSTURE_MOTION,
  BUILT_IN_MOTIONS,
  downloadSlotOf,
  isOfferedMotionNumber,
  soundLengthMs,
} from "../../protocol/catalog.ts";
import type { AppState } from "../app-state.ts";
import { errorNotice, technicalDetail } from "../error-text.ts";
import { focusSoon } from "../focus.ts";
import type { Session } from "../session.ts";
import type { Store } from "../store.ts";
import { motionsOf, patchMotions, robotBusyReason } from "./motions-store.ts";
import { formatSeconds } from "./plot-data.ts";
import { motionNumberOf, type SlotBook } from "./slot-book.ts";
import { ensureTicker } from "./ticker.ts";

/** Running motions and sounds (PROTOCOL.md §3.1, §3.3), with the 7-first rule and the movement warning. */

interface Ctx {
  session: Session;
  store: Store<AppState>;
}

export const BASIC_POSTURE_GUIDANCE =
  "After switching on, the robot only accepts Basic posture (7). Run it first.";
export const MOVEMENT_WARNING = "The robot will move. Hold it or give it room.";
/** How long basic posture takes after a stopped motion (its simulator duration; PROTOCOL.md §3.1). */
const BASIC_POSTURE_MS = BUILT_IN_MOTIONS.find((m) => m.number === BASIC_POSTURE_MOTION)?.durationMs ?? 1800;

export interface OfferedMotion {
  number: number;
  name: string;
  /** Known playback time; undefined for a download slot the panel did not fill. */
  expectedMs?: number;
  /** Set for downloads: "slot 1". */
  slot?: number;
}

export const BUILT_IN_OFFERS: readonly OfferedMotion[] = BUILT_IN_MOTIONS.map((m) => ({
  number: m.number,
  name: m.name,
  expectedMs: m.durationMs,
}));

/** Motions uploaded in this connection whose slot (so Run Motion number) is known. */
export function downloadedOffers(book: SlotBook): OfferedMotion[] {
  const out: OfferedMotion[] = [];
  for (const e of book.entries) {
    const number = motionNumberOf(e);
    if (number !== undefined) out.push({ number, name: e.name, expectedMs: e.durationMs, slot: e.slot });
  }
  return out.sort((a, b) => a.number - b.number);
}

/** What the panel knows about Run Motion `number` (a built-in, an upload of this connection, or a slot). */
export function offerFor(s: AppState, number: number): OfferedMotion | undefined {
  if (!isOfferedMotionNumber(number)) return undefined;
  const known =
    BUILT_IN_OFFERS.find((m) => m.number === number) ??
    downloadedOffers(motionsOf(s).motionBook).find((m) => m.number === number);
  if (known) return known;
  const slot = downloadSlotOf(number);
  return slot === undefined ? undefined : { number, name: `Download slot ${slot}`, slot };
}

let current: { number: number; stopRequested: boolean } | undefined;

/** A Run button: asks once per connection that the robot may move, then runs. */
export function requestRun(ctx: Ctx, number: number): void {
  const s = ctx.store.get();
  // There is no UI for other numbers; this guards the command layer all the same.
  if (!isOfferedMotionNumber(number) || robotBusyReason(s)) return;
  if (!s.acks?.movement) {
    patchMotions(ctx.store, { confirmMove: number, runNotice: undefined });
    focusSoon("confirm-move");
    return;
  }
  void runMotionNow(ctx, number);
}

export function confirmMovement(ctx: Ctx): void {
  const number = motionsOf(ctx.store.get()).confirmMove;
  ctx.store.update((s) => ({ acks: { ...s.acks, movement: true } }));
  patchMotions(ctx.store, { confirmMove: undefined });
  if (number !== undefined) void runMotionNow(ctx, number);
}

export function cancelMovement(store: Store<AppState>): void {
  patchMotions(store, { confirmMove: undefined });
}

function label(offer: OfferedMotion): string {
  return `motion ${offer.number} (${offer.name})`;
}

function capitalised(text: string): string {
  return text.charAt(0).toUpperCase() + text.slice(1);
}

export async function runMotionNow(ctx: Ctx, number: number): Promise<void> {
  const { store, session } = ctx;
  const offer = offerFor(store.get(), number);
  if (!offer || robotBusyReason(store.get())) return;
  const run = { number, stopRequested: false };
  current = run;
  const firstPosture = number === BASIC_POSTURE_MOTION && !store.get().connection.basicPostureConfirmed;
  patchMotions(store, {
    run: { number, name: offer.name, expectedMs: offer.expectedMs, startedAt: performance.now() },
    runNotice: undefined,
    confirmMove: undefined,
  });
  ensureTicker(store);
  try {
    await session.run(`Running motion ${number}`, (client) =>
      client.runMotion(number, { expectedMs: offer.expectedMs }),
    );
    if (run.stopRequested) {
      // "Stop motion" took effect: the motion ended with its scene; basic posture (7) plays now.
      patchMotions(store, {
        runNotice: {
          tone: "ok",
          text: `Motion ${number} (${offer.name}) stopped at the end of its scene. The robot now returns to Basic posture (about ${formatSeconds(BASIC_POSTURE_MS)}).`,
        },
        run: {
          number: BASIC_POSTURE_MOTION,
          name: "Basic posture (after Stop motion)",
          expectedMs: BASIC_POSTURE_MS,
          startedAt: performance.now(),
          stopping: true,
        },
      });
    } else {
      patchMotions(store, {
        runNotice: {
          tone: "ok",
          text: `${capitalised(label(offer))} finished.${firstPosture ? " The robot now accepts every motion." : ""}`,
        },
      });
    }
  } catch (e) {
    if (run.stopRequested) return;
    patchMotions(store, { runNotice: runFailure(offer, e) });
  } finally {
    if (!run.stopRequested) {
      patchMotions(store, { run: undefined });
      if (current === run) current = undefined;
    }
  }
}

function runFailure(offer: OfferedMotion, e: unknown) {
  if (e instanceof RbcError && e.code === "motion-ignored") {
    return {
      tone: "warning" as const,
      text: `${BASIC_POSTURE_GUIDANCE} The robot ignored ${label(offer)}: it did not answer.`,
      detail: technicalDetail(e),
    };
  }
  if (e instanceof RbcError && e.code === "cancelled") {
    return {
      tone: "warning" as const,
      text: `${capitalised(label(offer))} was interrupted by Stop — limp: every servo is limp now. Hold the robot.`,
    };
  }
  if (e instanceof RbcError && e.code === "timeout" && offer.expectedMs === undefined) {
    return {
      tone: "danger" as const,
      text: `The robot did not report the end of ${label(offer)}. If nothing was downloaded into that slot, the robot ignores the number (error 3).`,
      detail: technicalDetail(e),
    };
  }
  return errorNotice(`${capitalised(label(offer))} failed.`, e);
}

/**
 * "Stop motion": the client sends 7, which the RBC obeys at the end of the current scene; the running motion
 * then reports its end (see runMotionNow) and the robot plays basic posture, which this waits for.
 */
export async function stopMotion(ctx: Ctx): Promise<void> {
  const { store, session } = ctx;
  const run = current;
  const shown = motionsOf(store.get()).run;
  if (!run || run.stopRequested || !shown) return;
  run.stopRequested = true;
  patchMotions(store, { run: { ...shown, stopping: true } });
  try {
    await session.run("Stopping the motion", (client) => client.stopMotion());
    patchMotions(store, {
      runNotice: {
        tone: "ok",
        text: `Motion ${run.number} (${shown.name}) stopped at the end of its scene; the robot is back in Basic posture.`,
      },
    });
  } catch (e) {
    patchMotions(store, {
      runNotice:
        e instanceof RbcError && e.code === "cancelled"
          ? {
              tone: "warning",
              text: `Motion ${run.number} was interrupted by Stop — limp: every servo is limp now.`,
            }
          : errorNotice("Stop motion failed. If the robot still moves, press Stop — limp (Esc).", e),
    });
  } finally {
    patchMotions(store, { run: undefined });
    if (current === run) current = undefined;
    ensureTicker(store);
  }
}

export async function playSound(ctx: Ctx, n: number): Promise<void> {
  const { store, session } = ctx;
  const length = soundLengthMs(n);
  if (length === undefined || robotBusyReason(store.get())) return;
  patchMotions(store, { soundNotice: undefined });
  ensureTicker(store);
  try {
    await session.run(`Playing sound ${n}`, (client) => client.runSound(n));
    patchMotions(store, {
      soundNotice: { tone: "ok", text: `Sound ${n} played (${formatSeconds(length)}).` },
    });
  } catch (e) {
    patchMotions(store, {
      soundNotice:
        e instanceof RbcError && e.code === "cancelled"
          ? { tone: "warning", text: `Sound ${n} was interrupted by Stop — limp.` }
          : errorNotice(`Sound ${n} failed.`, e),
    });
  }
}
