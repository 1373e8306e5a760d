import { said } from "../../i18n/said.ts";
import { translator } from "../../i18n/translate.ts";
import { intOption, noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { EXIT, UsageError } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { Output } from "../output.ts";
import { createPtyPair } from "../pty.ts";
import { FAULT_KINDS, isFaultKind } from "../sim-faults.ts";
import { aboutRobot, describeVariant, VARIANT_OPTIONS, variantFromValues } from "../sim-variant.ts";
import { commandMessages } from "./messages.ts";

const OPTIONS = {
  pty: { type: "boolean" },
  "latency-ms": { type: "string" },
  "baud-pacing": { type: "boolean" },
  fault: { type: "string" },
  "fault-every": { type: "string" },
  "fault-delay-ms": { type: "string" },
  quiet: { type: "boolean" },
  count: { type: "string" },
  ...VARIANT_OPTIONS,
} as const;

/** The most robots `--count` serves (a classroom's). */
const MAX_COUNT = 12;

/** Robot `k`'s serial number with `--count`: the simulator's own with its last two digits k (…01, …02, …). */
export function countSerial(k: number): string {
  return `89588999893${String(k).padStart(2, "0")}`;
}

/** One robot's lines among several (`--count`): text lines start with "robot K:", JSON lines carry `robot`. */
class RobotOutput extends Output {
  constructor(
    private readonly base: Output,
    private readonly label: string,
    private readonly robot: number,
  ) {
    super(base.json, base.streams);
    if (base.isStreaming) this.streaming();
  }

  override line(text = ""): void {
    if (!this.base.isBroken("stdout")) super.line(`${this.label} ${text}`);
  }

  override jsonLine(data: unknown): void {
    if (!this.base.isBroken("stdout")) super.jsonLine({ robot: this.robot, ...(data as object) });
  }
}

export const simCommand: CommandDef = {
  name: "sim",
  usage:
    "rbc sim (--port PATH | --pty [--count N]) [--latency-ms N] [--baud-pacing] [--fault KIND] [variant switches] [--quiet]",
  help: COMMAND_HELP.sim,
  examples: [
    "rbc sim --pty",
    "rbc sim --port /dev/pts/5 --baud-pacing --latency-ms 16",
    "rbc sim --pty --fault garbage --fault-every 3",
    "rbc sim --pty --no-serial --no-status --firmware 9.99 --platform 4 --repeat-replies",
    "rbc sim --pty --user-firmware --busy-motion 1 --firmware-events",
    "rbc sim --pty --servo-replacement 12 --servo-loaded 4",
    "rbc sim --pty --count 3",
  ],
  talksToRobot: false,
  streams: true,
  async run(env) {
    const { values, positionals } = parseCommand("sim", env.argv, OPTIONS);
    noExtraArguments("sim", positionals, 0);
    if (values.demo) throw new UsageError(said(commandMessages, "cmd.sim.noDemo"), "sim");
    if (values.pty === (values.port !== undefined)) {
      throw new UsageError(said(commandMessages, "cmd.sim.portOrPty"), "sim");
    }
    const fault = values.fault;
    if (fault !== undefined && !isFaultKind(fault)) {
      throw new UsageError(
        said(commandMessages, "cmd.sim.unknownFault", { fault, kinds: FAULT_KINDS.join(", ") }),
        "sim",
      );
    }
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    const link = {
      latencyMs: intOption("sim", "latency-ms", values["latency-ms"], 0, 0, 10_000),
      baudPacing: values["baud-pacing"] === true,
      fault,
      faultEvery: intOption("sim", "fault-every", values["fault-every"], 1, 1, 1_000_000),
      faultDelayMs: intOption("sim", "fault-delay-ms", values["fault-delay-ms"], 500, 0, 60_000),
    };
    const variant = variantFromValues(values, "sim", link.baudPacing);
    const count = intOption("sim", "count", values.count, 1, 1, MAX_COUNT);
    if (count > 1 && !values.pty) throw new UsageError(said(commandMessages, "cmd.sim.countNeedsPty"), "sim");
    const { serveSimulator } = await import("../sim-server.ts");
    const serveOne = async (robot: number): Promise<void> => {
      const out =
        count > 1
          ? new RobotOutput(env.out, t("cmd.sim.robotLabel", { robot: String(robot) }), robot)
          : env.out;
      let path = values.port;
      let clientPath: string | undefined;
      if (values.pty) {
        const pair = await createPtyPair();
        env.onCleanup(() => pair.close());
        path = pair.simPath;
        clientPath = pair.clientPath;
      }
      if (path === undefined) throw new UsageError(said(commandMessages, "cmd.sim.portOrPtyShort"), "sim");
      await serveSimulator({
        ...link,
        variant,
        ...(count > 1 ? { serialNumber: countSerial(robot) } : {}),
        path,
        quiet: values.quiet === true,
        out,
        signal: env.signal,
        stdin: env.stdin,
        locale,
        onReady: (sim) => {
          const about = aboutRobot(
            sim.firmware,
            variant.answersSerialNumber === false ? undefined : sim.serialNumber,
            sim.platform,
            locale,
          );
          const every = String(link.faultEvery);
          const model = [
            link.baudPacing ? t("cmd.sim.baudPacing") : undefined,
            link.latencyMs > 0 ? t("cmd.sim.latency", { ms: String(link.latencyMs) }) : undefined,
            fault
              ? link.faultEvery > 1
                ? t("cmd.sim.faultEvery", { fault, every })
                : t("cmd.sim.fault", { fault })
              : undefined,
            ...describeVariant(variant, locale),
          ].filter((m) => m !== undefined);
          out.jsonLine({
            event: "ready",
            pid: process.pid,
            path,
            clientPath: clientPath ?? null,
            ...link,
            fault: fault ?? null,
            robot: {
              firmware: sim.firmware,
              serialNumber: variant.answersSerialNumber === false ? null : sim.serialNumber,
              platform: sim.platform,
              answersSerialNumber: variant.answersSerialNumber !== false,
              answersExecutionStatus: variant.answersExecutionStatus !== false,
              repeatReplies: variant.repeatReplies ?? null,
              firmwareEventPace: variant.firmwareEventPace === true,
              busyMotion: variant.busyMotion ?? null,
              userFirmware: variant.userFirmware === true,
              answersMemoryRead: variant.answersMemoryRead !== false,
              servosSilent: variant.servosSilent === true,
              soundReplyAtOnce: variant.soundReplyAtOnce === true,
              servoFaults: variant.servoFaults ?? null,
            },
          });
          out.line(
            model.length > 0
              ? t("cmd.sim.listeningWith", { about, path, model: model.join(", ") })
              : t("cmd.sim.listening", { about, path }),
          );
          if (clientPath) out.line(t("cmd.sim.clients", { path: clientPath }));
          const pid = String(process.pid);
          out.line(env.stdin.isTTY ? t("cmd.sim.powerCycleTty", { pid }) : t("cmd.sim.powerCycle", { pid }));
        },
      });
    };
    await Promise.all(Array.from({ length: count }, (_, i) => serveOne(i + 1)));
    return EXIT.ok;
  },
};
