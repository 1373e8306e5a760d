/**
 * Interop: the motion document on the third-party Motionbuilder samples in `../shared/fixtures/rbm` (not part
 * of this repository, see tests/interop/motionbuilder-samples.test.ts). Without that folder this prints one
 * line and its tests are reported as skipped; tests/unit/motion-document.test.ts covers the same code on the
 * project's own examples.
 */
import { existsSync, readdirSync, readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import {
  apply,
  createHistory,
  deleteScene,
  duplicateScene,
  type Motion,
  mirrorPose,
  openMotion,
  saveMotion,
  setPosition,
  undo,
} from "../../src/motion/index.ts";

const FIXTURES = new URL("../../../shared/fixtures/rbm/", import.meta.url);
const PRESENT = existsSync(FIXTURES);
if (!PRESENT) {
  console.log(
    "motion-document interop skipped: ../shared/fixtures not found (third-party Motionbuilder files are not part of this repository)",
  );
}

const NAMES = PRESENT ? readdirSync(FIXTURES).filter((n) => n.endsWith(".rbm")) : ["(none)"];
const fixture = (name: string): string => readFileSync(new URL(name, FIXTURES), "latin1");

describe.runIf(PRESENT)("interop: the motion document on Motionbuilder's files", () => {
  it("finds the 29 samples", () => {
    expect(NAMES).toHaveLength(29);
  });

  it.each(NAMES)("%s: open and save unchanged is byte-identical; an edit undone is too", (name) => {
    const text = fixture(name);
    const doc = openMotion(text);
    expect(saveMotion(doc)).toBe(text);
    const mid = doc.scenes.length >> 1;
    let h = createHistory(doc);
    h = apply(h, (d) => setPosition(d, mid, d.servos[0]!.id, 100), "edit");
    h = apply(h, (d) => duplicateScene(d, mid), "duplicate");
    expect(saveMotion(h.present)).not.toBe(text);
    expect(saveMotion(undo(undo(h)).present)).toBe(text);
    // Duplicating a scene and deleting the copy gives the file back, jumps between scenes included.
    expect(saveMotion(deleteScene(duplicateScene(doc, mid), mid + 1))).toBe(text);
  });

  /**
   * The mirror decision checked against Motionbuilder's own left/right pairs of motions: mirroring every scene
   * of the left one around the zeros comes closer to the right one than `254 − p` does.
   */
  it.each([
    ["SidewalkLeft.rbm", "SidewalkRight.rbm"],
    ["PunchLeft.rbm", "PunchRight.rbm"],
    ["TurnLeft.rbm", "TurnRight.rbm"],
  ])("mirroring %s approaches %s better around the zeros than as 254 − p", (left, right) => {
    const a = openMotion(fixture(left));
    const b = openMotion(fixture(right));
    let mirrored: Motion = a;
    for (let k = 0; k < a.scenes.length; k++) mirrored = mirrorPose(mirrored, k, { detach: true });
    let zeroRule = 0;
    let flipRule = 0;
    a.scenes.forEach((scene, k) => {
      scene.servos.forEach((rec, i) => {
        const partner = [5, 6, 7, 8, 9, 0, 1, 2, 3, 4, 13, 14, 15, 10, 11, 12][rec.id]!;
        const target = b.scenes[k]!.servos[partner]!.end;
        zeroRule += Math.abs(mirrored.scenes[k]!.servos[partner]!.end - target);
        flipRule += Math.abs(254 - scene.servos[i]!.end - target);
      });
    });
    expect(zeroRule).toBeLessThan(flipRule);
  });
});
