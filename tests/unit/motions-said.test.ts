import { describe, expect, it } from "vitest";
import { RbcCancelledError } from "../../src/device/errors.ts";
import { inEveryLanguage, said, wordOf } from "../../src/i18n/said.ts";
import { noticeOf, noticeText, runningWords } from "../../src/ui/app-state.ts";
import { motionsMessages } from "../../src/ui/features/motions/messages.ts";
import { cancelledEarlySaid } from "../../src/ui/features/motions/upload-results.ts";

// Issue 21 item 6 in Motions: an upload cancelled before any byte says "by Stop" from the device error's fact
// (set by Stop's own cancel), never from its English text; the names of operations under way are worded in the
// language of the moment; a text in every language is made when read (a language's words may load later).
describe("an upload cancelled before any byte", () => {
  it("says Stop only when the device's cancel says Stop made it", () => {
    const byStop = cancelledEarlySaid(new RbcCancelledError("Upload cancelled by Stop.", "stop"));
    expect(wordOf(byStop, "en")).toBe("Upload cancelled by Stop before any byte was sent.");
    expect(wordOf(byStop, "ko")).toBe("바이트를 하나도 보내기 전에 정지로 업로드를 취소했어요.");
  });

  it("does not read Stop from the message text (a cancel whose words mention Stop, without the fact)", () => {
    const plain = cancelledEarlySaid(new RbcCancelledError("Cancelled by Stop."));
    expect(wordOf(plain, "en")).toBe("Upload cancelled before any byte was sent.");
    const byLimp = cancelledEarlySaid(new RbcCancelledError("Cancelled by Limp.", "limp"));
    expect(wordOf(byLimp, "ko")).toBe("바이트를 하나도 보내기 전에 업로드를 취소했어요.");
  });
});

describe("operations under way", () => {
  it("are worded in the language asked for; a name already worded stays as it is", () => {
    const running = [said(motionsMessages, "motions.run.task", { number: 7 }), "Plain"];
    const en = runningWords(running, "en");
    const ko = runningWords(running, "ko");
    expect(en[1]).toBe("Plain");
    expect(ko[1]).toBe("Plain");
    expect(en[0]).toContain("7");
    expect(ko[0]).toMatch(/[가-힣]/);
    expect(ko[0]).not.toBe(en[0]);
  });
});

describe("a text in every language", () => {
  it("is made when read, so words that load later are used", () => {
    let loaded = false;
    const text = inEveryLanguage((l) => (l === "ko" && loaded ? "한국어" : "English"));
    const n = noticeOf("ok", "en", [
      said(motionsMessages, "motions.upload.errorAfter", {
        words: said(motionsMessages, "motions.upload.refused"),
      }),
    ]);
    expect(text.ko).toBe("English");
    loaded = true;
    expect(text.ko).toBe("한국어");
    expect(noticeText(n, "ko")).not.toBe(n.text);
  });
});
