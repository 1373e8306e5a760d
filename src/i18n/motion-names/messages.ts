import { defineMessages } from "../catalogue.ts";

/**
 * The names of the RBC's built-in motions 1-11 (src/protocol/catalog.ts names them in English), in the words
 * the panel and `rbc` share, so that a motion is called the same everywhere.
 */
export const builtInMotionMessages = defineMessages({
  "motion.builtIn.getUpA": { en: "Get up A (from front)", ko: "일어나기 A (엎드려서)" },
  "motion.builtIn.getUpB": { en: "Get up B (from back)", ko: "일어나기 B (누워서)" },
  "motion.builtIn.turnLeft": { en: "Turn left", ko: "왼쪽으로 돌기" },
  "motion.builtIn.walkForward": { en: "Walk forward", ko: "앞으로 걷기" },
  "motion.builtIn.turnRight": { en: "Turn right", ko: "오른쪽으로 돌기" },
  "motion.builtIn.sidestepLeft": { en: "Sidestep left", ko: "왼쪽 옆걸음" },
  "motion.builtIn.basicPosture": { en: "Basic posture", ko: "기본 자세" },
  "motion.builtIn.sidestepRight": { en: "Sidestep right", ko: "오른쪽 옆걸음" },
  "motion.builtIn.punchLeft": { en: "Punch left", ko: "왼손 펀치" },
  "motion.builtIn.walkBackward": { en: "Walk backward", ko: "뒤로 걷기" },
  "motion.builtIn.punchRight": { en: "Punch right", ko: "오른손 펀치" },
});
