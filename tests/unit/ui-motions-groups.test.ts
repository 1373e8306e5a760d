import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { parseRbm } from "../../src/protocol/rbm.ts";
import { type RbmIssue, validateRbm } from "../../src/protocol/rbm-validate.ts";
import { groupWarnings, largestJump } from "../../src/ui/features/motions/issue-groups.ts";
import { MOTIONS_TABS } from "../../src/ui/features/motions/view-actions.ts";
import { sameTarget } from "../../src/ui/features/motions/views/upload-in-place.ts";
import { tabAfterKey } from "../../src/ui/tabs-keyboard.ts";

const WAVE = readFileSync(new URL("../../examples/wave.rbm", import.meta.url), "latin1");

/** Wave with scene 1 starting every servo `steps` from where scene 0 left it. */
function jumpy(steps: number) {
  const motion = parseRbm(WAVE);
  motion.scenes[1]!.servos = motion.scenes[1]!.servos.map((r, i) => ({
    ...r,
    start: motion.scenes[0]!.servos[i]!.end + steps,
  }));
  return motion;
}

const issue = (code: string, message = code, where: Partial<RbmIssue> = {}): RbmIssue => ({
  code,
  message,
  ...where,
});

describe("warnings grouped by kind (issue #11)", () => {
  it("turns 16 small scene jumps into one minor kind with its count and largest jump", () => {
    const motion = jumpy(2);
    const { warnings } = validateRbm(motion);
    expect(warnings.map((w) => w.code)).toEqual(Array(16).fill("rbm-scene-jump"));
    const groups = groupWarnings(warnings, motion);
    expect(groups).toHaveLength(1);
    expect(groups[0]).toMatchObject({
      code: "rbm-scene-jump",
      weight: "minor",
      title: "Servos jump between scenes",
    });
    expect(groups[0]!.issues).toHaveLength(16);
    expect(groups[0]!.meaning).toContain("The largest jump is 2 steps, a twitch you will hardly see.");
    expect(largestJump(motion, warnings)).toBe(2);
  });

  it("asks for a check of large jumps, and cannot call them small without the motion", () => {
    const motion = jumpy(40);
    const warnings = validateRbm(motion).warnings.filter((w) => w.code === "rbm-scene-jump");
    expect(warnings.length).toBeGreaterThan(0);
    expect(groupWarnings(warnings, motion)[0]).toMatchObject({ weight: "check" });
    expect(groupWarnings(warnings, motion)[0]!.meaning).toContain("The largest jump is 40 steps.");
    // Without the motion the size is unknown: never "minor" on a guess.
    expect(largestJump(undefined, warnings)).toBeUndefined();
    expect(groupWarnings(warnings)[0]).toMatchObject({ weight: "check" });
  });

  it("puts serious kinds first, then keeps the order the kinds first appear in, one group per kind", () => {
    const groups = groupWarnings([
      issue("rbm-header-constant"),
      issue("rbm-scene-jump", "a", { scene: 1, servo: 0 }),
      issue("rbm-unsafe-position"),
      issue("rbm-serial-format"),
      issue("rbm-serial-mismatch"),
      issue("rbm-unsafe-position"),
      issue("rbm-something-new"),
    ]);
    expect(groups.map((g) => [g.weight, g.title, g.issues.length])).toEqual([
      ["serious", "Positions outside a joint's safe range", 2],
      ["check", "Servos jump between scenes", 1],
      ["check", "Made for another robot", 1],
      ["check", "Other warnings", 1],
      // Two header codes, one kind for the person.
      ["minor", "Unusual header fields", 2],
    ]);
  });

  it("has nothing to group in a clean file", () => {
    expect(groupWarnings(validateRbm(parseRbm(WAVE)).warnings)).toEqual([]);
  });
});

describe("the Motions view's tabs and in-place results", () => {
  it("moves between tabs with the arrow keys, Home and End, wrapping around", () => {
    expect(MOTIONS_TABS.map((t) => t.id)).toEqual(["files", "uploads", "run", "sounds"]);
    expect(tabAfterKey(MOTIONS_TABS, "files", "ArrowRight")).toBe("uploads");
    expect(tabAfterKey(MOTIONS_TABS, "files", "ArrowLeft")).toBe("sounds");
    expect(tabAfterKey(MOTIONS_TABS, "sounds", "ArrowRight")).toBe("files");
    expect(tabAfterKey(MOTIONS_TABS, "run", "Home")).toBe("files");
    expect(tabAfterKey(MOTIONS_TABS, "files", "End")).toBe("sounds");
    expect(tabAfterKey(MOTIONS_TABS, "files", "Enter")).toBeUndefined();
  });

  it("shows an upload's result only at the card or the action files where it started", () => {
    expect(sameTarget({ area: "motion", entryId: 2 }, { area: "motion", entryId: 2 })).toBe(true);
    expect(sameTarget({ area: "motion", entryId: 2 }, { area: "motion", entryId: 3 })).toBe(false);
    expect(sameTarget({ area: "action" }, { area: "motion", entryId: 2 })).toBe(false);
    expect(sameTarget({ area: "action" }, { area: "action" })).toBe(true);
    expect(sameTarget(undefined, { area: "action" })).toBe(false);
  });
});
