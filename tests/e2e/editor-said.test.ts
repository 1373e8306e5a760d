/**
 * Issue 21 item 6 in the Editor: its messages are kept as what they say (a catalogue key and its facts) and
 * worded when drawn, so a message made before a language switch follows the switch. Three messages of three
 * kinds, each in its own place: a tethered play's result (Play tab), a deleted draft (Drafts) and a file that
 * was not opened (the toolbar). Made in English, switched to Korean with the panel's own language control,
 * then back.
 */
import type { Locator, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { type AppHarness, FAST, squash, startHarness } from "./harness.ts";
import { rbmFile } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

let app: AppHarness;

beforeAll(async () => {
  app = await startHarness();
});

afterAll(async () => {
  await app?.close();
});

const switchLanguage = (page: Page, to: "en" | "ko") => page.getByLabel(/Language/).selectOption(to);

const textOf = async (where: Locator) => squash(await where.textContent());

describe("the Editor's messages follow a language switch", () => {
  it("a play result, a deleted draft and a file not opened read in Korean after the switch and in English after the switch back", async () => {
    const { page, context } = await app.newPage({ options: FAST });
    await page.goto(app.url);
    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await page.getByRole("link", { name: "Editor" }).click();
    await page.getByTestId("pose-table").waitFor();

    // A draft of the motion, named so that its name is a fact of the sentences below.
    await page.getByTestId("motion-name").fill("Said");
    await page.getByTestId("motion-name").press("Tab");
    await page.getByTestId("draft-status").filter({ hasText: "saved" }).waitFor();

    // 1. Tethered play of the selected scene (scene 0) on the demo robot: its one sentence of what happened.
    await page.locator("#editor-tab-play").click();
    await page.locator("#editor-panel-play").waitFor();
    await page.locator("#play-button").click();
    await page.locator("#confirm-play").click();
    const played = page.getByTestId("play-panel").locator(".live .notice p");
    await played.filter({ hasText: "the servos hold the last frame" }).waitFor();
    const playedEn = await textOf(played);
    const facts = /^Played scene 0 \((\d+) frames, (\d+\.\d) s\); the servos hold the last frame\.$/.exec(
      playedEn,
    );
    expect(facts, playedEn).not.toBeNull();
    const [, frames, seconds] = facts as RegExpExecArray;

    // 2. The open draft deleted from the Drafts list (after its one question).
    await page.getByRole("button", { name: "Delete Said" }).click();
    await page.locator("#confirm-delete-draft").click();
    const deleted = page.getByTestId("drafts-card").locator(".live .notice p");
    await deleted.filter({ hasText: "Deleted the draft Said" }).waitFor();
    const deletedEn =
      "Deleted the draft Said. The motion stays open in the editor; a change saves it as a new draft.";
    expect(await textOf(deleted)).toBe(deletedEn);

    // 3. A file that is not a motion: refused in words, nothing changes.
    await page.getByTestId("editor-file").setInputFiles(rbmFile("broken.rbm", "1:13:not a motion:"));
    const refused = page.getByTestId("editor-toolbar").locator(".live .notice p");
    await refused.filter({ hasText: "broken.rbm was not opened" }).waitFor();
    const refusedEn = await textOf(refused);
    expect(refusedEn).toMatch(/^broken\.rbm was not opened: .+\. The motion in the editor did not change\.$/);

    // The panel's own language control: every message made before it now reads in Korean.
    await switchLanguage(page, "ko");
    await page.getByRole("heading", { level: 1, name: "모션 편집기" }).waitFor();
    expect(await textOf(played)).toBe(
      `장면 0을(를) 재생했어요 (프레임 ${frames}개, ${seconds}초). 서보는 마지막 프레임 자세를 유지해요.`,
    );
    expect(await textOf(deleted)).toBe(
      "임시 저장본 Said을(를) 지웠어요. 모션은 편집기에 그대로 열려 있고, 바꾸면 새 임시 저장본으로 저장돼요.",
    );
    expect(await textOf(refused)).toBe(
      "broken.rbm 파일을 열지 않았어요. Motionbuilder 모션 파일(.rbm)로 읽을 수 없어요. 편집기의 모션은 그대로예요.",
    );

    // And back: the same English sentences as when they were made.
    await switchLanguage(page, "en");
    await page.getByRole("heading", { level: 1, name: "Motion editor" }).waitFor();
    expect(await textOf(played)).toBe(playedEn);
    expect(await textOf(deleted)).toBe(deletedEn);
    expect(await textOf(refused)).toBe(refusedEn);
    await context.close();
  });
});
