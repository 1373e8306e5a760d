import { defineMessages } from "../catalogue.ts";

/**
 * Limp (`RbcClient.limp`: every servo passive): the warning before it and what it made passive, worded by
 * `limp-words.ts` for `rbc limp` and the panel's Limp button alike. Part of the one outcome catalogue (docs/i18n.md
 * "Outcomes"); each front end adds only its framing (rbc's `--yes`, the panel's buttons).
 */
export const limpOutcomeMessages = defineMessages({
  "outcome.limp.warning": {
    en: "Hold the robot: every servo will go passive and it will fall if nobody holds it.",
    ko: "로봇을 잡아 주세요. 모든 서보의 힘이 빠져서, 아무도 잡고 있지 않으면 로봇이 넘어져요.",
  },
  "outcome.limp.allPassive": {
    en: "Limp: all {count} servos confirmed passive. Hold the robot, it cannot stand on its own now.",
    ko: "힘 빼기: 서보 {count}개 모두 힘이 빠졌다고 확인했어요. 로봇을 잡아 주세요. 이제 혼자 서 있을 수 없어요.",
  },
  "outcome.limp.someSilent": {
    en: "Limp: {confirmed} servos confirmed passive, but servo {silent} did not answer. If anything still moves, switch the robot off.",
    ko: "힘 빼기: 서보 {confirmed}개는 힘이 빠졌다고 확인했지만, 서보 {silent}번이 응답하지 않았어요. 아직 움직이는 것이 있으면 로봇의 전원을 꺼 주세요.",
  },
});
