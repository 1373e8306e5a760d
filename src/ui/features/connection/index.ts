/**
 * The connection feature as the rest of the panel uses it (docs/architecture.md, "Features"): connect and
 * disconnect, Stop and Limp, the connect card and the top bar. The shell and the session import it, so the first
 * page load carries it: it re-exports only modules the first load has anyway (the no-Web-Serial card and Stop's
 * sentences load lazily).
 */
export {
  busyChanged,
  disconnect,
  limpAll,
  probeAfterConnect,
  refreshKnownPorts,
  stopSessionRobot,
} from "./actions.ts";
export {
  busyElsewhere,
  cancellingNow,
  isCancelling,
  isLimp,
  isPlaying,
  isStopping,
  isUploading,
  playingMotion,
  playingSound,
} from "./activity.ts";
export { connectPlace } from "./connect-place.ts";
export { connectionMessages } from "./messages.ts";
export { robotName } from "./robot-name.ts";
export { type ConnectionState, connectingTo, mirrored, NOTHING_RUNNING, type RobotLabel } from "./state.ts";
export { topBar } from "./top-bar.ts";
