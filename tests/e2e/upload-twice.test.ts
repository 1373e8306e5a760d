/**
 * The same motion uploaded twice (issue 33 item 8) and the upload's words (item 10), on the demo robot: a second
 * upload of bytes this browser recorded as stored asks first, naming the motion that holds them and saying how
 * that is known, with Replace motion N, Keep both and Cancel. Cancel sends nothing (the robot's motions and free
 * memory stay as they were); Keep both stores a second copy; Replace erases the motion memory (the robot's only
 * way) and leaves one copy, as motion 12 again. The words: the file's error list is below the refusal that
 * points to it, the image size is "to send" before anything was sent, and the Motions view says "upload" (never
 * "download") for PC → robot. English and Korean.
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { openConnected } from "./connected-page.ts";
import { expectText, FAST, squash, useApp } from "./harness.ts";
import { exampleText, rbmFile, withShortFrames } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

const app = useApp();

/**
 * The files the demo robot's memory has received (its EEPROM slots written since it was new: a reset makes the
 * robot forget them, docs/protocol.md §6.1, but leaves their bytes until overwritten).
 */
const demoMotions = (page: Page) => page.evaluate(() => window.__rbcDemoSim?.motions.length ?? -1);

/** How many motions the robot holds, as its free memory counts them (Memory tab), then back to Files. */
async function motionCount(page: Page): Promise<string> {
  await showTabById(page, "uploads");
  const count = squash(await page.getByTestId("mem-motion-count").textContent());
  await showTabById(page, "files");
  return count;
}

const TABS = ["files", "uploads", "run", "sounds"] as const;

async function showTabById(page: Page, id: (typeof TABS)[number]): Promise<void> {
  await page.locator(`#motions-tab-${id}`).click();
  await page.locator(`#motions-panel-${id}`).waitFor();
}

/** Every word of every tab of the Motions view, in one string. */
async function motionsViewText(page: Page): Promise<string> {
  const all: string[] = [];
  for (const id of TABS) {
    await showTabById(page, id);
    all.push(squash(await page.locator("main").textContent()));
  }
  await showTabById(page, "files");
  return all.join(" ");
}

/** Opens the demo robot in Motions (free memory read), in `locale`. */
async function open(locale?: string) {
  const opened = await openConnected(app, {
    view: "motions",
    options: FAST,
    ...(locale ? { locale } : {}),
  });
  await opened.page.getByTestId("mem-motion-text").filter({ hasText: "24,576" }).waitFor();
  return opened;
}

const card = (page: Page, file: string) => page.getByTestId("motion-file").filter({ hasText: file });

/** The refusal beside Upload comes before (above) the file's error list. */
async function refusalAboveList(page: Page, file: string): Promise<boolean> {
  return card(page, file).evaluate((el) => {
    const why = el.querySelector('[data-testid="upload-why"]');
    const list = el.querySelector('[data-testid="rbm-issues"]');
    return !!why && !!list && (why.compareDocumentPosition(list) & Node.DOCUMENT_POSITION_FOLLOWING) !== 0;
  });
}

describe("the same motion uploaded twice (English)", () => {
  it("asks Replace / Keep both / Cancel naming the motion; Cancel sends nothing, Keep both adds one, Replace leaves one", async () => {
    const { page, context } = await open();
    await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", exampleText("wave.rbm")));
    const wave = card(page, "wave.rbm");
    await wave.waitFor();
    // Before anything is sent: the bytes are to be sent, not "sent".
    await expectText(wave, /To send to the robot\s*624 bytes/, { contains: true });
    expect(squash(await wave.textContent())).not.toContain("Sent to the robot");

    const upload = wave.getByTestId("upload-motion");
    const question = page.getByTestId("already-stored");
    await upload.click();
    await wave.getByText(/^Uploaded wave\.rbm/).waitFor();
    await expectText(wave, "Stored as motion 12 (key 1)", { contains: true });
    expect(await demoMotions(page)).toBe(1);
    expect(await question.count()).toBe(0);

    // Again: the question, before anything is sent.
    await upload.click();
    await question.waitFor();
    await expectText(
      question,
      "The same motion was stored as motion 12 (key 1) when it was uploaded from this browser.",
      { contains: true },
    );
    await expectText(question, "uploaded now; the robot's memory accounting showed it stored", {
      contains: true,
    });
    await expectText(
      question,
      "Keep both: this upload is stored as the next motion and takes 640 more bytes",
      {
        contains: true,
      },
    );
    const replace = question.getByRole("button", { name: "Replace motion 12" });
    const keep = question.getByRole("button", { name: "Keep both" });
    const cancel = question.getByRole("button", { name: "Cancel", exact: true });
    await expect.poll(() => replace.isEnabled()).toBe(true);
    await keep.waitFor();
    // The safe answer has the keyboard.
    await expect.poll(() => cancel.evaluate((b) => b === document.activeElement)).toBe(true);

    // Cancel: nothing sent, nothing stored.
    await cancel.click();
    await expect.poll(() => question.count()).toBe(0);
    expect(await page.getByTestId("upload-progress").count()).toBe(0);
    expect(await demoMotions(page)).toBe(1);
    await expectText(page.getByTestId("mem-motion-text"), "23,936 of 24,576 bytes free");

    // Keep both: a second copy, as motion 13.
    await upload.click();
    await question.waitFor();
    await keep.click();
    await wave
      .getByText(/^Uploaded wave\.rbm/)
      .filter({ hasText: "Stored as motion 13 (key 2)" })
      .waitFor();
    expect(await demoMotions(page)).toBe(2);
    await expectText(page.getByTestId("mem-motion-text"), "23,296 of 24,576 bytes free");
    expect(await motionCount(page)).toMatch(/^2 of 20 motions/);

    // Replace: the question names the first copy, says the second is erased too; one copy is left.
    await upload.click();
    await question.waitFor();
    await expectText(question, "motion 12 (key 1)", { contains: true });
    await expectText(question, "motions 13 too", { contains: true });
    await replace.click();
    await wave
      .getByText(/^Uploaded wave\.rbm/)
      .filter({ hasText: "Free motion memory: 23,936 of" })
      .waitFor();
    await expectText(wave, "Stored as motion 12 (key 1)", { contains: true });
    await expectText(wave, "The motion memory had been reset first", { contains: true });
    expect(await motionCount(page)).toMatch(/^1 of 20 motions/);
    await expectText(page.getByTestId("mem-motion-text"), "23,936 of 24,576 bytes free");
    // Slot 1 holds the image again (a reset forgets slot 2 without erasing its bytes).
    expect(await demoMotions(page)).toBe(2);

    // A file with errors: the list is below the refusal that points to it.
    await page
      .getByTestId("rbm-files")
      .setInputFiles(rbmFile("Edited.rbm", withShortFrames(exampleText("wave.rbm"))));
    const edited = card(page, "Edited.rbm");
    await expectText(
      edited.getByTestId("upload-why"),
      "Cannot upload: the file has 1 error (listed below). Nothing is sent.",
    );
    expect(await refusalAboveList(page, "Edited.rbm")).toBe(true);

    // One verb for PC → robot in the whole view.
    const words = await motionsViewText(page);
    expect(words).toContain("Upload to robot");
    expect(words).not.toMatch(/download/i);
    await context.close();
  });
});

describe("the same motion uploaded twice (Korean)", () => {
  it("asks in Korean, Cancel sends nothing, and the view says 업로드 for PC → robot", async () => {
    const { page, context } = await open("ko-KR");
    await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", exampleText("wave.rbm")));
    const wave = card(page, "wave.rbm");
    await wave.waitFor();
    await expectText(wave, /로봇에 보낼 크기\s*624바이트/, { contains: true });
    const upload = wave.getByTestId("upload-motion");
    await expectText(upload, "로봇에 업로드");
    await upload.click();
    await expect.poll(() => demoMotions(page)).toBe(1);
    await wave
      .getByText(/모션 12번/)
      .first()
      .waitFor();

    await upload.click();
    const question = page.getByTestId("already-stored");
    await question.waitFor();
    await expectText(
      question,
      "같은 모션을 이 브라우저에서 업로드했을 때 모션 12번(1번 키)으로 저장했어요.",
      {
        contains: true,
      },
    );
    await question.getByRole("button", { name: "모션 12번 바꾸기" }).waitFor();
    await question.getByRole("button", { name: "둘 다 두기" }).waitFor();
    await question.getByRole("button", { name: "취소", exact: true }).click();
    await expect.poll(() => question.count()).toBe(0);
    expect(await page.getByTestId("upload-progress").count()).toBe(0);
    expect(await demoMotions(page)).toBe(1);

    await page
      .getByTestId("rbm-files")
      .setInputFiles(rbmFile("Edited.rbm", withShortFrames(exampleText("wave.rbm"))));
    await expectText(
      card(page, "Edited.rbm").getByTestId("upload-why"),
      "업로드할 수 없어요. 파일에 오류가 1개 있어요 (아래 목록). 아무것도 보내지 않아요.",
    );
    expect(await refusalAboveList(page, "Edited.rbm")).toBe(true);

    const words = await motionsViewText(page);
    expect(words).toContain("업로드한 모션");
    expect(words).not.toContain("다운로드");
    await context.close();
  });
});

describe("the same motion uploaded twice from the Editor", () => {
  it("asks in the Editor's card, Cancel sends nothing, and Replace leaves one copy that the card knows", async () => {
    const { page, context } = await openConnected(app, { options: FAST });
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    await page.getByRole("link", { name: "Editor", exact: true }).click();
    await page.getByTestId("editor").waitFor();
    await page.getByRole("button", { name: "Add after" }).click();
    await page.locator("#scene-opt-1[aria-current=true]").waitFor();
    await page.locator("#editor-tab-play").click();
    const editorCard = page.getByTestId("editor-upload");
    await editorCard.waitFor();
    const upload = page.getByRole("button", { name: "Upload to robot" });
    const copy = editorCard.getByTestId("editor-robot-copy");
    await upload.click();
    await expectText(copy, "The robot holds this motion as motion 12 (remote key 1).");

    await upload.click();
    const question = editorCard.getByTestId("already-stored");
    await question.waitFor();
    await expectText(question, "stored as motion 12 (key 1)", { contains: true });
    await question.getByRole("button", { name: "Cancel", exact: true }).click();
    await expect.poll(() => question.count()).toBe(0);
    expect(await demoMotions(page)).toBe(1);

    await upload.click();
    await question.getByRole("button", { name: "Replace motion 12" }).click();
    await editorCard
      .locator(".upload-in-place .notice")
      .filter({ hasText: "The motion memory had been reset first" })
      .waitFor();
    await expectText(copy, "The robot holds this motion as motion 12 (remote key 1).");
    await context.close();
  });
});
