export { DirectMode, SERVO_IDS } from "./direct-mode.ts";
export * from "./errors.ts";
export { RbcClient, type RbcClientOptions, type RbcTimeouts } from "./rbc-client.ts";
export * from "./types.ts";
export { downloadChunk } from "./upload.ts";
