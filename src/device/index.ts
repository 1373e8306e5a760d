export {
  ActivityRefusedError,
  type ActivitySnapshot,
  type ActivityTransition,
  type BusyActivity,
  type DirectActivity,
  type DirectUse,
  type Doing,
  type FirmwareActivity,
  type Halt,
  type IdleActivity,
  type MotionActivity,
  type SoundActivity,
  type Stop7Sender,
  type UploadActivity,
} from "./activity.ts";
export { BOOTLOADER_PROMPTS_NEEDED } from "./bootloader-prompt.ts";
export type { ProbeResult } from "./busy-probe.ts";
export { DirectMode, SERVO_IDS } from "./direct-mode.ts";
export { RbcCannotLimpError, RbcNotIdleError, RbcStillPlayingError } from "./direct-mode-errors.ts";
export * from "./errors.ts";
export {
  DEFAULT_FIRMWARE_TIMEOUTS,
  type FirmwareIo,
  type FirmwareTimeouts,
  FirmwareUpdateError,
  type FirmwareUpdateFacts,
  type FirmwareUpdateOptions,
  type FirmwareUpdatePhase,
  type FirmwareUpdateProgress,
  type FirmwareUpdateResult,
  transportFirmwareIo,
  updateFirmware,
} from "./firmware-update.ts";
export type { MotionEndOutcome } from "./motion-end.ts";
export type { RunMotionOptions } from "./motion-run.ts";
export {
  type FileUploadOptions,
  type FileUploadResult,
  motionPayload,
  type UploadPhase,
} from "./motion-upload.ts";
export { RbcUnexpectedAckError } from "./raw-channel.ts";
export {
  type LimpResult,
  RbcClient,
  type RbcClientOptions,
  type RbcTimeouts,
  type StopActivityResult,
} from "./rbc-client.ts";
export {
  type LinkKind,
  type LinkTiming,
  MAX_BACKOFF,
  RoundTripEstimator,
  type RoundTripLimits,
} from "./round-trip.ts";
export {
  type BusySeen,
  builtInDurationMs,
  HAZARDOUS_MOTIONS,
  isHazardousMotion,
  judgeRun,
  type NoReplyCause,
  RUN_AT_ONCE_MS,
  RUN_DURATION_TOLERANCE,
  type RunBefore,
  type RunNoReply,
  type RunReport,
  type RunVerdict,
} from "./run-outcome.ts";
export * from "./servo-doctor/index.ts";
export {
  emptied,
  imageHash,
  type RobotShelf,
  reconcile,
  recordUpload,
  type ShelfDrop,
  type ShelfSlot,
  shelfDurationMs,
  shelfKey,
} from "./shelf.ts";
export type { SoundReport } from "./sound.ts";
export type { StopFound } from "./stop.ts";
export { technicalDetail } from "./technical-detail.ts";
export {
  frameLabel,
  TetheredPlayError,
  type TetheredPlayHolds,
  type TetheredPlayOptions,
  type TetheredPlayProgress,
  type TetheredPlayResult,
} from "./tethered-play.ts";
export * from "./types.ts";
export { downloadChunk } from "./upload.ts";
export {
  type SafeZeroWrite,
  type SaveZerosBackup,
  writeZerosWithBackup,
  type ZeroPolicyOptions,
} from "./zero-policy.ts";
