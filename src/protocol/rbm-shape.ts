/**
 * The shape of a motion (docs/protocol.md §7) for `validateRbm`: a zod schema of `RbmMotion`'s types, and each
 * place where a motion built in code does not have that shape as an issue's code and facts.
 */

import { type RbmIssue, type RbmIssueValues, rbmIssue } from "./rbm-issue.ts";
import { z } from "./zod.ts";

const whole = z.number().int().min(0);
const text = z.string();
const servoSchema = z.object({ id: whole, p: whole, d: whole, i: whole, portEnable: whole, zero: whole });
const recordSchema = z.object({
  id: whole,
  start: whole,
  end: whole,
  torque: whole,
  port: whole,
  reserved: whole.optional(),
});
const sceneSchema = z.object({
  index: whole,
  name: text,
  frames: whole,
  timeMs: whole,
  servos: z.array(recordSchema),
});

/** The shape of a motion (types only; the RBC's rules are checked by `validateRbm`). */
export const rbmMotionSchema = z.object({
  format: whole,
  serialNumber: text,
  text1: text,
  text2: text,
  name: text,
  motionIndex: whole,
  platform: whole,
  sceneCount: whole.optional(),
  unknown10: whole,
  servoCount: whole.optional(),
  unknown12: whole,
  servos: z.array(servoSchema),
  scenes: z.array(sceneSchema),
  raw: z.object({ fields: z.record(text, text), trailing: text }).optional(),
});

function valueAt(root: unknown, path: readonly PropertyKey[]): unknown {
  let v: unknown = root;
  for (const key of path) {
    v = typeof v === "object" && v !== null ? (v as Record<PropertyKey, unknown>)[key] : undefined;
  }
  return v;
}

/** What a value is, as issue values: `{ got: "list" }`, `{ got: "value", value: "12.5" }`. */
function describe(value: unknown): RbmIssueValues {
  if (value === undefined) return { got: "missing" };
  if (typeof value === "string") {
    return { got: "value", value: JSON.stringify(value.length > 30 ? `${value.slice(0, 30)}…` : value) };
  }
  if (Array.isArray(value)) return { got: "list" };
  if (typeof value === "object" && value !== null) return { got: "object" };
  return { got: "value", value: String(value) };
}

const TEXT_KEYS: readonly PropertyKey[] = ["serialNumber", "text1", "text2", "name", "trailing"];

/** A zod issue as an issue's code and facts: the path ("scenes.3.servos.2.end") and what the value is. */
export function shapeIssue(root: unknown, path: readonly PropertyKey[]): RbmIssue {
  if (path.length === 0) return rbmIssue("rbm-shape", { kind: "motion" });
  const sceneAt = path.findIndex((key, i) => key === "scenes" && typeof path[i + 1] === "number");
  const where = sceneAt < 0 ? {} : { scene: path[sceneAt + 1] as number };
  const last = path[path.length - 1];
  const at = { path: path.map(String).join("."), ...describe(valueAt(root, path)) };
  if (last === "servos" || last === "scenes") return rbmIssue("rbm-shape", { kind: "list", ...at }, where);
  if (TEXT_KEYS.includes(last ?? "")) return rbmIssue("rbm-shape", { kind: "text", ...at }, where);
  if (last === "raw" || last === "fields")
    return rbmIssue("rbm-shape", { kind: "form", path: at.path }, where);
  return rbmIssue("rbm-not-a-number", { kind: "shape", ...at }, where);
}
