import type { ActivitySnapshot, ClientState, LogEntry, RbcClient } from "../device/index.ts";
import { inEveryLanguage, said } from "../i18n/said.ts";
import type { LinkFacts, SerialPortLike } from "../link/index.ts";
import { type Clock, realClock } from "../shared/clock.ts";
import type { ServoBus } from "../sim/sim-servos.ts";
import type { SimulatedRbc } from "../sim/simulated-rbc.ts";
import {
  type AppState,
  freshConnectionState,
  noticeOf,
  type RunningLabel,
  runningWords,
} from "./app-state.ts";
import type { AppContext } from "./context.ts";
import type { DemoMemoryStorage } from "./demo-memory.ts";
import type { DemoRobotOptions, KeptDemoRobot } from "./demo-robot.ts";
import {
  busyChanged,
  busyElsewhere,
  type ConnectionState,
  connectingTo,
  mirrored,
  NOTHING_RUNNING,
  probeAfterConnect,
  type RobotLabel,
  refreshKnownPorts,
} from "./features/connection/index.ts";
import type { PacketLog } from "./features/log/index.ts";
import type { ShelfStorage } from "./features/shelf/index.ts";
import { uiMessages } from "./messages.ts";
import { Scope } from "./scope.ts";
import { choosePort, describePort, linkKindOf, webSerial } from "./serial-ports.ts";
import type { Store } from "./store.ts";

/**
 * The words of failures (the device's errors and outcomes, in every language) load when a failure is to be
 * said, not with the first page, which shows none (first load: issue 19).
 */
const failureWords = () => import("./failure-words.ts");

/** The demo robot; the panel names it in its language (`robotName`), `name` is its English name. */
export const DEMO_ROBOT: RobotLabel = { kind: "demo", name: "Demo robot" };
/** The demo robot behind a simulated Bluetooth link (replies 300 ± 150 ms late, in bursts). */
export const DEMO_BLUETOOTH_ROBOT: RobotLabel = {
  kind: "demo",
  name: "Demo robot (Bluetooth)",
  link: "bluetooth",
};

export interface SessionOptions {
  /** How the demo robot is made (browser tests run it faster). */
  demo?: DemoRobotOptions & {
    /** Where the demo robot's memory is kept (unit tests: a Map); default IndexedDB. */
    storage?: DemoMemoryStorage;
  };
  /** Where the robot's shelf is kept (unit tests: a Map, `memoryShelfStorage`); default IndexedDB. */
  shelfStorage?: () => Promise<ShelfStorage>;
}

/** A simulated robot in this page (the demo robot): its simulator and the clock it runs on. */
interface Simulated {
  sim: SimulatedRbc;
  clock: Clock;
}

/**
 * The connection to one robot (hardware or the demo) and everything that runs on it. It owns the RbcClient,
 * mirrors its state into the store, feeds the packet log, and tracks running operations so that a lost link
 * can say which of them did not finish. It owns the scopes of the features' controllers: `pageScope` for the
 * page's life, and `connectionScope`, a new one for every connection, ended (its controllers disposed) when
 * the connection ends.
 */
export class Session {
  private client: RbcClient | undefined;
  private simulated: Simulated | undefined;
  private detachClient: Array<() => void> = [];
  private readonly context: AppContext;
  readonly pageScope: Scope<AppContext>;
  private scope: Scope<AppContext>;

  constructor(
    private readonly store: Store<AppState>,
    /** The log to feed; without one, the session makes one with its first connection (`packetLog`). */
    packetLog: PacketLog | undefined,
    readonly options: SessionOptions = {},
  ) {
    this.context = { store, session: this, packetLog };
    this.pageScope = new Scope(this.context, "page");
    this.scope = new Scope(this.context, "connection");
  }

  /** The packet log: the one given, or the one made with the first connection; none before. */
  get packetLog(): PacketLog | undefined {
    return this.context.packetLog;
  }

  /** The connected client, or undefined. */
  get current(): RbcClient | undefined {
    return this.store.get().connection.phase === "connected" ? this.client : undefined;
  }

  /** The controllers of this connection (an empty scope while none is connected). */
  get connectionScope(): Scope<AppContext> {
    return this.scope;
  }

  /**
   * The robot's time: real time, or the clock of the simulated robot of this connection. Durations the robot
   * reports (the motion and sound of `connection.activity`) and progress shown against them are in this time.
   */
  get clock(): Clock {
    return this.client?.clock ?? realClock;
  }

  /** Wall-clock ms (epoch) of a time of the robot's clock (packet log lines, sensor events). */
  epochOf(clockMs: number): number {
    return performance.timeOrigin + performance.now() - (this.clock.now() - clockMs);
  }

  /** The demo robot's simulator while the demo robot is the connected robot. */
  get demoSim(): SimulatedRbc | undefined {
    return this.current ? this.simulated?.sim : undefined;
  }

  /** Bumped by every chooser opened and by `cancelChoosing()`: a chooser's answer counts only while current. */
  private chooser = 0;
  /**
   * The demo robot's servos, kept for the page: an id set survives a reconnect (docs/protocol.md §5). The Servo
   * check replaces them with servos carrying a fault and connects the demo robot again (a restart).
   */
  demoServos: ServoBus | undefined;
  /** The demo robot of the last connection: the next one starts with its memory (issue 23 item 2). */
  demoRobot: KeptDemoRobot | undefined;

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
    const chooser = ++this.chooser;
    this.setConnection({ phase: "choosing", problem: undefined, lostReason: undefined, showHelp: false });
    request.then(
      (port) => {
        // Abandoned with Cancel: the port the chooser gave late is not opened (it only joins the known ports).
        if (chooser !== this.chooser) {
          void refreshKnownPorts(this.store);
          return;
        }
        const info = port.getInfo();
        void this.connectPort(port, {
          kind: "hardware",
          name: describePort(info),
          link: linkKindOf(info),
          info,
        });
      },
      async (e: unknown) => {
        if (chooser !== this.chooser) return;
        const { chooserProblem } = await failureWords();
        if (chooser !== this.chooser) return;
        const { notice, showHelp } = chooserProblem(e, this.store.get().locale);
        this.setConnection({ phase: "disconnected", problem: notice, showHelp });
      },
    );
  }

  /**
   * Gives up waiting for the browser's port chooser. The chooser is the browser's own, but its promise may
   * never settle (it can hang): the page must offer a way back. A port it gives later is not opened.
   */
  cancelChoosing(): void {
    if (this.store.get().connection.phase !== "choosing") return;
    this.chooser++;
    this.setConnection({
      phase: "disconnected",
      problem: noticeOf("info", this.store.get().locale, [said(uiMessages, "session.stoppedWaiting")]),
    });
  }

  /**
   * Connects the same UI to a simulated RBC behind a mock serial port (loaded on demand); with `bluetooth`,
   * behind a simulated Bluetooth link.
   */
  async connectDemo(options: { bluetooth?: boolean } = {}): Promise<boolean> {
    const robot = options.bluetooth ? DEMO_BLUETOOTH_ROBOT : DEMO_ROBOT;
    this.setConnection({ phase: "connecting", robot, problem: undefined, lostReason: undefined });
    try {
      const { openDemoRobot } = await import("./demo-robot.ts");
      const demo = await openDemoRobot({
        ...this.options.demo,
        bluetooth: options.bluetooth,
        servoBus: this.demoServos,
        previous: this.demoRobot,
      });
      this.demoServos = demo.servoBus;
      this.demoRobot = demo;
      return await this.connectPort(demo.port, robot, demo);
    } catch (e) {
      const { failureNotice } = await failureWords();
      this.setConnection({
        phase: "disconnected",
        problem: failureNotice(said(uiMessages, "session.demoFailed"), e, this.store.get().locale),
      });
      return false;
    }
  }

  async connectPort(port: SerialPortLike, robot: RobotLabel, simulated?: Simulated): Promise<boolean> {
    const { locale } = this.store.get();
    await this.release();
    this.setConnection({ phase: "connecting", robot, problem: undefined, lostReason: undefined });
    let client: RbcClient;
    let duringFirmwareUpdate: (entry: LogEntry) => LogEntry;
    try {
      // The device and protocol code (and zod, through the .rbm validator) load with the first connection,
      // not with the first page. So do the bootloader's byte names for the log: they bring the bootloader
      // protocol and the firmware outcome words, which the first screen never shows (first load: issue 19).
      // The packet log's code, too, comes with the first connection: before it there is nothing to log.
      const [{ createRbcClient }, bootloaderBytes, { LOG_CAPACITY, PacketLog }] = await Promise.all([
        import("./robot-link.ts"),
        import("./features/log/bootloader-bytes.ts"),
        import("./features/log/packet-log.ts"),
      ]);
      duringFirmwareUpdate = bootloaderBytes.duringFirmwareUpdate;
      this.context.packetLog ??= new PacketLog(LOG_CAPACITY, (clockMs) => this.epochOf(clockMs));
      client = createRbcClient(port, simulated?.clock);
    } catch (e) {
      // If the code could not be loaded, the words of the failure may not load either: say it plainly then.
      const problem = await failureWords().then(
        ({ failureNotice }) => failureNotice(said(uiMessages, "session.codeNotLoaded"), e, locale),
        () => noticeOf("danger", locale, [said(uiMessages, "session.codeNotLoaded")]),
      );
      this.setConnection({ phase: "disconnected", problem });
      return false;
    }
    this.client = client;
    this.simulated = simulated;
    this.renewScope();
    this.store.update({ connection: connectingTo(robot), ...freshConnectionState() });
    const packetLog = this.context.packetLog;
    this.detachClient = [
      client.stateChanges.on((s) => this.onClientState(client, s)),
      client.activityChanges.on((a) => this.onActivity(client, a)),
      client.log.on((entry) => {
        // The bootloader's flow control and status bytes are the update's normal dialogue, not stray bytes.
        packetLog.push(this.updatingFirmware() ? duringFirmwareUpdate(entry) : entry);
        this.store.update((s) => ({ log: { ...s.log, revision: packetLog.revision } }));
      }),
    ];
    try {
      // The serial number is optional (docs/protocol.md §3.5): a firmware that does not answer 0x0C still connects.
      const identity = await client.identify(await client.connect());
      const serialNumber = identity.serialNumber;
      if (this.client !== client) {
        await client.close().catch(() => {});
        return false;
      }
      this.setConnection({
        phase: "connected",
        firmware: identity.firmware,
        platform: client.state.platform ?? identity.platform,
        serialNumber,
        identityWarnings: identity.warnings,
        mode: client.mode,
        ...mirrored(client.state),
        activity: client.activity,
      });
      void refreshKnownPorts(this.store);
      // Busy, not gone (docs/protocol.md §3.6): a motion started with the remote may be playing.
      probeAfterConnect(this.context);
      return true;
    } catch (e) {
      // If the link was lost meanwhile, onLost has already shown why.
      if (this.client === client) {
        this.forgetClient();
        await client.close().catch(() => {});
        const { failureNotice, outcomeCode } = await failureWords();
        const notice = failureNotice(said(uiMessages, "error.couldNotConnect"), e, locale);
        const code = outcomeCode(e);
        this.setConnection({ phase: "disconnected", problem: code ? { ...notice, code } : notice });
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
          ? noticeOf("warning", this.store.get().locale, [
              said(uiMessages, "session.disconnectedWhileRunning", {
                list: inEveryLanguage((l) => runningWords(interrupted, l).join(", ")),
              }),
            ])
          : undefined,
      lostReason: undefined,
      interrupted,
      ...NOTHING_RUNNING,
    });
    this.store.update({ running: [], stopNotice: undefined });
    await client.close().catch(() => {});
    void refreshKnownPorts(this.store);
  }

  /**
   * Runs an operation on the connected robot, listed in `running` while it lasts. By default it first leaves
   * direct mode (after Limp or servo control the client is on the servo bus; limp servos stay limp).
   */
  async run<T>(
    label: RunningLabel,
    fn: (client: RbcClient) => Promise<T>,
    options: { packetMode?: boolean } = {},
  ): Promise<T> {
    const client = this.current;
    if (!client) throw new (await import("../device/errors.ts")).RbcNotConnectedError();
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

  private onClientState(client: RbcClient, state: ClientState): void {
    if (client !== this.client) return;
    const phase = this.store.get().connection.phase;
    if (state.mode === "disconnected") {
      // A reason means the link was lost; without one, close() was called and the caller says what happened.
      if (state.reason) this.onLost(state.reason, state.lostCause);
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
        current.subscription !== next.subscription
      ) {
        this.setConnection({ mode: state.mode, platform: state.platform ?? current.platform, ...next });
      }
    }
  }

  /**
   * The device's activity machine changed: the store keeps its snapshot as the one copy of what the robot is
   * doing (views read it through features/connection/activity.ts). A motion started elsewhere, found or ended,
   * is said beside the top bar's Stop (`busyChanged`).
   */
  private onActivity(client: RbcClient, activity: ActivitySnapshot): void {
    if (client !== this.client || this.store.get().connection.phase !== "connected") return;
    const wasBusy = busyElsewhere(this.store.get().connection) !== undefined;
    this.setConnection({ activity });
    const busy = activity.doing.kind === "busy";
    if (busy !== wasBusy) void busyChanged(this.context, busy);
  }

  private onLost(reason: string, cause: LinkFacts | undefined): void {
    const state = this.store.get();
    const interrupted = [...state.running];
    this.forgetClient();
    this.setConnection({
      phase: "disconnected",
      mode: undefined,
      lostReason: reason,
      lostCause: cause,
      interrupted,
      ...NOTHING_RUNNING,
    });
    this.store.update((s) => ({
      running: [],
      stopNotice: undefined,
      device: { ...s.device, loading: false },
      zeros: { ...s.zeros, busy: undefined, confirming: false },
    }));
    void refreshKnownPorts(this.store);
  }

  /** The connection's controllers end with it: timers stop, an upload is cancelled, moves are dropped. */
  private renewScope(): void {
    this.scope.dispose();
    this.scope = new Scope(this.context, "connection");
  }

  private forgetClient(): void {
    for (const detach of this.detachClient) detach();
    this.detachClient = [];
    this.client = undefined;
    this.simulated = undefined;
    this.renewScope();
  }

  private async release(): Promise<void> {
    const previous = this.client;
    if (!previous) return;
    this.forgetClient();
    await previous.close().catch(() => {});
  }

  /** A firmware update runs on this connection (from the robot's bootloader entry to the new version read). */
  private updatingFirmware(): boolean {
    const run = this.store.get().firmware?.run;
    return run !== undefined && run.step !== "confirming" && !run.recovery;
  }

  private setConnection(patch: Partial<ConnectionState>): void {
    this.store.update((s) => ({ connection: { ...s.connection, ...patch } }));
  }
}
