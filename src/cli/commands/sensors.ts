import { distanceWarning } from "../../protocol/plausibility.ts";
import type { Clock } from "../../shared/clock.ts";
import { intOption, noExtraArguments, parseCommand } from "../args.ts";
import type { CommandDef } from "../command.ts";
import { connectRobot } from "../connect.ts";
import { EXIT } from "../errors.ts";

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

/** One reading, as a line for people, a JSON line, and the warning for an implausible value (if any). */
export function sensorReading(
  ms: number,
  distanceCm: number,
  accelerometer: { x: number; y: number; z: number },
) {
  const warning = distanceWarning(distanceCm);
  const { x, y, z } = accelerometer;
  const axis = (v: number) => String(v).padStart(4);
  const line = `${(ms / 1000).toFixed(1).padStart(7)} s  distance ${String(distanceCm).padStart(2)} cm${warning ? " (implausible)" : ""}   accel x ${axis(x)}  y ${axis(y)}  z ${axis(z)}`;
  const json = { ms, distanceCm, accelerometer, ...(warning ? { warnings: [warning] } : {}) };
  return { line, json, warning };
}

export const sensorsCommand: CommandDef = {
  name: "sensors",
  summary: "stream the distance sensor and the accelerometer until Ctrl-C",
  usage: "rbc sensors [--interval-ms MS] [--count N] (--port PATH | --demo)",
  description: `
Reads the distance sensor (cm, 10-50; 10 means nothing seen or no sensor) and the accelerometer (X, Y, Z,
signed) every --interval-ms and prints one line per reading, until Ctrl-C (or --count readings). A distance
outside 10-50 cm (which the standard firmware never sends) is shown as read, marked "(implausible)", with a
warning on stderr. With --json each reading is one JSON object per line (with "warnings" for an implausible
one), and a failure one last line {"ok":false,"error":{…}}.
Ctrl-C is the normal way to end it: exit code 0.`,
  options: [
    ["--interval-ms MS", "Time between readings (default 200, at least 20)."],
    ["--count N", "Stop after N readings (default: until Ctrl-C)."],
  ],
  examples: ["rbc sensors --demo", "rbc sensors --port /dev/ttyUSB0 --interval-ms 500 --json"],
  talksToRobot: true,
  streams: true,
  async run(env) {
    const { values, positionals } = parseCommand("sensors", env.argv, OPTIONS);
    noExtraArguments("sensors", positionals, 0);
    const interval = intOption("sensors", "interval-ms", values["interval-ms"], 200, 20, 3_600_000);
    const count = intOption("sensors", "count", values.count, Number.POSITIVE_INFINITY, 1, 1_000_000_000);
    const robot = await connectRobot("sensors", values, env, { handlesInterrupt: true });
    const started = robot.clock.now();
    if (!env.out.json) env.out.note("Reading the sensors; Ctrl-C to stop.");
    let lastWarning: string | undefined;
    for (let i = 0; i < count && !env.signal.aborted; i++) {
      const distanceCm = await robot.client.readDistance();
      const accelerometer = await robot.client.readAccelerometer();
      const ms = Math.round(robot.clock.now() - started);
      const reading = sensorReading(ms, distanceCm, accelerometer);
      // Shown as read, with the warning on stderr once per run of the same implausible value.
      if (reading.warning && reading.warning !== lastWarning) env.out.note(`Warning: ${reading.warning}`);
      lastWarning = reading.warning;
      env.out.jsonLine(reading.json);
      env.out.line(reading.line);
      if (i + 1 < count) await sleep(robot.clock, interval, env.signal);
    }
    return EXIT.ok;
  },
};
