import type { AppContext } from "../../context.ts";
import { type ListenChoice, type PollRate, patchSensors } from "./state.ts";
import { SENSOR_WATCH, sensorWatch } from "./watch.ts";

/** The Sensors view's actions: what to read and listen to, and the demo robot's world. */

export function setPollRate(ctx: AppContext, rateHz: PollRate): void {
  sensorWatch(ctx).setRate(rateHz);
}

export function setPolling(ctx: AppContext, on: boolean): void {
  sensorWatch(ctx).setPolling(on);
}

export function leaveDirectAndResume(ctx: AppContext): Promise<void> {
  return sensorWatch(ctx).leaveDirectAndResume();
}

export function listenTo(ctx: AppContext, listen: ListenChoice, threshold: number): Promise<void> {
  return sensorWatch(ctx).setListen(listen, threshold);
}

export function draftThreshold(ctx: AppContext, threshold: number): void {
  sensorWatch(ctx).draftThreshold(threshold);
}

/** The view is shown with a robot connected: start reading. */
export function startWatching(ctx: AppContext, onSample: () => void): void {
  const watch = sensorWatch(ctx);
  watch.onSample = onSample;
  watch.activate();
}

/** The view is left: stop reading (the watch of an ended connection has stopped already). */
export function stopWatching(ctx: AppContext): void {
  ctx.session.connectionScope.peek(SENSOR_WATCH)?.deactivate();
}

// ---- The demo robot's world (the simulator in this page; not in the store, so the view is told to redraw).

function worldChanged(ctx: AppContext): void {
  patchSensors(ctx.store, (x) => ({ demoRevision: x.demoRevision + 1 }));
}

export function setDemoDistance(ctx: AppContext, cm: number): void {
  ctx.session.demoSim?.setDistance(cm);
  worldChanged(ctx);
}

export function setDemoSoundLevel(ctx: AppContext, level: number): void {
  ctx.session.demoSim?.setSoundLevel(level);
  worldChanged(ctx);
}

export function pressDemoButton(ctx: AppContext, button: 1 | 2): void {
  ctx.session.demoSim?.pressButton(button, 300);
}

export function chooseDemoIrKey(ctx: AppContext, key: number): void {
  patchSensors(ctx.store, { demoIrKey: key });
}

export function sendDemoIrKey(ctx: AppContext, key: number): void {
  ctx.session.demoSim?.pressRemoteKey(key);
}
