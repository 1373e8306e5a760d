/**
 * The upload notices are said by the device layer (`UPLOAD_NOTICES`, for the CLI and the panel) and by the
 * Motions view's catalogue (in the panel's language): in English they are the same sentences, so the two
 * cannot drift apart.
 */
import { describe, expect, it } from "vitest";
import { UPLOAD_NOTICES } from "../../src/device/index.ts";
import { motionsMessages } from "../../src/ui/features/motions/messages.ts";

describe("the Motions view's upload notices", () => {
  it("are, in English, the device layer's UPLOAD_NOTICES word for word", () => {
    expect(motionsMessages["motions.upload.experimental"].en).toBe(UPLOAD_NOTICES.experimental);
    expect(motionsMessages["motions.upload.holdAdvice"].en).toBe(UPLOAD_NOTICES.holdAdvice);
    expect(motionsMessages["motions.upload.actionUnchecked"].en).toBe(UPLOAD_NOTICES.action);
  });

  it("have a Korean text of their own", () => {
    for (const key of [
      "motions.upload.experimental",
      "motions.upload.holdAdvice",
      "motions.upload.actionUnchecked",
    ] as const) {
      expect(motionsMessages[key].ko).toMatch(/\p{Script=Hangul}/u);
    }
  });
});
