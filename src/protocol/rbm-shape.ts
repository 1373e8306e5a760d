/**
 * The shape of a motion (docs/protocol.md §7) for `validateRbm`: a zod schema of `RbmMotion`'s types, and each
 * place where a motion built in code does not have that shape put into words and values.
 */

import { rbmIssueMessages } from "../i18n/outcomes/rbm/messages.ts";
import { translator } from "../i18n/translate.ts";
import type { RbmIssue, RbmIssueValues } from "./rbm-validate.ts";
import { z } from "./zod.ts";

/** A file problem's English sentence, from the outcome catalogue (src/i18n/outcomes/rbm/), as Korean is. */
const en = translator(rbmIssueMessages, "en");

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

/** What a value is, in words and as issue values: "it is a list" / `{ got: "list" }`. */
function describe(value: unknown): [string, RbmIssueValues] {
  if (value === undefined) return [en("outcome.rbm.got.missing"), { got: "missing" }];
  if (typeof value === "string") {
    const shown = JSON.stringify(value.length > 30 ? `${value.slice(0, 30)}…` : value);
    return [en("outcome.rbm.got.value", { value: shown }), { got: "value", value: shown }];
  }
  if (Array.isArray(value)) return [en("outcome.rbm.got.list"), { got: "list" }];
  if (typeof value === "object" && value !== null) return [en("outcome.rbm.got.object"), { got: "object" }];
  return [en("outcome.rbm.got.value", { value: String(value) }), { got: "value", value: String(value) }];
}

const TEXT_KEYS: readonly PropertyKey[] = ["serialNumber", "text1", "text2", "name", "trailing"];

/** Puts a zod issue into words: "scene 3, servo record 2, end must be a whole number of 0 or more (it is -1)." */
export function shapeIssue(root: unknown, path: readonly PropertyKey[]): RbmIssue {
  if (path.length === 0) {
    return {
      code: "rbm-shape",
      message: en("outcome.rbm.shape.motion"),
      values: { kind: "motion" },
    };
  }
  const issue: RbmIssue = { code: "rbm-shape", message: "" };
  const parts: string[] = [];
  for (let i = 0; i < path.length; i++) {
    const [key, next] = [path[i], path[i + 1]];
    if ((key === "scenes" || key === "servos") && typeof next === "number") {
      parts.push(key === "scenes" ? `scene ${next}` : `servo record ${next}`);
      if (key === "scenes") issue.scene = next;
      i++;
    } else {
      parts.push(String(key));
    }
  }
  const where = parts.join(", ");
  const [got, gotValues] = describe(valueAt(root, path));
  const last = path[path.length - 1];
  const at = { path: path.map(String).join("."), ...gotValues };
  // The catalogue's sentences, with the protocol's own English for the place (`where`) and the value (`got`).
  if (last === "servos" || last === "scenes") {
    issue.message = en("outcome.rbm.shape.list", { path: where, got });
    issue.values = { kind: "list", ...at };
  } else if (TEXT_KEYS.includes(last ?? "")) {
    issue.message = en("outcome.rbm.shape.text", { path: where, got });
    issue.values = { kind: "text", ...at };
  } else if (last === "raw" || last === "fields") {
    issue.message = en("outcome.rbm.shape.form", { path: where });
    issue.values = { kind: "form", path: at.path };
  } else {
    issue.code = "rbm-not-a-number";
    issue.message = en("outcome.rbm.shape.number", { path: where, got });
    issue.values = { kind: "shape", ...at };
  }
  return issue;
}
