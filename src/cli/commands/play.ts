import { readFile } from "node:fs/promises";
import { basename, resolve } from "node:path";
import { TetheredPlayError, type TetheredPlayProgress, type TetheredPlayResult } from "../../device/index.ts";
import type { Locale } from "../../i18n/locale.ts";
import { nothingSentText } from "../../i18n/outcomes/device.ts";
import { motionRefusalText } from "../../i18n/outcomes/motion/motion-words.ts";
import { sceneText } from "../../i18n/outcomes/motion/position-words.ts";
import { playStoppedText } from "../../i18n/outcomes/stop-words.ts";
import { inEveryLanguage, said, saidBy, saidText } from "../../i18n/said.ts";
import { translator } from "../../i18n/translate.ts";
import { formatSeconds } from "../../i18n/units.ts";
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
import { type CommandDef, localeOf, type RunEnv } from "../command.ts";
import { confirm } from "../confirm.ts";
import { connectRobot } from "../connect.ts";
import { CliError, EXIT, errorLine, UsageError } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { cliMessages } from "../messages.ts";
import type { Output } from "../output.ts";
import { issueLines, issuesJson } from "../upload-report.ts";
import { unreadable } from "../zeros-files.ts";
import { commandMessages } from "./messages.ts";
import { issueWords, rbmInvalid } from "./upload.ts";

const OPTIONS = {
  scenes: { type: "string" },
  yes: { type: "boolean", short: "y" },
} as const;

/** The move warning in `locale`: said before a real robot moves (docs/ui.md: moving actions ask once). */
function moveWarning(locale: Locale): string {
  return translator(cliMessages, locale)("cli.play.moveWarning");
}

const MAX_WARNINGS_SHOWN = 5;

type Range = { from: number; to: number };

/** `--scenes 2` or `--scenes 1-3` (scene numbers as in the file, the first is 0); all scenes by default. */
export function parseScenes(text: string | undefined, doc: Motion, file: string): Range {
  const last = doc.scenes.length - 1;
  if (text === undefined) return { from: 0, to: last };
  const m = /^(\d+)(?:-(\d+))?$/.exec(text.trim());
  if (!m) throw new UsageError(said(commandMessages, "cmd.play.scenesForm", { value: text }), "play");
  const from = Number(m[1]);
  const to = m[2] === undefined ? from : Number(m[2]);
  if (to < from) {
    throw new UsageError(
      said(commandMessages, "cmd.play.scenesBackwards", { from: String(from), to: String(to) }),
      "play",
    );
  }
  if (to > last) {
    const beyond = { file: basename(file), last: String(last), value: text };
    throw new UsageError(said(commandMessages, "cmd.play.scenesBeyond", beyond), "play");
  }
  return { from, to };
}

function scenesText({ from, to }: Range, doc: Motion, locale: Locale): string {
  const t = translator(commandMessages, locale);
  if (from === 0 && to === doc.scenes.length - 1)
    return t("cmd.play.allScenes", { total: String(doc.scenes.length) });
  return from === to
    ? sceneText(from, locale)
    : t("cmd.play.someScenes", { from: String(from), to: String(to) });
}

const seconds = (ms: number, locale: Locale) => formatSeconds(ms / 1000, locale);

/** Reads and checks the file; nothing is opened or sent when it is wrong. */
async function readMotion(env: RunEnv, file: string): Promise<Motion> {
  let text: string;
  try {
    text = await readFile(resolve(env.cwd, file), "utf8");
  } catch (e) {
    throw unreadable(file, e);
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
    private readonly locale: Locale = "en",
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
    const t = translator(commandMessages, this.locale);
    const time = t("cmd.play.time", {
      elapsed: (p.elapsedMs / 1000).toFixed(1),
      duration: seconds(p.durationMs, this.locale),
    });
    if (p.scene < 0) return t("cmd.play.toFirstPose", { step: String(p.frame.frame), time });
    const scene = this.doc.scenes[p.scene]!;
    const k = p.scene - this.range.from + 1;
    const n = this.range.to - this.range.from + 1;
    return t("cmd.play.progress", {
      scene: String(p.scene),
      name: scene.name,
      k: String(k),
      n: String(n),
      frame: String(p.frame.frame),
      frames: String(scene.frames),
      time,
    });
  }
}

/** The one sentence of what the robot confirmed after a finished play; `what` is said in `locale`. */
export function finishedSentence(result: TetheredPlayResult, what: string, locale: Locale = "en"): string {
  const t = translator(commandMessages, locale);
  const played = {
    what,
    frames: String(result.framesSent),
    duration: seconds(result.durationMs, locale),
    late: result.maxLateMs >= 5 ? ` ${t("cmd.play.late", { ms: String(Math.round(result.maxLateMs)) })}` : "",
  };
  const back = result.readBack;
  if (!back) return t("cmd.play.playedUnread", played);
  const answered = back.positions.filter((p) => p !== undefined).length;
  const servos = back.silent.join(", ");
  const silent =
    back.silent.length === 0
      ? ""
      : ` ${back.silent.length === 1 ? t("cmd.play.silentOne", { servos }) : t("cmd.play.silentMany", { servos })}`;
  const read = { ...played, answered: String(answered), silent };
  return back.maxDeviation === 0
    ? t("cmd.play.playedAt", read)
    : t("cmd.play.playedWithin", { ...read, deviation: String(back.maxDeviation) });
}

export const playCommand: CommandDef = {
  name: "play",
  usage: "rbc play FILE.rbm [--scenes A-B] [--yes] (--port PATH | --demo)",
  help: COMMAND_HELP.play,
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
    if (file === undefined) throw new UsageError(said(commandMessages, "cmd.play.noFile"), "play");
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    const nothingSent = () => new CliError("interrupted", saidBy(nothingSentText), EXIT.interrupted);
    const doc = await readMotion(env, file);
    const range = parseScenes(values.scenes, doc, file);
    const what = t("cmd.play.what", { scenes: scenesText(range, doc, locale), file: basename(file) });
    // The plan with standard zeros, for the summary (the robot's own zeros shift positions, not times).
    let plan: ReturnType<typeof playFrames>;
    try {
      plan = playFrames(doc, { range, robotZeros: STANDARD_ZEROS, platform: PLATFORM_PF2 });
    } catch (e) {
      if (!(e instanceof MotionError)) throw e;
      // The motion core's reason, from the outcome catalogue, in every language.
      const words = said(commandMessages, "cmd.play.refused", {
        file: basename(file),
        reason: inEveryLanguage((l) => motionRefusalText(e, l)),
      });
      throw new CliError("motion-refused", words);
    }
    const validation = motionIssues(doc);
    env.out.line(
      t("cmd.play.summary", {
        file,
        name: doc.name,
        servos: String(doc.servos.length),
        scenes: String(doc.scenes.length),
        playing: scenesText(range, doc, locale),
        frames: String(plan.frames.length),
        duration: seconds(plan.durationMs, locale),
      }),
    );
    const warnings = issueLines("warning", validation.warnings, issueWords(env));
    for (const line of warnings.slice(0, MAX_WARNINGS_SHOWN)) env.out.line(line);
    if (warnings.length > MAX_WARNINGS_SHOWN) {
      env.out.line(`  ${t("cmd.moreWarnings", { more: String(warnings.length - MAX_WARNINGS_SHOWN) })}`);
    }
    const real = !values.demo;
    if (real && !values.yes && !env.stdin.isTTY) {
      throw new CliError(
        "confirmation-required",
        said(commandMessages, "cmd.play.needsYes", { warning: inEveryLanguage(moveWarning) }),
      );
    }

    const robot = await connectRobot("play", values, env, { handlesInterrupt: true });
    const { client } = robot;
    if (real && !values.yes) {
      const question = translator(cliMessages, locale)("cli.play.question", { warning: moveWarning(locale) });
      const answer = await confirm(env, question);
      if (answer === "interrupted") throw nothingSent();
      if (answer === "no")
        throw new CliError("not-confirmed", said(commandMessages, "cmd.play.notConfirmed"));
    }
    if (env.signal.aborted) throw nothingSent();

    const progress = new PlayProgressLine(env.out, doc, range, locale);
    env.setExitNote(t("cmd.play.exitNote"));
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
        // The catalogue's sentence says what the servos hold (nothing sent, the last frame, unknown).
        const words = saidText({ en: errorLine(e, "en"), ko: errorLine(e, "ko") });
        throw new CliError(e.code, words, EXIT.failed, {
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
      const held = `${playStoppedText(result, locale)} ${t("cmd.play.nothingPassive")}`;
      env.out.note(`rbc: ${t("cmd.interruptedBecause", { what: held })}`);
      env.out.result({ ok: false, ...json, error: { code: "interrupted", message: "Interrupted." } });
      return EXIT.interrupted;
    }
    env.out.line(finishedSentence(result, what, locale));
    env.out.line(t("cmd.play.left"));
    env.out.result({ ok: true, ...json });
    return EXIT.ok;
  },
};
