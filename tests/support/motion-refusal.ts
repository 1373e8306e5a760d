import { MotionError } from "../../src/motion/index.ts";

/** The `MotionError` that `change` throws; fails the test when it throws nothing or something else. */
export function motionRefusal(change: () => unknown): MotionError {
  try {
    change();
  } catch (e) {
    if (e instanceof MotionError) return e;
    throw e;
  }
  throw new Error("expected a MotionError");
}
