import { describe, expect, it } from "vitest";
import { motionName } from "../../src/cli/motion-names.ts";

/**
 * How `rbc` names a motion (issue 23 item 2: one number per motion, the one Run takes, with its remote key —
 * docs/protocol.md §3.1: 12-21 are keys 1-9 and 0, 33-42 the same keys after `*`).
 */
describe("rbc's motion names", () => {
  it("built-in motions by their names, in both languages", () => {
    expect(motionName(7)).toBe("7 (Basic posture)");
    expect(motionName(7, "ko")).toBe("7 (기본 자세)");
  });

  it("a downloaded motion by the number Run takes and its remote key, never the slot's own count", () => {
    expect(motionName(12)).toBe("12 (uploaded, key 1)");
    expect(motionName(21)).toBe("21 (uploaded, key 0)");
    expect(motionName(33)).toBe("33 (uploaded, * then 1)");
    expect(motionName(42, "ko")).toBe("42 (업로드한 모션, * 다음 0번 키)");
    expect(motionName(12, "ko")).toBe("12 (업로드한 모션, 1번 키)");
  });

  it("with the name rbc recorded uploading it (rbc shelf)", () => {
    expect(motionName(13, "en", "RbcPanel_Wave")).toBe("13 (RbcPanel_Wave, key 2)");
    expect(motionName(13, "ko", "RbcPanel_Wave")).toBe("13 (RbcPanel_Wave, 2번 키)");
  });

  it("a number that is neither built in nor a download: the number alone", () => {
    expect(motionName(25)).toBe("25");
  });
});
