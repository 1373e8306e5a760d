import { said } from "../../../i18n/said.ts";
import { type AppState, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { focusSoon } from "../../focus.ts";
import { forgetPort, grantedPorts, webSerial } from "../../serial-ports.ts";
import type { Store } from "../../store.ts";
import { busyElsewhere, isLimp } from "./activity.ts";
import { connectionMessages } from "./messages.ts";
import type { ConnectionState, RobotLabel } from "./state.ts";

/** Connecting, disconnecting and the list of earlier ports; Stop, Limp and their outcome banner. */

/**
 * The words of failures (the device's errors and outcomes) load when a failure is to be said: the first page
 * shows none, and leaves them out of its load (first load: issue 19).
 */
const failureWords = () => import("../../failure-words.ts");
/** Stop's and Limp's sentences load with the first press (or a robot found busy), not with the first page. */
const stopWords = () => import("../../stop-outcome.ts");

function setConnection(store: Store<AppState>, patch: Partial<ConnectionState>): void {
  store.update((s) => ({ connection: { ...s.connection, ...patch } }));
}

/** Ports this site was granted earlier (for one-click reconnect). */
export async function refreshKnownPorts(store: Store<AppState>): Promise<void> {
  const serial = webSerial();
  if (!serial) return;
  try {
    store.update({ knownPorts: await grantedPorts(serial) });
  } catch {
    store.update({ knownPorts: [] });
  }
}

export async function forgetKnownPort(ctx: AppContext, port: SerialPort): Promise<void> {
  const { locale } = ctx.store.get();
  try {
    if (!(await forgetPort(port))) {
      const problem = noticeOf("warning", locale, [said(connectionMessages, "connection.cannotForget")]);
      setConnection(ctx.store, { problem });
    }
  } catch (e) {
    const { failureNotice } = await failureWords();
    setConnection(ctx.store, {
      problem: failureNotice(said(connectionMessages, "connection.forgetFailed"), e, locale),
    });
  }
  await refreshKnownPorts(ctx.store);
}

export function setShowAllPorts(ctx: AppContext, on: boolean): void {
  ctx.store.update({ showAllPorts: on });
}

/** "Connect robot": opens the browser's chooser. Call it straight from the click handler. */
export function chooseAndConnect(ctx: AppContext): void {
  ctx.session.chooseAndConnect();
}

/** Cancel while "Waiting for you to choose a port…": the page stops waiting for the browser's chooser. */
export function cancelChoosing(ctx: AppContext): void {
  ctx.session.cancelChoosing();
}

/** "Try the demo robot"; with `bluetooth`, the demo robot behind a simulated Bluetooth link. */
export function connectDemo(ctx: AppContext, options: { bluetooth?: boolean } = {}): void {
  void ctx.session.connectDemo(options);
}

export function connectKnownPort(ctx: AppContext, port: SerialPort, robot: RobotLabel): void {
  void ctx.session.connectPort(port, robot);
}

export function disconnect(ctx: AppContext): void {
  void ctx.session.disconnect();
}

/**
 * Stop for the top-bar robot (the page's Stop, `stopAll` in src/ui/stop-all.ts, runs it beside the class
 * robots' own): ends what the robot is doing, which then holds the pose it stopped in, not necessarily standing
 * (`RbcClient.stopActivity`). It never makes a servo passive: that is Limp. Stop is asked of the robot first; its words load beside it (`stop-outcome.ts`,
 * not in the first page load). The top bar says the outcome (`stopNotice`).
 */
export async function stopSessionRobot(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const client = session.current;
  if (!client) return;
  const now = session.clock.now();
  const stopping = store.get();
  // Whether every servo was limp before: Stop's leave sequence moves no servo (a 7 it sends ends that).
  const limp = isLimp(stopping.connection);
  store.update({ limpAsked: undefined });
  const done = client.stopActivity().then(
    (result) => ({ result }),
    (error: unknown) => ({ error }),
  );
  const words = await stopWords();
  if (session.current === client) store.update({ stopNotice: words.stoppingNotice(stopping, now) });
  const outcome = await done;
  const { locale } = store.get();
  const notice =
    "result" in outcome
      ? words.stopOutcome(outcome.result, limp, locale)
      : (await failureWords()).failureNotice(words.stopFailedSaid(), outcome.error, locale);
  if (session.current === client) store.update({ stopNotice: notice });
}

/**
 * "Limp…": asks first, in place (the robot falls unless someone holds it). The question takes the place of an
 * earlier Stop or Limp result, so the top bar says one thing at a time.
 */
export async function askLimp(ctx: AppContext): Promise<void> {
  if (!ctx.session.current) return;
  const warning = (await stopWords()).limpWarningSaid();
  ctx.store.update({ limpAsked: warning, stopNotice: undefined });
  // Cancel first: Enter right after the question appears must not make the robot fall.
  focusSoon("cancel-limp");
}

export function cancelLimp(ctx: AppContext): void {
  ctx.store.update({ limpAsked: undefined });
  focusSoon("limp-button");
}

/** Limp, confirmed: every servo passive (`RbcClient.limp`), whatever was running is cancelled first. */
export async function limpAll(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const client = session.current;
  store.update({ limpAsked: undefined });
  if (!client) return;
  const done = client.limp().then(
    (result) => ({ result }),
    (error: unknown) => ({ error }),
  );
  const words = await stopWords();
  const { locale } = store.get();
  if (session.current === client) store.update({ stopNotice: words.limpingNotice(locale) });
  const outcome = await done;
  const notice =
    "result" in outcome
      ? words.limpNotice(outcome.result, locale)
      : (await failureWords()).failureNotice(words.limpFailedSaid(), outcome.error, locale);
  if (session.current === client) {
    // The robot is limp and someone is holding it: the next movement asks again.
    store.update((s) => ({ stopNotice: notice, acks: { ...s.acks, movement: false } }));
  }
}

/**
 * The client found the robot busy with a motion started elsewhere, or no longer (docs/protocol.md §3.6; the busy
 * probe runs on connect and before a main-loop read is blamed on the link): the top bar says so beside Stop.
 */
export async function busyChanged(ctx: AppContext, busy: boolean): Promise<void> {
  const { store, session } = ctx;
  if (!busy) {
    setConnection(store, { busyNotice: undefined });
    return;
  }
  const client = session.current;
  const words = await stopWords();
  if (session.current === client && busyElsewhere(store.get().connection)) {
    setConnection(store, { busyNotice: words.busyNotice(store.get().locale) });
  }
}

/**
 * Just connected: the busy probe (docs/protocol.md §3.6). A robot busy with a motion started with the remote or
 * another program is told apart from a silent one, and the top bar offers Stop (`busyChanged`).
 */
export function probeAfterConnect(ctx: AppContext): void {
  void ctx.session.current?.probeBusy().catch(() => {});
}

export function dismissStopNotice(ctx: AppContext): void {
  ctx.store.update({ stopNotice: undefined, robotStops: undefined });
}
