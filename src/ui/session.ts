import { RbcNotConnectedError } from "../device/errors.ts";
import type { ClientState, RbcClient } from "../device/index.ts";
import type { SerialPortLike } from "../link/index.ts";
import type { AppState, ConnectionState, Notice, RobotLabel } from "./app-state.ts";
import { chooserProblem, connectProblem, errorNotice } from "./error-text.ts";
import type { PacketLog } from "./packet-log.ts";
import { choosePort, describePort, forgetPort, grantedPorts, webSerial } from "./serial-ports.ts";
import type { Store } from "./store.ts";

export const DEMO_ROBOT: RobotLabel = { kind: "demo", name: "Demo robot" };

/** The client state the views show (the 7-first rule, what is playing, the subscription). */
function mirrored(state: ClientState): Partial<ConnectionState> {
  return {
    basicPostureConfirmed: state.basicPostureConfirmed,
    playing: state.playing,
    sounding: state.sounding,
    subscription: state.subscription,
  };
}

const NOTHING_RUNNING: Partial<ConnectionState> = {
  limp: undefined,
  playing: undefined,
  sounding: undefined,
  subscription: undefined,
};

/**
 * The connection to one robot (hardware or the demo) and everything that runs on it. It owns the RbcClient,
 * mirrors its state into the store, feeds the packet log, and tracks running operations so that a lost link
 * can say which of them did not finish.
 */
export class Session {
  private client: RbcClient | undefined;
  private detachClient: Array<() => void> = [];

  constructor(
    private readonly store: Store<AppState>,
    private readonly packetLog: PacketLog,
  ) {}

  /** The connected client, or undefined. */
  get current(): RbcClient | undefined {
    return this.store.get().connection.phase === "connected" ? this.client : undefined;
  }

  /** Opens the chooser and connects to the chosen port. Call it straight from the click handler. */
  chooseAndConnect(): void {
    const serial = webSerial();
    if (!serial) return;
    let request: Promise<SerialPort>;
    try {
      request = choosePort(serial, this.store.get().showAllPorts);
    } catch (e) {
      request = Promise.reject(e);
    }
    this.setConnection({ phase: "choosing", problem: undefined, lostReason: undefined, showHelp: false });
    request.then(
      (port) => this.connectPort(port, { kind: "hardware", name: describePort(port.getInfo()) }),
      (e: unknown) => {
        const { notice, showHelp } = chooserProblem(e);
        this.setConnection({ phase: "disconnected", problem: notice, showHelp });
      },
    );
  }

  /** Connects the same UI to a simulated RBC behind a mock serial port (loaded on demand). */
  async connectDemo(): Promise<boolean> {
    this.setConnection({ phase: "connecting", robot: DEMO_ROBOT, problem: undefined, lostReason: undefined });
    try {
      const { createDemoPort } = await import("./demo-robot.ts");
      return await this.connectPort(createDemoPort(), DEMO_ROBOT);
    } catch (e) {
      this.setConnection({
        phase: "disconnected",
        problem: errorNotice("The demo robot could not start.", e),
      });
      return false;
    }
  }

  async connectPort(port: SerialPortLike, robot: RobotLabel): Promise<boolean> {
    await this.release();
    this.setConnection({ phase: "connecting", robot, problem: undefined, lostReason: undefined });
    let client: RbcClient;
    try {
      // The device and protocol code (and zod, through the .rbm validator) load with the first connection,
      // not with the first page.
      const { createRbcClient } = await import("./robot-link.ts");
      client = createRbcClient(port);
    } catch (e) {
      this.setConnection({
        phase: "disconnected",
        problem: errorNotice("The panel's connection code did not load.", e),
      });
      return false;
    }
    this.client = client;
    this.setConnection({
      phase: "connecting",
      robot,
      mode: undefined,
      limp: undefined,
      basicPostureConfirmed: undefined,
      playing: undefined,
      sounding: undefined,
      subscription: undefined,
      firmware: undefined,
      serialNumber: undefined,
      platform: undefined,
      lostReason: undefined,
      interrupted: [],
      problem: undefined,
      showHelp: false,
    });
    this.store.update({
      device: { loading: false },
      zeros: { draft: [], confirming: false },
      stopNotice: undefined,
      running: [],
      motions: undefined,
      sensors: undefined,
      servos: undefined,
      acks: undefined,
    });
    this.detachClient = [
      client.stateChanges.on((s) => this.onClientState(client, s)),
      client.log.on((entry) => {
        this.packetLog.push(entry);
        this.store.update((s) => ({ log: { ...s.log, revision: this.packetLog.revision } }));
      }),
    ];
    try {
      const identity = await client.connect();
      const serialNumber = this.client === client ? await client.readSerialNumber() : "";
      if (this.client !== client) {
        await client.close().catch(() => {});
        return false;
      }
      this.setConnection({
        phase: "connected",
        firmware: identity.firmware,
        platform: client.state.platform ?? identity.platform,
        serialNumber,
        mode: client.mode,
        ...mirrored(client.state),
      });
      void this.refreshKnownPorts();
      return true;
    } catch (e) {
      // If the link was lost meanwhile, onLost has already shown why.
      if (this.client === client) {
        this.forgetClient();
        await client.close().catch(() => {});
        this.setConnection({ phase: "disconnected", problem: connectProblem(e) });
      }
      return false;
    }
  }

  /** Closes the link on the user's request (or when the page goes away). */
  async disconnect(): Promise<void> {
    const client = this.client;
    if (!client) return;
    const interrupted = [...this.store.get().running];
    this.forgetClient();
    this.setConnection({
      phase: "disconnected",
      mode: undefined,
      problem:
        interrupted.length > 0
          ? {
              tone: "warning",
              text: `Disconnected while this was running: ${interrupted.join(", ")}. It did not finish; check the result after reconnecting.`,
            }
          : undefined,
      lostReason: undefined,
      interrupted,
      ...NOTHING_RUNNING,
    });
    this.store.update({ running: [], stopNotice: undefined });
    await client.close().catch(() => {});
    void this.refreshKnownPorts();
  }

  /**
   * Runs an operation on the connected robot, listed in `running` while it lasts. By default it first leaves
   * direct mode (after Stop the client is on the servo bus; the servos stay limp).
   */
  async run<T>(
    label: string,
    fn: (client: RbcClient) => Promise<T>,
    options: { packetMode?: boolean } = {},
  ): Promise<T> {
    const client = this.current;
    if (!client) throw new RbcNotConnectedError();
    this.store.update((s) => ({ running: [...s.running, label] }));
    try {
      if ((options.packetMode ?? true) && client.mode === "direct") await client.exitDirectMode();
      return await fn(client);
    } finally {
      this.store.update((s) => {
        const i = s.running.indexOf(label);
        return { running: i < 0 ? s.running : [...s.running.slice(0, i), ...s.running.slice(i + 1)] };
      });
    }
  }

  /** Stop — limp: every servo passive, whatever was running is cancelled. */
  async stop(): Promise<void> {
    const client = this.current;
    if (!client) return;
    this.store.update({ stopNotice: { tone: "warning", text: "Stopping: making every servo limp…" } });
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
    if (this.client === client) {
      // The robot is limp and someone is holding it: the next movement asks again.
      this.store.update((s) => ({ stopNotice: notice, acks: { ...s.acks, movement: false } }));
      if (client.mode === "direct") this.setConnection({ limp: true });
    }
  }

  /** Tells the panel that a servo was moved or the user took servo control: the servos are no longer all limp. */
  servosTaken(): void {
    if (this.store.get().connection.limp) this.setConnection({ limp: false });
  }

  async refreshKnownPorts(): Promise<void> {
    const serial = webSerial();
    if (!serial) return;
    try {
      this.store.update({ knownPorts: await grantedPorts(serial) });
    } catch {
      this.store.update({ knownPorts: [] });
    }
  }

  async forget(port: SerialPort): Promise<void> {
    try {
      if (!(await forgetPort(port))) {
        this.setConnection({
          problem: {
            tone: "warning",
            text: "This browser cannot forget ports. Remove the permission in the site settings instead.",
          },
        });
      }
    } catch (e) {
      this.setConnection({ problem: errorNotice("The port could not be forgotten.", e) });
    }
    await this.refreshKnownPorts();
  }

  private onClientState(client: RbcClient, state: ClientState): void {
    if (client !== this.client) return;
    const phase = this.store.get().connection.phase;
    if (state.mode === "disconnected") {
      // A reason means the link was lost; without one, close() was called and the caller says what happened.
      if (state.reason) this.onLost(state.reason);
      return;
    }
    if (phase === "connecting" && state.mode === "packet") this.setConnection({ phase: "handshaking" });
    if (phase === "connected") {
      const current = this.store.get().connection;
      const next = mirrored(state);
      if (
        current.mode !== state.mode ||
        (state.platform !== undefined && current.platform !== state.platform) ||
        current.basicPostureConfirmed !== next.basicPostureConfirmed ||
        current.playing !== next.playing ||
        current.sounding !== next.sounding ||
        current.subscription !== next.subscription
      ) {
        this.setConnection({
          mode: state.mode,
          platform: state.platform ?? current.platform,
          ...next,
          // Leaving direct mode (or a download) ends the "all limp" state the top bar reports.
          limp: state.mode === "direct" ? current.limp : false,
        });
      }
    }
  }

  private onLost(reason: string): void {
    const state = this.store.get();
    const interrupted = [...state.running];
    this.forgetClient();
    this.setConnection({
      phase: "disconnected",
      mode: undefined,
      lostReason: reason,
      interrupted,
      ...NOTHING_RUNNING,
    });
    this.store.update((s) => ({
      running: [],
      stopNotice: undefined,
      device: { ...s.device, loading: false },
      zeros: { ...s.zeros, busy: undefined, confirming: false },
    }));
    void this.refreshKnownPorts();
  }

  private forgetClient(): void {
    for (const detach of this.detachClient) detach();
    this.detachClient = [];
    this.client = undefined;
  }

  private async release(): Promise<void> {
    const previous = this.client;
    if (!previous) return;
    this.forgetClient();
    await previous.close().catch(() => {});
  }

  private setConnection(patch: Partial<ConnectionState>): void {
    this.store.update((s) => ({ connection: { ...s.connection, ...patch } }));
  }
}
