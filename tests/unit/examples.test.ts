/**
 * The project's example motions (examples/*.rbm): committed exactly as scripts/make-examples.ts writes them,
 * usable on the RBC (no validation errors, only the warnings listed here), byte-identical after a parse and
 * serialize, and shaped as examples/README.md promises. Literal tables (basic posture, safe ranges, standard
 * zeros, motion area) are from docs/protocol.md, not from the code under test.
 */
import { readdirSync, readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { buildExamples, exampleTexts, LONG_WALK_SCENES } from "../../scripts/make-examples.ts";
import { errorText } from "../../src/i18n/index.ts";
import { motionImage } from "../../src/protocol/motion-image.ts";
import {
  motionDurationMs,
  parseRbm,
  type RbmMotion,
  serializeRbm,
  validateRbm,
} from "../../src/protocol/rbm.ts";
import { EXAMPLE_NAMES, EXAMPLES_DIR, type ExampleName, exampleText } from "../data/project-data.ts";
import { makeRig } from "../support/rig.ts";

const BASIC = [125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205];
const SAFE_UPPER = [174, 228, 254, 130, 185, 254, 180, 126, 208, 208, 254, 224, 198, 254, 228, 254];
const SAFE_LOWER = [1, 70, 124, 40, 41, 73, 22, 1, 120, 57, 1, 23, 1, 1, 25, 40];
const STANDARD_ZEROS = [125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127];
const MOTION_AREA = 24_576;

/** What each example is: servos, scenes, duration (ms), image size (bytes), and the only warnings allowed. */
const EXPECTED: Record<
  ExampleName,
  { servos: number; scenes: number; ms: number; image: number; warnings: string[] }
> = {
  "wave.rbm": { servos: 16, scenes: 6, ms: 3200, image: 624, warnings: [] },
  "bow.rbm": { servos: 16, scenes: 4, ms: 3200, image: 452, warnings: [] },
  "squat.rbm": { servos: 16, scenes: 8, ms: 7200, image: 796, warnings: [] },
  "long-walk.rbm": { servos: 16, scenes: 284, ms: 18_600, image: 24_532, warnings: [] },
  // W ≠ 16 on a HUNO: expected for a file that drives only the six arm servos.
  "arms-only.rbm": { servos: 6, scenes: 7, ms: 4800, image: 300, warnings: ["rbm-huno-servo-count"] },
};

const motionOf = (name: ExampleName): RbmMotion => parseRbm(exampleText(name));

describe("examples/*.rbm", () => {
  it("holds exactly the five examples", () => {
    const files = readdirSync(EXAMPLES_DIR)
      .filter((n) => n.endsWith(".rbm"))
      .sort();
    expect(files).toEqual([...EXAMPLE_NAMES].sort());
    expect(Object.keys(buildExamples()).sort()).toEqual([...EXAMPLE_NAMES].sort());
  });

  it.each(EXAMPLE_NAMES)("%s is what scripts/make-examples.ts writes now, byte for byte", (name) => {
    expect(exampleText(name)).toBe(exampleTexts()[name]);
  });

  it.each(EXAMPLE_NAMES)("%s validates without errors and only the expected warnings", (name) => {
    const { errors, warnings } = validateRbm(motionOf(name));
    expect(errors).toEqual([]);
    expect([...new Set(warnings.map((w) => w.code))]).toEqual(EXPECTED[name].warnings);
  });

  it.each(EXAMPLE_NAMES)("%s round-trips parse → serialize byte for byte", (name) => {
    const text = exampleText(name);
    const motion = parseRbm(text);
    expect(motion.raw).toBeUndefined();
    expect(serializeRbm(motion)).toBe(text);
    expect(serializeRbm(buildExamples()[name])).toBe(text);
  });

  it.each(EXAMPLE_NAMES)("%s has the servos, scenes, duration and image size its README row says", (name) => {
    const m = motionOf(name);
    const e = EXPECTED[name];
    expect(m.servos).toHaveLength(e.servos);
    expect(m.scenes).toHaveLength(e.scenes);
    expect(motionDurationMs(m)).toBe(e.ms);
    expect(motionImage(m)).toHaveLength(e.image);
    const readme = readFileSync(new URL("README.md", EXAMPLES_DIR), "utf8");
    const row = readme.split("\n").find((line) => line.startsWith(`| \`${name}\``));
    expect(row).toBeDefined();
    const cells = row!.split("|").map((c) => c.trim());
    expect(cells.slice(3, 7)).toEqual([
      String(e.servos),
      e.scenes.toLocaleString("en-US"),
      `${(e.ms / 1000).toFixed(1)} s`,
      `${e.image.toLocaleString("en-US")} B`,
    ]);
  });

  it.each(EXAMPLE_NAMES)("%s follows the authoring rules of examples/README.md", (name) => {
    const m = motionOf(name);
    expect(m).toMatchObject({
      format: 1,
      serialNumber: "0000000000000",
      platform: 1,
      unknown10: 2,
      unknown12: 4,
    });
    expect(m.servos.map((s) => s.zero)).toEqual(m.servos.map((s) => STANDARD_ZEROS[s.id]));
    const ids = m.servos.map((s) => s.id);
    // Starts and ends in the basic posture.
    expect(m.scenes[0]!.servos.map((r) => r.start)).toEqual(ids.map((id) => BASIC[id]));
    expect(m.scenes.at(-1)!.servos.map((r) => r.end)).toEqual(ids.map((id) => BASIC[id]));
    m.scenes.forEach((scene, k) => {
      expect(scene.timeMs / scene.frames).toBeGreaterThanOrEqual(20);
      expect(scene.frames).toBeLessThanOrEqual(100);
      expect(scene.timeMs).toBeLessThanOrEqual(10_000);
      scene.servos.forEach((r, i) => {
        expect(r.start).toBe(k === 0 ? BASIC[r.id] : m.scenes[k - 1]!.servos[i]!.end);
        for (const v of [r.start, r.end]) {
          expect(v).toBeGreaterThanOrEqual(SAFE_LOWER[r.id]!);
          expect(v).toBeLessThanOrEqual(SAFE_UPPER[r.id]!);
        }
      });
    });
  });

  it("every example moves: each has scenes whose start and end differ", () => {
    for (const name of EXAMPLE_NAMES) {
      const moving = motionOf(name).scenes.filter((s) => s.servos.some((r) => r.start !== r.end));
      expect(moving.length, name).toBeGreaterThanOrEqual(2);
    }
  });
});

describe("long-walk.rbm fills the motion area", () => {
  it("has the most scenes that fit: 108 + 86·284 = 24,532 ≤ 24,576 < 108 + 86·285", () => {
    const m = motionOf("long-walk.rbm");
    expect(m.scenes).toHaveLength(284);
    expect(LONG_WALK_SCENES).toBe(284);
    const size = motionImage(m).length;
    expect(size).toBe(108 + 86 * 284);
    expect(size).toBeLessThanOrEqual(MOTION_AREA);
    // One more scene (a copy of the last) would not fit.
    const more: RbmMotion = {
      ...m,
      sceneCount: undefined,
      scenes: [...m.scenes, { ...m.scenes.at(-1)!, index: 284 }],
    };
    expect(validateRbm(more).errors).toEqual([]);
    expect(motionImage(more).length).toBe(24_618);
    expect(motionImage(more).length).toBeGreaterThan(MOTION_AREA);
  });

  it("uploads to an empty robot, leaving 0 bytes free; one scene more is refused before the first byte", async () => {
    const { client, run, sim } = await makeRig();
    const m = motionOf("long-walk.rbm");
    const more: RbmMotion = {
      ...m,
      sceneCount: undefined,
      scenes: [...m.scenes, { ...m.scenes.at(-1)!, index: 284 }],
    };
    const refused = await run(client.writeMotion(motionImage(more)).catch((e: unknown) => e));
    expect(refused).toMatchObject({ code: "invalid-argument" });
    expect(errorText(refused, "en")).toMatch(/1-24576 bytes; this one is 24618\. Nothing was sent/);
    expect(sim.motions).toHaveLength(0);
    const result = await run(client.writeMotion(motionImage(m)));
    expect(result).toMatchObject({ total: 24_532, chunks: 384, freeBefore: 24_576, freeAfter: 0 });
    expect(sim.motions).toHaveLength(1);
  });
});
