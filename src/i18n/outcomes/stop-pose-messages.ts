import { defineMessages } from "../catalogue.ts";

/**
 * What Stop leaves the robot in, said the same way wherever Stop is described (issue 33 item 6): the top bar's
 * Stop button, the questions before a motion, what Stop did (the panel's and `rbc stop`'s, `rbc run`'s Ctrl-C)
 * and the help. The firmware ends a motion at the end of its current scene and holds that pose with the servos
 * on (docs/protocol.md §3.6): the robot does not fall, but nothing makes it stand; only Basic posture (7) does.
 * Its own small module, so that the top bar's Stop hint (src/ui/stop-hint.ts) brings nothing else. Part of the one
 * outcome catalogue (docs/i18n.md "Outcomes").
 */
export const stopPoseMessages = defineMessages({
  "outcome.stop.holdsPose": {
    en: "The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing.",
    ko: "로봇은 서보에 힘이 들어간 채로 멈춘 자세를 유지해요. 넘어지지는 않지만, 꼭 서 있는 자세는 아니에요.",
  },
});
