import { RbcError } from "../../device/errors.ts";
import { errorSaid } from "../../i18n/error-said.ts";
import type { Locale } from "../../i18n/locale.ts";
import { distanceWarning } from "../../i18n/outcomes/plausibility.ts";
import { said, saidTogether } from "../../i18n/said.ts";
import { translator } from "../../i18n/translate.ts";
import type { Clock } from "../../shared/clock.ts";
import { intOption, noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { connectRobot } from "../connect.ts";
import { CliError, EXIT, SEE_LOG } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { commandMessages } from "./messages.ts";

const OPTIONS = {
  "interval-ms": { type: "string" },
  count: { type: "string" },
} as const;

/** Waits `ms` of the robot's time (see Robot.clock), or until `signal` aborts. */
function sleep(clock: Clock, ms: number, signal: AbortSignal): Promise<void> {
  return new Promise((resolve) => {
    if (signal.aborted) return resolve();
    const timer = clock.setTimeout(done, ms);
    function done() {
      clock.clearTimeout(timer);
      signal.removeEventListener("abort", done);
      resolve();
    }
    signal.addEventListener("abort", done, { once: true });
  });
}

/**
 * One reading, as a line for people (in `locale`), a JSON line, and the warning for an implausible value (if
 * any): `warning` is the protocol's English sentence (the JSON's), `said` the warning in `locale`.
 */
export function sensorReading(
  ms: number,
  distanceCm: number,
  accelerometer: { x: number; y: number; z: number },
  locale: Locale = "en",
) {
  const t = translator(commandMessages, locale);
  const warning = distanceWarning(distanceCm);
  const { x, y, z } = accelerometer;
  const axis = (v: number) => String(v).padStart(4);
  const line = t("cmd.sensors.reading", {
    // A column of a stream: not grouped by thousands (1234.5 s), in every language.
    time: (ms / 1000).toFixed(1).padStart(7),
    distance: String(distanceCm).padStart(2),
    implausible: warning ? ` ${t("cmd.sensors.implausible")}` : "",
    x: axis(x),
    y: axis(y),
    z: axis(z),
  });
  const json = { ms, distanceCm, accelerometer, ...(warning ? { warnings: [warning] } : {}) };
  const said = distanceWarning(distanceCm, locale);
  return { line, json, warning, said };
}

export const sensorsCommand: CommandDef = {
  name: "sensors",
  usage: "rbc sensors [--interval-ms MS] [--count N] (--port PATH | --demo)",
  help: COMMAND_HELP.sensors,
  examples: ["rbc sensors --demo", "rbc sensors --port /dev/ttyUSB0 --interval-ms 500 --json"],
  talksToRobot: true,
  streams: true,
  async run(env) {
    const { values, positionals } = parseCommand("sensors", env.argv, OPTIONS);
    noExtraArguments("sensors", positionals, 0);
    const interval = intOption("sensors", "interval-ms", values["interval-ms"], 200, 20, 3_600_000);
    const count = intOption("sensors", "count", values.count, Number.POSITIVE_INFINITY, 1, 1_000_000_000);
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    const robot = await connectRobot("sensors", values, env, { handlesInterrupt: true });
    const started = robot.clock.now();
    if (!env.out.json) env.out.note(t("cmd.sensors.start"));
    let lastWarning: string | undefined;
    for (let i = 0; i < count && !env.signal.aborted; i++) {
      const distanceCm = await robot.client.readDistance().catch((e: unknown) => {
        // Busy, not gone (docs/protocol.md §3.6): say so, and how to end what plays.
        if (e instanceof RbcError && e.code === "busy") {
          throw new CliError(
            "busy",
            saidTogether([errorSaid(e, { detailHint: SEE_LOG }), said(commandMessages, "cmd.run.stopHint")]),
          );
        }
        throw e;
      });
      const accelerometer = await robot.client.readAccelerometer();
      const ms = Math.round(robot.clock.now() - started);
      const reading = sensorReading(ms, distanceCm, accelerometer, locale);
      // Shown as read, with the warning on stderr once per run of the same implausible value.
      if (reading.said && reading.warning !== lastWarning)
        env.out.note(t("cmd.warning", { warning: reading.said }));
      lastWarning = reading.warning;
      env.out.jsonLine(reading.json);
      env.out.line(reading.line);
      if (i + 1 < count) await sleep(robot.clock, interval, env.signal);
    }
    return EXIT.ok;
  },
};
