import { readFile } from "node:fs/promises";
import { basename } from "node:path";
import {
  FIRMWARE_NOTICES,
  FirmwareUpdateError,
  type FirmwareUpdateOptions,
  type FirmwareUpdateProgress,
  type FirmwareUpdateResult,
  firmwareFileSummary,
  firmwareResultSentence,
  transportFirmwareIo,
  updateFirmware,
} from "../../device/firmware-update.ts";
import { IntelHexError, type IntelHexImage, parseIntelHex } from "../../protocol/intel-hex.ts";
import { formatFirmware } from "../../shared/format.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import type { CommandDef } from "../command.ts";
import { confirm } from "../confirm.ts";
import { connectRobot, openRobotPort } from "../connect.ts";
import { CliError, EXIT, UsageError } from "../errors.ts";
import type { Output } from "../output.ts";

const OPTIONS = {
  yes: { type: "boolean", short: "y" },
  recover: { type: "boolean" },
} as const;

/** How long after asking the demo robot's bootloader is started (robot time): a person takes longer. */
const DEMO_POWER_CYCLE_MS = 500;

/** Reads and checks the file; nothing is opened or sent when it is wrong. */
async function readHex(file: string): Promise<IntelHexImage> {
  let text: string;
  try {
    text = await readFile(file, "utf8");
  } catch (e) {
    const why = (e as NodeJS.ErrnoException).code === "ENOENT" ? "no such file" : String(e);
    throw new CliError("file-unreadable", `Cannot read ${file}: ${why}.`);
  }
  try {
    return parseIntelHex(text);
  } catch (e) {
    if (!(e instanceof IntelHexError)) throw e;
    throw new CliError(
      "hex-invalid",
      `${basename(file)} is not a firmware file the RBC's bootloader can take. ${e.message} Nothing was sent.`,
      EXIT.failed,
      { file, reason: e.code, line: e.line ?? null },
    );
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

  constructor(private readonly out: Output) {}

  update(p: FirmwareUpdateProgress): void {
    if (p.phase !== "sending" && p.phase !== "starting") return;
    const done = p.linesDone >= p.lines;
    if (this.out.stderrIsTty) {
      const t = performance.now();
      if (!done && t - this.lastDraw < 100) return;
      this.lastDraw = t;
      this.out.err(`\r${renderProgress(p)}\x1b[K`);
      this.drawn = true;
      return;
    }
    const step = Math.floor((p.bytesDone / Math.max(1, p.bytes)) * 10);
    if (step === this.lastStep) return;
    this.lastStep = step;
    this.out.err(`${renderProgress(p)}\n`);
  }

  finish(): void {
    if (this.drawn) this.out.err("\n");
    this.drawn = false;
  }
}

export function renderProgress(p: FirmwareUpdateProgress): string {
  const n = (v: number) => Math.round(v).toLocaleString("en-US");
  const fraction = p.bytes > 0 ? Math.min(1, p.bytesDone / p.bytes) : 1;
  const width = 20;
  const filled = Math.round(fraction * width);
  const bar = `[${"#".repeat(filled)}${"-".repeat(width - filled)}]`;
  const rate = p.bytesPerSecond === undefined ? "" : `${n(p.bytesPerSecond).padStart(6)} B/s`;
  const left =
    p.linesDone >= p.lines
      ? "done"
      : p.msLeft === undefined
        ? ""
        : `${(p.msLeft / 1000).toFixed(1)} s left${p.paused ? " (page write)" : ""}`;
  const lines = `${n(p.linesDone).padStart(n(p.lines).length)}/${n(p.lines)} lines`;
  const bytes = `${n(p.bytesDone).padStart(n(p.bytes).length)}/${n(p.bytes)} bytes`;
  return `${bar} ${lines}  ${bytes} ${String(Math.floor(fraction * 100)).padStart(3)}%  ${rate}  ${left}`
    .replace(/ {3,}$/, "")
    .trimEnd();
}

export const flashCommand: CommandDef = {
  name: "flash",
  summary: "check a firmware file (.hex) and write it to the robot through its bootloader",
  usage: "rbc flash FILE.hex [--yes] [--recover] (--port PATH | --demo)",
  description: `
Replaces the robot's firmware with an Intel HEX file, through the bootloader in the RBC's ATmega128 (the
protocol of RBCLoader, PROTOCOL.md §11). First the file is checked — record checksums, record types 00, 01,
02 and 04 only, every address inside the 128 KiB flash and below the bootloader's section (0x1E000) — and
summarised (size, address range, flash pages, lines); a bad file is refused with the line to blame, and
nothing is sent. Then rbc reads the robot's current version, asks once for confirmation (a real robot only:
y at the prompt, or --yes), and asks you to switch the robot off and on: the bootloader announces itself
when the robot starts, and the file goes to it line by line, with a progress bar on stderr (lines, bytes,
rate, time left). At the end rbc reads the version the new firmware reports and says it in a sentence.

Experimental on real robots. The bootloader itself is never written, so a failed or interrupted update is
fixed by running the update again. Keep the robot powered and lying down, and the cable plugged in.

The demo robot (--demo) has the same bootloader; it restarts by itself when asked to. Try it with the
project's example file, which declares firmware 2.50:
  rbc flash examples/firmware/demo-2.50.hex --demo

A robot whose firmware no longer answers (after a failed update) cannot be connected to as usual: --recover
opens the port without the usual handshake and runs the update the same way.

Ctrl-C stops the update: rbc says what the robot holds (nothing written, or a firmware that may be
incomplete) and how to recover, and exits with code 130.`,
  options: [
    ["-y, --yes", "Confirm an update of a real robot without the prompt."],
    ["--recover", "Do not expect the robot to answer first (a robot left without a working firmware)."],
  ],
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
    if (file === undefined) {
      throw new UsageError(
        "Give the firmware file to write, e.g. rbc flash examples/firmware/demo-2.50.hex --demo.",
        "flash",
      );
    }
    const image = await readHex(file);
    const name = basename(file);
    env.out.line(`${name}: ${firmwareFileSummary(image.summary)}.`);
    const real = !values.demo;
    if (real && !values.yes && !env.stdin.isTTY) {
      throw new CliError(
        "confirmation-required",
        `${FIRMWARE_NOTICES.experimental} Add --yes to update anyway (nothing was sent).`,
      );
    }
    if (env.signal.aborted) throw new CliError("interrupted", "Nothing was sent.", EXIT.interrupted);

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
      env.out.line(`Opened ${where} without asking the robot anything (--recover).`);
    } else {
      const robot = await connectRobot("flash", values, env, { handlesInterrupt: true });
      where = robot.where;
      bootloader = robot.bootloader;
      clock = robot.clock;
      before = robot.identity.firmware;
      flash = (options) => robot.client.updateFirmware(image, options);
      env.out.line(
        `${robot.demo ? "The demo robot" : `The robot on ${where}`} reports firmware ${formatFirmware(before)}.`,
      );
    }

    if (real) {
      env.out.note(FIRMWARE_NOTICES.experimental);
      env.out.note(FIRMWARE_NOTICES.recovery);
      env.out.note(FIRMWARE_NOTICES.keepPowered);
      const answer = values.yes
        ? "yes"
        : await confirm(env, `Write ${name} to the robot on ${where}, replacing its firmware?`);
      if (answer === "interrupted") throw new CliError("interrupted", "Nothing was sent.", EXIT.interrupted);
      if (answer === "no") throw new CliError("not-confirmed", "Update not confirmed; nothing was sent.");
    }
    if (env.signal.aborted) throw new CliError("interrupted", "Nothing was sent.", EXIT.interrupted);

    const bar = new FirmwareProgressBar(env.out);
    let announced = false;
    let result: FirmwareUpdateResult;
    try {
      result = await flash({
        signal: env.signal,
        onAskPowerCycle: () => {
          if (bootloader) {
            env.out.note(`${FIRMWARE_NOTICES.askPowerCycle} ${FIRMWARE_NOTICES.demoRestarts}`);
            const boot = bootloader;
            clock.setTimeout(() => boot.powerCycle(), DEMO_POWER_CYCLE_MS);
          } else {
            env.out.note(`${FIRMWARE_NOTICES.askPowerCycle} Waiting up to 60 s; keep the cable plugged in.`);
          }
        },
        onProgress: (p) => {
          if (!announced && p.phase === "sending") {
            announced = true;
            env.out.note("The bootloader answered; sending the file.");
            env.setExitNote(
              "The firmware update was interrupted: the robot's firmware may be incomplete. Switch the robot off and on and run the update again (the bootloader is never overwritten).",
            );
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
          env.out.note(`rbc: firmware update interrupted. ${e.message}`);
          env.out.result({ ok: false, error: { code: "interrupted", message: e.message, ...details } });
          return EXIT.interrupted;
        }
        throw new CliError(e.failure, e.message, EXIT.failed, details);
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
    const n = (v: number) => Math.round(v).toLocaleString("en-US");
    env.out.line(firmwareResultSentence(result, before));
    env.out.line(
      `Sent ${n(result.bytes)} bytes at ${n(result.bytesPerSecond)} bytes/s (${n(result.linesPerSecond)} lines/s).`,
    );
    env.out.line("The robot was restarted: run Basic posture (`rbc run 7`) before other motions.");
    return EXIT.ok;
  },
};
