import { closeSync, constants, openSync, writeSync } from "node:fs";
import { ReadStream } from "node:tty";
import { describe, expect, it } from "vitest";
import { UsageError } from "../../src/cli/errors.ts";
import { createPtyPair } from "../../src/cli/pty.ts";
import {
  DEMO_VARIANT_VAR,
  demoVariant,
  describeVariant,
  variantFromValues,
} from "../../src/cli/sim-variant.ts";
import { toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { createDemoRbc } from "../../src/sim/index.ts";
import { CliScope } from "../cli/spawn-cli.ts";

/**
 * The servo-bus faults as switches of `rbc sim` and RBC_DEMO_VARIANT (docs/protocol.md §5; the simulator's side is
 * tests/unit/sim-servo-bus.test.ts).
 */

const T = 30_000;
const fromHex = (hex: string) => Uint8Array.from(hex.split(" "), (h) => Number.parseInt(h, 16));
const ENTER_DIRECT = "FF FF AA 55 AA 55 37 BA 10 00 00 00 00 01 01 01";
const ENTER_DIRECT_REPLY = "FF FF AA 55 AA 55 37 BA 10 01 00 00 00 01 01 01";

const SWITCHES = [
  { args: ["--servo-missing", "7"], faults: { missing: [7] }, words: "no servo at id 7" },
  {
    args: ["--servo-duplicate", "3"],
    faults: { duplicate: [3] },
    words: "two servos at id 3 (replies garbled)",
  },
  {
    args: ["--servo-replacement", "12"],
    faults: { replacement: [12] },
    words: "servo 12 replaced by one still at id 0",
  },
  {
    args: ["--servo-loaded", "4"],
    faults: { loaded: [4] },
    words: "servo 4 under high load (follows a move only part of the way)",
  },
] as const;

describe("RBC_DEMO_VARIANT takes the servo-fault switches", () => {
  for (const s of SWITCHES) {
    it(s.args.join(" "), () => {
      expect(demoVariant({ [DEMO_VARIANT_VAR]: s.args.join(" ") }, "info")).toEqual({
        servoFaults: s.faults,
      });
    });
  }

  it("all at once, one switch given twice", () => {
    const text = `${SWITCHES.flatMap((s) => s.args).join(" ")} --servo-missing 9`;
    expect(demoVariant({ [DEMO_VARIANT_VAR]: text })).toEqual({
      servoFaults: { missing: [7, 9], duplicate: [3], replacement: [12], loaded: [4] },
    });
  });

  it("a bad id is a usage error that names the switch and the range", () => {
    for (const [option, bad, range] of [
      ["servo-missing", "16", "0 to 15"],
      ["servo-duplicate", "x", "0 to 15"],
      ["servo-loaded", "-1", "0 to 15"],
      ["servo-replacement", "0", "1 to 15"],
    ] as const) {
      expect(() => variantFromValues({ [option]: [bad] }, "sim")).toThrow(UsageError);
      expect(() => demoVariant({ [DEMO_VARIANT_VAR]: `--${option}=${bad}` })).toThrow(
        `--${option} must be a servo id from ${range}, got "${bad}".`,
      );
    }
  });

  it("--servo-late N:MS: servo N answers MS ms late (docs/protocol.md §9), in words in both languages", () => {
    const variant = demoVariant({ [DEMO_VARIANT_VAR]: "--servo-late 7:60 --servo-late 3:110" });
    expect(variant).toEqual({ servoFaults: { late: { 7: 60, 3: 110 } } });
    expect(describeVariant(variant, "en")).toEqual([
      "servo 3 answers 110 ms late",
      "servo 7 answers 60 ms late",
    ]);
    expect(describeVariant(variant, "ko")).toEqual([
      "서보 3번이 110ms 늦게 응답함",
      "서보 7번이 60ms 늦게 응답함",
    ]);
    for (const bad of ["16:60", "7", "7:x", "7:6000"]) {
      expect(() => demoVariant({ [DEMO_VARIANT_VAR]: `--servo-late=${bad}` })).toThrow(
        `--servo-late takes a servo id from 0 to 15 and a delay of 0 to 5000 ms, as 7:60, got "${bad}".`,
      );
    }
  });

  it("the demo robot made from --servo-late 7:60: read 7 is answered 60 ms after it is received, not at once", async () => {
    const clock = new VirtualClock();
    const sim = createDemoRbc({ clock, ...demoVariant({ [DEMO_VARIANT_VAR]: "--servo-late 7:60" }) });
    const out: string[] = [];
    sim.onTransmit((b) => out.push(toHex(b)));
    sim.receive(fromHex(ENTER_DIRECT));
    sim.receive(fromHex("FF A7 00 27"));
    expect(out).toEqual([ENTER_DIRECT_REPLY]);
    await clock.advance(59);
    expect(out).toEqual([ENTER_DIRECT_REPLY]);
    await clock.advance(1);
    expect(out).toEqual([ENTER_DIRECT_REPLY, "00 31"]);
  });

  it("one servo both missing and replaced is refused", () => {
    expect(() => demoVariant({ [DEMO_VARIANT_VAR]: "--servo-missing 5 --servo-replacement 5" })).toThrow(
      /Servo 5 cannot be both missing/,
    );
  });

  it("the words in Korean too", () => {
    const variant = demoVariant({ [DEMO_VARIANT_VAR]: "--servo-replacement 12 --servo-missing 7" });
    expect(describeVariant(variant, "ko")).toEqual([
      "ID 7에 서보 없음",
      "서보 12번을 ID 0 그대로인 새 서보로 교체함",
    ]);
  });

  it("the demo robot made from the variable has the fault: id 0 garbled, id 12 silent", () => {
    const variant = demoVariant({ [DEMO_VARIANT_VAR]: "--servo-replacement 12" });
    const sim = createDemoRbc({ clock: new VirtualClock(), ...variant });
    const out: string[] = [];
    sim.onTransmit((b) => out.push(toHex(b)));
    sim.receive(fromHex(ENTER_DIRECT));
    sim.receive(fromHex("FF A0 00 20"));
    sim.receive(fromHex("FF AC 00 2C"));
    expect(out).toEqual([ENTER_DIRECT_REPLY, "00 00 31"]);
  });
});

/**
 * The client end of a PTY opened as a plain terminal (the serialport addon cannot run in this worker thread):
 * `collect(n)` resolves with the next `n` bytes once they have arrived (an event, not a wait on a clock).
 */
function openClient(path: string) {
  const fd = openSync(path, constants.O_RDWR | constants.O_NOCTTY);
  const input = new ReadStream(fd);
  let got: number[] = [];
  let want: { count: number; resolve: (hex: string) => void } | undefined;
  const check = () => {
    if (want && got.length >= want.count) {
      const bytes = got.splice(0, want.count);
      want.resolve(toHex(Uint8Array.from(bytes)));
      want = undefined;
    }
  };
  input.on("data", (chunk: Buffer) => {
    got.push(...chunk);
    check();
  });
  return {
    write: (hex: string) => writeSync(fd, fromHex(hex)),
    collect: (count: number) =>
      new Promise<string>((resolve) => {
        want = { count, resolve };
        check();
      }),
    /** Bytes received beyond those collected. */
    extra: () => toHex(Uint8Array.from(got)),
    close: () => {
      got = [];
      input.destroy();
      try {
        closeSync(fd);
      } catch {
        // Already closed with the stream.
      }
    },
  };
}

describe("rbc sim accepts the switches", () => {
  it("rbc sim --pty with every servo switch: ready, says each in its ready line and its JSON", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const sim = scope.start(["sim", "--pty", "--json", ...SWITCHES.flatMap((s) => s.args)], { timeoutMs: T });
    const [line] = await sim.waitFor("stdout", /^\{"event":"ready".*$/m, 20_000);
    const ready = JSON.parse(line);
    expect(ready.robot.servoFaults).toEqual({ missing: [7], duplicate: [3], replacement: [12], loaded: [4] });
    sim.child.kill("SIGINT");
    expect((await sim.done).code).toBe(0);
    const human = scope.start(["sim", "--pty", ...SWITCHES.flatMap((s) => s.args)], { timeoutMs: T });
    const [words] = await human.waitFor("stdout", /^Simulated RBC .* listening on .*$/m, 20_000);
    for (const s of SWITCHES) expect(words).toContain(s.words);
    human.child.kill("SIGINT");
    expect((await human.done).code).toBe(0);
  });

  it("rbc sim --port with --servo-replacement 12, over a PTY: id 0 answers 3 garbled bytes, id 12 nothing", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const pty = await createPtyPair();
    onTestFinished(() => pty.close());
    const sim = scope.start(["sim", "--port", pty.simPath, "--servo-replacement", "12"], { timeoutMs: T });
    await sim.waitFor("stdout", /listening on/, 20_000);
    const link = openClient(pty.clientPath);
    onTestFinished(link.close);
    const entered = link.collect(16);
    link.write(ENTER_DIRECT);
    expect(await entered).toBe(ENTER_DIRECT_REPLY);
    // Id 12 first (silent), then id 0: the only bytes that come back are id 0's collided replies.
    const garbled = link.collect(3);
    link.write("FF AC 00 2C FF A0 00 20");
    expect(await garbled).toBe("00 00 31");
    const read7 = link.collect(2);
    link.write("FF A7 00 27 FF E0 FB 01 00 1A");
    expect(await read7).toBe("00 31");
    expect(link.extra()).toBe("");
    sim.child.kill("SIGINT");
    expect((await sim.done).code).toBe(0);
  });

  it("rbc sim --pty --servo-replacement 0 is refused (exit 2) with the sentence", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const r = await scope.run(["sim", "--pty", "--servo-replacement", "0"]);
    expect(r.code).toBe(2);
    expect(r.stderr).toContain('--servo-replacement must be a servo id from 1 to 15, got "0".');
  });
});

describe("rbc servos against rbc sim over a PTY (the serial path, not the demo robot)", () => {
  it("scan with every fault: id 7 silent, id 3 garbled, id 0 garbled and id 12 silent (a replacement), id 4 loaded; exit 1", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const sim = scope.start(["sim", "--pty", "--quiet", ...SWITCHES.flatMap((s) => s.args)], {
      timeoutMs: T,
    });
    const [, client] = await sim.waitFor("stdout", /Clients connect to (\S+),/, 20_000);
    const scan = await scope.run(["servos", "scan", "--port", client!, "--json"], { timeoutMs: T });
    expect(scan.code, scan.stderr).toBe(1);
    const result = JSON.parse(scan.stdout) as {
      servos: { id: number; status: string; load?: number }[];
      findings: { code: string; ids: number[] }[];
    };
    const status = (id: number) => result.servos.find((s) => s.id === id)?.status;
    expect([0, 3, 4, 7, 12].map(status)).toEqual(["garbled", "garbled", "answered", "silent", "silent"]);
    // 16 ids: 0 and 3 garbled, 7 and 12 silent, the other 12 answered (4 among them, loaded).
    expect(result.servos.filter((s) => s.status === "answered")).toHaveLength(12);
    expect(result.servos.find((s) => s.id === 4)!.load).toBeGreaterThan(100);
    // Id 0 garbled with ids 7 and 12 silent reads as a replacement servo for one of them (the scan cannot tell
    // which); id 3 garbled alone is a duplicate; servo 4 is loaded.
    expect(result.findings.map((f) => [f.code, f.ids])).toEqual([
      ["servo-replacement", [0, 7, 12]],
      ["servo-duplicate", [3]],
      ["servo-high-load", [4]],
    ]);
    sim.child.kill("SIGINT");
    expect((await sim.done).code).toBe(0);
  });

  it("a replacement servo for 12 alone: set-id 0 12 is refused while two servos answer at id 0 (exit 1, nothing written)", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const sim = scope.start(["sim", "--pty", "--servo-replacement", "12"], { timeoutMs: T });
    const [, client] = await sim.waitFor("stdout", /Clients connect to (\S+),/, 20_000);
    const fix = await scope.run(["servos", "set-id", "0", "12", "--yes", "--port", client!], {
      timeoutMs: T,
    });
    expect(fix.code).toBe(1);
    // The refusal is the command's result (stdout), with exit 1.
    expect(fix.stdout).toContain("Not changed: more than one servo answers at id 0");
    // The sim's trace: no id-set packet (FF E0 0C …) ever reached the servo bus.
    expect(sim.stdout).not.toMatch(/FF E0 0C/);
    sim.child.kill("SIGINT");
    expect((await sim.done).code).toBe(0);
  });
});
