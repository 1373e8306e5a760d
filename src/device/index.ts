export {
  BOOTLOADER_PROMPTS_NEEDED,
  type BootloaderPromptFacts,
  RbcInBootloaderError,
} from "./bootloader-prompt.ts";
export { DirectMode, SERVO_IDS } from "./direct-mode.ts";
export { type ErrorTextOptions, errorText, technicalDetail, uploadOutcomeText } from "./error-text.ts";
export * from "./errors.ts";
export {
  DEFAULT_FIRMWARE_TIMEOUTS,
  type FirmwareIo,
  type FirmwareTimeouts,
  FirmwareUpdateError,
  type FirmwareUpdateOptions,
  type FirmwareUpdatePhase,
  type FirmwareUpdateProgress,
  type FirmwareUpdateResult,
  transportFirmwareIo,
  updateFirmware,
} from "./firmware-update.ts";
export { deviceErrorMessages } from "./messages.ts";
export {
  type FileUploadOptions,
  type FileUploadResult,
  motionPayload,
  UPLOAD_NOTICES,
  type UploadPhase,
} from "./motion-upload.ts";
export { RbcUnexpectedAckError } from "./raw-channel.ts";
export {
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
  ZeroBackupError,
  type ZeroPolicyOptions,
  ZeroWriteFailedError,
} from "./zero-policy.ts";
