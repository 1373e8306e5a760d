/**
 * The Servos feature as the rest of the panel uses it (docs/architecture.md, "Features"): the servos' safe
 * ranges and the latest-wins move sender (teach-in, trim live).
 */
export { LatestMoveSender } from "./move-sender.ts";
export { clampToSafe, DEFAULT_TORQUE, servoRange, servosOf } from "./state.ts";
