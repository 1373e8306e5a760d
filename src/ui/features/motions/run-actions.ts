import { RbcError } from "../../../device/errors.ts";
import {
  BASIC_POSTURE_MOTION,
  BUILT_IN_MOTIONS,
  downloadSlotOf,
  isOfferedMotionNumber,
  soundLengthMs,
} from "../../../protocol/catalog.ts";
import type { AppState } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice, technicalDetail } from "../../error-text.ts";
import { focusSoon } from "../../focus.ts";
import { type MotionRun, motionsController } from "./controllers.ts";
import { formatSeconds } from "./plot-data.ts";
import { motionNumberOf, type SlotBook } from "./slot-book.ts";
import { motionsOf, patchMotions, robotBusyReason } from "./state.ts";

/** Running motions and sounds (PROTOCOL.md §3.1, §3.3), with the 7-first rule and the movement warning. */

export const BASIC_POSTURE_GUIDANCE =
  "After switching on, the robot only accepts Basic posture (7). Run it first.";
export const MOVEMENT_WARNING = "The robot will move. Hold it or give it room.";

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

/** A Run button: asks once per connection that the robot may move, then runs. */
export function requestRun(ctx: AppContext, number: number): void {
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

export function confirmMovement(ctx: AppContext): void {
  const number = motionsOf(ctx.store.get()).confirmMove;
  ctx.store.update((s) => ({ acks: { ...s.acks, movement: true } }));
  patchMotions(ctx.store, { confirmMove: undefined });
  if (number !== undefined) void runMotionNow(ctx, number);
}

export function cancelMovement(ctx: AppContext): void {
  patchMotions(ctx.store, { confirmMove: undefined });
}

function label(offer: OfferedMotion): string {
  return `motion ${offer.number} (${offer.name})`;
}

function capitalised(text: string): string {
  return text.charAt(0).toUpperCase() + text.slice(1);
}

export async function runMotionNow(ctx: AppContext, number: number): Promise<void> {
  const { store, session } = ctx;
  const offer = offerFor(store.get(), number);
  if (!offer || robotBusyReason(store.get())) return;
  const run: MotionRun = { number, stopRequested: false };
  const controller = motionsController(ctx);
  controller.run = run;
  const firstPosture = number === BASIC_POSTURE_MOTION && !store.get().connection.basicPostureConfirmed;
  patchMotions(store, {
    run: { number, name: offer.name, expectedMs: offer.expectedMs, startedAt: session.clock.now() },
    runNotice: undefined,
    confirmMove: undefined,
  });
  controller.ticker.ensure();
  try {
    await session.run(`Running motion ${number}`, (client) =>
      client.runMotion(number, { expectedMs: offer.expectedMs }),
    );
    // After "Stop motion", stopMotion says how it ended.
    if (!run.stopRequested) {
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
      if (controller.run === run) controller.run = undefined;
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
      text: `${capitalised(label(offer))} did not finish. ${e.message}`,
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
 * "Stop motion": the client sends 7, which the RBC obeys at the end of the current scene (PROTOCOL.md §3.6). It
 * answers once, `07`, and does not play basic posture: the robot holds the pose it stopped in.
 */
export async function stopMotion(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const controller = motionsController(ctx);
  const run = controller.run;
  const shown = motionsOf(store.get()).run;
  if (!run || run.stopRequested || !shown) return;
  run.stopRequested = true;
  patchMotions(store, { run: { ...shown, stopping: true } });
  try {
    await session.run("Stopping the motion", (client) => client.stopMotion());
    patchMotions(store, {
      runNotice: {
        tone: "ok",
        text: `Motion ${run.number} (${shown.name}) stopped at the end of its scene. The robot holds the pose it stopped in; run Basic posture (7) to bring it back to standing.`,
      },
    });
  } catch (e) {
    patchMotions(store, {
      runNotice:
        e instanceof RbcError && e.code === "cancelled"
          ? {
              tone: "warning",
              text: `Motion ${run.number} was ended by Stop or Limp; the banner under the top bar says what the robot confirmed.`,
            }
          : errorNotice("Stop motion failed. If the robot still moves, hold it and press Limp (top bar).", e),
    });
  } finally {
    patchMotions(store, { run: undefined });
    if (controller.run === run) controller.run = undefined;
    controller.ticker.ensure();
  }
}

export async function playSound(ctx: AppContext, n: number): Promise<void> {
  const { store, session } = ctx;
  const length = soundLengthMs(n);
  if (length === undefined || robotBusyReason(store.get())) return;
  patchMotions(store, { soundNotice: undefined });
  motionsController(ctx).ticker.ensure();
  try {
    await session.run(`Playing sound ${n}`, (client) => client.runSound(n));
    patchMotions(store, {
      soundNotice: { tone: "ok", text: `Sound ${n} played (${formatSeconds(length)}).` },
    });
  } catch (e) {
    patchMotions(store, {
      soundNotice:
        e instanceof RbcError && e.code === "cancelled"
          ? {
              tone: "warning",
              text: `Sound ${n}: its wait was cancelled by Limp (the robot plays a sound to its end).`,
            }
          : errorNotice(`Sound ${n} failed.`, e),
    });
  }
}
