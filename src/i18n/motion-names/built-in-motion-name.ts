import type { KeysWithoutParams } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { builtInMotionMessages } from "./messages.ts";

const NAME_KEYS: Readonly<Record<number, KeysWithoutParams<typeof builtInMotionMessages>>> = {
  1: "motion.builtIn.getUpA",
  2: "motion.builtIn.getUpB",
  3: "motion.builtIn.turnLeft",
  4: "motion.builtIn.walkForward",
  5: "motion.builtIn.turnRight",
  6: "motion.builtIn.sidestepLeft",
  7: "motion.builtIn.basicPosture",
  8: "motion.builtIn.sidestepRight",
  9: "motion.builtIn.punchLeft",
  10: "motion.builtIn.walkBackward",
  11: "motion.builtIn.punchRight",
};

/** Built-in motion `number`'s name (1-11) in `locale`, or undefined for any other number. */
export function builtInMotionName(number: number, locale: Locale): string | undefined {
  const key = NAME_KEYS[number];
  return key === undefined ? undefined : translator(builtInMotionMessages, locale)(key);
}
