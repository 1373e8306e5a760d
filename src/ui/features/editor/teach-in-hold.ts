/**
 * Teach-in's end: "Hold" makes the limp servos hold where the hand left them (a move of each to the position it
 * reads, torque on); "End teach-in" holds first, then leaves direct mode.
 */
import { RbcCancelledError, RbcTimeoutError } from "../../../device/errors.ts";
import { said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { HUNO_SERVO_IDS } from "../../../protocol/servo-limits.ts";
import { noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice } from "../../error-text.ts";
import { isLimp } from "../connection/index.ts";
import { clampToSafe, DEFAULT_TORQUE } from "../servos/index.ts";
import { liveOf, patchTeachIn, teachInOn } from "./live-state.ts";
import { editorMessages } from "./messages.ts";
import { TEACH_IN_WATCH } from "./teach-in.ts";
import { type HeldServo, holdNotice } from "./teach-in-model.ts";

/**
 * Makes the limp servos hold where they are: reads each and moves it to that position (within its safe range)
 * with torque on. After Limp (top bar) every servo is limp, so every servo is held.
 */
async function holdLimp(ctx: AppContext): Promise<{ held: HeldServo[]; silent: number[]; stopped: boolean }> {
  const { store, session } = ctx;
  const state = store.get();
  const ids = isLimp(state.connection) ? [...HUNO_SERVO_IDS] : [...liveOf(state).teach.passive];
  const held: HeldServo[] = [];
  const silent: number[] = [];
  let stopped = false;
  try {
    await session.run(
      said(editorMessages, "editor.teach.run.hold"),
      async (c) => {
        for (const id of ids) {
          try {
            const read = (await c.servos.read(id)).position;
            const target = clampToSafe(id, read);
            await c.servos.move(id, target, DEFAULT_TORQUE);
            held.push({ id, read, held: target });
          } catch (e) {
            if (!(e instanceof RbcTimeoutError)) throw e;
            silent.push(id);
          }
        }
      },
      { packetMode: false },
    );
  } catch (e) {
    if (!(e instanceof RbcCancelledError)) throw e;
    stopped = true;
  } finally {
    const heldIds = new Set(held.map((h) => h.id));
    patchTeachIn(store, (t) => ({ passive: t.passive.filter((id) => !heldIds.has(id)) }));
  }
  return { held, silent, stopped };
}

/** "Hold": the limp servos hold where they were posed. */
export async function holdPassive(ctx: AppContext): Promise<void> {
  const { store } = ctx;
  if (!teachInOn(store.get()) || liveOf(store.get()).teach.busy) return;
  const t = translator(editorMessages, store.get().locale);
  patchTeachIn(store, { busy: "holding", notice: undefined });
  try {
    const { held, silent, stopped } = await holdLimp(ctx);
    patchTeachIn(store, { busy: undefined, notice: holdNotice(held, silent, stopped, t.locale) });
  } catch (e) {
    patchTeachIn(store, {
      busy: undefined,
      notice: errorNotice(said(editorMessages, "editor.teach.holdFailed"), e, t.locale),
    });
  }
}

/** "End teach-in": holds the limp servos first, then leaves direct mode (the servos keep holding). */
export async function endTeachIn(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  if (!teachInOn(store.get()) || liveOf(store.get()).teach.busy) return;
  const t = translator(editorMessages, store.get().locale);
  patchTeachIn(store, { phase: "ending", busy: "holding", notice: undefined });
  let held: Awaited<ReturnType<typeof holdLimp>>;
  try {
    held = await holdLimp(ctx);
  } catch (e) {
    patchTeachIn(store, {
      phase: "on",
      busy: undefined,
      notice: errorNotice(said(editorMessages, "editor.teach.endHoldFailed"), e, t.locale),
    });
    return;
  }
  if (held.stopped) {
    const stoppedNotice = holdNotice(held.held, held.silent, true, t.locale);
    const sentences = [...(stoppedNotice.said ?? []), said(editorMessages, "editor.teach.staysOn")];
    patchTeachIn(store, {
      phase: "on",
      busy: undefined,
      notice: noticeOf(stoppedNotice.tone, t.locale, sentences),
    });
    return;
  }
  session.connectionScope.peek(TEACH_IN_WATCH)?.end();
  try {
    await session.run(said(editorMessages, "editor.teach.run.end"), (c) => c.exitDirectMode(), {
      packetMode: false,
    });
  } catch (e) {
    patchTeachIn(store, {
      phase: "off",
      busy: undefined,
      notice: errorNotice(said(editorMessages, "editor.teach.leaveFailed"), e, t.locale),
    });
    return;
  }
  const heldSaid =
    held.held.length > 0 || held.silent.length > 0
      ? (holdNotice(held.held, held.silent, false, t.locale).said ?? [])
      : [];
  const ended = said(
    editorMessages,
    held.silent.length > 0 ? "editor.teach.ended" : "editor.teach.endedHolding",
  );
  // `passive` keeps the servos that did not answer Hold (holdLimp removed the held ones): they may still be limp.
  patchTeachIn(store, {
    phase: "off",
    busy: undefined,
    notice: noticeOf(held.silent.length > 0 ? "warning" : "ok", t.locale, [...heldSaid, ended]),
  });
}
