import { readFileSync } from "node:fs";
import { join, relative } from "node:path";
import { describe, expect, it } from "vitest";
import { tsFiles } from "../support/source-files.ts";

/**
 * Issue 19's rule for the robot's outcomes: no English sentence about what the robot, the link, a motion file,
 * a motion edit or the simulated robot did is written twice in src/. The device, link, protocol, motion and sim
 * layers take their sentences from the outcome catalogue (src/i18n/outcomes) or write them once; a second copy
 * (a CLI or panel catalogue repeating the device's English, two device files each spelling the same refusal,
 * the Editor repeating the motion layer's refusals) is how the Korean drifted before. The scan reads every
 * string and template literal of src/ (comments removed), keeps sentences of six words or more, treats `${…}`
 * and `{name}` alike, and reports each sentence of those layers found in more than one place.
 */

const ROOT = join(import.meta.dirname, "../../src");

const LITERAL = /"((?:[^"\\\n]|\\.)*)"|`((?:[^`\\]|\\.)*)`|'((?:[^'\\\n]|\\.)*)'/g;

/** A literal's words with every placeholder (`${x}`, `{x}`) made the same. */
function sentenceOf(literal: string): string {
  return literal
    .replace(/\$\{[^}]*\}/g, "{}")
    .replace(/\{[a-zA-Z0-9_]+\}/g, "{}")
    .trim();
}

/** Every sentence of six words or more, with the files (and how many times) it is written in. */
function sentencesIn(files: readonly { path: string; text: string }[]): Map<string, string[]> {
  const seen = new Map<string, string[]>();
  for (const { path, text } of files) {
    const code = text.replace(/\/\*[\s\S]*?\*\//g, "").replace(/^\s*\/\/.*$/gm, "");
    for (const m of code.matchAll(LITERAL)) {
      const sentence = sentenceOf(m[1] ?? m[2] ?? m[3] ?? "");
      if (sentence.split(/\s+/).length < 6 || !/[a-z]/.test(sentence)) continue;
      seen.set(sentence, [...(seen.get(sentence) ?? []), path]);
    }
  }
  return seen;
}

/** The layers whose outcomes are worded once, and the outcome catalogue itself (no second copy of its entries). */
const OUTCOME_LAYERS = /^(device|link|protocol|motion|sim|i18n\/outcomes)\//;

describe("one wording for the robot's outcomes", () => {
  it("finds a sentence written twice, whatever its placeholders are called", () => {
    const found = sentencesIn([
      {
        path: "device/a.ts",
        // A template literal with placeholders, as a device file writes it (`$` kept apart from `{` here).
        text: "throw new E(`Servo $-{id} may only move within $-{min}-$-{max}.`);".replaceAll("$-", "$"),
      },
      { path: "cli/m.ts", text: '"x": { en: "Servo {servo} may only move within {low}-{high}." },' },
      {
        path: "device/b.ts",
        text: '// "Servo 3 may only move within 1-2." in a comment is not a sentence\nf("short one");',
      },
    ]);
    expect(found.get("Servo {} may only move within {}-{}.")).toEqual(["device/a.ts", "cli/m.ts"]);
    expect([...found.keys()]).toHaveLength(1);
  });

  it("no sentence of the device, link, protocol, motion or sim layer is written twice in src/", () => {
    const files = tsFiles(ROOT).map((path) => ({
      path: relative(ROOT, path),
      text: readFileSync(path, "utf8"),
    }));
    const twice = [...sentencesIn(files)]
      .filter(([, where]) => where.length > 1 && where.some((p) => OUTCOME_LAYERS.test(p)))
      .map(([sentence, where]) => `${where.join(", ")}: ${sentence}`);
    expect(twice).toEqual([]);
  });
});
