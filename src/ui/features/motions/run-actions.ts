import { RbcError } from "../../../device/errors.ts";
import { isHazardousMotion } from "../../../device/run-outcome.ts";
import { errorSaid } from "../../../i18n/error-said.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { builtInMotionName } from "../../../i18n/motion-names/built-in-motion-name.ts";
import { runReportText } from "../../../i18n/outcomes/run-words.ts";
import { soundOutcomeMessages } from "../../../i18n/outcomes/sound-messages.ts";
import { stopPoseMessages } from "../../../i18n/outcomes/stop-pose-messages.ts";
import { inEveryLanguage, type LocalText, said, saidBy } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import {
  BASIC_POSTURE_MOTION,
  BUILT_IN_MOTIONS,
  downloadSlotOf,
  isOfferedMotionNumber,
  soundLengthMs,
} from "../../../protocol/catalog.ts";
import { type AppState, type Notice, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice, technicalDetail } from "../../error-text.ts";
import { focusSoon } from "../../focus.ts";
import { stopAll } from "../../stop-all.ts";
import { stopMessages } from "../../stop-messages.ts";
import { playingMotion } from "../connection/index.ts";
import { remoteKeyWords } from "../shelf/index.ts";
import { type MotionRun, motionsController } from "./controllers.ts";
import { motionsMessages } from "./messages.ts";
import { formatSeconds } from "./plot-data.ts";
import { type BookEntry, motionNumberOf } from "./slot-book.ts";
import { motionsOf, patchMotions, robotBusyReason } from "./state.ts";

/** Running motions and sounds (docs/protocol.md §3.1, §3.3), with the 7-first rule and the movement warning. */

export interface OfferedMotion {
  number: number;
  name: string;
  /** Known playback time; undefined for a download slot the panel did not fill. */
  expectedMs?: number;
  /** Set for downloads: the download slot (never shown: the panel shows the number Run takes). */
  slot?: number;
  /**
   * For downloads the panel knows: `now`, uploaded on this connection (the robot's memory accounting showed
   * it stored); `recorded`, on the shelf from an earlier upload (`checked`: the robot's free memory read on this
   * connection still has room for it; never more than "may still be there").
   */
  stored?: { kind: "now" } | { kind: "recorded"; at: string; checked: boolean };
}

/** The built-in motions (Run Motion 1-11) with their names in the panel's language. */
export function builtInOffers(locale: Locale): OfferedMotion[] {
  return BUILT_IN_MOTIONS.map((m) => ({
    number: m.number,
    name: builtInMotionName(m.number, locale) ?? m.name,
    expectedMs: m.durationMs,
  }));
}

export function isBuiltIn(number: number): boolean {
  return BUILT_IN_MOTIONS.some((m) => m.number === number);
}

/**
 * The downloaded motions the panel knows by number: those on the robot's shelf (issue 23 item 2: recorded by
 * this browser, names and durations kept across connections) and those uploaded on this connection into a
 * known slot (which win: the robot's memory accounting showed them stored).
 */
export function downloadedOffers(s: AppState): OfferedMotion[] {
  const m = motionsOf(s);
  const byNumber = new Map<number, OfferedMotion>();
  const shelf = s.shelf;
  for (const r of shelf?.slots ?? []) {
    byNumber.set(r.motionNumber, {
      number: r.motionNumber,
      name: r.name,
      expectedMs: r.durationMs,
      slot: r.slot,
      stored: { kind: "recorded", at: r.storedAt, checked: shelf?.checked === true },
    });
  }
  for (const e of m.motionBook.entries) addBookEntry(byNumber, e);
  return [...byNumber.values()].sort((a, b) => a.number - b.number);
}

function addBookEntry(byNumber: Map<number, OfferedMotion>, e: BookEntry): void {
  const number = motionNumberOf(e);
  if (number === undefined) return;
  byNumber.set(number, {
    number,
    name: e.name,
    expectedMs: e.durationMs,
    slot: e.slot,
    stored: { kind: "now" },
  });
}

/**
 * What the panel knows about Run Motion `number` (a built-in, an upload of this connection, or a slot), named
 * in the panel's language.
 */
export function offerFor(s: AppState, number: number): OfferedMotion | undefined {
  if (!isOfferedMotionNumber(number)) return undefined;
  const known =
    builtInOffers(s.locale).find((m) => m.number === number) ??
    downloadedOffers(s).find((m) => m.number === number);
  if (known) return known;
  const slot = downloadSlotOf(number);
  if (slot === undefined) return undefined;
  return {
    number,
    name: translator(motionsMessages, s.locale)("motions.run.downloadSlot", {
      key: remoteKeyWords(number, s.locale),
    }),
    slot,
  };
}

/** A Run button: asks once per connection that the robot may move, then runs. */
export function requestRun(ctx: AppContext, number: number): void {
  const s = ctx.store.get();
  // There is no UI for other numbers; this guards the command layer all the same.
  if (!isOfferedMotionNumber(number) || robotBusyReason(s)) return;
  // Motions 20 and 21 carry a warning (docs/protocol.md §3.1): asked every time, not once per connection.
  if (!s.acks?.movement || isHazardousMotion(number)) {
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

/**
 * The motion's facts for a sentence ("Motion 7 (Basic posture) finished."): its name in every language (a
 * built-in's name is translated; a download's is the name it was uploaded with), so the sentence follows a
 * language switch.
 */
function named(s: AppState, offer: OfferedMotion): { number: number; name: LocalText } {
  return {
    number: offer.number,
    name: inEveryLanguage((locale) => offerFor({ ...s, locale }, offer.number)?.name ?? offer.name),
  };
}

export async function runMotionNow(ctx: AppContext, number: number): Promise<void> {
  const { store, session } = ctx;
  const offer = offerFor(store.get(), number);
  if (!offer || robotBusyReason(store.get())) return;
  const run: MotionRun = { number, stopRequested: false };
  const controller = motionsController(ctx);
  controller.run = run;
  const firstPosture = number === BASIC_POSTURE_MOTION && !store.get().connection.basicPostureConfirmed;
  const facts = named(store.get(), offer);
  patchMotions(store, {
    run: { number, name: offer.name, expectedMs: offer.expectedMs, startedAt: session.clock.now() },
    runNotice: undefined,
    confirmMove: undefined,
  });
  controller.ticker.ensure();
  try {
    const report = await session.run(said(motionsMessages, "motions.run.task", { number }), (client) =>
      client.runMotionReport(number, { expectedMs: offer.expectedMs }),
    );
    // After "Stop motion", stopMotion says how it ended.
    if (!run.stopRequested) {
      const { locale } = store.get();
      patchMotions(store, {
        // Played only when the robot was seen busy with it (docs/protocol.md §3.1 [decision, turn 4]); otherwise
        // what was seen, in the words rbc run uses.
        runNotice:
          report.verdict === "played"
            ? noticeOf("ok", locale, [
                said(motionsMessages, "motions.run.finished", facts),
                ...(firstPosture ? [said(motionsMessages, "motions.run.nowAcceptsAll")] : []),
              ])
            : noticeOf("warning", locale, [saidBy((l) => runReportText(report, l) ?? "")]),
      });
    }
  } catch (e) {
    if (run.stopRequested) return;
    patchMotions(store, { runNotice: runFailure(store.get().locale, offer, facts, e) });
  } finally {
    if (!run.stopRequested) {
      patchMotions(store, { run: undefined });
      if (controller.run === run) controller.run = undefined;
    }
  }
}

function runFailure(
  locale: Locale,
  offer: OfferedMotion,
  facts: ReturnType<typeof named>,
  e: unknown,
): Notice {
  const say = (key: RunFailureKey) => said(motionsMessages, key, facts);
  if (e instanceof RbcError && e.code === "motion-ignored") {
    return noticeOf(
      "warning",
      locale,
      [said(motionsMessages, "motions.run.postureGuidance"), say("motions.run.ignored")],
      technicalDetail(e),
    );
  }
  if (e instanceof RbcError && e.code === "cancelled") {
    return noticeOf("warning", locale, [say("motions.run.notFinished"), errorSaid(e)]);
  }
  if (e instanceof RbcError && e.code === "timeout" && offer.expectedMs === undefined) {
    return noticeOf("danger", locale, [say("motions.run.noEnd")], technicalDetail(e));
  }
  return errorNotice(say("motions.run.failed"), e, locale);
}

type RunFailureKey =
  | "motions.run.ignored"
  | "motions.run.notFinished"
  | "motions.run.noEnd"
  | "motions.run.failed";

/**
 * "Stop motion": the client sends 7, which the RBC obeys at the end of the current scene (docs/protocol.md §3.6). It
 * answers once, `07`, and does not play basic posture: the robot holds the pose it stopped in, not necessarily
 * standing (`outcome.stop.holdsPose`). Pressed before the Run has gone out (its own checks come first), it is the
 * page's Stop, which cancels the Run before it is sent: the client's Stop motion would run Basic posture after it
 * instead.
 */
export async function stopMotion(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const controller = motionsController(ctx);
  const run = controller.run;
  const shown = motionsOf(store.get()).run;
  if (!run || run.stopRequested || !shown) return;
  if (!playingMotion(store.get().connection)) {
    await stopAll(ctx);
    return;
  }
  run.stopRequested = true;
  const then = store.get();
  const { locale } = then;
  try {
    await session.run(said(motionsMessages, "motions.run.stopTask"), (client) => client.stopMotion());
    patchMotions(store, {
      runNotice: noticeOf("ok", locale, [
        said(motionsMessages, "motions.run.stopped", {
          number: run.number,
          name: inEveryLanguage((l) => offerFor({ ...then, locale: l }, run.number)?.name ?? shown.name),
        }),
        said(stopPoseMessages, "outcome.stop.holdsPose"),
        said(stopMessages, "stop.outcome.straighten"),
      ]),
    });
  } catch (e) {
    patchMotions(store, {
      runNotice:
        e instanceof RbcError && e.code === "cancelled"
          ? noticeOf("warning", locale, [
              said(motionsMessages, "motions.run.endedByStop", { number: run.number }),
            ])
          : errorNotice(said(motionsMessages, "motions.run.stopFailed"), e, locale),
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
  const { locale } = store.get();
  patchMotions(store, { soundNotice: undefined });
  motionsController(ctx).ticker.ensure();
  try {
    const report = await session.run(said(motionsMessages, "motions.sound.task", { sound: n }), (client) =>
      client.playSound(n),
    );
    // A firmware that answers at once proves only that the request arrived (docs/protocol.md §9).
    const seconds = (ms: number) => inEveryLanguage((l) => formatSeconds(ms, l));
    patchMotions(store, {
      soundNotice: report.repliedAtOnce
        ? noticeOf("warning", locale, [
            said(soundOutcomeMessages, "outcome.sound.repliedAtOnce", {
              reply: seconds(report.replyAfterMs),
              length: seconds(report.expectedMs),
            }),
          ])
        : noticeOf("ok", locale, [
            said(motionsMessages, "motions.sound.played", { sound: n, time: seconds(length) }),
          ]),
    });
  } catch (e) {
    patchMotions(store, {
      soundNotice:
        e instanceof RbcError && e.code === "cancelled"
          ? noticeOf("warning", locale, [said(motionsMessages, "motions.sound.cancelled", { sound: n })])
          : errorNotice(said(motionsMessages, "motions.sound.failed", { sound: n }), e, locale),
    });
  }
}
