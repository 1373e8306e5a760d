import { readFileSync } from "node:fs";
import { join, relative } from "node:path";
import { describe, expect, it } from "vitest";
import { HUNO_JOINT_NAMES, servoLabel } from "../../src/i18n/index.ts";
import { jointName, jointOf } from "../../src/i18n/joint-names/joint-name.ts";
import type { Locale } from "../../src/i18n/locale.ts";
import { servoText } from "../../src/i18n/outcomes/servos/servo-words.ts";
import { HUNO_MIRROR_PAIRS } from "../../src/motion/mirror.ts";
import { figurePoints } from "../../src/ui/features/doctor/model.ts";
import { jointLabel } from "../../src/ui/features/motions/plot-data.ts";
import { HUNO_JOINTS } from "../../src/ui/robot3d/huno-model.ts";
import { tsFiles } from "../support/source-files.ts";

/**
 * One name per joint, in both languages, everywhere: the joint-name catalogue (src/i18n/joint-names/) is the only
 * list of the HUNO's joint names in src/, and every view, `rbc` and outcome that names a joint says its name.
 * The names are docs/protocol.md §4's, the robot's own left and right: ids 0-4 left leg, 5-9 right leg (hip roll,
 * hip pitch, knee, ankle pitch, ankle roll), 10-12 left arm, 13-15 right arm (shoulder pitch, shoulder roll,
 * elbow). Korean per docs/i18n.md's glossary: pitch 앞뒤, roll 좌우.
 */

const EN = [
  "Left hip roll",
  "Left hip pitch",
  "Left knee",
  "Left ankle pitch",
  "Left ankle roll",
  "Right hip roll",
  "Right hip pitch",
  "Right knee",
  "Right ankle pitch",
  "Right ankle roll",
  "Left shoulder pitch",
  "Left shoulder roll",
  "Left elbow",
  "Right shoulder pitch",
  "Right shoulder roll",
  "Right elbow",
];

const KO = [
  "왼쪽 엉덩이 좌우",
  "왼쪽 엉덩이 앞뒤",
  "왼쪽 무릎",
  "왼쪽 발목 앞뒤",
  "왼쪽 발목 좌우",
  "오른쪽 엉덩이 좌우",
  "오른쪽 엉덩이 앞뒤",
  "오른쪽 무릎",
  "오른쪽 발목 앞뒤",
  "오른쪽 발목 좌우",
  "왼쪽 어깨 앞뒤",
  "왼쪽 어깨 좌우",
  "왼쪽 팔꿈치",
  "오른쪽 어깨 앞뒤",
  "오른쪽 어깨 좌우",
  "오른쪽 팔꿈치",
];

const IDS = EN.map((_, id) => id);
const NAMES: Record<Locale, readonly string[]> = { en: EN, ko: KO };

const SRC = join(import.meta.dirname, "../../src");
const CATALOGUE = "i18n/joint-names/messages.ts";

const SOURCES = tsFiles(SRC).map((path) => ({ path: relative(SRC, path), text: readFileSync(path, "utf8") }));

const LITERAL = /"((?:[^"\\\n]|\\.)*)"|`((?:[^`\\]|\\.)*)`|'((?:[^'\\\n]|\\.)*)'/g;

/**
 * A string that names a joint as a name list would: a side then a part ("Left knee", "right ankle pitch",
 * "왼쪽 발목 피치"), whatever words follow. A sentence with a joint inside it ("bows from the hips") is not one.
 */
const JOINT_NAME =
  /^(?:left|right) (?:hip|knee|ankle|shoulder|elbow)\b|^(?:왼쪽|오른쪽) (?:엉덩이|무릎|발목|어깨|팔꿈치)/i;

/** The joint names written as string literals in each file (comments removed), by file. */
function jointLiterals(files: readonly { path: string; text: string }[]): Map<string, string[]> {
  const found = new Map<string, string[]>();
  for (const { path, text } of files) {
    const code = text.replace(/\/\*[\s\S]*?\*\//g, "").replace(/^\s*\/\/.*$/gm, "");
    for (const m of code.matchAll(LITERAL)) {
      const literal = (m[1] ?? m[2] ?? m[3] ?? "").trim();
      if (JOINT_NAME.test(literal)) found.set(path, [...(found.get(path) ?? []), literal]);
    }
  }
  return found;
}

describe("the joints' names", () => {
  it("are docs/protocol.md §4's, the robot's own left and right, in both languages", () => {
    expect(IDS.map((id) => jointName(id, "en"))).toEqual(EN);
    expect(IDS.map((id) => jointName(id, "ko"))).toEqual(KO);
    expect(IDS.map((id) => jointOf(id, "ko"))).toEqual(KO);
    expect(jointName(16, "en")).toBe("Servo 16");
    expect(jointName(16, "ko")).toBe("서보 16번");
    expect(jointOf(16, "en")).toBeUndefined();
    expect(jointOf(-1, "ko")).toBeUndefined();
  });

  it("are what every consumer says for servo n: views, charts, the servo check, rbc, the protocol's English", () => {
    expect(HUNO_JOINT_NAMES).toEqual(EN);
    for (const id of IDS) {
      expect(servoLabel(id)).toBe(`servo ${id} (${EN[id]})`);
      for (const locale of ["en", "ko"] as const) {
        const name = NAMES[locale][id];
        expect(jointLabel(id, locale)).toBe(`${id} ${name}`);
        expect(servoText(id, locale)).toBe(
          locale === "en" ? `Servo ${id} (${name})` : `서보 ${id}번(${name})`,
        );
      }
    }
    expect(servoText(20, "ko")).toBe("서보 20번");
    expect(jointLabel(20, "ko")).toBe("서보 20번");
  });

  it("put each joint on the side its name says: the 3D robot, the Servo check's figure, the mirror's pairs", () => {
    const sideOf = (id: number) => (EN[id]?.startsWith("Left ") ? "left" : "right");
    expect(HUNO_JOINTS.map((j) => j.side)).toEqual(IDS.map(sideOf));
    expect(figurePoints().map((p) => p.side)).toEqual(IDS.map(sideOf));
    for (const [left, right] of HUNO_MIRROR_PAIRS) {
      expect(EN[left]).toMatch(/^Left /);
      expect(EN[right]).toBe(EN[left]?.replace(/^Left /, "Right "));
    }
    expect(HUNO_MIRROR_PAIRS).toHaveLength(8);
  });

  it("are written in one file of src/ only: the catalogue", () => {
    const found = jointLiterals(SOURCES);
    expect([...found.keys()]).toEqual([CATALOGUE]);
    // The catalogue holds each name once per language (its keys are not names).
    expect([...(found.get(CATALOGUE) ?? [])].sort()).toEqual([...EN, ...KO].sort());
  });

  it("the scan finds a second list, whatever its case or Korean words, and not a comment or a sentence", () => {
    const found = jointLiterals([
      { path: "a.ts", text: '"cmd.joint.leftKnee": { en: "Left knee", ko: "왼쪽 무릎" },' },
      { path: "b.ts", text: 'const J = ["left ankle pitch", `right elbow`];' },
      { path: "c.ts", text: "  x: { en: 'x', ko: '왼쪽 발목 피치' }," },
      { path: "d.ts", text: '/** "Left knee" */\n// "Right knee"\nconst s = "bows from the hips";' },
    ]);
    expect(Object.fromEntries(found)).toEqual({
      "a.ts": ["Left knee", "왼쪽 무릎"],
      "b.ts": ["left ankle pitch", "right elbow"],
      "c.ts": ["왼쪽 발목 피치"],
    });
  });

  it("HUNO_JOINT_NAMES (read from the catalogue when loaded) is imported by no file of src/ but the i18n index", () => {
    const importers = SOURCES.filter(({ text }) =>
      /from\s+["'][^"']*\/huno-joint-names\.ts["']/.test(text),
    ).map((f) => f.path);
    expect(importers).toEqual(["i18n/index.ts"]);
    // …which marks it pure, so that the panel's build, which imports that index, leaves it out.
    const source = SOURCES.find((f) => f.path === "i18n/joint-names/huno-joint-names.ts");
    expect(source?.text).toMatch(
      /HUNO_JOINT_NAMES: readonly string\[\] = \/\* @__PURE__ \*\/ Object\.freeze\(/,
    );
  });
});
