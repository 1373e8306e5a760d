export { HIGH_LOAD_AT_REST, scanFindings } from "./findings.ts";
export { ALL_SERVO_IDS, checkServoIds, HUNO_SCAN_IDS, type ScanOptions, scanServos } from "./scan.ts";
export { ADAPTER_LATENCY_MS, BYTE_MS, SERVO_REPLY_WINDOW_MS, ServoBus, wireMs } from "./servo-bus.ts";
export { INFO_PARAMETERS, type ParameterReading, type ServoInfo, servoInfo } from "./servo-info.ts";
export {
  type SetIdFailure,
  type SetIdOptions,
  type SetIdRefusal,
  type SetIdResult,
  setServoId,
} from "./set-id.ts";
export * from "./types.ts";
export {
  followSummary,
  WIGGLE_COUNTS,
  WIGGLE_TORQUE,
  type WiggleResult,
  type WiggleStep,
  wiggleServo,
} from "./wiggle.ts";
