import { readFile } from "node:fs/promises";
import { basename, resolve } from "node:path";
import {
  FirmwareUpdateError,
  type FirmwareUpdateOptions,
  type FirmwareUpdateProgress,
  type FirmwareUpdateResult,
  transportFirmwareIo,
  updateFirmware,
} from "../../device/firmware-update.ts";
import type { Locale } from "../../i18n/locale.ts";
import { nothingSentText } from "../../i18n/outcomes/device.ts";
import {
  demoFileCannotRunText,
  demoFileWords,
  firmwareFailureText,
  firmwareNoticeText as firmwareNotice,
  firmwareRestartedText,
  firmwareResultText,
  firmwareSummaryText,
  hexProblemText,
  notIntelHexText,
} from "../../i18n/outcomes/firmware/firmware-words.ts";
import { demoFirmwareParts } from "../../i18n/outcomes/robot-facts.ts";
import { inEveryLanguage, said, saidBy, saidText, saidTogether } from "../../i18n/said.ts";
import { formatNumber, translator } from "../../i18n/translate.ts";
import { declaredVersion } from "../../protocol/firmware-marker.ts";
import {
  IntelHexError,
  type IntelHexImage,
  looksLikeIntelHex,
  parseIntelHex,
} from "../../protocol/intel-hex.ts";
import { formatFirmware } from "../../shared/format.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { confirm } from "../confirm.ts";
import { connectRobot, openRobotPort, robotPlace } from "../connect.ts";
import { CliError, EXIT, UsageError } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import type { Output } from "../output.ts";
import { unreadable } from "../zeros-files.ts";
import { commandMessages } from "./messages.ts";

const OPTIONS = {
  yes: { type: "boolean", short: "y" },
  "demo-file": { type: "boolean" },
  recover: { type: "boolean" },
} as const;

/** How long after asking the demo robot's bootloader is started (robot time): a person takes longer. */
const DEMO_POWER_CYCLE_MS = 500;

/** Reads and checks the file; nothing is opened or sent when it is wrong. */
async function readHex(file: string, cwd: string): Promise<IntelHexImage> {
  let text: string;
  try {
    text = await readFile(resolve(cwd, file), "utf8");
  } catch (e) {
    throw unreadable(file, e);
  }
  try {
    return parseIntelHex(text);
  } catch (e) {
    if (!(e instanceof IntelHexError)) throw e;
    const reason = inEveryLanguage((l) => hexProblemText(e, l));
    // Not Intel HEX at all (a binary, a document): said first, the parser's complaint second (issue 33).
    const words =
      (e.code === "no-colon" || e.code === "not-hex") && !looksLikeIntelHex(text)
        ? saidTogether([
            saidBy((l) => notIntelHexText(basename(file), l)),
            saidText(reason),
            saidBy(nothingSentText),
          ])
        : said(commandMessages, "cmd.flash.notFirmware", { file: basename(file), reason });
    throw new CliError("hex-invalid", words, EXIT.failed, { file, reason: e.code, line: e.line ?? null });
  }
}

/**
 * The firmware progress bar on stderr: lines, bytes, percent, bytes/s and time left (the robot's time).
 *
 *     [########------------]   412/1,025 lines   18,540/46,137 bytes  40%   10,800 B/s   2.5 s left
 *
 * Redrawn in place on a terminal (at most every 100 ms); otherwise one line per 10% step.
 */
class FirmwareProgressBar {
  private lastDraw = Number.NEGATIVE_INFINITY;
  private lastStep = -1;
  private drawn = false;

  constructor(
    private readonly out: Output,
    private readonly locale: Locale = "en",
  ) {}

  update(p: FirmwareUpdateProgress): void {
    if (p.phase !== "sending" && p.phase !== "starting") return;
    const done = p.linesDone >= p.lines;
    if (this.out.stderrIsTty) {
      const t = performance.now();
      if (!done && t - this.lastDraw < 100) return;
      this.lastDraw = t;
      this.out.err(`\r${renderProgress(p, this.locale)}\x1b[K`);
      this.drawn = true;
      return;
    }
    const step = Math.floor((p.bytesDone / Math.max(1, p.bytes)) * 10);
    if (step === this.lastStep) return;
    this.lastStep = step;
    this.out.err(`${renderProgress(p, this.locale)}\n`);
  }

  finish(): void {
    if (this.drawn) this.out.err("\n");
    this.drawn = false;
  }
}

export function renderProgress(p: FirmwareUpdateProgress, locale: Locale = "en"): string {
  const t = translator(commandMessages, locale);
  const n = (v: number) => formatNumber(Math.round(v), locale);
  const fraction = p.bytes > 0 ? Math.min(1, p.bytesDone / p.bytes) : 1;
  const width = 20;
  const filled = Math.round(fraction * width);
  const bar = `[${"#".repeat(filled)}${"-".repeat(width - filled)}]`;
  const rate =
    p.bytesPerSecond === undefined ? "" : t("cmd.flash.rate", { rate: n(p.bytesPerSecond).padStart(6) });
  const seconds = p.msLeft === undefined ? "" : (p.msLeft / 1000).toFixed(1);
  const left =
    p.linesDone >= p.lines
      ? t("cmd.flash.done")
      : p.msLeft === undefined
        ? ""
        : p.paused
          ? t("cmd.flash.leftPaused", { seconds })
          : t("cmd.flash.left", { seconds });
  const lines = t("cmd.flash.lines", { done: n(p.linesDone).padStart(n(p.lines).length), total: n(p.lines) });
  const bytes = t("cmd.flash.bytes", { done: n(p.bytesDone).padStart(n(p.bytes).length), total: n(p.bytes) });
  return `${bar} ${lines}  ${bytes} ${String(Math.floor(fraction * 100)).padStart(3)}%  ${rate}  ${left}`
    .replace(/ {3,}$/, "")
    .trimEnd();
}

export const flashCommand: CommandDef = {
  name: "flash",
  usage: "rbc flash FILE.hex [--yes] [--recover] [--demo-file] (--port PATH | --demo)",
  help: COMMAND_HELP.flash,
  examples: [
    "rbc flash examples/firmware/demo-2.50.hex --demo",
    "rbc flash firmware.hex --port /dev/ttyUSB0",
    "rbc flash firmware.hex --port /dev/ttyUSB0 --recover --yes --json",
  ],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("flash", env.argv, OPTIONS);
    noExtraArguments("flash", positionals, 1);
    const file = positionals[0];
    if (file === undefined) throw new UsageError(said(commandMessages, "cmd.flash.noFile"), "flash");
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    const nothingSent = () => new CliError("interrupted", saidBy(nothingSentText), EXIT.interrupted);
    const image = await readHex(file, env.cwd);
    const name = basename(file);
    const summary = firmwareSummaryText(image.summary, locale);
    env.out.line(`${name}: ${summary}.`);
    const real = !values.demo;
    const declared = declaredVersion(image);
    if (real && declared && !values["demo-file"]) {
      // A demo file on a real robot would leave it without working firmware (docs/firmware-update.md).
      throw new CliError(
        "demo-file",
        said(commandMessages, "cmd.flash.demoFileRefused", {
          title: inEveryLanguage((l) => demoFileWords(declared, l).title),
          text: inEveryLanguage((l) => demoFileWords(declared, l).text),
          cannotRun: inEveryLanguage(demoFileCannotRunText),
          file,
        }),
        EXIT.failed,
        { declaredVersion: formatFirmware(declared) },
      );
    }
    if (real && !values.yes && !env.stdin.isTTY) {
      throw new CliError(
        "confirmation-required",
        said(commandMessages, "cmd.flash.needsYes", {
          notice: inEveryLanguage((l) => firmwareNotice("experimental", l)),
        }),
      );
    }
    if (env.signal.aborted) throw nothingSent();

    // The robot: connected as usual (its version read first), or for --recover a bare port.
    let before: { major: number; minor: number } | undefined;
    let flash: (options: FirmwareUpdateOptions) => Promise<FirmwareUpdateResult>;
    let where: string;
    let bootloader: { powerCycle(): void } | undefined;
    let clock: { setTimeout(fn: () => void, ms: number): unknown };
    if (values.recover) {
      const port = await openRobotPort("flash", values, env);
      where = port.where;
      bootloader = port.bootloader;
      clock = port.clock;
      flash = (options) =>
        updateFirmware(transportFirmwareIo(port.transport, { clock: port.clock }), image, options);
      env.out.line(t("cmd.flash.opened", { robot: robotPlace(port, locale) }));
    } else {
      const robot = await connectRobot("flash", values, env, { handlesInterrupt: true });
      where = robot.where;
      bootloader = robot.bootloader;
      clock = robot.clock;
      before = robot.identity.firmware;
      flash = (options) => robot.client.updateFirmware(image, options);
      const version = { version: formatFirmware(before) };
      env.out.line(
        robot.demo
          ? demoFirmwareParts(version.version, locale).join("")
          : t("cmd.flash.robotReports", { ...version, port: where }),
      );
    }

    if (real) {
      env.out.note(firmwareNotice("experimental", locale));
      env.out.note(firmwareNotice("recovery", locale));
      env.out.note(firmwareNotice("keepPowered", locale));
      const answer = values.yes
        ? "yes"
        : await confirm(env, t("cmd.flash.question", { file: name, port: where }));
      if (answer === "interrupted") throw nothingSent();
      if (answer === "no")
        throw new CliError("not-confirmed", said(commandMessages, "cmd.flash.notConfirmed"));
    }
    if (env.signal.aborted) throw nothingSent();

    const bar = new FirmwareProgressBar(env.out, locale);
    let announced = false;
    let result: FirmwareUpdateResult;
    try {
      result = await flash({
        signal: env.signal,
        // The demo robot's link has no baud pacing: its answers may come sooner than a wire could carry them.
        wireTimed: bootloader === undefined,
        onAskPowerCycle: () => {
          const ask = firmwareNotice("askPowerCycle", locale);
          if (bootloader) {
            env.out.note(`${ask} ${firmwareNotice("demoRestarts", locale)}`);
            const boot = bootloader;
            clock.setTimeout(() => boot.powerCycle(), DEMO_POWER_CYCLE_MS);
          } else {
            env.out.note(`${ask} ${t("cmd.flash.waiting")}`);
          }
        },
        onProgress: (p) => {
          if (!announced && p.phase === "sending") {
            announced = true;
            env.out.note(t("cmd.flash.sending"));
            env.setExitNote(t("cmd.flash.exitNote"));
          }
          bar.update(p);
        },
      });
    } catch (e) {
      bar.finish();
      env.setExitNote(undefined);
      if (e instanceof FirmwareUpdateError) {
        const details = { failure: e.failure, holds: e.holds, line: e.line ?? null, file };
        if (e.failure === "cancelled") {
          const what = firmwareFailureText(e, locale);
          env.out.note(`rbc: ${t("cmd.flash.interrupted", { what })}`);
          env.out.result({
            ok: false,
            error: { code: "interrupted", message: firmwareFailureText(e, "en"), ...details },
          });
          return EXIT.interrupted;
        }
        const words = saidText({ en: firmwareFailureText(e, "en"), ko: firmwareFailureText(e, "ko") });
        throw new CliError(e.failure, words, EXIT.failed, details);
      }
      throw e;
    }
    bar.finish();
    env.setExitNote(undefined);
    env.out.result({
      ok: true,
      file,
      demo: !real,
      recover: values.recover === true,
      before: before ? formatFirmware(before) : null,
      firmware: formatFirmware(result.firmware),
      summary: image.summary,
      lines: result.lines,
      bytes: result.bytes,
      resends: result.resends,
      seconds: Math.round(result.sendingMs) / 1000,
      bytesPerSecond: Math.round(result.bytesPerSecond),
      linesPerSecond: Math.round(result.linesPerSecond),
    });
    const n = (v: number) => Math.round(v);
    env.out.line(firmwareResultText(result, before, locale));
    env.out.line(
      t("cmd.flash.sent", {
        bytes: n(result.bytes),
        rate: n(result.bytesPerSecond),
        lines: n(result.linesPerSecond),
      }),
    );
    env.out.line(`${firmwareRestartedText(locale)} ${t("cmd.flash.runPosture")}`);
    return EXIT.ok;
  },
};
