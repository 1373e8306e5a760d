import type { StopActivityResult } from "../../../device/rbc-client.ts";
import { frameLabel } from "../../../device/tethered-play-types.ts";
import type { AppState, Notice } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice } from "../../error-text.ts";
import { focusSoon } from "../../focus.ts";
import { forgetPort, grantedPorts, webSerial } from "../../serial-ports.ts";
import type { Store } from "../../store.ts";
import type { ConnectionState, RobotLabel } from "./state.ts";

/** Connecting, disconnecting and the list of earlier ports; Stop, Limp and their outcome banner. */

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
  try {
    if (!(await forgetPort(port))) {
      setConnection(ctx.store, {
        problem: {
          tone: "warning",
          text: "This browser cannot forget ports. Remove the permission in the site settings instead.",
        },
      });
    }
  } catch (e) {
    setConnection(ctx.store, { problem: errorNotice("The port could not be forgotten.", e) });
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
function secondsLeft(ms: number): string {
  return `${Math.max(1, Math.ceil(ms / 1000))} s`;
}

/** What Stop is waiting for, said before it is done (the robot's state mirrored in the store). */
function stoppingText(state: AppState, now: number): string {
  const c = state.connection;
  if (c.sounding) {
    const left = c.sounding.startedAt + c.sounding.expectedMs - now;
    return `Stopping: a sound is playing and the robot takes nothing until it ends; the sound ends in about ${secondsLeft(left)}.`;
  }
  if (c.playing) return `Stopping: motion ${c.playing.motion} ends at the end of its current scene…`;
  if (c.mode === "download") return "Stopping: cancelling the upload…";
  return "Stopping…";
}

/**
 * What Stop did, as plain sentences, never more certain than the robot confirmed. `limp` says whether every
 * servo had been made limp before (Stop does not change that).
 */
export function stopOutcome(result: StopActivityResult, limp: boolean): Notice {
  const parts: string[] = [];
  let unsure = false;
  if (result.uploadCancelled) {
    parts.push("The upload was cancelled; its result says what the robot's memory holds now.");
  }
  if (result.sound) {
    const { number, confirmed } = result.sound;
    if (confirmed)
      parts.push(`Sound ${number} was waited out (the robot takes nothing while a sound plays).`);
    else {
      unsure = true;
      parts.push(`Sound ${number} was waited out, but the robot did not report its end.`);
    }
  }
  if (result.motion) {
    const { number, outcome } = result.motion;
    switch (outcome) {
      case "stopped":
        parts.push(
          `Motion ${number} stopped at the end of its scene (the robot confirmed with 07). The robot keeps standing in the pose it stopped in; Basic posture (7) straightens it.`,
        );
        break;
      case "ended-then-posture":
        parts.push(
          `Motion ${number} had just ended by itself, so the robot took Stop's 7 as Basic posture and confirmed it (07).`,
        );
        break;
      case "posture":
        parts.push("Basic posture (7) cannot be interrupted; it finished (the robot confirmed with 07).");
        break;
      case "unconfirmed":
        unsure = true;
        parts.push(
          `Stop sent 7 to end motion ${number}; the robot did not confirm. If it still moves, hold it (Limp makes every servo passive).`,
        );
        break;
    }
  }
  if (result.tetheredPlay) {
    const { framesSent, totalFrames, lastFrame } = result.tetheredPlay;
    parts.push(
      lastFrame
        ? `Tethered play stopped after ${frameLabel(lastFrame)} (${framesSent} of ${totalFrames} frames sent); the servos hold that frame.`
        : `Tethered play stopped before its first frame; nothing moved.`,
    );
  } else if (result.servoMovesDropped) {
    parts.push(
      limp
        ? "Servo moves stopped. The servos stay limp (Limp); moving a slider makes that servo hold again."
        : "Servo moves stopped: no further move is sent, and the servos hold their last position.",
    );
  }
  if (parts.length === 0) parts.push("Nothing was running; the robot keeps its pose.");
  return { tone: unsure ? "warning" : "ok", text: parts.join(" ") };
}

/**
 * Stop (the top bar's red button, and Escape when nothing else takes it): ends what the robot is doing and
 * keeps it standing (`RbcClient.stopActivity`). It never makes a servo passive: that is Limp.
 */
export async function stopActivity(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const client = session.current;
  if (!client) return;
  store.update((s) => ({
    stopNotice: { tone: "info", text: stoppingText(s, session.clock.now()) },
    limpAsked: false,
  }));
  let notice: Notice;
  try {
    notice = stopOutcome(await client.stopActivity(), store.get().connection.limp === true);
  } catch (e) {
    notice = errorNotice("Stop failed. If the robot still moves, hold it and press Limp.", e);
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
  store.update({ stopNotice: { tone: "warning", text: "Limp: making every servo passive…" } });
  let notice: Notice;
  try {
    const { confirmed, silent } = await client.limp();
    notice =
      silent.length === 0
        ? {
            tone: "warning",
            text: `Limp: all ${confirmed.length} servos confirmed passive. Hold the robot, it cannot stand on its own now.`,
          }
        : {
            tone: "danger",
            text: `Limp: ${confirmed.length} servos confirmed passive, but servo ${silent.join(", ")} did not answer. If anything still moves, switch the robot off.`,
          };
  } catch (e) {
    notice = errorNotice("Limp failed. Hold the robot and switch it off.", e);
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
