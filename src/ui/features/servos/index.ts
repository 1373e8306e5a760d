export { LatestMoveSender } from "./move-sender.ts";
export { clampToSafe, DEFAULT_TORQUE, servoRange, servosOf } from "./state.ts";
