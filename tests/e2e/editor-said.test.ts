/**
 * Issue 21 item 6 in the Editor: its messages are kept as what they say (a catalogue key and its facts) and
 * worded when drawn, so a message made before a language switch follows the switch. Messages of every kind,
 * each in its own place: a tethered play's result (Play tab), a deleted draft (Drafts) and a file that was not
 * opened (the toolbar); a refusal beside a field (the motion core's, and the Editor's own), the undo and redo
 * steps' names (the buttons and the notice) and why a stored draft is not usable (Drafts). Made in English,
 * switched to Korean with the panel's own language control, then back.
 */
import type { Locator, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { DEMO } from "./connected-page.ts";
import { openEditorOnDemo, storeDraft } from "./editor-fixtures.ts";
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

/** Types a value into a field and leaves it (a `change`, as a person pressing Tab). */
async function typeInto(page: Page, testId: string, value: string): Promise<void> {
  const field = page.getByTestId(testId);
  await field.fill(value);
  await field.press("Tab");
}

/** Shows a tab of the selected scene's work (only the shown tab's panel is drawn) and waits for its panel. */
async function showTab(page: Page, tab: "pose" | "tools"): Promise<void> {
  await page.locator(`#editor-tab-${tab}`).click();
  await page.locator(`#editor-panel-${tab}`).waitFor();
}

describe("the Editor's messages follow a language switch", () => {
  it("a play result, a deleted draft and a file not opened read in Korean after the switch and in English after the switch back", async () => {
    const { page, context } = await app.newPage({ start: DEMO, options: FAST });
    await openEditorOnDemo(page, app.url);

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

  it("a refusal beside a field, the undo and redo steps' names and a draft set aside read in Korean after the switch and in English after the switch back", async () => {
    const { page, context } = await app.newPage();
    await page.goto(`${app.url}#/editor`, { waitUntil: "domcontentloaded" });
    await page.getByTestId("pose-table").waitFor();
    // A draft a newer panel saved: the Editor lists it apart, with why, when it opens.
    await storeDraft(page, "d-newer", {
      version: 2,
      id: "d-newer",
      name: "Later",
      savedAt: Date.now(),
      rbm: "x",
    });
    await page.reload({ waitUntil: "domcontentloaded" });
    await page.getByTestId("pose-table").waitFor();
    // In a closed <details> (the list of drafts set aside): on the page, not shown until opened.
    const aside = page.getByTestId("broken-drafts").locator("li");
    await aside.waitFor({ state: "attached" });
    const asideEn = "It was saved by a newer panel (draft format 2); this panel reads format 1.";
    expect(await textOf(aside)).toContain(`d-newer: ${asideEn}`);

    // Two edits, the second one undone: the buttons and the notice name both steps.
    await typeInto(page, "end-2", "120");
    await page.getByTestId("editor-undo").filter({ hasText: "Left knee" }).waitFor();
    await typeInto(page, "end-4", "100");
    await page.getByTestId("editor-undo").filter({ hasText: "Left ankle roll" }).waitFor();
    await page.getByTestId("editor-undo").click();
    const undo = page.getByTestId("editor-undo");
    const redo = page.getByTestId("editor-redo");
    const undone = page.getByTestId("editor-toolbar").locator(".live .notice p");
    await redo.filter({ hasText: "Left ankle roll" }).waitFor();
    const steps = async () => [await textOf(undo), await textOf(redo), await textOf(undone)];
    const stepsEn = [
      "Undo: set Left knee (end of scene 0)",
      "Redo: set Left ankle roll (end of scene 0)",
      "Undone: set Left ankle roll (end of scene 0).",
    ];
    expect(await steps()).toEqual(stepsEn);

    // Refused: a position the motion file cannot hold (the motion core's, on the Pose tab) and a time factor
    // that is not a number (the Editor's own, on the Tools tab). Nothing changes; each reason stays beside its
    // field, and a tab shows its own when shown again.
    await typeInto(page, "end-3", "300");
    const position = page.locator("#problem-end-3");
    await position.waitFor();
    const positionEn =
      "The end position of Left ankle pitch (servo 3) must be a whole number from 0 to 254, not 300.";
    expect(await textOf(position)).toBe(positionEn);
    await showTab(page, "tools");
    await page.getByTestId("retime-mode").selectOption("factor");
    await page.getByTestId("retime-value").fill("fast");
    await page.getByTestId("retime-apply").click();
    const factor = page.locator("#retime-problem");
    await factor.waitFor();
    const factorEn =
      'A time factor is a number above 0 (2 = half as fast, 0.5 = twice as fast); "fast" is not.';
    expect(await textOf(factor)).toBe(factorEn);

    await switchLanguage(page, "ko");
    await page.getByRole("heading", { level: 1, name: "모션 편집기" }).waitFor();
    expect(await textOf(factor)).toBe(
      '시간 배수는 0보다 큰 수여야 해요 (2 = 절반 속도, 0.5 = 두 배 속도). 입력한 값: "fast".',
    );
    await showTab(page, "pose");
    expect(await textOf(position)).toBe(
      "왼쪽 발목 앞뒤(서보 3)의 끝 위치에는 0에서 254 사이의 정수만 쓸 수 있어요. 입력한 값: 300.",
    );
    expect(await steps()).toEqual([
      "실행 취소: 왼쪽 무릎 설정 (장면 0 끝)",
      "다시 실행: 왼쪽 발목 좌우 설정 (장면 0 끝)",
      "실행 취소: 왼쪽 발목 좌우 설정 (장면 0 끝).",
    ]);
    expect(await textOf(aside)).toContain(
      "d-newer: 더 새로운 패널이 저장했어요 (임시 저장본 형식 2). 이 패널은 형식 1만 읽을 수 있어요.",
    );

    await switchLanguage(page, "en");
    await page.getByRole("heading", { level: 1, name: "Motion editor" }).waitFor();
    expect(await textOf(position)).toBe(positionEn);
    expect(await steps()).toEqual(stepsEn);
    expect(await textOf(aside)).toContain(`d-newer: ${asideEn}`);
    await showTab(page, "tools");
    expect(await textOf(factor)).toBe(factorEn);
    await context.close();
  });
});
