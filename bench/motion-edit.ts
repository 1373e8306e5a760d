/**
 * Time to apply one edit to the largest motion that fits the robot (issue #12: target ≤ 50 ms): examples/
 * long-walk.rbm, 284 scenes, opened as a motion document (src/motion/). Each figure is the median and p95 of N
 * runs, in ms, after a warm-up: one servo's position changed in the middle scene and committed to the undo
 * history, its undo, a structural edit (moving the first scene to the end, which renumbers every scene), a
 * retime of the whole motion, a mirror, opening, saving as .rbm text and validating the whole motion (what
 * an editor would do after each edit). With `node --expose-gc` it also
 * reports the heap one undo step costs (10,000 edits kept in the history).
 *
 *   npx tsx bench/motion-edit.ts            (figures as text)
 *   node --expose-gc --import tsx bench/motion-edit.ts
 */
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import {
  apply,
  createHistory,
  type Motion,
  type MotionHistory,
  mirrorPose,
  motionIssues,
  moveScene,
  openMotion,
  retime,
  saveMotion,
  setPosition,
  undo,
} from "../src/motion/index.ts";
import { median, round } from "./stats.ts";

export const EDIT_BENCH_MOTION = new URL("../examples/long-walk.rbm", import.meta.url);
export const EDIT_TARGET_MS = 50;

export interface Timing {
  medianMs: number;
  p95Ms: number;
}

export interface MotionEditFigures {
  file: string;
  scenes: number;
  runs: number;
  open: Timing;
  /** setPosition in the middle scene + commit to the history: the figure the issue's target is about. */
  edit: Timing;
  undo: Timing;
  moveScene: Timing;
  retime: Timing;
  mirror: Timing;
  save: Timing;
  /** The validator's errors and warnings for the whole motion (what an editor shows after each edit). */
  validate: Timing;
  /** Heap per undo step (bytes), or null without `--expose-gc`. */
  bytesPerStep: number | null;
}

function p95(values: readonly number[]): number {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.ceil(sorted.length * 0.95) - 1)]!;
}

function time(runs: number, fn: (n: number) => void): Timing {
  for (let n = 0; n < Math.min(50, runs); n++) fn(n); // warm-up
  const ms: number[] = [];
  for (let n = 0; n < runs; n++) {
    const t0 = performance.now();
    fn(n);
    ms.push(performance.now() - t0);
  }
  return { medianMs: round(median(ms), 4), p95Ms: round(p95(ms), 4) };
}

function heapPerStep(doc: Motion, mid: number): number | null {
  const gc = (globalThis as { gc?: () => void }).gc;
  if (gc === undefined) return null;
  const steps = 10_000;
  gc();
  gc();
  const before = process.memoryUsage().heapUsed;
  let h: MotionHistory = createHistory(doc);
  for (let n = 0; n < steps; n++)
    h = apply(h, (d) => setPosition(d, mid, 2, 130 + (n % 100)), "Move servo 2");
  gc();
  gc();
  const after = process.memoryUsage().heapUsed;
  if (h.undoCount !== steps) throw new Error("history lost steps");
  return Math.round((after - before) / steps);
}

export function measureMotionEdit(runs = 500): MotionEditFigures {
  const text = readFileSync(EDIT_BENCH_MOTION, "latin1");
  const doc = openMotion(text);
  const mid = doc.scenes.length >> 1;
  let sink = 0;
  const open = time(Math.min(runs, 100), () => {
    sink += openMotion(text).scenes.length;
  });
  let h = createHistory(doc);
  const edit = time(runs, (n) => {
    h = apply(h, (d) => setPosition(d, mid, 2, 130 + (n % 100)), "Move servo 2");
  });
  const undoT = time(runs, () => {
    h = undo(h);
  });
  const move = time(runs, () => {
    sink += moveScene(doc, 0, doc.scenes.length - 1).scenes.length;
  });
  const retimeT = time(runs, () => {
    sink += retime(doc, 1.1).scenes.length;
  });
  const mirror = time(runs, (n) => {
    sink += mirrorPose(doc, n % doc.scenes.length).scenes.length;
  });
  const save = time(Math.min(runs, 100), () => {
    sink += saveMotion(doc).length;
  });
  const validate = time(Math.min(runs, 100), () => {
    sink += motionIssues(doc).warnings.length + 1;
  });
  if (sink === 0) throw new Error("nothing measured");
  return {
    file: "examples/long-walk.rbm",
    scenes: doc.scenes.length,
    runs,
    open,
    edit,
    undo: undoT,
    moveScene: move,
    retime: retimeT,
    mirror,
    save,
    validate,
    bytesPerStep: heapPerStep(doc, mid),
  };
}

export function describeMotionEdit(f: MotionEditFigures): string {
  const row = (label: string, t: Timing) => `| ${label} | ${t.medianMs.toFixed(3)} | ${t.p95Ms.toFixed(3)} |`;
  return [
    `Motion editing on ${f.file} (${f.scenes} scenes), ${f.runs} runs each; target for one edit ≤ ${EDIT_TARGET_MS} ms`,
    "| Operation | Median ms | p95 ms |",
    "|---|---:|---:|",
    row("Edit: one servo's position in the middle scene + commit", f.edit),
    row("Undo", f.undo),
    row("Move the first scene to the end (renumbers all)", f.moveScene),
    row("Retime the whole motion ×1.1", f.retime),
    row("Mirror one scene", f.mirror),
    row("Open (.rbm text → document)", f.open),
    row("Save (document → .rbm text)", f.save),
    row("Validate the whole motion (errors and warnings)", f.validate),
    f.bytesPerStep === null
      ? "Heap per undo step: run with node --expose-gc to measure."
      : `Heap per undo step (10,000 edits kept): ${f.bytesPerStep.toLocaleString("en-US")} bytes.`,
  ].join("\n");
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  process.stdout.write(`${describeMotionEdit(measureMotionEdit())}\n`);
}
