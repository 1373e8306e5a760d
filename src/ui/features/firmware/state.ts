import type { FirmwareUpdateProgress } from "../../../device/firmware-update.ts";
import type { IntelHexImage } from "../../../protocol/intel-hex.ts";
import type { Notice } from "../../notices.ts";
import type { Store } from "../../store.ts";

/**
 * The Firmware view's part of the app state, kept across connections: the opened file is a file on this
 * computer, and an update's outcome still matters after the robot was reconnected. An update in flight ends
 * with its connection (its controller aborts it), and says so.
 */

/** A checked firmware file. */
export interface FirmwareFile {
  fileName: string;
  /** Size of the file on disk. */
  fileBytes: number;
  image: IntelHexImage;
  /** The demo firmware (2.50) the panel made, rather than a file of this computer. */
  demo?: boolean;
  /**
   * The version the file states with the mark of this project's demo and test files (`declaredVersion`);
   * undefined: the file states none, as real firmware does. A file with the mark is not firmware a real robot
   * can run.
   */
  declared?: { major: number; minor: number };
}

export type FirmwareStep =
  /** "Update firmware…" was pressed: the one confirmation is shown. */
  | "confirming"
  /** Waiting for the robot to be switched off and on and its bootloader to answer. */
  | "power-cycle"
  /** The bootloader takes the file. */
  | "sending"
  /** `@` came: the new firmware starts and its version is read. */
  | "starting";

export interface FirmwareRun {
  /** Where the update is, as its progress reports tell it (the panel's own steps, drawn from the device's). */
  step: FirmwareStep;
  fileName: string;
  /** The version the robot reported before the update. */
  before?: { major: number; minor: number };
  progress?: FirmwareUpdateProgress;
  /**
   * Recover only: Cancel was pressed and the update is ending. Recover runs on a bare port, outside any client,
   * so no device activity machine knows it; the connected robot's update is read from its machine instead
   * (`isCancelling`, features/connection).
   */
  recoveryCancelling?: boolean;
  /** The update runs on a bare port (Recover), not on the connected robot. */
  recovery?: boolean;
  /**
   * The file carries the demo mark and the robot is not the demo robot: the confirmation warns, and the update
   * starts only once the person has ticked that they understand (`demoFileAccepted`).
   */
  demoFileOnRealRobot?: boolean;
  demoFileAccepted?: boolean;
}

export interface FirmwareState {
  file?: FirmwareFile;
  /** Why the last file was not opened (with the line to blame). */
  fileProblem?: Notice;
  /** The demo firmware is being made. */
  loadingFile?: boolean;
  run?: FirmwareRun;
  /** The last update's outcome, in a sentence. */
  result?: Notice;
}

export function initialFirmware(): FirmwareState {
  return {};
}

/** The part of the app state this feature owns (src/ui/app-state.ts composes the parts). */
export interface FirmwareSlice {
  firmware?: FirmwareState;
}

export function firmwareOf(state: FirmwareSlice): FirmwareState {
  return state.firmware ?? initialFirmware();
}

export function patchFirmware(store: Store<FirmwareSlice>, patch: Partial<FirmwareState>): void {
  store.update((s) => ({ firmware: { ...firmwareOf(s), ...patch } }));
}
