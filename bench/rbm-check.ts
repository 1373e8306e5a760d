/**
 * How long the motion file check takes: `checkRbm` (tests/support/fuzz-targets.ts: parseRbm, validateRbm,
 * serializeRbm and motionImage, docs/protocol.md §7) on each of the project's example motions and on the hostile
 * inputs of tests/support/rbm-hostile.ts (huge declared counts, a megabyte of digits). The fuzz test
 * (tests/unit/fuzz-rbm.test.ts) only tells a hang from an answer; the speed is this figure. Each input's time is
 * the median of N runs in this process, in ms, after one warm-up run.
 *
 *   npx tsx bench/rbm-check.ts            (figures as text)
 */
import { fileURLToPath } from "node:url";
import { EXAMPLE_NAMES, exampleText } from "../tests/data/project-data.ts";
import { checkRbm } from "../tests/support/fuzz-targets.ts";
import { hostileRbmInputs } from "../tests/support/rbm-hostile.ts";
import { median, round } from "./stats.ts";

/** Targets the fuzz test asserted before it left speed to the bench: an example within 500 ms, the rest 1,500. */
export const RBM_CHECK_EXAMPLE_TARGET_MS = 500;
export const RBM_CHECK_HOSTILE_TARGET_MS = 1500;

export interface RbmCheckTiming {
  name: string;
  chars: number;
  /** The check's verdict ("ok", or the typed error's code). */
  verdict: string;
  medianMs: number;
}

export interface RbmCheckFigures {
  runs: number;
  examples: RbmCheckTiming[];
  hostile: RbmCheckTiming[];
  /** The slowest example's median. */
  slowestExampleMs: number;
  /** The slowest hostile input's median. */
  slowestHostileMs: number;
}

function timeCheck(name: string, text: string, runs: number): RbmCheckTiming {
  const first = checkRbm(text);
  if (first.kind === "violation") throw new Error(`checkRbm found a violation in ${name}: ${first.detail}`);
  const times: number[] = [];
  for (let i = 0; i < runs; i++) {
    const start = performance.now();
    checkRbm(text);
    times.push(performance.now() - start);
  }
  return {
    name,
    chars: text.length,
    verdict: first.kind === "typed-error" ? first.code : first.kind,
    medianMs: round(median(times), 3),
  };
}

export function measureRbmCheck(runs = 5): RbmCheckFigures {
  const texts = EXAMPLE_NAMES.map(exampleText);
  const examples = EXAMPLE_NAMES.map((name, i) => timeCheck(name, texts[i]!, runs));
  const hostile = hostileRbmInputs(texts[0]!, texts).map(({ name, text }) => timeCheck(name, text, runs));
  return {
    runs,
    examples,
    hostile,
    slowestExampleMs: Math.max(...examples.map((t) => t.medianMs)),
    slowestHostileMs: Math.max(...hostile.map((t) => t.medianMs)),
  };
}

export function describeRbmCheck(f: RbmCheckFigures): string {
  const row = (t: RbmCheckTiming) =>
    `| ${t.name} | ${t.chars.toLocaleString("en-US")} | ${t.verdict} | ${t.medianMs.toFixed(3)} |`;
  return [
    `Motion file check (parse, validate, serialize, encode), median of ${f.runs} runs; targets ≤ ${RBM_CHECK_EXAMPLE_TARGET_MS} ms an example, ≤ ${RBM_CHECK_HOSTILE_TARGET_MS} ms a hostile input`,
    "| Input | Characters | Verdict | Median ms |",
    "|---|---:|---|---:|",
    ...f.examples.map(row),
    ...f.hostile.map(row),
  ].join("\n");
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  process.stdout.write(`${describeRbmCheck(measureRbmCheck())}\n`);
}
