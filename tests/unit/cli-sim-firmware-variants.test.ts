import { describe, expect, it } from "vitest";
import { UsageError } from "../../src/cli/errors.ts";
import { DEMO_VARIANT_VAR, demoVariant, variantFromValues } from "../../src/cli/sim-variant.ts";
import { runInProcess } from "../cli/in-process.ts";
import { CliScope } from "../cli/spawn-cli.ts";

/**
 * The switches of `rbc sim` and RBC_DEMO_VARIANT for the firmware behaviours of docs/protocol.md §3.1, §3.5,
 * §3.6 (the simulator's side is tests/unit/sim-firmware-variants.test.ts).
 */

const T = 30_000;

/** Each switch, the simulator option it sets, and the words of `rbc sim`'s ready line. */
const SWITCHES = [
  {
    args: ["--firmware-events"],
    option: { firmwareEventPace: true },
    words: "events at the firmware's pace",
  },
  {
    args: ["--busy-motion", "3"],
    option: { busyMotion: 3 },
    words: "busy with motion 3 from the remote at connect",
  },
  { args: ["--user-firmware"], option: { userFirmware: true }, words: 'the official "user" build\'s keys' },
  {
    args: ["--no-memory-read"],
    option: { answersMemoryRead: false },
    words: "no answer to 0x0F (free memory)",
  },
  { args: ["--servos-silent"], option: { servosSilent: true }, words: "servos silent" },
  {
    args: ["--sound-reply-at-once"],
    option: { soundReplyAtOnce: true },
    words: "Run Sound answered at once",
  },
  {
    args: ["--repeat-distance"],
    option: { repeatReplies: { type: 0x16, intervalMs: 0.955 } },
    words: "the first 0x16 (Distance sensor) reply repeated endlessly",
  },
] as const;

describe("RBC_DEMO_VARIANT takes each switch", () => {
  for (const s of SWITCHES) {
    it(s.args.join(" "), () => {
      expect(demoVariant({ [DEMO_VARIANT_VAR]: s.args.join(" ") }, "info")).toEqual(s.option);
    });
  }

  it("all of them at once", () => {
    const text = SWITCHES.flatMap((s) => s.args).join(" ");
    expect(demoVariant({ [DEMO_VARIANT_VAR]: text })).toEqual(
      Object.assign({}, ...SWITCHES.map((s) => s.option)),
    );
  });

  it("--busy-motion outside 1-11 is a usage error that names the switch", () => {
    for (const bad of ["0", "12", "x", "4.5"]) {
      expect(() => variantFromValues({ "busy-motion": bad }, "sim")).toThrow(UsageError);
      expect(() => demoVariant({ [DEMO_VARIANT_VAR]: `--busy-motion ${bad}` })).toThrow(
        /--busy-motion must be a built-in motion number from 1 to 11/,
      );
    }
  });
});

describe("the CLI accepts the switches", () => {
  it("rbc sim --pty with every switch: ready, and says each in its ready line", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const sim = scope.start(["sim", "--pty", ...SWITCHES.flatMap((s) => s.args)], { timeoutMs: T });
    const [ready] = await sim.waitFor("stdout", /^Simulated RBC .* listening on .*$/m, 20_000);
    for (const s of SWITCHES) expect(ready).toContain(s.words);
    sim.child.kill("SIGINT");
    expect((await sim.done).code).toBe(0);
  });

  it("rbc sim --pty --busy-motion 12 is refused (exit 2) with the sentence", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const r = await scope.run(["sim", "--pty", "--busy-motion", "12"]);
    expect(r.code).toBe(2);
    expect(r.stderr).toContain('--busy-motion must be a built-in motion number from 1 to 11, got "12".');
  });

  it("rbc info --demo with RBC_DEMO_VARIANT of the user build, firmware pace, sound reply at once", {
    timeout: T,
  }, async () => {
    // In this process, the demo robot on a virtual clock (tests/cli/in-process.ts).
    const r = await runInProcess(["info", "--demo", "--json"], {
      env: { [DEMO_VARIANT_VAR]: "--user-firmware --firmware-events --sound-reply-at-once" },
    });
    expect(r.code, r.stderr).toBe(0);
    expect(JSON.parse(r.stdout)).toMatchObject({ firmware: "2.23", platform: 1 });
  });
});
