import { RbcNotConnectedError } from "../../../device/errors.ts";
import {
  FirmwareUpdateError,
  type FirmwareUpdateOptions,
  type FirmwareUpdateProgress,
  type FirmwareUpdateResult,
  transportFirmwareIo,
  updateFirmware,
} from "../../../device/firmware-update.ts";
import type { Locale } from "../../../i18n/locale.ts";
import {
  firmwareFailureText,
  firmwareRestartedText,
  firmwareResultText,
} from "../../../i18n/outcomes/firmware/firmware-words.ts";
import { type Said, said, saidBy } from "../../../i18n/said.ts";
import { declaredVersion } from "../../../protocol/firmware-marker.ts";
import { MAX_HEX_TEXT_CHARS, parseIntelHex } from "../../../protocol/intel-hex.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice, technicalDetail } from "../../error-text.ts";
import { focusSoon } from "../../focus.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { choosePort, webSerial } from "../../serial-ports.ts";
import { hexProblem, tooLargeProblem } from "./file-problem.ts";
import { firmwareMessages } from "./messages.ts";
import { type FirmwareFile, type FirmwareRun, firmwareOf, patchFirmware } from "./state.ts";

/**
 * What the Firmware view does: open and check a .hex file, update the connected robot's firmware (one
 * confirmation, the power-cycle step, progress, Cancel, the result in a sentence), and Recover: the same update
 * on a port opened without a handshake, for a robot whose firmware no longer answers. Sentences are made in the
 * language of the moment the action starts (`store.get().locale`).
 */

/** The demo firmware the panel offers on the demo robot: the example file of `rbc flash` (2.50, 16 KiB). */
export const DEMO_FIRMWARE = {
  fileName: "demo-2.50.hex",
  version: { major: 2, minor: 50 },
  bytes: 16 * 1024,
};

/** How long after the panel asks the demo robot's bootloader is started: a person takes longer. */
const DEMO_POWER_CYCLE_MS = 800;

/** The update in flight on this connection (its Cancel); ended with the connection. */
class FirmwareController implements Controller {
  abort: AbortController | undefined;

  dispose(): void {
    // The link ends with the connection, so the update would fail as disconnected anyway; say it was cut off.
    this.abort?.abort();
    this.abort = undefined;
  }
}

const FIRMWARE = controllerKey("firmware", () => new FirmwareController());

function controller(ctx: AppContext): FirmwareController {
  return ctx.session.connectionScope.get(FIRMWARE);
}

/** Opens a file's text as firmware: checked at once; what is wrong is said with the line to blame. */
export function openFirmwareText(ctx: AppContext, fileName: string, text: string, fileBytes: number): void {
  if (firmwareOf(ctx.store.get()).run) return;
  try {
    const image = parseIntelHex(text);
    const file: FirmwareFile = { fileName, fileBytes, image, declared: declaredVersion(image) };
    patchFirmware(ctx.store, { file, fileProblem: undefined, result: undefined, loadingFile: false });
  } catch (e) {
    patchFirmware(ctx.store, {
      loadingFile: false,
      fileProblem: hexProblem(fileName, e, ctx.store.get().locale, text),
    });
  }
}

/** A file from the picker or a drop. Files far bigger than any firmware are not read at all. */
export async function openFirmwareFile(ctx: AppContext, file: File | undefined): Promise<void> {
  if (!file) return;
  const { locale } = ctx.store.get();
  // A HEX file is ASCII: one character a byte.
  if (file.size > MAX_HEX_TEXT_CHARS) {
    patchFirmware(ctx.store, { fileProblem: tooLargeProblem(file.name, file.size, locale) });
    return;
  }
  patchFirmware(ctx.store, { loadingFile: true });
  let text: string;
  try {
    text = await file.text();
  } catch (e) {
    patchFirmware(ctx.store, {
      loadingFile: false,
      fileProblem: errorNotice(
        said(firmwareMessages, "firmware.fileUnreadable", { file: file.name }),
        e,
        locale,
      ),
    });
    return;
  }
  openFirmwareText(ctx, file.name, text, file.size);
}

/** "Use the demo firmware file (2.50)": made by the simulator's code, loaded only when asked for. */
export async function openDemoFirmware(ctx: AppContext): Promise<void> {
  const { locale } = ctx.store.get();
  patchFirmware(ctx.store, { loadingFile: true });
  try {
    const { demoFirmwareHex } = await import("../../../sim/sim-bootloader.ts");
    const text = demoFirmwareHex(DEMO_FIRMWARE.version, DEMO_FIRMWARE.bytes);
    openFirmwareText(ctx, DEMO_FIRMWARE.fileName, text, text.length);
    const file = firmwareOf(ctx.store.get()).file;
    if (file) patchFirmware(ctx.store, { file: { ...file, demo: true } });
  } catch (e) {
    patchFirmware(ctx.store, {
      loadingFile: false,
      fileProblem: errorNotice(said(firmwareMessages, "firmware.demoFileFailed"), e, locale),
    });
  }
}

export function closeFirmwareFile(ctx: AppContext): void {
  if (firmwareOf(ctx.store.get()).run) return;
  patchFirmware(ctx.store, { file: undefined, fileProblem: undefined });
}

/** "Update firmware…": the one confirmation, in place. */
export function askToFlash(ctx: AppContext, recovery = false): void {
  const f = firmwareOf(ctx.store.get());
  if (!f.file || f.run) return;
  // Recover always writes to a real robot's port; an update, unless the robot connected is the demo robot.
  const demoRobot = !recovery && ctx.store.get().connection.robot?.kind === "demo";
  const demoFileOnRealRobot = f.file.declared !== undefined && !demoRobot;
  patchFirmware(ctx.store, {
    run: { step: "confirming", fileName: f.file.fileName, recovery, demoFileOnRealRobot },
    result: undefined,
  });
  focusSoon(demoFileOnRealRobot ? "accept-demo-file" : "confirm-flash");
}

/** The tick under a demo file's warning: "I understand: the robot will not work until real firmware is written". */
export function acceptDemoFile(ctx: AppContext, accepted: boolean): void {
  const run = firmwareOf(ctx.store.get()).run;
  if (run?.step === "confirming") patchFirmware(ctx.store, { run: { ...run, demoFileAccepted: accepted } });
}

/** A demo file is written to a real robot only after its warning was ticked. */
function mayWrite(run: FirmwareRun): boolean {
  return run.demoFileOnRealRobot !== true || run.demoFileAccepted === true;
}

export function cancelConfirm(ctx: AppContext): void {
  if (firmwareOf(ctx.store.get()).run?.step === "confirming") patchFirmware(ctx.store, { run: undefined });
}

/** Cancel during the update: ends it after the line in flight and says what that leaves on the robot. */
export function cancelFlash(ctx: AppContext): void {
  const run = firmwareOf(ctx.store.get()).run;
  if (!run || run.step === "confirming") return;
  // The connected robot's machine marks its update `cancelling`; Recover has no machine (see FirmwareRun).
  if (run.recovery) patchFirmware(ctx.store, { run: { ...run, recoveryCancelling: true } });
  const c = ctx.session.connectionScope.peek(FIRMWARE);
  c?.abort?.abort();
  // Recovery runs outside any connection: its controller is the page's.
  ctx.session.pageScope.peek(RECOVERY)?.abort?.abort();
}

function patchRun(ctx: AppContext, patch: Partial<FirmwareRun>): void {
  const run = firmwareOf(ctx.store.get()).run;
  if (run) patchFirmware(ctx.store, { run: { ...run, ...patch } });
}

/** Progress is drawn at most this often (real time): the bootloader confirms hundreds of lines a second. */
const PROGRESS_DRAW_MS = 150;

function progressHandler(ctx: AppContext) {
  let lastStep = "";
  let lastDraw = Number.NEGATIVE_INFINITY;
  return (p: FirmwareUpdateProgress) => {
    const step =
      p.phase === "waiting-for-bootloader" || p.phase === "entering"
        ? "power-cycle"
        : p.phase === "starting" || p.phase === "complete"
          ? "starting"
          : "sending";
    const now = performance.now();
    if (step === lastStep && now - lastDraw < PROGRESS_DRAW_MS && p.linesDone < p.lines) return;
    lastStep = step;
    lastDraw = now;
    patchRun(ctx, { step, progress: p });
  };
}

/**
 * Updates the connected robot: asks to switch it off and on (the demo robot restarts by itself), sends the
 * file with progress in place, reads the version the new firmware reports, says the result in a sentence.
 */
export async function startFlash(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const f = firmwareOf(store.get());
  const file = f.file;
  if (!file || f.run?.step !== "confirming" || !mayWrite(f.run)) return;
  const { locale } = store.get();
  if (f.run.recovery) {
    await startRecovery(ctx);
    return;
  }
  const before = store.get().connection.firmware;
  const demoSim = session.demoSim;
  const c = controller(ctx);
  const abort = new AbortController();
  c.abort = abort;
  patchFirmware(store, { run: { step: "power-cycle", fileName: file.fileName, before }, result: undefined });
  focusSoon("flash-cancel");
  try {
    // The demo robot's bootloader, to switch it off and on (the simulator's code is loaded already then).
    const boot = demoSim
      ? (await import("../../../sim/sim-bootloader.ts")).BootloaderRbc.of(demoSim)
      : undefined;
    const result = await session.run(said(firmwareMessages, "firmware.running"), (client) =>
      client.updateFirmware(file.image, {
        signal: abort.signal,
        wireTimed: boot === undefined, // the demo robot's link has no baud pacing
        onProgress: progressHandler(ctx),
        onAskPowerCycle: () => {
          // The demo robot is switched off and on by the panel, as a person would switch a real one.
          if (boot) client.clock.setTimeout(() => boot.powerCycle(), DEMO_POWER_CYCLE_MS);
        },
      }),
    );
    finish(ctx, [resultSaid(result, before), saidBy(firmwareRestartedText)], result);
  } catch (e) {
    patchFirmware(store, {
      run: undefined,
      result:
        e instanceof RbcNotConnectedError
          ? noticeOf("warning", locale, [said(firmwareMessages, "firmware.notConnected")])
          : failureNotice(e, locale),
    });
  } finally {
    if (c.abort === abort) c.abort = undefined;
    focusSoon("flash-result");
  }
}

/** What the update did (the outcome catalogue's words), as a message worded when drawn. */
function resultSaid(result: FirmwareUpdateResult, before: Parameters<typeof firmwareResultText>[1]): Said {
  return saidBy((l) => firmwareResultText(result, before, l));
}

/** The update succeeded: `sentences` say so (worded when drawn, so a language switch rewords them). */
function finish(ctx: AppContext, sentences: readonly Said[], result: FirmwareUpdateResult): void {
  const { store } = ctx;
  patchFirmware(store, { run: undefined, result: noticeOf("ok", store.get().locale, sentences) });
  // The version the robot itself just reported.
  if (store.get().connection.phase === "connected") {
    store.update((s) => ({ connection: { ...s.connection, firmware: result.firmware } }));
  }
}

// ---- Recover: a robot whose firmware does not answer --------------------------------------------------------

/** The recovery update in flight (the page's: no connection exists during it). */
class RecoveryController implements Controller {
  abort: AbortController | undefined;
  dispose(): void {
    this.abort?.abort();
  }
}

const RECOVERY = controllerKey("firmware-recovery", () => new RecoveryController());

/**
 * Recover: the browser's port chooser, then the update on the bare port (no handshake, which a robot without
 * a working firmware cannot answer), then the port is closed. Connect afterwards as usual.
 */
export async function startRecovery(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const f = firmwareOf(store.get());
  const file = f.file;
  const serial = webSerial();
  if (!file || !serial || (f.run && !mayWrite(f.run))) return;
  const { locale } = store.get();
  if (store.get().connection.phase !== "disconnected") {
    patchFirmware(store, {
      run: undefined,
      result: noticeOf("warning", locale, [said(firmwareMessages, "firmware.disconnectFirst")]),
    });
    return;
  }
  let port: SerialPort;
  try {
    port = await choosePort(serial, store.get().showAllPorts);
  } catch (e) {
    patchFirmware(store, {
      run: undefined,
      result: errorNotice(said(firmwareMessages, "firmware.noPortChosen"), e, locale),
    });
    return;
  }
  const c = session.pageScope.get(RECOVERY);
  const abort = new AbortController();
  c.abort = abort;
  patchFirmware(store, {
    run: { step: "power-cycle", fileName: file.fileName, recovery: true },
    result: undefined,
  });
  focusSoon("flash-cancel");
  const { WebSerialTransport } = await import("../../../link/web-serial-transport.ts");
  const transport = new WebSerialTransport(port);
  try {
    await transport.open();
    const options: FirmwareUpdateOptions = { signal: abort.signal, onProgress: progressHandler(ctx) };
    const result = await updateFirmware(transportFirmwareIo(transport), file.image, options);
    patchFirmware(store, {
      run: undefined,
      result: noticeOf("ok", locale, [
        resultSaid(result, undefined),
        said(firmwareMessages, "firmware.connectNow"),
      ]),
    });
  } catch (e) {
    patchFirmware(store, { run: undefined, result: failureNotice(e, locale) });
  } finally {
    if (c.abort === abort) c.abort = undefined;
    await transport.close().catch(() => {});
    focusSoon("flash-result");
  }
}

/**
 * A failed or cancelled update, in the outcome catalogue's words (what went wrong, what the robot holds, what to
 * do) after the panel's lead; a cancel says so itself. What the robot holds decides the tone (nothing written: a
 * warning). The device's technical line is the technical detail.
 */
function failureNotice(e: unknown, locale: Locale): Notice {
  if (!(e instanceof FirmwareUpdateError))
    return errorNotice(said(firmwareMessages, "firmware.failed"), e, locale);
  const tone = e.holds === "previous-firmware" ? "warning" : "danger";
  const what = saidBy((l) => firmwareFailureText(e, l));
  const sentences = e.failure === "cancelled" ? [what] : [said(firmwareMessages, "firmware.failed"), what];
  return noticeOf(tone, locale, sentences, technicalDetail(e));
}
