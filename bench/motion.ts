import { existsSync, readFileSync } from "node:fs";
import { relative } from "node:path";
import { motionImage, parseRbm } from "../src/protocol/index.ts";
import { PROJECT_ROOT } from "./bundle-size.ts";

/**
 * The motion the upload figures send: one of the project's own examples (a plain clone has it), as the motion
 * image the panel and the CLI upload (docs/protocol.md §6.3).
 */
export const BENCH_MOTION = new URL("../examples/wave.rbm", import.meta.url);

export interface BenchMotion {
  /** Path relative to the repository root, for the report. */
  file: string;
  image: Uint8Array;
}

export function benchMotion(): BenchMotion {
  const path = BENCH_MOTION.pathname;
  const file = relative(PROJECT_ROOT, path);
  if (!existsSync(BENCH_MOTION))
    throw new Error(`${file} is missing (the bench uploads that example motion)`);
  return { file, image: motionImage(parseRbm(readFileSync(BENCH_MOTION, "latin1"))) };
}
