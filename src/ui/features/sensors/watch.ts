import { RbcError } from "../../../device/errors.ts";
import type { RbcClient } from "../../../device/rbc-client.ts";
import type { RbcEvent } from "../../../device/types.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice } from "../../error-text.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { addEvent } from "./events.ts";
import { sensorsMessages } from "./messages.ts";
import { RingSeries } from "./ring-series.ts";
import { type ListenChoice, type PollRate, patchSensors, type SensorsState, sensorsOf } from "./state.ts";

/**
 * The Sensors view's live side, one per connection: polls distance and accelerometer at the chosen rate while
 * the view is shown and the tab visible, and keeps the one subscription the RBC can run (sound level, PF
 * buttons or the IR remote). Everything stops when the view is left, the tab hidden or the robot
 * disconnected (the session ends the connection's scope, which disposes this).
 */

export const CHART_WINDOW_MS = 30_000;
const FAILURES_BEFORE_PAUSE = 3;

/**
 * The RBC ends a subscription at every request and reports the sound level only after 100 ms of quiet, so
 * while listening to sound the readings leave it that time: at most 5 a second.
 */
export const SOUND_LISTEN_MAX_HZ = 5;

export function effectiveRate(s: Pick<SensorsState, "rateHz" | "listen">): number {
  return s.listen === "sound" ? Math.min(s.rateHz, SOUND_LISTEN_MAX_HZ) : s.rateHz;
}

/** Why polling waits while the robot is in direct mode, in the panel's language. */
function inServoControl(locale: Locale): Notice {
  return noticeOf("warning", locale, [said(sensorsMessages, "sensors.inServoControl")]);
}

export class SensorWatch implements Controller {
  /** Distance readings of the last 30 s (robot-clock ms). */
  readonly distance = new RingSeries(1, CHART_WINDOW_MS);
  /** Accelerometer X, Y, Z of the last 30 s. */
  readonly accel = new RingSeries(3, CHART_WINDOW_MS);
  /** Called whenever a reading arrives (the view redraws its charts). */
  onSample: (() => void) | undefined;
  private shown = false;
  private token = 0;
  private client: RbcClient | undefined;
  private detachEvents: (() => void) | undefined;

  constructor(private readonly ctx: AppContext) {}

  /** The moment's language (notices are kept as messages and worded when drawn). */
  private words() {
    const { locale } = this.ctx.store.get();
    return { locale, t: translator(sensorsMessages, locale) };
  }

  private readonly onVisibility = () => {
    if (!this.shown) return;
    if (document.hidden) {
      this.halt();
      void this.quiet();
      patchSensors(this.ctx.store, {
        pausedWhy: noticeOf("info", this.words().locale, [said(sensorsMessages, "sensors.tabHidden")]),
      });
    } else {
      patchSensors(this.ctx.store, { pausedWhy: undefined });
      void this.resume();
    }
  };

  /** The view is shown with a robot connected. */
  activate(): void {
    const client = this.ctx.session.current;
    if (client !== this.client) {
      this.distance.clear();
      this.accel.clear();
    }
    this.client = client;
    this.shown = true;
    this.detachEvents?.();
    this.detachEvents = client?.events.on((e) => this.onEvent(e));
    document.addEventListener("visibilitychange", this.onVisibility);
    patchSensors(this.ctx.store, { pausedWhy: undefined });
    void this.resume();
  }

  /** The view is left: stop polling and end the subscription. */
  deactivate(): void {
    document.removeEventListener("visibilitychange", this.onVisibility);
    this.halt();
    void this.quiet();
    this.detachEvents?.();
    this.detachEvents = undefined;
    this.shown = false;
  }

  dispose(): void {
    this.deactivate();
    this.onSample = undefined;
  }

  get active(): boolean {
    return this.shown;
  }

  /** Starts what the user asked for (polling, the chosen subscription), if the view is shown and visible. */
  async resume(): Promise<void> {
    const client = this.ctx.session.current;
    if (!this.shown || !client || document.hidden) return;
    if (client.mode === "direct") {
      patchSensors(this.ctx.store, { pausedWhy: inServoControl(this.words().locale), running: false });
      return;
    }
    const s = sensorsOf(this.ctx.store.get());
    await this.applyListen(s.listen, s.threshold);
    // The view may have been left, the tab hidden or polling paused while the subscription was sent.
    if (this.shown && !document.hidden && sensorsOf(this.ctx.store.get()).polling) this.startLoop();
  }

  /** Leaves servo control (after Limp or the Servos view) and resumes. */
  async leaveDirectAndResume(): Promise<void> {
    if (!this.shown) return;
    const { locale } = this.words();
    try {
      await this.ctx.session.run(said(sensorsMessages, "sensors.leavingServoControl"), (client) =>
        client.exitDirectMode(),
      );
      patchSensors(this.ctx.store, { pausedWhy: undefined });
      await this.resume();
    } catch (e) {
      patchSensors(this.ctx.store, {
        pausedWhy: errorNotice(said(sensorsMessages, "sensors.normalModeFailed"), e, locale),
      });
    }
  }

  setPolling(on: boolean): void {
    if (!this.shown) return;
    patchSensors(this.ctx.store, { polling: on, pausedWhy: undefined });
    if (on) void this.resume();
    else this.halt();
  }

  setRate(rateHz: PollRate): void {
    if (this.shown) patchSensors(this.ctx.store, { rateHz });
  }

  /**
   * Keeps the threshold being typed in the store, so that the redraws of live readings (5 a second) do not put
   * the old value back into the input before the change is applied.
   */
  draftThreshold(threshold: number): void {
    if (this.shown) patchSensors(this.ctx.store, { threshold });
  }

  async setListen(listen: ListenChoice, threshold: number): Promise<void> {
    if (!this.shown) return;
    patchSensors(this.ctx.store, { listen, threshold, listenNotice: undefined });
    if (this.ctx.session.current?.mode === "direct") {
      patchSensors(this.ctx.store, { pausedWhy: inServoControl(this.words().locale) });
      return;
    }
    await this.applyListen(listen, threshold);
  }

  private async applyListen(listen: ListenChoice, threshold: number): Promise<void> {
    const client = this.ctx.session.current;
    if (!this.shown || !client) return;
    try {
      if (listen === "none") await client.unsubscribe();
      else await client.subscribe(listen, listen === "sound" ? threshold : 0);
    } catch (e) {
      const { locale } = this.words();
      patchSensors(this.ctx.store, {
        listenNotice: errorNotice(said(sensorsMessages, "sensors.listenFailed"), e, locale),
      });
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
    if (this.shown) patchSensors(this.ctx.store, { running: false });
  }

  private startLoop(): void {
    if (!this.shown) return;
    const token = ++this.token;
    patchSensors(this.ctx.store, { running: true });
    void this.loop(token);
  }

  /** Reads at the chosen rate, in the robot's time (the session's clock: real time but for a faster demo). */
  private async loop(token: number): Promise<void> {
    const { store, session } = this.ctx;
    let failures = 0;
    while (token === this.token) {
      const client = session.current;
      if (!client) break;
      const clock = session.clock;
      const started = clock.now();
      try {
        if (client.mode === "direct") throw new RbcError("wrong-mode", "direct mode");
        const distanceCm = await client.readDistance();
        const accel = await client.readAccelerometer();
        if (token !== this.token) break;
        const t = clock.now();
        this.distance.push(t, [distanceCm]);
        this.accel.push(t, [accel.x, accel.y, accel.z]);
        failures = 0;
        patchSensors(store, (x) => ({ distanceCm, accel, readAt: Date.now(), readings: x.readings + 1 }));
        this.onSample?.();
      } catch (e) {
        if (token !== this.token) break;
        if (e instanceof RbcError && e.code === "wrong-mode") {
          patchSensors(store, { pausedWhy: inServoControl(this.words().locale), running: false });
          this.token++;
          break;
        }
        // Stop cancels the requests waiting their turn, a reading among them: polling goes on (Stop keeps the
        // robot in its normal mode). Limp switches it to servo control, which the next reading finds.
        const cancelled = e instanceof RbcError && e.code === "cancelled";
        if (e instanceof RbcError && (e.code === "disconnected" || e.code === "not-connected")) break;
        if (!cancelled) failures++;
        if (failures >= FAILURES_BEFORE_PAUSE) {
          const { locale } = this.words();
          patchSensors(store, {
            pausedWhy: errorNotice(said(sensorsMessages, "sensors.readFailures", { failures }), e, locale),
            running: false,
          });
          this.token++;
          break;
        }
      }
      const period = 1000 / effectiveRate(sensorsOf(store.get()));
      const wait = period - (clock.now() - started);
      if (wait > 0) await new Promise<void>((r) => clock.setTimeout(r, wait));
    }
  }

  private onEvent(e: RbcEvent): void {
    if (!this.shown) return;
    const at = this.ctx.session.epochOf(e.time);
    patchSensors(this.ctx.store, (x) => ({
      events: addEvent(x.events, { at, kind: e.kind, value: e.value }),
      ...(e.kind === "sound" ? { soundLevel: { value: e.value, at } } : {}),
    }));
  }
}

export const SENSOR_WATCH = controllerKey("sensor watch", (ctx: AppContext) => new SensorWatch(ctx));

/** The sensor watch of this connection. */
export function sensorWatch(ctx: AppContext): SensorWatch {
  return ctx.session.connectionScope.get(SENSOR_WATCH);
}
