import { readFile } from "node:fs/promises";
import { basename } from "node:path";
import {
  frameLabel,
  TetheredPlayError,
  type TetheredPlayProgress,
  type TetheredPlayResult,
} from "../../device/index.ts";
import {
  type Motion,
  MotionError,
  motionIssues,
  openMotion,
  PLATFORM_PF2,
  playFrames,
} from "../../motion/index.ts";
import { RbmError, STANDARD_ZEROS } from "../../protocol/index.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import type { CommandDef, RunEnv } from "../command.ts";
import { confirm } from "../confirm.ts";
import { connectRobot } from "../connect.ts";
import { CliError, EXIT, UsageError } from "../errors.ts";
import type { Output } from "../output.ts";
import { issueLines, issuesJson } from "../upload-report.ts";
import { rbmInvalid } from "./upload.ts";

const OPTIONS = {
  scenes: { type: "string" },
  yes: { type: "boolean", short: "y" },
} as const;

/** Said before a real robot moves (UI.md: moving actions ask once and say what will happen). */
export const MOVE_WARNING = "The robot will move. Hold it or make sure it can stand.";

const MAX_WARNINGS_SHOWN = 5;

type Range = { from: number; to: number };

/** `--scenes 2` or `--scenes 1-3` (scene numbers as in the file, the first is 0); all scenes by default. */
export function parseScenes(text: string | undefined, doc: Motion, file: string): Range {
  const last = doc.scenes.length - 1;
  if (text === undefined) return { from: 0, to: last };
  const m = /^(\d+)(?:-(\d+))?$/.exec(text.trim());
  if (!m) {
    throw new UsageError(
      `--scenes takes a scene or a range of scenes, e.g. 2 or 1-3 (the first scene is 0), not "${text}".`,
      "play",
    );
  }
  const from = Number(m[1]);
  const to = m[2] === undefined ? from : Number(m[2]);
  if (to < from) throw new UsageError(`--scenes runs forwards: ${from}-${to} does not.`, "play");
  if (to > last) {
    throw new UsageError(
      `${basename(file)} has scenes 0-${last}; --scenes ${text} goes beyond them.`,
      "play",
    );
  }
  return { from, to };
}

function scenesText({ from, to }: Range, doc: Motion): string {
  if (from === 0 && to === doc.scenes.length - 1) return `all ${doc.scenes.length} scenes`;
  return from === to ? `scene ${from}` : `scenes ${from}-${to}`;
}

const seconds = (ms: number) => `${(ms / 1000).toFixed(1)} s`;

/** Reads and checks the file; nothing is opened or sent when it is wrong. */
async function readMotion(env: RunEnv, file: string): Promise<Motion> {
  let text: string;
  try {
    text = await readFile(file, "utf8");
  } catch (e) {
    const why = (e as NodeJS.ErrnoException).code === "ENOENT" ? "no such file" : String(e);
    throw new CliError("file-unreadable", `Cannot read ${file}: ${why}.`);
  }
  try {
    return openMotion(text);
  } catch (e) {
    if (!(e instanceof RbmError)) throw e;
    throw rbmInvalid(env, file, e);
  }
}

/**
 * Where play is, on stderr: redrawn in place on a terminal (at most every 100 ms), otherwise one line per scene.
 *     Scene 2 "WaveIn" (3 of 6), frame 4 of 10, 1.6 of 3.2 s
 */
class PlayProgressLine {
  private lastDraw = Number.NEGATIVE_INFINITY;
  private lastScene: number | undefined;
  private drawn = false;

  constructor(
    private readonly out: Output,
    private readonly doc: Motion,
    private readonly range: Range,
  ) {}

  update(p: TetheredPlayProgress): void {
    const text = this.render(p);
    if (this.out.stderrIsTty) {
      const t = performance.now();
      if (p.index + 1 < p.total && t - this.lastDraw < 100) return;
      this.lastDraw = t;
      this.out.err(`\r${text}\x1b[K`);
      this.drawn = true;
      return;
    }
    if (p.scene === this.lastScene) return;
    this.lastScene = p.scene;
    this.out.err(`${text}\n`);
  }

  finish(): void {
    if (this.drawn) this.out.err("\n");
    this.drawn = false;
  }

  render(p: TetheredPlayProgress): string {
    const time = `${seconds(p.elapsedMs).slice(0, -2)} of ${seconds(p.durationMs)}`;
    if (p.scene < 0) return `Moving to the first pose, step ${p.frame.frame}, ${time}`;
    const scene = this.doc.scenes[p.scene]!;
    const k = p.scene - this.range.from + 1;
    const n = this.range.to - this.range.from + 1;
    return `Scene ${p.scene} "${scene.name}" (${k} of ${n}), frame ${p.frame.frame} of ${scene.frames}, ${time}`;
  }
}

/** The one sentence of what the robot confirmed after a finished play. */
export function finishedSentence(result: TetheredPlayResult, what: string): string {
  const played = `Played ${what}: ${result.framesSent} frames in ${seconds(result.durationMs)}`;
  const late =
    result.maxLateMs >= 5 ? ` (frames went out up to ${Math.round(result.maxLateMs)} ms late)` : "";
  const back = result.readBack;
  if (!back) return `${played}${late}; the robot was not read afterwards, so nothing is confirmed.`;
  const answered = back.positions.filter((p) => p !== undefined).length;
  const silent =
    back.silent.length === 0
      ? ""
      : ` Servo ${back.silent.join(", ")} did not answer: check ${back.silent.length === 1 ? "its cable" : "their cables"}.`;
  const within = back.maxDeviation === 0 ? "at" : `within ${back.maxDeviation} counts of`;
  return `${played}${late}. Read back afterwards, ${answered} servos are ${within} the last frame sent.${silent}`;
}

export const playCommand: CommandDef = {
  name: "play",
  summary: "play a motion file (.rbm) on the robot frame by frame, without uploading it",
  usage: "rbc play FILE.rbm [--scenes A-B] [--yes] (--port PATH | --demo)",
  description: `
Tethered play (PROTOCOL.md §10): rbc plays a Motionbuilder motion file on the robot itself, frame by frame,
as the RBC would play it from its memory, but without uploading anything, so it works with any firmware.
The file is checked first (a file the robot would refuse is refused, and nothing is sent). rbc reads the
robot's stored zeros and applies them, switches the robot to servo control (direct mode), reads where the
servos are, and sends one synchronised move of every servo per frame at the file's timing, every position
inside the servos' safe ranges. Servos the file does not list hold where they are. If a servo is far from the
motion's first pose, rbc first moves there smoothly, as the RBC does.

On a real robot rbc asks once before anything moves:
  ${MOVE_WARNING} Play? [y/N]
--yes skips the question, and without a terminal --yes is required. The demo robot does not ask.

Progress is shown on stderr. At the end rbc reads the servos back and says what the robot confirmed, then
leaves servo control: the servos keep holding the last frame.

Ctrl-C stops after the frame on the wire and nothing more is sent: the servos hold that frame, with torque
(nothing goes limp), and rbc says which frame it was (exit code 130). A second Ctrl-C exits at once.`,
  options: [
    ["--scenes A-B", "Play only scenes A to B, or one scene with --scenes A (the first scene is 0)."],
    ["-y, --yes", "Play on a real robot without the question."],
  ],
  examples: [
    "rbc play examples/wave.rbm --demo",
    "rbc play examples/wave.rbm --scenes 1-4 --port /dev/ttyUSB0",
    "rbc play examples/bow.rbm --port /dev/ttyUSB0 --yes --json",
  ],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("play", env.argv, OPTIONS);
    noExtraArguments("play", positionals, 1);
    const file = positionals[0];
    if (file === undefined) {
      throw new UsageError("Give the motion file to play, e.g. rbc play examples/wave.rbm --demo.", "play");
    }
    const doc = await readMotion(env, file);
    const range = parseScenes(values.scenes, doc, file);
    const what = `${scenesText(range, doc)} of ${basename(file)}`;
    // The plan with standard zeros, for the summary (the robot's own zeros shift positions, not times).
    let plan: ReturnType<typeof playFrames>;
    try {
      plan = playFrames(doc, { range, robotZeros: STANDARD_ZEROS, platform: PLATFORM_PF2 });
    } catch (e) {
      if (!(e instanceof MotionError)) throw e;
      throw new CliError("motion-refused", `${basename(file)}: ${e.message} Nothing was sent.`);
    }
    const validation = motionIssues(doc);
    env.out.line(
      `${file}: motion "${doc.name}", ${doc.servos.length} servos, ${doc.scenes.length} scenes. Playing ${scenesText(range, doc)}: ${plan.frames.length} frames, ${seconds(plan.durationMs)}.`,
    );
    const warnings = issueLines("warning", validation.warnings);
    for (const line of warnings.slice(0, MAX_WARNINGS_SHOWN)) env.out.line(line);
    if (warnings.length > MAX_WARNINGS_SHOWN) {
      env.out.line(`  … and ${warnings.length - MAX_WARNINGS_SHOWN} more warnings (--json lists them all).`);
    }
    const real = !values.demo;
    if (real && !values.yes && !env.stdin.isTTY) {
      throw new CliError("confirmation-required", `${MOVE_WARNING} Add --yes to play (nothing was sent).`);
    }

    const robot = await connectRobot("play", values, env, { handlesInterrupt: true });
    const { client } = robot;
    if (real && !values.yes) {
      const answer = await confirm(env, `${MOVE_WARNING} Play?`);
      if (answer === "interrupted") throw new CliError("interrupted", "Nothing was sent.", EXIT.interrupted);
      if (answer === "no") throw new CliError("not-confirmed", "Play not confirmed; nothing moved.");
    }
    if (env.signal.aborted) throw new CliError("interrupted", "Nothing was sent.", EXIT.interrupted);

    const progress = new PlayProgressLine(env.out, doc, range);
    env.setExitNote(
      "tethered play was interrupted: the servos hold the last frame they got, with torque. The robot stays in servo control until the next rbc command or the panel connects (`rbc limp` makes every servo passive).",
    );
    let result: TetheredPlayResult;
    try {
      result = await client.playTethered(doc, {
        range,
        signal: env.signal,
        onFrame: (p) => progress.update(p),
      });
    } catch (e) {
      env.setExitNote(undefined);
      if (e instanceof TetheredPlayError) {
        throw new CliError(e.code, e.message, EXIT.failed, {
          framesSent: e.framesSent,
          totalFrames: e.totalFrames,
          lastFrame: e.lastFrame ?? null,
          holds: e.holds,
        });
      }
      throw e;
    } finally {
      progress.finish();
    }
    // Back to the normal mode: the servos keep holding the last frame.
    await client.exitDirectMode().catch(() => {});
    env.setExitNote(undefined);
    const json = {
      file,
      demo: robot.demo,
      motion: doc.name,
      scenes: range,
      validation: issuesJson(validation),
      ...result,
      durationMs: Math.round(result.durationMs),
      maxLateMs: Math.round(result.maxLateMs),
    };
    if (result.outcome === "stopped") {
      const held = result.lastFrame
        ? `tethered play stopped after ${result.framesSent} of ${result.totalFrames} frames; the servos hold the last one sent (${frameLabel(result.lastFrame)}), with torque. Nothing was made passive.`
        : "tethered play stopped before the first frame: nothing moved.";
      env.out.note(`rbc: interrupted: ${held}`);
      env.out.result({ ok: false, ...json, error: { code: "interrupted", message: "Interrupted." } });
      return EXIT.interrupted;
    }
    env.out.line(finishedSentence(result, what));
    env.out.line("Left servo control; the servos keep holding the last frame.");
    env.out.result({ ok: true, ...json });
    return EXIT.ok;
  },
};
