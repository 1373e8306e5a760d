import { SERVO_IDS } from "../../../../device/index.ts";
import type { TimerId } from "../../../../shared/clock.ts";
import { type AppState, noticeOf } from "../../../app-state.ts";
import type { AppContext } from "../../../context.ts";
import { failureNotice } from "../../../failure-notice.ts";
import { focusSoon } from "../../../focus.ts";
import { type Controller, controllerKey } from "../../../scope.ts";
import type { Store } from "../../../store.ts";
import { isLimp, limpAll } from "../../connection/index.ts";
import { toDraft } from "../editor.ts";
import { patchZeros } from "../state.ts";
import { discardFirst } from "../unwritten.ts";
import type { CaptureState } from "./live-state.ts";
import { say } from "./say.ts";
import { checkCapture } from "./trim-model.ts";

/**
 * Capture zeros (issue 23 item 5): after one question the robot goes limp (Limp, as the top bar's: it can fall),
 * the owner poses it by hand in its zero pose during a visible countdown (cancellable) on the robot's clock, then
 * every servo's position is read in direct mode and checked against its ±15 window (docs/protocol.md §4). The
 * view shows the per-joint diff; only a pose with every joint read and inside its window can go into the editor,
 * and Write is the editor's (its checks, backup and read-back). Nothing is written here.
 */

/** The countdown, in seconds. */
export const CAPTURE_SECONDS = 5;

function patchCapture(store: Store<AppState>, patch: Partial<CaptureState>): void {
  store.update((s) =>
    s.zeros.capture ? { zeros: { ...s.zeros, capture: { ...s.zeros.capture, ...patch } } } : {},
  );
}

/** The countdown's timer on the robot's clock (a virtual one in tests), ended with the connection. */
class Countdown implements Controller {
  #timer: TimerId | undefined;
  #clear: ((id: TimerId) => void) | undefined;

  start(ctx: AppContext, tick: () => void): void {
    this.cancel();
    const clock = ctx.session.clock;
    this.#clear = (id) => clock.clearTimeout(id);
    this.#timer = clock.setTimeout(() => {
      this.#timer = undefined;
      tick();
    }, 1000);
  }

  cancel(): void {
    if (this.#timer !== undefined) this.#clear?.(this.#timer);
    this.#timer = undefined;
  }

  dispose(): void {
    this.cancel();
  }
}

const COUNTDOWN = controllerKey("capture zeros: countdown", () => new Countdown());

/** "Capture zeros…": asks once, in place (the robot goes limp and can fall); nothing is sent. */
export function askCapture(ctx: AppContext): void {
  const z = ctx.store.get().zeros;
  if (z.busy || z.live || z.stored === undefined || (z.capture && z.capture.phase !== "checked")) return;
  patchZeros(ctx.store, { capture: { phase: "asking" }, liveNotice: undefined, liveRefused: false });
  focusSoon("capture-cancel");
}

/** Cancel: the question, or the countdown (nothing is read; limp servos stay limp). */
export function cancelCapture(ctx: AppContext): void {
  const capture = ctx.store.get().zeros.capture;
  ctx.session.connectionScope.peek(COUNTDOWN)?.cancel();
  if (!capture) return;
  if (capture.phase === "asking" || capture.phase === "checked") {
    patchZeros(ctx.store, { capture: undefined });
    focusSoon("capture-zeros");
    return;
  }
  if (capture.phase === "counting") {
    patchZeros(ctx.store, {
      capture: {
        phase: "checked",
        notice: noticeOf("info", ctx.store.get().locale, [say("capture.cancelled")]),
      },
    });
  }
}

/** The question answered: Limp, then the countdown, then the read. */
export async function startCapture(ctx: AppContext): Promise<void> {
  const { store } = ctx;
  if (store.get().zeros.capture?.phase !== "asking" || !ctx.session.current) return;
  patchCapture(store, { phase: "limping", notice: undefined });
  await limpAll(ctx);
  const s = store.get();
  if (!s.zeros.capture) return;
  if (s.connection.phase !== "connected" || s.connection.mode !== "direct" || !isLimp(s.connection)) {
    patchCapture(store, { phase: "checked", notice: noticeOf("danger", s.locale, [say("capture.notLimp")]) });
    return;
  }
  patchCapture(store, { phase: "counting", secondsLeft: CAPTURE_SECONDS });
  focusSoon("capture-cancel");
  const countdown = ctx.session.connectionScope.get(COUNTDOWN);
  const tick = (): void => {
    const now = store.get();
    const capture = now.zeros.capture;
    if (capture?.phase !== "counting") return;
    if (now.connection.mode !== "direct") {
      patchCapture(store, {
        phase: "checked",
        notice: noticeOf("info", now.locale, [say("capture.stopped")]),
      });
      return;
    }
    const left = (capture.secondsLeft ?? 1) - 1;
    if (left > 0) {
      patchCapture(store, { secondsLeft: left });
      countdown.start(ctx, tick);
    } else {
      void readCapture(ctx);
    }
  };
  countdown.start(ctx, tick);
}

/** The countdown ended: every servo's position is read (direct mode) and checked. */
async function readCapture(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const stored = store.get().zeros.stored;
  if (!stored) return;
  patchCapture(store, { phase: "reading", secondsLeft: undefined });
  try {
    const { servos } = await session.run(say("capture.run"), (client) => client.servos.readAll(SERVO_IDS), {
      packetMode: false,
    });
    const positions: (number | undefined)[] = [];
    for (const s of servos) positions[s.id] = s.position;
    patchCapture(store, { phase: "checked", check: checkCapture(positions, stored) });
    focusSoon("capture-result");
  } catch (e) {
    patchCapture(store, {
      phase: "checked",
      notice: failureNotice(say("capture.readFailed"), e, store.get().locale),
    });
  }
}

/** "Put into the editor": only a pose with every joint read and inside its window; Write is the editor's. */
export function useCapture(ctx: AppContext): void {
  const { store } = ctx;
  const table = store.get().zeros.capture?.check?.table;
  if (!table) return;
  // It replaces the table: unwritten changes there are asked about first.
  discardFirst(ctx, { kind: "capture" }, () => {
    patchZeros(store, {
      draft: toDraft(table),
      source: { kind: "capture" },
      confirming: false,
      result: undefined,
      capture: undefined,
      fileNotice: noticeOf("info", store.get().locale, [say("capture.used")]),
    });
    focusSoon("zero-0");
  });
}
