import { intOption, noExtraArguments, parseCommand } from "../args.ts";
import type { CommandDef } from "../command.ts";
import { EXIT, UsageError } from "../errors.ts";
import { createPtyPair } from "../pty.ts";
import { FAULT_KINDS, isFaultKind } from "../sim-faults.ts";
import {
  aboutRobot,
  DEMO_VARIANT_VAR,
  describeVariant,
  VARIANT_HELP,
  VARIANT_OPTIONS,
  variantFromValues,
} from "../sim-variant.ts";

const OPTIONS = {
  pty: { type: "boolean" },
  "latency-ms": { type: "string" },
  "baud-pacing": { type: "boolean" },
  fault: { type: "string" },
  "fault-every": { type: "string" },
  "fault-delay-ms": { type: "string" },
  quiet: { type: "boolean" },
  ...VARIANT_OPTIONS,
} as const;

export const simCommand: CommandDef = {
  name: "sim",
  summary: "serve the simulated RBC on a serial device (or a PTY pair it makes)",
  usage:
    "rbc sim (--port PATH | --pty) [--latency-ms N] [--baud-pacing] [--fault KIND] [variant switches] [--quiet]",
  description: `
Runs the simulated RBC (firmware 2.23, serial 8958899989309, HUNO, just switched on, unless a variant
switch below says otherwise) on a serial device, so that any program can talk to it as if it were a robot:
rbc itself (\`rbc info --port …\`), the panel's tests, or other RBC software. It prints one line per request
and per reply (hex and command name) until Ctrl-C. Exit code 0 on Ctrl-C.

  --port PATH   serve this device, e.g. one end of a pair made with
                socat -d -d pty,raw,echo=0 pty,raw,echo=0   (then connect clients to the other end)
  --pty         make that pair with socat (if installed), serve one end and print the other end's path;
                the pair goes away when rbc sim exits.

Link modelling: --baud-pacing makes every byte take 86.8 µs (115200 baud) in each direction, and
--latency-ms adds a USB adapter's delay to every reply (16 is a common FTDI setting), so uploads run at a
realistic speed. --fault KIND disturbs the replies (every one, or every --fault-every N-th):
  drop     the last content byte of a packet is lost (a download acknowledgement is lost)
  corrupt  that byte is changed, so the checksum fails
  split    the reply arrives byte by byte, 1 ms apart
  delay    the reply arrives --fault-delay-ms late (default 500, beyond the client's 400 ms timeout)
  silent   no reply at all
  garbage  noise with a partial header arrives before the reply

Firmware updates (rbc flash, PROTOCOL.md §11): the simulated RBC has the bootloader of a real one. When a
client asks you to switch the robot off and on, send the simulator SIGUSR1 (kill -USR1 PID), or type p and
Enter in its terminal: it restarts, its bootloader sends ^ and waits 300 ms for the entry bytes, then takes
the HEX file line by line (4.5 ms per 256-byte page write, between XOFF and XON). A file carrying the marker
"RBCFW M.mm" makes the robot report version M.mm afterwards; docs/firmware-update.md has the details.
  rbc sim --pty                                      # prints the client end, e.g. /dev/pts/7
  rbc flash examples/firmware/demo-2.50.hex --port /dev/pts/7 --yes    # then: kill -USR1 <rbc sim's pid>

Firmware variants (PROTOCOL.md §3.5), to try a client against the builds that differ from the standard one:
--no-serial and --no-status leave 0x0C and 0x1E unanswered (neither firmware source answers them),
--firmware 9.99 and --platform 4 report what the homebrew port reports, and --repeat-replies repeats the
first distance reply (0x16) endlessly, as that port does (--repeat-type picks another reply). The demo robot
of --demo takes the same switches from the ${DEMO_VARIANT_VAR} environment variable, e.g.
${DEMO_VARIANT_VAR}="--no-serial --firmware 9.99" rbc info --demo`,
  options: [
    ["--pty", "Create a PTY pair with socat and print the path for clients."],
    ["--latency-ms N", "Delay every reply by N ms (default 0)."],
    ["--baud-pacing", "Pace bytes at 115200 baud (86.8 µs per byte) in both directions."],
    ["--fault KIND", `Disturb replies: ${FAULT_KINDS.join(", ")}.`],
    ["--fault-every N", "Disturb only every N-th reply (default 1: all)."],
    ["--fault-delay-ms N", "Delay of --fault delay (default 500)."],
    ...VARIANT_HELP,
    ["--quiet", "Do not print the packet trace."],
    ["-p, --port PATH", "The serial device to serve."],
  ],
  examples: [
    "rbc sim --pty",
    "rbc sim --port /dev/pts/5 --baud-pacing --latency-ms 16",
    "rbc sim --pty --fault garbage --fault-every 3",
    "rbc sim --pty --no-serial --no-status --firmware 9.99 --platform 4 --repeat-replies",
  ],
  talksToRobot: false,
  streams: true,
  async run(env) {
    const { values, positionals } = parseCommand("sim", env.argv, OPTIONS);
    noExtraArguments("sim", positionals, 0);
    if (values.demo)
      throw new UsageError("rbc sim serves the simulator itself; --demo is not needed.", "sim");
    if (values.pty === (values.port !== undefined)) {
      throw new UsageError("Give either --port PATH (a serial device to serve) or --pty.", "sim");
    }
    const fault = values.fault;
    if (fault !== undefined && !isFaultKind(fault)) {
      throw new UsageError(`Unknown --fault "${fault}"; use one of ${FAULT_KINDS.join(", ")}.`, "sim");
    }
    const link = {
      latencyMs: intOption("sim", "latency-ms", values["latency-ms"], 0, 0, 10_000),
      baudPacing: values["baud-pacing"] === true,
      fault,
      faultEvery: intOption("sim", "fault-every", values["fault-every"], 1, 1, 1_000_000),
      faultDelayMs: intOption("sim", "fault-delay-ms", values["fault-delay-ms"], 500, 0, 60_000),
    };
    const variant = variantFromValues(values, "sim", link.baudPacing);
    let path = values.port;
    let clientPath: string | undefined;
    if (values.pty) {
      const pair = await createPtyPair();
      env.onCleanup(() => pair.close());
      path = pair.simPath;
      clientPath = pair.clientPath;
    }
    if (path === undefined) throw new UsageError("Give --port PATH or --pty.", "sim");
    const { serveSimulator } = await import("../sim-server.ts");
    await serveSimulator({
      ...link,
      variant,
      path,
      quiet: values.quiet === true,
      out: env.out,
      signal: env.signal,
      stdin: env.stdin,
      onReady: (sim) => {
        const about = aboutRobot(
          sim.firmware,
          variant.answersSerialNumber === false ? undefined : sim.serialNumber,
          sim.platform,
        );
        const model = [
          link.baudPacing ? "115200 baud pacing" : undefined,
          link.latencyMs > 0 ? `${link.latencyMs} ms latency` : undefined,
          fault
            ? `fault ${fault}${link.faultEvery > 1 ? ` on 1 reply in ${link.faultEvery}` : ""}`
            : undefined,
          ...describeVariant(variant),
        ].filter((m) => m !== undefined);
        env.out.jsonLine({
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
          },
        });
        env.out.line(
          `Simulated RBC (${about}) listening on ${path}${model.length ? ` with ${model.join(", ")}` : ""}.`,
        );
        if (clientPath) env.out.line(`Clients connect to ${clientPath}, e.g.: rbc info --port ${clientPath}`);
        env.out.line(
          `Power cycle (for rbc flash): kill -USR1 ${process.pid}${env.stdin.isTTY ? ", or p and Enter here" : ""}. Ctrl-C to stop.`,
        );
      },
    });
    return EXIT.ok;
  },
};
