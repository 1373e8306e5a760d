/**
 * The Robot feature as the rest of the panel uses it (docs/architecture.md, "Features"): reading the device
 * card's figures (the robot's free memory).
 */
export { refreshDeviceInfo } from "./actions.ts";
