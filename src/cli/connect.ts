import { RbcInBootloaderError } from "../device/bootloader-prompt.ts";
import { RbcPortError } from "../device/errors.ts";
import { RbcClient } from "../device/rbc-client.ts";
import type { LinkKind } from "../device/round-trip.ts";
import type { DeviceIdentity } from "../device/types.ts";
import type { Locale } from "../i18n/locale.ts";
import { inBootloaderText } from "../i18n/outcomes/device.ts";
import { said, saidBy, saidTogether } from "../i18n/said.ts";
import { translator } from "../i18n/translate.ts";
import { LinkError, type Transport } from "../link/transport.ts";
import { WebSerialTransport } from "../link/web-serial-transport.ts";
import { type Clock, realClock } from "../shared/clock.ts";
import { createDemoRbc } from "../sim/demo-world.ts";
import { MockSerialPort } from "../sim/mock-serial-port.ts";
import { BootloaderRbc } from "../sim/sim-bootloader.ts";
import type { GlobalValues } from "./args.ts";
import { localeOf, type RunEnv } from "./command.ts";
import { demoClock } from "./demo-clock.ts";
import { CliError, UsageError } from "./errors.ts";
import { cliMessages } from "./messages.ts";
import { formatLogEntry, logEntryJson } from "./packet-trace.ts";
import { portOpenSaid } from "./port-errors.ts";
import { demoVariant, rbcOptionsOf, type SimVariant } from "./sim-variant.ts";

/** A connected robot: the real one on a serial port, or the demo robot. */
export interface Robot {
  client: RbcClient;
  /**
   * The robot's time: the real clock, or for the demo robot the clock it shares with the client (faster under
   * RBC_DEMO_TIME_SCALE). Durations rbc reports are read off it, so they are the robot's time.
   */
  clock: Clock;
  identity: DeviceIdentity;
  /** True for `--demo` (the built-in simulated RBC). */
  demo: boolean;
  /** "the demo robot" or the port path, for English messages (`robotPlace` says it in a language). */
  where: string;
  /**
   * The demo robot's bootloader (docs/protocol.md §11), which sits in front of its simulated RBC: `rbc flash --demo`
   * switches the demo robot off and on with its `powerCycle()`, as a person would switch a real one.
   */
  bootloader?: BootloaderRbc;
  close(): Promise<void>;
}

/** A port opened without a handshake (`rbc flash --recover`: a robot whose firmware does not answer). */
export interface OpenedPort {
  transport: Transport;
  clock: Clock;
  demo: boolean;
  where: string;
  bootloader?: BootloaderRbc;
  close(): Promise<void>;
}

export interface ConnectOptions {
  /**
   * The command reacts to Ctrl-C itself once connected (an upload must end its download cleanly). Otherwise
   * Ctrl-C closes the connection, which ends whatever request is waiting.
   */
  handlesInterrupt?: boolean;
}

/** `Robot.where` of the demo robot. */
const DEMO_WHERE = translator(cliMessages, "en")("cli.connect.demoRobot");

/** The robot in a sentence of `locale`: "the demo robot" / "데모 로봇", or its port. */
export function robotPlace(robot: { demo: boolean; where: string }, locale: Locale): string {
  return robot.demo ? translator(cliMessages, locale)("cli.connect.demoRobot") : robot.where;
}

/** Which robot the options name: `--demo`, `--port PATH`, or the RBC_PORT environment variable. */
export function robotTarget(command: string, values: GlobalValues, env: NodeJS.ProcessEnv) {
  if (values.demo && values.port !== undefined) {
    throw new UsageError(said(cliMessages, "cli.connect.portOrDemo"), command);
  }
  if (values.demo) return { demo: true as const };
  const port = values.port ?? env.RBC_PORT;
  if (port === undefined || port === "") {
    throw new UsageError(said(cliMessages, "cli.connect.whichRobot"), command);
  }
  return { demo: false as const, port };
}

/** For tests and developers: the demo robot's time runs this many times faster than real time. */
export const DEMO_TIME_SCALE_VAR = "RBC_DEMO_TIME_SCALE";

/**
 * RBC_DEMO_TIME_SCALE: how many times faster than real time the demo robot runs (default 1). The simulator
 * and the client share that one clock (`demoClock`), so every duration and timeout keeps its proportions and
 * the reported durations are the robot's time: `run 7` still reports about 1.8 s, after 0.18 real s at 10.
 */
export function demoTimeScale(env: NodeJS.ProcessEnv, command?: string): number {
  const text = env[DEMO_TIME_SCALE_VAR]?.trim();
  if (text === undefined || text === "") return 1;
  const scale = Number(text);
  if (!Number.isFinite(scale) || scale <= 0 || scale > 1000) {
    throw new UsageError(
      said(cliMessages, "cli.connect.timeScale", { variable: DEMO_TIME_SCALE_VAR, value: text }),
      command,
    );
  }
  return scale;
}

/**
 * The demo robot: a SimulatedRbc in the demo world the panel's demo robot lives in (firmware 2.23, HUNO, just
 * switched on, standing upright: its accelerometer reads with a little noise), or the firmware variant of
 * RBC_DEMO_VARIANT, with its bootloader in front (so that `rbc flash --demo` works), behind a MockSerialPort
 * with 2 ms of adapter latency and a WebSerialTransport — the same stack as the panel's "demo robot" — all on
 * `clock`.
 */
function demoTransport(
  clock: Clock,
  variant: SimVariant,
): { transport: Transport; dispose: () => void; bootloader: BootloaderRbc } {
  const sim = createDemoRbc({ clock, ...rbcOptionsOf(variant) });
  const bootloader = new BootloaderRbc(sim, { faults: { waiting: variant.inBootloader } });
  const port = new MockSerialPort(bootloader, { latencyMs: 2, clock, record: false });
  return {
    transport: new WebSerialTransport(port, { clock }),
    dispose: () => bootloader.dispose(),
    bootloader,
  };
}

/** The transport to the named robot (not opened yet): the demo robot, or a serial port. */
async function robotTransport(
  target: ReturnType<typeof robotTarget>,
  command: string,
  env: RunEnv,
): Promise<{ transport: Transport; dispose: () => void; clock: Clock; bootloader?: BootloaderRbc }> {
  if (target.demo) {
    const clock = env.demoClock ?? demoClock(demoTimeScale(env.env, command));
    return { clock, ...demoTransport(clock, demoVariant(env.env, command)) };
  }
  // Loaded here only: the native serialport binding is not needed for --demo (and never in the web app).
  const { NodeSerialTransport } = await import("../link/node-serial-transport.ts");
  return { transport: new NodeSerialTransport(target.port), dispose: () => {}, clock: realClock };
}

/**
 * Opens the named robot's port and nothing more: no handshake, so it works with a robot whose firmware does
 * not answer (`rbc flash --recover`). The port is closed by `close()` or when rbc exits.
 */
export async function openRobotPort(command: string, values: GlobalValues, env: RunEnv): Promise<OpenedPort> {
  const target = robotTarget(command, values, env.env);
  const { transport, dispose, clock, bootloader } = await robotTransport(target, command, env);
  let closed: Promise<void> | undefined;
  const close = () => {
    closed ??= transport.close().finally(dispose);
    return closed;
  };
  env.onCleanup(close);
  try {
    await transport.open();
  } catch (e) {
    await close().catch(() => {});
    if (!target.demo && e instanceof LinkError) {
      const error = RbcPortError.fromLink(e);
      throw new CliError(error.code, portOpenSaid(target.port, error, error.code));
    }
    throw e;
  }
  return {
    transport,
    clock,
    demo: target.demo,
    where: target.demo ? DEMO_WHERE : target.port,
    bootloader,
    close,
  };
}

/**
 * What a port's path says about its link: a Bluetooth serial port (Linux `/dev/rfcomm0`, macOS
 * `/dev/tty.RBC-Bluetooth-SerialPort` and the like) starts with generous timeouts until its round trip is
 * measured (src/device/round-trip.ts); anything else is taken as a wired adapter, as before.
 */
export function linkKindOfPath(path: string): LinkKind {
  return /rfcomm|bluetooth|[-_.]spp\b/i.test(path) ? "bluetooth" : "wired";
}

/** The port could not be opened at all (not lost later): the link's "open-failed" or "port-busy". */
function isOpenFailure(e: RbcPortError): boolean {
  const cause = e.cause;
  return cause instanceof LinkError && (cause.code === "open-failed" || cause.code === "port-busy");
}

/** Opens the named robot, handshakes (RbcClient.connect) and registers its closing with `env`. */
export async function connectRobot(
  command: string,
  values: GlobalValues,
  env: RunEnv,
  options: ConnectOptions = {},
): Promise<Robot> {
  const target = robotTarget(command, values, env.env);
  const { transport, dispose, clock, bootloader } = await robotTransport(target, command, env);
  const client = new RbcClient(transport, {
    clock,
    link: target.demo ? "wired" : linkKindOfPath(target.port),
  });
  if (values.log) {
    const t0 = client.clock.now();
    client.log.on((entry) =>
      env.out.err(`${values.json ? JSON.stringify(logEntryJson(entry, t0)) : formatLogEntry(entry, t0)}\n`),
    );
  }
  let closed: Promise<void> | undefined;
  const close = () => {
    closed ??= client.close().finally(() => {
      dispose();
      const unasked = client.stats.unansweredReplies;
      // Said once, at the end: a firmware that repeats a reply (docs/protocol.md §3.5) is worth knowing about.
      if (unasked > 0) {
        env.out.note(
          `rbc: ${translator(cliMessages, localeOf(env))("cli.connect.unasked", { count: unasked })}`,
        );
      }
    });
    return closed;
  };
  env.onCleanup(close);
  const onAbort = () => void close();
  env.signal.addEventListener("abort", onAbort, { once: true });
  try {
    const identity = await client.connect();
    if (options.handlesInterrupt) env.signal.removeEventListener("abort", onAbort);
    return {
      client,
      clock,
      identity,
      demo: target.demo,
      where: target.demo ? DEMO_WHERE : target.port,
      bootloader,
      close,
    };
  } catch (e) {
    env.signal.removeEventListener("abort", onAbort);
    await close();
    if (e instanceof RbcInBootloaderError) {
      // Not the cable: the robot answers in its bootloader only, and the firmware update recovers it.
      const robot = target.demo ? "--demo" : `--port ${target.port}`;
      throw new CliError(
        e.code,
        saidTogether([
          saidBy((l) => inBootloaderText(e.facts.prompts, l)),
          said(cliMessages, "cli.connect.recoverWith", { robot }),
        ]),
        undefined,
        { prompts: e.facts.prompts, overMs: Math.round(e.facts.overMs) },
      );
    }
    if (!target.demo && e instanceof RbcPortError && isOpenFailure(e)) {
      throw new CliError(e.code, portOpenSaid(target.port, e, e.code));
    }
    throw e;
  }
}
