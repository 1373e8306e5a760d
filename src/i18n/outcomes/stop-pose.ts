import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { stopPoseMessages } from "./stop-pose-messages.ts";

/**
 * "The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing."
 * What Stop leaves the robot in (docs/protocol.md §3.6): the one sentence wherever Stop is described, by the
 * panel and `rbc` alike.
 */
export function stopHoldsPoseText(locale: Locale): string {
  return translator(stopPoseMessages, locale)("outcome.stop.holdsPose");
}
