import type { AppState, Notice } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice } from "../../error-text.ts";
import { forgetPort, grantedPorts, webSerial } from "../../serial-ports.ts";
import type { Store } from "../../store.ts";
import type { ConnectionState, RobotLabel } from "./state.ts";

/** Connecting, disconnecting and the list of earlier ports; Stop's outcome banner. */

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

export function connectDemo(ctx: AppContext): void {
  void ctx.session.connectDemo();
}

export function connectKnownPort(ctx: AppContext, port: SerialPort, robot: RobotLabel): void {
  void ctx.session.connectPort(port, robot);
}

export function disconnect(ctx: AppContext): void {
  void ctx.session.disconnect();
}

/** Stop — limp (the top bar's button and Escape): every servo passive, whatever was running is cancelled. */
export async function stopAll(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const client = session.current;
  if (!client) return;
  store.update({ stopNotice: { tone: "warning", text: "Stopping: making every servo limp…" } });
  let notice: Notice;
  try {
    const { confirmed, silent } = await client.stop();
    notice =
      silent.length === 0
        ? {
            tone: "warning",
            text: `Stopped: all ${confirmed.length} servos are limp. Hold the robot, it cannot stand on its own now.`,
          }
        : {
            tone: "danger",
            text: `Stopped, but servo ${silent.join(", ")} did not confirm (${confirmed.length} limp). If anything still moves, switch the robot off.`,
          };
  } catch (e) {
    notice = errorNotice("Stop failed. Switch the robot off.", e);
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
