export { HIGH_LOAD_AT_REST, scanFindings } from "./findings.ts";
export { ALL_SERVO_IDS, checkServoIds, HUNO_SCAN_IDS, type ScanOptions, scanServos } from "./scan.ts";
export { ADAPTER_LATENCY_MS, BYTE_MS, SERVO_REPLY_WINDOW_MS, ServoBus, wireMs } from "./servo-bus.ts";
export {
  type SetIdFailure,
  type SetIdOptions,
  type SetIdRefusal,
  type SetIdResult,
  setServoId,
} from "./set-id.ts";
export * from "./types.ts";
