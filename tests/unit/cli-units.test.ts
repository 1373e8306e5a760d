import { mkdtemp, readdir, readFile, rm, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { PassThrough } from "node:stream";
import { describe, expect, it } from "vitest";
import { bundleState } from "../../scripts/build-cli.mjs";
import { splitCommand, wantsHelp } from "../../src/cli/args.ts";
import { Cleanups } from "../../src/cli/cleanups.ts";
import type { RunEnv } from "../../src/cli/command.ts";
import { runCommand } from "../../src/cli/commands/run.ts";
import { uploadedSlot } from "../../src/cli/commands/upload.ts";
import { parseZeroList } from "../../src/cli/commands/zeros.ts";
import { type ConfirmAnswer, confirm } from "../../src/cli/confirm.ts";
import { demoTimeScale } from "../../src/cli/connect.ts";
import { demoClock, OrderedClock } from "../../src/cli/demo-clock.ts";
import { errorLine, UsageError } from "../../src/cli/errors.ts";
import { Output } from "../../src/cli/output.ts";
import { portOpenMessage } from "../../src/cli/port-errors.ts";
import { ProgressBar } from "../../src/cli/progress.ts";
import { applyFault, GARBAGE } from "../../src/cli/sim-faults.ts";
import { SimLink } from "../../src/cli/sim-link.ts";
import { SimTrace, type SimTraceLine } from "../../src/cli/sim-trace.ts";
import { RbcError } from "../../src/device/errors.ts";
import { encodeDownloadStart, fromHex, toHex } from "../../src/protocol/index.ts";
import { type Clock, type TimerId, VirtualClock } from "../../src/shared/clock.ts";
import { SimulatedRbc } from "../../src/sim/index.ts";
import { cliEntry, REPO } from "../cli/spawn-cli.ts";
import { driveClock } from "../support/drive-clock.ts";

const VERSION_REPLY = fromHex("FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 15");

describe("command line parsing", () => {
  it("finds the subcommand wherever the global options are", () => {
    expect(splitCommand(["--demo", "info", "--json"])).toEqual({
      command: "info",
      rest: ["--demo", "--json"],
    });
    expect(splitCommand(["-p", "/dev/ttyUSB0", "zeros", "read"])).toEqual({
      command: "zeros",
      rest: ["-p", "/dev/ttyUSB0", "read"],
    });
    expect(splitCommand(["--port=/dev/x", "run", "7"]).command).toBe("run");
    expect(splitCommand(["--help"])).toEqual({ command: undefined, rest: ["--help"] });
    expect(wantsHelp(["upload", "-h"])).toBe(true);
    expect(wantsHelp(["--", "-h"])).toBe(false);
  });

  it("reads a zero list written with commas or as separate words", () => {
    expect(parseZeroList(["125,202,162"])).toEqual([125, 202, 162]);
    expect(parseZeroList(["125", "202,", "162"])).toEqual([125, 202, 162]);
    expect(() => parseZeroList(["125,x"])).toThrow(UsageError);
    expect(() => parseZeroList([])).toThrow(UsageError);
  });
});

/** An Output that collects what it writes. */
function collectingOutput(json: boolean) {
  const text = { stdout: "", stderr: "" };
  const stdout = new PassThrough();
  const stderr = new PassThrough();
  stdout.on("data", (d: Buffer) => {
    text.stdout += d.toString();
  });
  stderr.on("data", (d: Buffer) => {
    text.stderr += d.toString();
  });
  return { out: new Output(json, { stdout, stderr }), text };
}

describe("output", () => {
  it("--json: one pretty document, but one compact line for a streaming command", async () => {
    const plain = collectingOutput(true);
    plain.out.result({ ok: false, error: { code: "no-robot" } });
    const stream = collectingOutput(true);
    stream.out.streaming();
    stream.out.jsonLine({ ms: 0, distanceCm: 10 });
    stream.out.result({ ok: false, error: { code: "timeout" } });
    await new Promise((r) => setImmediate(r));
    expect(plain.text.stdout.trim().split("\n").length).toBeGreaterThan(1);
    const lines = stream.text.stdout.trim().split("\n");
    expect(lines.map((l) => JSON.parse(l))).toEqual([
      { ms: 0, distanceCm: 10 },
      { ok: false, error: { code: "timeout" } },
    ]);
  });

  it("writes nothing more to a stream whose reader went away", async () => {
    const { out, text } = collectingOutput(false);
    const told: string[] = [];
    out.onBroken((which) => told.push(which));
    out.line("one");
    out.markBroken("stdout");
    out.markBroken("stdout");
    out.line("two");
    out.note("still on stderr");
    await new Promise((r) => setImmediate(r));
    expect(text.stdout).toBe("one\n");
    expect(text.stderr).toBe("still on stderr\n");
    expect(told).toEqual(["stdout"]);
  });

  it("adds the busy-robot case to the connect failure 'no robot answered'", () => {
    const line = errorLine(
      new RbcError("no-robot", "The port opened but no robot answered. Check that the robot is switched on."),
    );
    expect(line).toBe(
      "The port opened but no robot answered. Check that the robot is switched on; or the robot is busy playing a motion or a sound: wait until it ends and try again.",
    );
    expect(errorLine(new RbcError("timeout", "No reply."))).toBe("No reply.");
  });
});

describe("cleanups", () => {
  it("run once, in reverse order, however often and concurrently they are asked for", async () => {
    const cleanups = new Cleanups(1000);
    const ran: string[] = [];
    cleanups.add(async () => {
      await new Promise((r) => setTimeout(r, 10));
      ran.push("port");
    });
    cleanups.add(() => {
      ran.push("pty");
    });
    const first = cleanups.run();
    const second = cleanups.run();
    expect(second).toBe(first);
    await Promise.all([first, second, cleanups.run()]);
    expect(ran).toEqual(["pty", "port"]);
    cleanups.add(() => {
      ran.push("late");
    });
    await cleanups.run();
    expect(ran).toEqual(["pty", "port", "late"]);
  });

  it("a cleanup that hangs or fails does not stop the others", async () => {
    const cleanups = new Cleanups(20);
    const ran: string[] = [];
    cleanups.add(() => {
      ran.push("first");
    });
    cleanups.add(() => new Promise<void>(() => {}));
    cleanups.add(() => {
      throw new Error("boom");
    });
    await cleanups.run();
    expect(ran).toEqual(["first"]);
  });
});

describe("y/N confirmation", () => {
  /** Asks with a fake terminal on stdin and types `keys` once the prompt is shown. */
  async function ask(keys: string, signal = new AbortController().signal): Promise<ConfirmAnswer> {
    const stdin = Object.assign(new PassThrough(), { isTTY: true });
    const { out, text } = collectingOutput(false);
    const env: RunEnv = {
      argv: [],
      signal,
      onCleanup: () => {},
      out,
      setExitNote: () => {},
      stdin: stdin as unknown as NodeJS.ReadStream,
      cwd: REPO,
      env: {},
    };
    const answer = confirm(env, "Upload Hi.rbm?");
    await new Promise((r) => setImmediate(r));
    if (keys) stdin.write(keys);
    const result = await answer;
    expect(text.stderr).toContain("Upload Hi.rbm? [y/N] ");
    return result;
  }

  it("y is yes, anything else no, Ctrl-C (a key in raw mode) an interrupt", async () => {
    expect(await ask("y\r")).toBe("yes");
    expect(await ask("\r")).toBe("no");
    expect(await ask("nope\r")).toBe("no");
    expect(await ask("\x04")).toBe("no"); // Ctrl-D: end of input
    expect(await ask("\x03")).toBe("interrupted");
  });

  it("a SIGINT while the prompt waits is an interrupt too", async () => {
    const controller = new AbortController();
    setTimeout(() => controller.abort(), 20);
    expect(await ask("", controller.signal)).toBe("interrupted");
  });
});

describe("upload progress bar", () => {
  it("shows bytes, percent, bytes/s and time left", () => {
    let t = 0;
    const bar = new ProgressBar(new Output(false), () => t);
    t = 500;
    expect(bar.render(256, 538)).toBe("[##########----------] 256/538 bytes  47%     512 B/s  0.6 s left");
    t = 1000;
    expect(bar.render(538, 538)).toBe("[####################] 538/538 bytes 100%     538 B/s  done");
  });
});

describe("rbc sim reply faults", () => {
  it("maps each fault onto one reply", () => {
    const n = VERSION_REPLY.length;
    expect(toHex(applyFault("drop", VERSION_REPLY, 0).chunks[0]!)).toBe(
      "FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 15",
    );
    expect(applyFault("corrupt", VERSION_REPLY, 0).chunks[0]![n - 2]).toBe(0x16);
    expect(applyFault("split", VERSION_REPLY, 0).chunks).toHaveLength(n);
    expect(applyFault("delay", VERSION_REPLY, 500).delayMs).toBe(500);
    expect(applyFault("silent", VERSION_REPLY, 0).chunks).toEqual([]);
    const garbage = applyFault("garbage", VERSION_REPLY, 0).chunks[0]!;
    expect(garbage.subarray(0, GARBAGE.length)).toEqual(GARBAGE);
    expect(toHex(applyFault("corrupt", Uint8Array.of(0x40), 0).chunks[0]!)).toBe("41");
  });

  it("applies a fault to every N-th reply only", () => {
    const written: string[] = [];
    const notes: Array<string | undefined> = [];
    const link = new SimLink(
      { baudPacing: false, latencyMs: 0, fault: "silent", faultEvery: 2, faultDelayMs: 0 },
      () => {},
      (b) => written.push(toHex(b)),
      (_r, note) => notes.push(note),
    );
    for (let i = 0; i < 4; i++) link.fromRobot(Uint8Array.of(0x40 + i));
    expect(written).toEqual(["40", "42"]);
    expect(notes).toEqual([undefined, "fault: never sent", undefined, "fault: never sent"]);
  });
});

describe("rbc sim packet trace", () => {
  it("names requests, download parts, replies and what the simulator dropped", () => {
    const sim = new SimulatedRbc({ clock: new VirtualClock() });
    const lines: SimTraceLine[] = [];
    const trace = new SimTrace(sim, (l) => lines.push(l));
    sim.onTransmit((b) => trace.reply(b, undefined));
    const feed = (bytes: Uint8Array) => {
      trace.incoming(bytes);
      sim.receive(bytes);
      trace.afterReceive();
    };
    feed(fromHex("FF E0 FB 01 00 1A FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01"));
    feed(fromHex("FF FF AA 55 AA 55 37 BA 14 00 00 00 00 01 04 04")); // motion 4 before 7: ignored
    feed(encodeDownloadStart(0x01, 3));
    const labels = lines.map((l) => `${l.direction} ${l.label}`);
    expect(labels).toEqual([
      "pc-to-rbc leave direct mode (no effect now)",
      "pc-to-rbc 0x12 Read firmware version",
      "rbc-to-pc 0x12 Read firmware version",
      "pc-to-rbc 0x14 Run motion",
      "note ignored: motion 7 has not run since power-up",
      "pc-to-rbc 0x01 Write motion: first part, 3 bytes",
      "rbc-to-pc download acknowledged (40)",
    ]);
    feed(Uint8Array.of(1, 2, 3, 0)); // its `40` comes after a 5 ms page write (the clock stands still)
    expect(lines.at(-1)).toMatchObject({
      label: "motion chunk 1/1 (3 bytes + checksum)",
      hex: "01 02 03 00",
    });
  });
});

describe("rbc sim packet trace in direct mode", () => {
  it("a request written right after the exit bytes, in the same write, gets its own line", () => {
    const sim = new SimulatedRbc({ clock: new VirtualClock() });
    const lines: SimTraceLine[] = [];
    const trace = new SimTrace(sim, (l) => lines.push(l));
    sim.onTransmit((b) => trace.reply(b, undefined));
    const feed = (hex: string) => {
      const bytes = fromHex(hex);
      trace.incoming(bytes);
      sim.receive(bytes);
      trace.afterReceive();
    };
    feed("FF FF AA 55 AA 55 37 BA 10 00 00 00 00 01 01 01"); // 0x10: direct mode on
    feed("FF A5 00 25"); // wCK: read servo 5's position
    // One write: a wCK move of servo 5, the exit (docs/protocol.md §5), then 0x12.
    feed("FF 05 7F 7A FF E0 FB 01 00 1A FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01");
    const shown = lines.map((l) => [l.direction, l.label, l.hex]);
    // Requests are traced as they arrive, before the simulator answers them: the move's reply (servo 5 at
    // 127, load 0) follows the lines of the whole write.
    expect(shown.slice(2)).toEqual([
      ["pc-to-rbc", "servo bus (direct mode)", "FF A5 00 25"],
      ["rbc-to-pc", "servo bus reply", expect.stringMatching(/^00 [0-9A-F]{2}$/)],
      ["pc-to-rbc", "servo bus (direct mode)", "FF 05 7F 7A"],
      ["pc-to-rbc", "servo bus: leave direct mode", "FF E0 FB 01 00 1A"],
      ["pc-to-rbc", "0x12 Read firmware version", "FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01"],
      ["rbc-to-pc", "servo bus reply", "00 7F"],
      ["rbc-to-pc", "0x12 Read firmware version", "FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 15"],
    ]);
    expect(sim.directMode).toBe(false);
  });
});

describe("rbc sim packet trace of a reply repeated unasked", () => {
  it("prints the reply once, then how many times it came again, before the next request's line", async () => {
    const clock = new VirtualClock();
    const sim = new SimulatedRbc({ clock, repeatReplies: { type: 0x16, intervalMs: 1 } });
    const lines: SimTraceLine[] = [];
    const trace = new SimTrace(sim, (l) => lines.push(l));
    sim.onTransmit((b) => trace.reply(b, undefined));
    const feed = (hex: string) => {
      const bytes = fromHex(hex);
      trace.incoming(bytes);
      sim.receive(bytes);
      trace.afterReceive();
    };
    feed("FF FF AA 55 AA 55 37 BA 16 00 00 00 00 01 01 01"); // distance: 10 cm
    await clock.advance(25);
    feed("FF FF AA 55 AA 55 37 BA 11 00 00 00 00 01 01 01");
    expect(lines.map((l) => [l.direction, l.label, l.hex])).toEqual([
      ["pc-to-rbc", "0x16 Distance sensor", "FF FF AA 55 AA 55 37 BA 16 00 00 00 00 01 01 01"],
      ["rbc-to-pc", "0x16 Distance sensor", "FF FF AA 55 AA 55 37 BA 16 01 00 00 00 02 0A 00 0A"],
      ["note", "0x16 Distance sensor: the same reply 25 more times, unasked", ""],
      ["pc-to-rbc", "0x11 Read error code", "FF FF AA 55 AA 55 37 BA 11 00 00 00 00 01 01 01"],
      ["rbc-to-pc", "0x11 Read error code", "FF FF AA 55 AA 55 37 BA 11 01 00 00 00 02 FF 01 FE"],
    ]);
  });
});

describe("a port that cannot be opened", () => {
  it("one sentence that names the port and points to `rbc ports`, without serialport's 'Error: '", () => {
    // What NodeSerialTransport passes on: RbcPortError → LinkError → serialport's Error.
    const chain = (message: string) =>
      new Error("wrapper", { cause: new Error("link", { cause: new Error(message) }) });
    expect(
      portOpenMessage("/dev/ttyUSB0", chain("Error: No such file or directory, cannot open /dev/ttyUSB0")),
    ).toBe(
      "Cannot open /dev/ttyUSB0 (no such file or directory). Run `rbc ports` to list the serial ports on this computer.",
    );
    expect(
      portOpenMessage(
        "/dev/ttyUSB0",
        chain("Error: Permission denied, cannot open /dev/ttyUSB0"),
        "port-busy",
      ),
    ).toBe(
      "Cannot open /dev/ttyUSB0 (permission denied): another program may be using it, or you may not have permission (on Linux, join the dialout group). Run `rbc ports` to list the serial ports.",
    );
    expect(portOpenMessage("COM3", new Error("Error: Opening COM3: File not found\n"))).toBe(
      "Cannot open COM3 (opening COM3: File not found). Run `rbc ports` to list the serial ports on this computer.",
    );
  });
});

describe("which motion number an upload became", () => {
  const base = {
    area: "motion" as const,
    total: 624,
    chunks: 10,
    footprint: 640,
    freeAfter: 23_936,
    errorCode: 0xff,
    elapsedMs: 100,
    reset: false,
  };
  it("known after --reset, or when the motion memory was empty before; otherwise not guessed", () => {
    expect(uploadedSlot({ ...base, freeBefore: 24_576, slot: 1, motionNumber: 12, reset: true })).toEqual({
      slot: 1,
      motionNumber: 12,
    });
    expect(uploadedSlot({ ...base, freeBefore: 24_576, slot: undefined, motionNumber: undefined })).toEqual({
      slot: 1,
      motionNumber: 12,
    });
    expect(uploadedSlot({ ...base, freeBefore: 23_936, slot: undefined, motionNumber: undefined })).toEqual({
      slot: undefined,
      motionNumber: undefined,
    });
    expect(
      uploadedSlot({ ...base, area: "action", freeBefore: 8192, slot: undefined, motionNumber: undefined }),
    ).toEqual({ slot: undefined, motionNumber: undefined });
  });
});

describe("layering", () => {
  async function sources(dir: string): Promise<string[]> {
    const entries = await readdir(dir, { withFileTypes: true, recursive: true });
    return entries.filter((e) => e.isFile() && e.name.endsWith(".ts")).map((e) => join(e.parentPath, e.name));
  }

  it("only the CLI loads the Node serial transport; the web app never imports it", async () => {
    const offenders: string[] = [];
    for (const file of await sources(join(REPO, "src"))) {
      if (file.includes("/src/cli/") || file.endsWith("/link/node-serial-transport.ts")) continue;
      const text = await readFile(file, "utf8");
      if (/node-serial-transport|from "serialport"/.test(text)) offenders.push(file);
    }
    expect(offenders).toEqual([]);
  });
});

describe("demo robot time scale (RBC_DEMO_TIME_SCALE)", () => {
  it("is 1 unless set, and refuses what is not a number above 0 (up to 1000)", () => {
    expect(demoTimeScale({})).toBe(1);
    expect(demoTimeScale({ RBC_DEMO_TIME_SCALE: "" })).toBe(1);
    expect(demoTimeScale({ RBC_DEMO_TIME_SCALE: "10" })).toBe(10);
    expect(demoTimeScale({ RBC_DEMO_TIME_SCALE: " 0.5 " })).toBe(0.5);
    for (const bad of ["0", "-2", "fast", "Infinity", "1001"]) {
      expect(() => demoTimeScale({ RBC_DEMO_TIME_SCALE: bad }, "run")).toThrow(UsageError);
    }
  });

  /** A base clock that moves only when told, and whose timers fire only when told: a stalled process. */
  class StallingClock implements Clock {
    time = 0;
    private readonly timers = new Map<TimerId, () => void>();
    private id = 0;
    now = () => this.time;
    setTimeout = (fn: () => void): TimerId => {
      this.timers.set(++this.id, fn);
      return this.id;
    };
    clearTimeout = (id: TimerId) => void this.timers.delete(id);
    /** Resumes at `time`: every timer set meanwhile fires now, at once. */
    resume(time: number) {
      this.time = time;
      const due = [...this.timers.values()];
      this.timers.clear();
      for (const fn of due) fn();
    }
  }
  const settled = async () => {
    for (let i = 0; i < 20; i++) await new Promise((r) => setImmediate(r));
  };

  it("after a stall, a reply set off step by step still comes before a timeout that was due later", async () => {
    const base = new StallingClock();
    const clock = new OrderedClock(base);
    const events: string[] = [];
    const timeout = clock.setTimeout(() => events.push("timeout"), 400);
    // The simulator's reply: a first step at 10 ms whose promise chain sets the last step, 5 ms later.
    clock.setTimeout(() => {
      events.push(`step at ${clock.now()}`);
      void Promise.resolve().then(() =>
        clock.setTimeout(() => {
          events.push(`reply at ${clock.now()}`);
          clock.clearTimeout(timeout);
        }, 5),
      );
    }, 10);
    expect(clock.now()).toBe(0);
    base.resume(1000); // a stall: everything is overdue at once
    expect(clock.now()).toBe(10); // robot time waits for the timer that has not run yet
    await settled();
    expect(events).toEqual(["step at 10", "reply at 15"]);
    expect(clock.now()).toBe(1000); // nothing pending: robot time catches up with the base clock
    base.resume(2000);
    await settled();
    expect(events).toHaveLength(2); // the timeout was cleared
  });

  it("runs the simulator and the client on one faster clock; rbc reports the robot's time", async () => {
    // The demo clock of RBC_DEMO_TIME_SCALE=20 (what connect.ts builds from the variable), over a virtual base
    // clock that stands for real time: the test drives it, so the proportions hold however busy the machine.
    const base = new VirtualClock();
    const { out, text } = collectingOutput(true);
    const cleanups = new Cleanups();
    const env: RunEnv = {
      argv: ["7", "--demo", "--json"],
      signal: new AbortController().signal,
      onCleanup: (fn) => cleanups.add(fn),
      out,
      setExitNote: () => {},
      stdin: process.stdin,
      cwd: REPO,
      env: {},
      demoClock: demoClock(20, base),
    };
    try {
      expect(await driveClock(base, runCommand.run(env))).toBe(0);
    } finally {
      await driveClock(base, cleanups.run());
    }
    await new Promise((r) => setImmediate(r));
    const [done] = JSON.parse(text.stdout).completed;
    // The basic posture takes about 1.8 s of robot time: about 90 ms of the base clock at 20 times.
    expect(done.elapsedMs).toBeGreaterThanOrEqual(1700);
    expect(base.now()).toBeGreaterThanOrEqual(done.elapsedMs / 20);
    expect(base.now()).toBeLessThan(done.elapsedMs / 10);
  });
});

describe("the built CLI (dist-cli/)", () => {
  it("is fresh, missing or stale by its manifest and the times of the files it was built from", async () => {
    const dir = await mkdtemp(join(tmpdir(), "rbc-bundle-"));
    try {
      const manifest = (builtAt: number, inputs: string[]) =>
        writeFile(join(dir, "manifest.json"), JSON.stringify({ entry: "main.js", builtAt, inputs }));
      expect(bundleState(dir)).toBe("missing");
      await manifest(Date.now(), ["package.json"]);
      expect(bundleState(dir)).toBe("missing"); // no main.js
      await writeFile(join(dir, "main.js"), "");
      expect(bundleState(dir)).toBe("fresh");
      await manifest(0, ["package.json"]);
      expect(bundleState(dir)).toBe("stale"); // package.json changed after the build
      await manifest(Date.now(), ["package.json", "src/cli/gone.ts"]);
      expect(bundleState(dir)).toBe("stale"); // a source went away
    } finally {
      await rm(dir, { recursive: true, force: true });
    }
  });

  it("--help and --demo never load serialport: only chunks reached by a dynamic import do", async () => {
    const main = cliEntry(); // built if missing or stale
    const outDir = dirname(main);
    const STATIC = /(?:^|\n)\s*(?:import|export)\s[^;]*?from\s*"([^"]+)"|(?:^|\n)\s*import\s*"([^"]+)"/g;
    const DYNAMIC = /\bimport\(\s*"([^"]+)"\s*\)/g;
    /** The bare specifiers (packages) a module and its static imports load, and its dynamic imports. */
    async function walk(files: string[]) {
      const seen = new Set<string>();
      const packages = new Set<string>();
      const dynamic = new Set<string>();
      const queue = [...files];
      for (let file = queue.shift(); file !== undefined; file = queue.shift()) {
        if (seen.has(file)) continue;
        seen.add(file);
        const code = await readFile(join(outDir, file), "utf8");
        for (const m of code.matchAll(STATIC)) {
          const spec = (m[1] ?? m[2])!;
          if (spec.startsWith("./")) queue.push(spec.slice(2));
          else packages.add(spec);
        }
        for (const m of code.matchAll(DYNAMIC)) if (m[1]!.startsWith("./")) dynamic.add(m[1]!.slice(2));
      }
      return { seen, packages, dynamic };
    }
    const start = await walk(["main.js"]);
    expect(start.packages.has("serialport")).toBe(false);
    expect([...start.packages].filter((p) => !p.startsWith("node:"))).toEqual([]); // all else is bundled
    const later = await walk([...start.dynamic]);
    expect(later.packages.has("serialport")).toBe(true);
  });
});

describe("linkKindOfPath", () => {
  it("takes Bluetooth serial ports by their usual names, everything else as wired", async () => {
    const { linkKindOfPath } = await import("../../src/cli/connect.ts");
    expect(linkKindOfPath("/dev/rfcomm0")).toBe("bluetooth");
    expect(linkKindOfPath("/dev/tty.RBC-Bluetooth-SerialPort")).toBe("bluetooth");
    expect(linkKindOfPath("/dev/cu.HC-06-SPP")).toBe("bluetooth");
    expect(linkKindOfPath("/dev/ttyUSB0")).toBe("wired");
    expect(linkKindOfPath("COM3")).toBe("wired");
    expect(linkKindOfPath("/dev/ttyS0")).toBe("wired");
  });
});
