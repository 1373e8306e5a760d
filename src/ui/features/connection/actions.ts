import type { StopActivityResult } from "../../../device/rbc-client.ts";
import type { ParamArgs } from "../../../i18n/catalogue.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { formatSeconds } from "../../../i18n/units.ts";
import { type AppState, type Notice, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { focusSoon } from "../../focus.ts";
import { inEveryLanguage, type LocalText, type Said, said } from "../../said.ts";
import { forgetPort, grantedPorts, webSerial } from "../../serial-ports.ts";
import type { Store } from "../../store.ts";
import { stopClassRobots } from "../class/stop-all.ts";
import { connectionMessages } from "./messages.ts";
import type { ConnectionState, RobotLabel } from "./state.ts";

/** Connecting, disconnecting and the list of earlier ports; Stop, Limp and their outcome banner. */

/**
 * The words of failures (the device's errors and outcomes) load when a failure is to be said: the first page
 * shows none, and leaves them out of its load (first load: issue 19).
 */
const failureWords = () => import("../../failure-words.ts");

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
  const t = translator(connectionMessages, ctx.store.get().locale);
  try {
    if (!(await forgetPort(port))) {
      setConnection(ctx.store, { problem: { tone: "warning", text: t("connection.cannotForget") } });
    }
  } catch (e) {
    const { errorNotice } = await failureWords();
    setConnection(ctx.store, { problem: errorNotice(t("connection.forgetFailed"), e, t.locale) });
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

/** Whole seconds, rounded up, for "the sound ends in 3 s". */
function secondsLeft(ms: number): LocalText {
  return inEveryLanguage((locale) => formatSeconds(Math.max(1, Math.ceil(ms / 1000)), locale, 0));
}

const say = <K extends keyof typeof connectionMessages & string>(
  key: K,
  ...facts: ParamArgs<(typeof connectionMessages)[K], Said | LocalText>
): Said => said(connectionMessages, key, ...facts);

/** What Stop is waiting for, said before it is done (the robot's state mirrored in the store). */
function stopping(state: AppState, now: number): Said {
  const c = state.connection;
  if (c.sounding) {
    const left = c.sounding.startedAt + c.sounding.expectedMs - now;
    return say("connection.stopping.sound", { time: secondsLeft(left) });
  }
  if (c.playing) return say("connection.stopping.motion", { motion: String(c.playing.motion) });
  if (c.mode === "download") return say("connection.stopping.upload");
  return say("connection.stopping");
}

/** Where tethered play stopped, and how far it got. */
function playStopped(play: NonNullable<StopActivityResult["tetheredPlay"]>): Said {
  const { framesSent: sent, totalFrames: total, lastFrame } = play;
  if (!lastFrame) return say("connection.outcome.playNotStarted");
  const frame = String(lastFrame.frame);
  return lastFrame.scene < 0
    ? say("connection.outcome.playStoppedTransition", { frame, sent, total })
    : say("connection.outcome.playStoppedScene", { scene: String(lastFrame.scene), frame, sent, total });
}

/**
 * What Stop did, as plain sentences, never more certain than the robot confirmed. `limp` says whether every
 * servo had been made limp before (Stop does not change that). Kept as messages: worded in the language of the
 * moment.
 */
export function stopOutcome(result: StopActivityResult, limp: boolean, locale: Locale = "en"): Notice {
  const parts: Said[] = [];
  let unsure = false;
  if (result.uploadCancelled) parts.push(say("connection.outcome.uploadCancelled"));
  if (result.sound) {
    const sound = String(result.sound.number);
    if (result.sound.confirmed) parts.push(say("connection.outcome.soundWaited", { sound }));
    else {
      unsure = true;
      parts.push(say("connection.outcome.soundUnconfirmed", { sound }));
    }
  }
  if (result.motion) {
    const motion = String(result.motion.number);
    switch (result.motion.outcome) {
      case "stopped":
        parts.push(say("connection.outcome.motionStopped", { motion }));
        break;
      case "ended-then-posture":
        parts.push(say("connection.outcome.motionEnded", { motion }));
        break;
      case "posture":
        parts.push(say("connection.outcome.posture"));
        break;
      case "unconfirmed":
        unsure = true;
        parts.push(say("connection.outcome.motionUnconfirmed", { motion }));
        break;
    }
  }
  if (result.tetheredPlay) {
    parts.push(playStopped(result.tetheredPlay));
  } else if (result.servoMovesDropped) {
    parts.push(limp ? say("connection.outcome.servoMovesLimp") : say("connection.outcome.servoMoves"));
  }
  if (parts.length === 0) parts.push(say("connection.outcome.nothing"));
  return noticeOf(unsure ? "warning" : "ok", locale, parts);
}

/**
 * Stop (the top bar's red button, and Escape when nothing else takes it): ends what the robot is doing and
 * keeps it standing (`RbcClient.stopActivity`). It never makes a servo passive: that is Limp.
 */
export async function stopActivity(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  void stopClassRobots(ctx);
  const client = session.current;
  if (!client) return;
  store.update((s) => ({
    stopNotice: noticeOf("info", s.locale, [stopping(s, session.clock.now())]),
    limpAsked: false,
  }));
  const { locale } = store.get();
  let notice: Notice;
  try {
    notice = stopOutcome(await client.stopActivity(), store.get().connection.limp === true, locale);
  } catch (e) {
    notice = (await failureWords()).failureNotice(say("connection.stopFailed"), e, locale);
  }
  if (session.current === client) store.update({ stopNotice: notice });
}

/** "Limp…": asks first, in place (the robot falls unless someone holds it). */
export function askLimp(ctx: AppContext): void {
  if (!ctx.session.current) return;
  ctx.store.update({ limpAsked: true });
  // Cancel first: Enter right after the question appears must not make the robot fall.
  focusSoon("cancel-limp");
}

export function cancelLimp(ctx: AppContext): void {
  ctx.store.update({ limpAsked: false });
  focusSoon("limp-button");
}

/** Limp, confirmed: every servo passive (`RbcClient.limp`), whatever was running is cancelled first. */
export async function limpAll(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const client = session.current;
  store.update({ limpAsked: false });
  if (!client) return;
  const { locale } = store.get();
  store.update({ stopNotice: noticeOf("warning", locale, [say("connection.limping")]) });
  let notice: Notice;
  try {
    const { confirmed, silent } = await client.limp();
    notice =
      silent.length === 0
        ? noticeOf("warning", locale, [say("connection.limpDone", { count: confirmed.length })])
        : noticeOf("danger", locale, [
            say("connection.limpPartial", { confirmed: confirmed.length, silent: silent.join(", ") }),
          ]);
  } catch (e) {
    notice = (await failureWords()).failureNotice(say("connection.limpFailed"), e, locale);
  }
  if (session.current === client) {
    // The robot is limp and someone is holding it: the next movement asks again.
    store.update((s) => ({ stopNotice: notice, acks: { ...s.acks, movement: false } }));
    if (client.mode === "direct") setConnection(store, { limp: true });
  }
}

/** A servo was moved or the user took servo control: the servos are no longer all limp. */
export function servosTaken(ctx: AppContext): void {
  if (ctx.store.get().connection.limp) setConnection(ctx.store, { limp: false });
}

export function dismissStopNotice(ctx: AppContext): void {
  ctx.store.update({ stopNotice: undefined });
}
