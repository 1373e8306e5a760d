import type { RbcClient, TetheredPlayResult } from "../../../../device/index.ts";
import type { Locale } from "../../../../i18n/locale.ts";
import { inEveryLanguage, type Said, wordOf } from "../../../../i18n/said.ts";
import { ZERO_COUNT } from "../../../../protocol/zeros.ts";
import { type AppState, type Notice, noticeOf, type RunningLabel } from "../../../app-state.ts";
import type { AppContext } from "../../../context.ts";
import { failureNotice } from "../../../failure-notice.ts";
import { focusSoon } from "../../../focus.ts";
import { formatDateTime } from "../../../format.ts";
import { type Controller, controllerKey } from "../../../scope.ts";
import { stopAll } from "../../../stop-all.ts";
import type { Store } from "../../../store.ts";
import { isLimp } from "../../connection/index.ts";
import { LatestMoveSender } from "../../servos/index.ts";
import { checkDraft, toDraft } from "../editor.ts";
import { patchZeros } from "../state.ts";
import type { TrimLiveState } from "./live-state.ts";
import { say } from "./say.ts";
import { trimTarget, zeroPose } from "./trim-model.ts";
import { zeroPoseMotion } from "./zero-pose-motion.ts";

/**
 * Trim live (issue 23 item 5): the robot takes its zero pose in direct mode, gently (tethered play's transition,
 * `zeroPoseMotion`), and each change to a zero moves that servo, and only that one, with a wCK move (docs/protocol.md
 * §5, torque 2), clamped into its window and safe range; the servo's reply confirms where it went. Direct mode
 * only when the robot is idle (§3.6): a busy robot refuses it, and the view offers Stop beside the sentence.
 * Write (actions.ts) stores the table through the existing path and ends trim live; Cancel returns to the
 * stored zeros and leaves direct mode, the servos holding. Stop (or Escape), Limp, or anything else that leaves
 * direct mode ends it with a sentence that says what the servos hold; a lost link is remembered for the page and
 * said on the next connection's Zeros view (which zeros the robot has, whether a write was under way).
 */

/** wCK move torque for a nudged servo (docs/protocol.md §5: 0 strongest .. 4 weakest; the Servos view's default). */
export const TRIM_TORQUE = 2;

function patchLive(store: Store<AppState>, patch: Partial<TrimLiveState>): void {
  store.update((s) => (s.zeros.live ? { zeros: { ...s.zeros, live: { ...s.zeros.live, ...patch } } } : {}));
}

/** What a lost link left behind, kept for the page: said on the next connection's Zeros view. */
export interface LostTrim {
  /** Wall-clock ms when the loss was seen. */
  at: number;
  /** The zeros the robot held (read or verified) when the link was lost. */
  stored: number[];
  /** The table a write was sending when the link was lost; undefined when none was under way. */
  writing?: number[];
  /** Servos moved away from the stored zero pose, with the position each last confirmed. */
  moved: { id: number; position: number | undefined }[];
  /** The servos were on their way to (or back to) the zero pose: the last frame they got is not known. */
  onTheWay?: boolean;
  /** Disconnect (the link was open: the panel sent the exit sequence), not a lost link. */
  closed: boolean;
}

class LostTrimRecord implements Controller {
  lost: LostTrim | undefined;
  dispose(): void {
    this.lost = undefined;
  }
}

const LOST_TRIM = controllerKey("trim live: a lost link", () => new LostTrimRecord());

/** The trim live a lost link ended, on an earlier connection of this page, if any. */
export function lostTrimOf(ctx: AppContext): LostTrim | undefined {
  return ctx.session.pageScope.peek(LOST_TRIM)?.lost;
}

export function dismissLostTrim(ctx: AppContext): void {
  const record = ctx.session.pageScope.peek(LOST_TRIM);
  if (record) record.lost = undefined;
  ctx.store.update({});
}

/** The moves of this connection's trim: one in flight, the latest target per servo wins; a watch on the link. */
class TrimLive implements Controller {
  readonly sender: LatestMoveSender<number>;
  #unwatch: (() => void) | undefined;
  /** This connection's client: when the scope ends, its mode tells a lost link from Disconnect. */
  readonly #client: RbcClient | undefined;

  constructor(private readonly ctx: AppContext) {
    this.sender = new LatestMoveSender((id, position) => this.move(id, position));
    this.#client = ctx.session.current;
  }

  private async move(id: number, position: number): Promise<void> {
    const { store, session } = this.ctx;
    const client = session.current;
    if (client?.mode !== "direct" || store.get().zeros.live?.phase !== "on") {
      this.sender.clear();
      return;
    }
    try {
      const status = await client.servos.move(id, position, TRIM_TORQUE);
      store.update((s) => {
        const live = s.zeros.live;
        if (!live) return {};
        const positions = [...live.positions];
        positions[id] = status.position;
        const moved = live.moved.includes(id) ? live.moved : [...live.moved, id];
        const asked = this.clampedFrom.get(id);
        const last = {
          id,
          sent: position,
          position: status.position,
          ...(asked !== undefined ? { asked } : {}),
        };
        return { zeros: { ...s.zeros, live: { ...live, positions, moved, last } } };
      });
    } catch (e) {
      if (e instanceof Error && "code" in e && e.code === "cancelled") {
        this.sender.clear();
        return;
      }
      patchZeros(store, {
        liveNotice: failureNotice(say("live.moveFailed", { id: String(id) }), e, store.get().locale),
      });
    }
  }

  /** Servo id → the value asked for, when it had to be clamped (said with the move's confirmation). */
  readonly clampedFrom = new Map<number, number>();

  /** Watches the link while trim live is on: Stop, Limp, another view's request, a lost link. */
  watch(): void {
    this.#unwatch?.();
    this.#unwatch = this.ctx.store.subscribe((s) => this.check(s));
  }

  unwatch(): void {
    this.#unwatch?.();
    this.#unwatch = undefined;
  }

  private check(s: AppState): void {
    const live = s.zeros.live;
    if (live?.phase !== "on") return;
    const c = s.connection;
    if (c.phase !== "connected") return; // `dispose` (the connection's scope ends first) keeps what it left.
    if (isLimp(c)) {
      this.end();
      patchZeros(this.ctx.store, {
        live: undefined,
        liveNotice: noticeOf("warning", s.locale, [say("live.endedLimp")]),
      });
    } else if (c.mode !== "direct") {
      this.end();
      patchZeros(this.ctx.store, {
        live: undefined,
        liveNotice: noticeOf("info", s.locale, [say("live.endedLeft", { pose: poseSaid(live) })]),
      });
    }
  }

  end(): void {
    this.sender.clear();
    this.clampedFrom.clear();
    this.unwatch();
  }

  /**
   * The connection ended (a pulled cable, a lost link, Disconnect): its scope ends before the state says so.
   * Trim live under way leaves a record for the page: which zeros the robot has, what its servos held.
   */
  dispose(): void {
    this.end();
    const s = this.ctx.store.get();
    const live = s.zeros.live;
    if (!live || live.phase === "asking") return;
    this.ctx.session.pageScope.get(LOST_TRIM).lost = {
      at: Date.now(),
      stored: [...(s.zeros.stored ?? [])],
      ...(live.phase === "writing" ? { writing: tableOf(s) } : {}),
      ...(live.phase === "moving" || live.phase === "returning" ? { onTheWay: true } : {}),
      // Disconnect closes a link that is still open, with direct mode's exit sequence (RbcConnection.close).
      closed: this.#client !== undefined && this.#client.mode !== "disconnected",
      moved: live.moved.map((id) => ({ id, position: live.positions[id] })),
    };
    this.ctx.store.update((x) => ({ zeros: { ...x.zeros, live: undefined } }));
  }
}

const TRIM_LIVE = controllerKey("trim live", (ctx: AppContext) => new TrimLive(ctx));

function tableOf(s: AppState): number[] | undefined {
  const values = checkDraft(s.zeros.draft).values;
  return values.every((v) => v !== undefined) ? (values as number[]) : undefined;
}

/** "the stored zero pose" or "the zero pose with these servos moved: servo 5 at 126, …". */
export function poseSaid(live: Pick<TrimLiveState, "moved" | "positions">): Said {
  if (live.moved.length === 0) return say("live.poseStored");
  const list = inEveryLanguage((locale) =>
    live.moved
      .map((id) => {
        const position = live.positions[id];
        const at = say("live.servoAt", {
          id: String(id),
          position: position === undefined ? "?" : String(position),
        });
        return wordOf(at, locale);
      })
      .join(", "),
  );
  return say("live.poseMoved", { list });
}

/** "Trim live…": asks once, in place; nothing is sent. */
export function askTrimLive(ctx: AppContext): void {
  const z = ctx.store.get().zeros;
  if (z.busy || z.live || z.capture || z.stored === undefined) return;
  patchZeros(ctx.store, {
    live: { phase: "asking", positions: [], moved: [] },
    liveNotice: undefined,
    liveRefused: false,
  });
  focusSoon("live-cancel");
}

/** The question's Cancel: nothing was sent. */
export function dismissTrimQuestion(ctx: AppContext): void {
  if (ctx.store.get().zeros.live?.phase === "asking") patchZeros(ctx.store, { live: undefined });
  focusSoon("trim-live");
}

/** Plays the zero pose of `zeros` (tethered play: transition frames, then the pose), in direct mode. */
function playZeroPose(
  ctx: AppContext,
  zeros: readonly number[],
  label: RunningLabel,
): Promise<TetheredPlayResult> {
  return ctx.session.run(
    label,
    (client) => client.playTethered(zeroPoseMotion(zeros), { robotZeros: zeros }),
    {
      packetMode: false,
    },
  );
}

/** The question answered: the robot takes its zero pose and holds it; then every change moves its servo. */
export async function startTrimLive(ctx: AppContext): Promise<void> {
  const { store } = ctx;
  const z = store.get().zeros;
  const stored = z.stored;
  if (z.live?.phase !== "asking" || !stored || !ctx.session.current) return;
  patchZeros(store, {
    live: { phase: "moving", positions: [], moved: [] },
    liveNotice: undefined,
    liveRefused: false,
  });
  const controller = ctx.session.connectionScope.get(TRIM_LIVE);
  let result: TetheredPlayResult;
  try {
    result = await playZeroPose(ctx, stored, say("live.run"));
  } catch (e) {
    const code = e instanceof Error && "code" in e ? e.code : undefined;
    const refused = code === "not-idle" || code === "wrong-mode" || code === "activity-refused";
    patchZeros(store, {
      live: undefined,
      liveRefused: refused,
      liveNotice: failureNotice(say(refused ? "live.notStarted" : "live.failed"), e, store.get().locale),
    });
    return;
  }
  if (result.outcome === "stopped" || ctx.session.current?.mode !== "direct") {
    patchZeros(store, {
      live: undefined,
      liveNotice: noticeOf("info", store.get().locale, [say("live.stoppedOnTheWay")]),
    });
    return;
  }
  const pose = zeroPose(stored);
  patchZeros(store, {
    live: { phase: "on", positions: [...pose], moved: [] },
    liveNotice: undefined,
  });
  controller.watch();
  // Values already changed in the editor (typed before trim live began) move their servos now.
  const values = checkDraft(store.get().zeros.draft).values;
  for (let id = 0; id < ZERO_COUNT; id++) {
    const v = values[id];
    if (v !== undefined && v !== stored[id]) requestTrim(ctx, id, v);
  }
  focusSoon("zero-0");
}

/** A zero changed in the editor while trim live is on: that servo moves (only that one), clamped. */
export function trimChanged(ctx: AppContext, id: number, text: string): void {
  if (ctx.store.get().zeros.live?.phase !== "on") return;
  const trimmed = text.trim();
  if (!/^-?\d+$/.test(trimmed)) return;
  requestTrim(ctx, id, Number(trimmed));
}

function requestTrim(ctx: AppContext, id: number, value: number): void {
  const target = trimTarget(id, value);
  if (target === undefined) return;
  const controller = ctx.session.connectionScope.get(TRIM_LIVE);
  if (target !== value) controller.clampedFrom.set(id, value);
  else controller.clampedFrom.delete(id);
  controller.sender.request(id, target);
}

/** Cancel trim: the servos return to the stored zeros (gently), direct mode is left, the servos holding. */
export async function cancelTrimLive(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const z = store.get().zeros;
  const stored = z.stored;
  if (z.live?.phase !== "on" || !stored) return;
  const controller = session.connectionScope.get(TRIM_LIVE);
  controller.end();
  patchLive(store, { phase: "returning" });
  try {
    const result = await playZeroPose(ctx, stored, say("live.returning"));
    if (result.outcome === "stopped") {
      patchZeros(store, {
        live: undefined,
        draft: toDraft(stored),
        liveNotice: noticeOf("info", store.get().locale, [say("live.stoppedOnTheWay")]),
      });
      return;
    }
    await session.run(say("live.returning"), (client) => client.exitDirectMode(), {
      packetMode: false,
    });
  } catch (e) {
    patchZeros(store, {
      live: undefined,
      liveNotice: failureNotice(say("live.failed"), e, store.get().locale),
    });
    return;
  }
  patchZeros(store, {
    live: undefined,
    draft: toDraft(stored),
    source: { kind: "robot" },
    liveNotice: noticeOf("ok", store.get().locale, [say("live.cancelled")]),
  });
  focusSoon("trim-live");
}

/** Write began while trim live was on: the watch lets Write leave direct mode (the servos hold). */
export function trimWriteBegins(ctx: AppContext): boolean {
  if (ctx.store.get().zeros.live?.phase !== "on") return false;
  ctx.session.connectionScope.peek(TRIM_LIVE)?.sender.clear();
  patchLive(ctx.store, { phase: "writing" });
  return true;
}

/** Write ended (written or not): trim live is over; the sentence says so beside the write's result. */
export function trimWriteEnded(ctx: AppContext): Said {
  ctx.session.connectionScope.peek(TRIM_LIVE)?.end();
  patchZeros(ctx.store, { live: undefined });
  return say("live.endedByWrite");
}

/** Stop, offered beside a refusal (the robot is busy): the top bar's Stop. */
export function stopFromTrim(ctx: AppContext): void {
  void stopAll(ctx);
}

/** The sentence a lost link left for the page, worded for the next connection's view. */
export function lostTrimNotice(lost: LostTrim, locale: Locale): Notice {
  const time = inEveryLanguage((l) => formatDateTime(new Date(lost.at), l));
  const positions: (number | undefined)[] = [];
  for (const m of lost.moved) positions[m.id] = m.position;
  const pose = lost.onTheWay
    ? say("live.poseOnTheWay")
    : poseSaid({ moved: lost.moved.map((m) => m.id), positions });
  return noticeOf("warning", locale, [
    say("live.lost", { time }),
    lost.writing
      ? say("live.lostWriting", { zeros: lost.writing.join(" ") })
      : lost.closed
        ? say("live.closedNothingWritten", { zeros: lost.stored.join(" "), pose })
        : say("live.lostNothingWritten", { zeros: lost.stored.join(" "), pose }),
  ]);
}
