/**
 * Tethered play's actions (issue #12 item 4, docs/protocol.md §10): play the selected scene, a range or the whole
 * motion on the robot in direct mode, after one question; progress in place; Stop (top bar, Escape or the
 * panel's own button) holds the last frame; one sentence of what the robot confirmed.
 */
import { RbcCancelledError, RbcDisconnectedError, RbcNotConnectedError } from "../../../device/errors.ts";
import { TetheredPlayError } from "../../../device/tethered-play.ts";
import { errorSaid } from "../../../i18n/error-said.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { type Motion, MotionError } from "../../../motion/index.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { technicalDetail } from "../../error-text.ts";
import { focusSoon } from "../../focus.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { stopAll } from "../../stop-all.ts";
import type { EditorHost } from "./host.ts";
import { liveOf, type PlayChoice, type PlayProgress, patchPlay, patchTeachIn } from "./live-state.ts";
import { editorMessages } from "./messages.ts";
import { type PlayHolds, playFailureSaid, playRange, playResultNotice, playSpan } from "./play-model.ts";
import { refusalWords } from "./refusal-text.ts";

/** The play of this connection: aborted when the connection ends. */
export class PlayControl implements Controller {
  abort: AbortController | undefined;

  dispose(): void {
    this.abort?.abort();
    this.abort = undefined;
  }
}

export const PLAY_CONTROL = controllerKey("tethered play", () => new PlayControl());

export function setPlayChoice(ctx: AppContext, choice: PlayChoice): void {
  patchPlay(ctx.store, { choice, confirming: undefined });
}

export function setPlayRange(ctx: AppContext, end: "from" | "to", scene: number): void {
  if (!Number.isFinite(scene)) return;
  patchPlay(
    ctx.store,
    end === "from" ? { rangeFrom: scene, confirming: undefined } : { rangeTo: scene, confirming: undefined },
  );
}

/** The scenes the panel's current choice plays in `doc`. */
export function chosenRange(ctx: AppContext, host: EditorHost): { from: number; to: number } {
  const p = liveOf(ctx.store.get()).play;
  return playRange(host.doc, p.choice, host.scene, p.rangeFrom, p.rangeTo);
}

/**
 * "Play on robot…": checks the scenes as the RBC would (frames under 20 ms apart: the core's message, nothing
 * moves) and asks once, Cancel focused first.
 */
export function askPlay(ctx: AppContext, host: EditorHost): void {
  const state = ctx.store.get();
  if (!ctx.session.current || liveOf(state).play.running) return;
  const { from, to } = chosenRange(ctx, host);
  try {
    const { frames, durationMs } = playSpan(host.doc, from, to);
    patchPlay(ctx.store, { confirming: { from, to, frames, durationMs }, notice: undefined });
    focusSoon("cancel-play");
  } catch (e) {
    patchPlay(ctx.store, { confirming: undefined, notice: notSentNotice(state.locale, e) });
  }
}

/** "Not sent: …": the motion core's refusal (or another error) kept in every language, the detail apart. */
function notSentNotice(locale: Locale, e: unknown): Notice {
  const reason = e instanceof MotionError ? refusalWords(e) : errorSaid(e);
  return noticeOf(
    "danger",
    locale,
    [said(editorMessages, "editor.play.notSent", { reason })],
    technicalDetail(e),
  );
}

export function cancelPlay(ctx: AppContext): void {
  patchPlay(ctx.store, { confirming: undefined });
  focusSoon("play-button");
}

/** The positions of a frame, by servo id 0-15. */
function byId(positions: readonly (number | undefined)[]): (number | undefined)[] {
  return Array.from({ length: 16 }, (_, id) => positions[id]);
}

/** What the servos hold after play failed with `e`, and the last frame sent. */
function failure(
  e: unknown,
  last: PlayProgress | undefined,
): { holds: PlayHolds; lastFrame?: { scene: number; frame: number } } {
  if (e instanceof TetheredPlayError) return { holds: e.holds, lastFrame: e.lastFrame };
  const lastFrame = last ? { scene: last.scene, frame: last.frame } : undefined;
  if (e instanceof RbcDisconnectedError || e instanceof RbcNotConnectedError)
    return { holds: "unknown", lastFrame };
  return { holds: last ? "last-frame" : "nothing-sent", lastFrame };
}

/** Confirmed: plays the scenes asked about (the document as it is now; edits during play do not change it). */
export async function confirmPlay(ctx: AppContext, host: EditorHost): Promise<void> {
  const { store, session } = ctx;
  const play = liveOf(store.get()).play;
  const asked = play.confirming;
  if (!asked || play.running) return;
  const client = session.current;
  if (!client) {
    patchPlay(store, { confirming: undefined });
    return;
  }
  const doc: Motion = host.doc;
  const { from, to } = asked;
  const control = session.connectionScope.get(PLAY_CONTROL);
  const abort = new AbortController();
  control.abort = abort;
  const state = store.get();
  const t = translator(editorMessages, state.locale);
  // Zeros read in this connection (teach-in, the Zeros view); otherwise tethered play reads them itself.
  const robotZeros = liveOf(state).teach.robotZeros ?? state.zeros.stored;
  const platform = state.connection.platform;
  let last: PlayProgress | undefined;
  patchPlay(store, { confirming: undefined, running: { from, to }, notice: undefined });
  try {
    const result = await session.run(
      said(editorMessages, "editor.play.run"),
      (c) =>
        c.playTethered(doc, {
          range: { from, to },
          ...(robotZeros ? { robotZeros } : {}),
          ...(platform !== undefined ? { platform } : {}),
          signal: abort.signal,
          onFrame: (p) => {
            last = {
              index: p.index + 1,
              total: p.total,
              scene: p.scene,
              frame: p.frame.frame,
              positions: byId(p.positions),
              elapsedMs: p.elapsedMs,
              durationMs: p.durationMs,
            };
            patchPlay(store, (x) => (x.running ? { running: { ...x.running, progress: last } } : {}));
          },
        }),
      { packetMode: false },
    );
    patchPlay(store, { running: undefined, notice: playResultNotice(result, from, to, t.locale) });
  } catch (e) {
    const connected = session.current === client;
    if (e instanceof RbcCancelledError && connected) {
      const lastFrame = last ? { scene: last.scene, frame: last.frame } : undefined;
      const framesSent = last?.index ?? 0;
      patchPlay(store, {
        running: undefined,
        notice: playResultNotice(
          { outcome: "stopped", framesSent, durationMs: 0, lastFrame },
          from,
          to,
          t.locale,
        ),
      });
    } else {
      const { holds, lastFrame } = failure(e, last);
      const notice =
        e instanceof MotionError
          ? notSentNotice(t.locale, e)
          : noticeOf(
              "danger",
              t.locale,
              [
                playFailureSaid(connected ? holds : "unknown", lastFrame, client.mode === "direct"),
                errorSaid(e),
              ],
              technicalDetail(e),
            );
      patchPlay(store, { running: undefined, notice });
    }
  } finally {
    if (control.abort === abort) control.abort = undefined;
    if (last && session.current === client) {
      // Every servo took a synchronised move (the device's activity no longer says limp): teach-in's limp
      // servos hold too.
      patchTeachIn(store, { passive: [] });
    }
  }
}

/** The panel's Stop: the same as the top bar's (the robot holds the last frame; nothing goes limp). */
export function stopPlay(ctx: AppContext): void {
  void stopAll(ctx);
}
