export {
  busyChanged,
  disconnect,
  limpAll,
  probeAfterConnect,
  refreshKnownPorts,
  servosTaken,
  stopActivity,
} from "./actions.ts";
export { connectPlace } from "./connect-place.ts";
export { connectionMessages } from "./messages.ts";
export { robotName } from "./robot-name.ts";
export { type ConnectionState, connectingTo, mirrored, NOTHING_RUNNING, type RobotLabel } from "./state.ts";
export { topBar } from "./top-bar.ts";
