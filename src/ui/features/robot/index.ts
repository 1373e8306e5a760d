export { refreshDeviceInfo } from "./actions.ts";
