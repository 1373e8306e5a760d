import { describe, expect, it } from "vitest";
import { inEveryLanguage, said, saidText, wordOf } from "../../src/i18n/said.ts";
import { noticeOf, noticeText } from "../../src/ui/app-state.ts";
import { stopMessages } from "../../src/ui/stop-messages.ts";

// Issue 21 item 6: a message is kept as its code and facts and worded when drawn, so one made before a
// language switch follows it.
describe("messages kept as codes and facts", () => {
  it("words the same notice in the language of the moment", () => {
    const n = noticeOf("ok", "en", [said(stopMessages, "stop.outcome.nothing")]);
    expect(n.text).toBe("Nothing was running; the robot keeps its pose.");
    expect(noticeText(n, "ko")).toBe("실행 중인 것이 없었어요. 로봇은 지금 자세를 유지해요.");
    expect(noticeText(n, "en")).toBe(n.text);
  });

  it("words facts that are messages or texts made in every language", () => {
    const time = inEveryLanguage((locale) => (locale === "en" ? "3 s" : "3초"));
    const s = said(stopMessages, "stop.stopping.sound", { time });
    expect(wordOf(s, "en")).toContain("3 s");
    expect(wordOf(s, "ko")).toContain("3초");
    expect(wordOf(saidText({ en: "Plain.", ko: "그냥요." }), "ko")).toBe("그냥요.");
  });

  it("makes a text in every language when it is drawn, not when it is made (a language's words may load later)", () => {
    const words: Record<string, string> = { en: "later" };
    const text = inEveryLanguage((locale) => words[locale] ?? "not loaded");
    words.ko = "나중에";
    expect(text.ko).toBe("나중에");
    expect(wordOf(saidText(text), "en")).toBe("later");
  });

  it("keeps a notice made as a sentence as it was made", () => {
    expect(noticeText({ tone: "info", text: "As made." }, "ko")).toBe("As made.");
  });
});
