import { RbcError } from "../../device/errors.ts";
import type { RbcClient } from "../../device/rbc-client.ts";
import type { RbcEvent } from "../../device/types.ts";
import type { AppState, Notice } from "../app-state.ts";
import { errorNotice } from "../error-text.ts";
import type { Session } from "../session.ts";
import type { Store } from "../store.ts";
import { RingSeries } from "./ring-series.ts";
import { addEvent } from "./sensor-events.ts";
import type { ListenChoice, PollRate, SensorsState } from "./sensors-state.ts";

/**
 * The Sensors view's live side: polls distance and accelerometer at the chosen rate while the view is shown
 * and the tab visible, and keeps the one subscription the RBC can run (sound level, PF buttons or the IR
 * remote). Everything stops when the view is left, the tab hidden or the robot disconnected.
 */

export const CHART_WINDOW_MS = 30_000;
const FAILURES_BEFORE_PAUSE = 3;

export const distanceSeries = new RingSeries(1, CHART_WINDOW_MS);
export const accelSeries = new RingSeries(3, CHART_WINDOW_MS);

interface Ctx {
  session: Session;
  store: Store<AppState>;
}

/**
 * The RBC ends a subscription at every request and reports the sound level only after 100 ms of quiet, so
 * while listening to sound the readings leave it that time: at most 5 a second.
 */
export const SOUND_LISTEN_MAX_HZ = 5;

export function effectiveRate(s: Pick<SensorsState, "rateHz" | "listen">): number {
  return s.listen === "sound" ? Math.min(s.rateHz, SOUND_LISTEN_MAX_HZ) : s.rateHz;
}

export function sensorsOf(s: AppState): SensorsState {
  return (
    s.sensors ?? {
      rateHz: 5,
      polling: true,
      running: false,
      readings: 0,
      listen: "none",
      threshold: 30,
      events: [],
    }
  );
}

function patch(
  store: Store<AppState>,
  p: Partial<SensorsState> | ((x: SensorsState) => Partial<SensorsState>),
) {
  store.update((s) => {
    const cur = sensorsOf(s);
    return { sensors: { ...cur, ...(typeof p === "function" ? p(cur) : p) } };
  });
}

const STOPPED_BY_STOP: Notice = {
  tone: "warning",
  text: "Paused: Stop — limp switched the robot to servo control, where it reads no sensors. Resume returns it to normal mode (the servos stay limp).",
};

class SensorWatch {
  private ctx: Ctx | undefined;
  private token = 0;
  private client: RbcClient | undefined;
  private detachEvents: (() => void) | undefined;
  /** Called whenever a reading arrives (the view redraws its charts). */
  onSample: (() => void) | undefined;

  private readonly onVisibility = () => {
    if (!this.ctx) return;
    if (document.hidden) {
      this.halt();
      void this.quiet();
      patch(this.ctx.store, { pausedWhy: { tone: "info", text: "Paused while this tab is hidden." } });
    } else {
      patch(this.ctx.store, { pausedWhy: undefined });
      void this.resume();
    }
  };

  /** The view is shown with a robot connected. */
  activate(ctx: Ctx): void {
    this.ctx = ctx;
    const client = ctx.session.current;
    if (client !== this.client) {
      distanceSeries.clear();
      accelSeries.clear();
    }
    this.client = client;
    this.detachEvents?.();
    this.detachEvents = client?.events.on((e) => this.onEvent(e));
    document.addEventListener("visibilitychange", this.onVisibility);
    patch(ctx.store, { pausedWhy: undefined });
    void this.resume();
  }

  /** The view is left or the robot disconnected: stop polling and end the subscription. */
  deactivate(): void {
    document.removeEventListener("visibilitychange", this.onVisibility);
    this.halt();
    void this.quiet();
    this.detachEvents?.();
    this.detachEvents = undefined;
    this.ctx = undefined;
  }

  get active(): boolean {
    return this.ctx !== undefined;
  }

  /** Starts what the user asked for (polling, the chosen subscription), if the view is shown and visible. */
  async resume(): Promise<void> {
    const ctx = this.ctx;
    const client = ctx?.session.current;
    if (!ctx || !client || document.hidden) return;
    if (client.mode === "direct") {
      patch(ctx.store, { pausedWhy: STOPPED_BY_STOP, running: false });
      return;
    }
    const s = sensorsOf(ctx.store.get());
    await this.applyListen(s.listen, s.threshold);
    // The view may have been left, the tab hidden or polling paused while the subscription was sent.
    if (this.ctx === ctx && !document.hidden && sensorsOf(ctx.store.get()).polling) this.startLoop();
  }

  /** Leaves servo control (after Stop) and resumes. */
  async leaveDirectAndResume(): Promise<void> {
    const ctx = this.ctx;
    if (!ctx) return;
    try {
      await ctx.session.run("Leaving servo control", (client) => client.exitDirectMode());
      patch(ctx.store, { pausedWhy: undefined });
      await this.resume();
    } catch (e) {
      patch(ctx.store, { pausedWhy: errorNotice("Could not return to normal mode.", e) });
    }
  }

  setPolling(on: boolean): void {
    if (!this.ctx) return;
    patch(this.ctx.store, { polling: on, pausedWhy: undefined });
    if (on) void this.resume();
    else this.halt();
  }

  setRate(rateHz: PollRate): void {
    if (!this.ctx) return;
    patch(this.ctx.store, { rateHz });
  }

  /**
   * Keeps the threshold being typed in the store, so that the redraws of live readings (5 a second) do not put
   * the old value back into the input before the change is applied.
   */
  draftThreshold(threshold: number): void {
    if (this.ctx) patch(this.ctx.store, { threshold });
  }

  async setListen(listen: ListenChoice, threshold: number): Promise<void> {
    if (!this.ctx) return;
    patch(this.ctx.store, { listen, threshold, listenNotice: undefined });
    const client = this.ctx.session.current;
    if (client?.mode === "direct") {
      patch(this.ctx.store, { pausedWhy: STOPPED_BY_STOP });
      return;
    }
    await this.applyListen(listen, threshold);
  }

  private async applyListen(listen: ListenChoice, threshold: number): Promise<void> {
    const ctx = this.ctx;
    const client = ctx?.session.current;
    if (!ctx || !client) return;
    try {
      if (listen === "none") await client.unsubscribe();
      else await client.subscribe(listen, listen === "sound" ? threshold : 0);
    } catch (e) {
      patch(ctx.store, { listenNotice: errorNotice("Listening could not start.", e) });
    }
  }

  /** Ends the subscription (the RBC stops at the next packet). */
  private async quiet(): Promise<void> {
    const client = this.client;
    if (client && client.mode === "packet" && client.state.subscription) {
      await client.unsubscribe().catch(() => {});
    }
  }

  private halt(): void {
    this.token++;
    if (this.ctx) patch(this.ctx.store, { running: false });
  }

  private startLoop(): void {
    const ctx = this.ctx;
    if (!ctx) return;
    const token = ++this.token;
    patch(ctx.store, { running: true });
    void this.loop(ctx, token);
  }

  private async loop(ctx: Ctx, token: number): Promise<void> {
    let failures = 0;
    while (token === this.token) {
      const client = ctx.session.current;
      if (!client) break;
      const started = performance.now();
      try {
        if (client.mode === "direct") throw new RbcError("wrong-mode", "direct mode");
        const distanceCm = await client.readDistance();
        const accel = await client.readAccelerometer();
        if (token !== this.token) break;
        const t = performance.now();
        distanceSeries.push(t, [distanceCm]);
        accelSeries.push(t, [accel.x, accel.y, accel.z]);
        failures = 0;
        patch(ctx.store, (x) => ({ distanceCm, accel, readAt: Date.now(), readings: x.readings + 1 }));
        this.onSample?.();
      } catch (e) {
        if (token !== this.token) break;
        if (e instanceof RbcError && (e.code === "wrong-mode" || e.code === "cancelled")) {
          patch(ctx.store, { pausedWhy: STOPPED_BY_STOP, running: false });
          this.token++;
          break;
        }
        if (e instanceof RbcError && (e.code === "disconnected" || e.code === "not-connected")) break;
        failures++;
        if (failures >= FAILURES_BEFORE_PAUSE) {
          patch(ctx.store, {
            pausedWhy: errorNotice(`Paused: reading the sensors failed ${failures} times in a row.`, e),
            running: false,
          });
          this.token++;
          break;
        }
      }
      const period = 1000 / effectiveRate(sensorsOf(ctx.store.get()));
      const wait = period - (performance.now() - started);
      if (wait > 0) await new Promise((r) => setTimeout(r, wait));
    }
  }

  private onEvent(e: RbcEvent): void {
    const ctx = this.ctx;
    if (!ctx) return;
    const at = performance.timeOrigin + e.time;
    patch(ctx.store, (x) => ({
      events: addEvent(x.events, { at, kind: e.kind, value: e.value }),
      ...(e.kind === "sound" ? { soundLevel: { value: e.value, at } } : {}),
    }));
  }
}

export const sensorWatch = new SensorWatch();
