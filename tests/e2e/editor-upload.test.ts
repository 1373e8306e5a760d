/**
 * Upload and run from the Editor (issue 23 item 1), on the demo robot: the Play tab's "Store on the robot" card
 * uploads the document on screen through the Motions view's upload (progress in place, the truthful result),
 * then runs it by the number Run takes, labelled with its remote key (docs/protocol.md §3.1: slot 1 = motion
 * 12 = key 1). The packet log must show the Run packet with that number, byte for byte (§2, §8 example 6 with
 * 0C for 07). An edit after the upload makes the card say the robot holds the earlier version; undoing it makes
 * it the same again. While a motion plays the buttons refuse, with the busy sentence and a Stop. A real robot
 * (the fake cable) asks first (§6.3). Korean, at phone width, and axe.
 *
 * The robot runs on the paced virtual clock (FAST); moments that pass quickly in robot time (the upload's
 * first progress report, a motion playing) are held by an event in the page, never by waiting a while.
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import type { TestStart } from "../../src/ui/test-start.ts";
import { CABLE, DEMO, loadConnected } from "./connected-page.ts";
import { expectText, FAST, type PageOptions, releaseRobot, squash, useApp, watchText } from "./harness.ts";
import { axeProblems, expectPageOk, PHONE, pageProblems, shot } from "./i18n-checks.ts";
import "./rbc-test-globals.ts";

const app = useApp();

/** docs/protocol.md §2 and §8 example 6: Run motion 12 (0x0C), its checksum the one content byte. */
const RUN_12 = "FF FF AA 55 AA 55 37 BA 14 00 00 00 00 01 0C 0C";

const card = (page: Page) => page.getByTestId("editor-upload");
const copyText = async (page: Page) => squash(await page.getByTestId("editor-robot-copy").textContent());

/**
 * Holds the robot's clock the moment the demo robot's servos move in motion `number` (its servo listener: an
 * event), so a test can look at the panel while that motion plays.
 */
async function holdWhenPlaying(page: Page, number: number): Promise<void> {
  await page.evaluate((n) => {
    const sim = window.__rbcDemoSim;
    if (!sim) throw new Error("no demo robot in this page");
    const stop = sim.onServos(() => {
      if (sim.playingMotion !== n) return;
      stop();
      window.__rbcTest?.clock.hold();
    });
  }, number);
}

/** The card's buttons that reach past its right edge (a long label that does not wrap). */
async function outsideCard(page: Page): Promise<string[]> {
  return card(page).evaluate((el) => {
    const right = el.getBoundingClientRect().right;
    return [...el.querySelectorAll("button")]
      .filter((b) => b.getBoundingClientRect().right > right + 0.5)
      .map((b) => (b.textContent ?? "").replace(/\s+/g, " ").trim());
  });
}

/** Opens the Editor with a second scene added (a motion of 2 × 0.5 s) and shows its Play tab. */
async function openEditorPlay(page: Page, words: { editor: string; addAfter: string }): Promise<void> {
  await page.getByRole("link", { name: words.editor, exact: true }).click();
  await page.getByTestId("editor").waitFor();
  await page.getByRole("button", { name: words.addAfter }).click();
  await page.locator("#scene-opt-1[aria-current=true]").waitFor();
  await page.locator("#editor-tab-play").click();
  await page.locator("#editor-panel-play").waitFor();
  await card(page).waitFor();
}

const EN = { editor: "Editor", addAfter: "Add after" };

/**
 * A new page with a robot connected at start (`start`: the demo robot or the fake cable), once the Robot view has
 * read its motion memory (all 24,576 bytes free), showing the Editor's Play tab with a second scene added.
 */
async function openOnRobot(options: PageOptions, start: TestStart, words: typeof EN) {
  const opened = await app.newPage({ ...options, start });
  const { page } = opened;
  await loadConnected(page, app.url);
  await page.getByTestId("device-card").waitFor();
  await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
  await openEditorPlay(page, words);
  return opened;
}

/** Sets scene 1's end position of servo 0 on the Pose tab, then shows the Play tab again. */
async function editServo0End(page: Page, value: string): Promise<void> {
  await openEditorTab(page, "pose");
  await page.getByTestId("end-0").fill(value);
  await page.getByTestId("end-0").press("Tab");
  await openEditorTab(page, "play");
}

describe("the Editor: upload to the robot and run it there", () => {
  it("uploads the draft with progress in place, runs it as motion 12 (remote key 1), and says when the robot holds an earlier version", async () => {
    const { page, context } = await openOnRobot({ options: FAST }, DEMO, EN);

    // One line near the two buttons says how storing differs from tethered play.
    await expectText(
      page.getByTestId("editor-robot-difference"),
      "Play on robot (above) tries the motion from this computer and stores nothing. Upload to robot stores it in the robot's memory, where it runs by its number or from the remote, without the cable.",
    );
    await page.getByRole("button", { name: "Play on robot…" }).waitFor();
    await expectText(page.getByTestId("editor-upload-why"), "Uploads to the demo robot's simulated memory.");
    // Nothing stored from here yet: no Run button.
    expect(await page.getByTestId("editor-run").count()).toBe(0);

    // Upload: the progress in place, held at the first progress report (bytes, percent, Cancel).
    const firstReport = await watchText(
      page,
      '[data-testid="editor-upload"] [data-testid="upload-figures"]',
      /^\s*[1-9]/,
      { hold: true },
    );
    await page.getByRole("button", { name: "Upload to robot" }).click();
    await firstReport.moment();
    const progress = card(page).getByTestId("upload-progress");
    await progress.waitFor();
    await card(page).getByTestId("upload-figures").waitFor();
    // 2 scenes × 16 servos: 12 + 6·16 + 2·(6 + 5·16) = 280 bytes (docs/protocol.md §6.3), in chunks of 64.
    await expectText(
      card(page).getByTestId("upload-figures"),
      /^(64|128|192|256) of 280 bytes \((22|45|68|91)%\)/,
    );
    await expectText(progress, "Uploading NewMotion.rbm", { contains: true });
    await expect.poll(() => progress.getByRole("button", { name: "Cancel upload" }).isEnabled()).toBe(true);
    await expect.poll(() => page.getByRole("button", { name: "Upload to robot" }).isDisabled()).toBe(true);
    // Its own upload is not "busy" beside it: the progress and Cancel are right there.
    expect(await page.getByTestId("editor-robot-busy").count()).toBe(0);
    await shot(card(page), "editor-upload-progress");
    await releaseRobot(page);

    // Stored: the Motions view's result, then the number and the remote key.
    const result = card(page).locator(".upload-in-place .notice");
    await result.waitFor();
    await expectText(
      result,
      /^Uploaded NewMotion\.rbm: 280 bytes in 5 chunks .* Stored as motion 12 \(key 1\): Run takes this number\. Free motion memory: 24,256 of 24,576 bytes \(was 24,576; the file takes 320\)\. Error code after the upload: no error\.$/,
    );
    await expect.poll(() => copyText(page)).toBe("The robot holds this motion as motion 12 (remote key 1).");
    const run = page.getByRole("button", { name: "Run on robot: motion 12 (remote key 1)", exact: true });
    await run.waitFor();
    expect(await page.evaluate(() => window.__rbcDemoSim?.motions.length)).toBe(1);

    // After switching on, only Basic posture: the card says so, with its button (and asks once before moving).
    const posture = page.getByTestId("editor-posture");
    await expectText(posture, "After switching on, the robot only accepts Basic posture (7). Run it first.", {
      contains: true,
    });
    await posture.getByRole("button", { name: "Run motion 7 (Basic posture)" }).click();
    await page.getByTestId("move-confirm").waitFor();
    // The question takes the focus, so the keyboard answers it.
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("confirm-move");
    await page.keyboard.press("Enter");
    await card(page).getByText("Motion 7 (Basic posture) finished.").waitFor();
    await posture.waitFor({ state: "detached" });

    // Run on robot: the Run tab's rule (played only when nothing was playing and the reply came no sooner than
    // its 1.0 s allows); the packet log shows Run with number 12, byte for byte.
    await run.click();
    await card(page).getByTestId("running-motion").waitFor();
    await card(page).getByText("Motion 12 (NewMotion) finished.").waitFor();
    expect(await page.evaluate(() => window.__rbcDemoSim?.playingMotion)).toBeUndefined();
    expect(await axeProblems(page, { within: '[data-testid="editor-upload"]' })).toEqual([]);

    await page.getByRole("link", { name: "Log", exact: true }).click();
    const log = page.getByTestId("log-card");
    await log.getByText(RUN_12).first().waitFor();
    await expectText(log, `→ out Run motion ${RUN_12}`, { contains: true });
    // The robot's reply, after the motion: type 14 from the robot (platform 01, HUNO), number 12.
    await expectText(log, "← in Run motion FF FF AA 55 AA 55 37 BA 14 01 00 00 00 01 0C 0C", {
      contains: true,
    });

    // An edit after the upload: the robot holds the earlier version; Undo makes the draft the uploaded one again.
    await page.getByRole("link", { name: "Editor", exact: true }).click();
    await page.getByTestId("editor").waitFor();
    await editServo0End(page, "120");
    await expect
      .poll(() => copyText(page))
      .toBe(
        "The robot holds an earlier version of this motion as motion 12 (remote key 1): the draft changed after the upload. Upload again to store what is on screen.",
      );
    await page
      .getByRole("button", { name: "Run the earlier version: motion 12 (remote key 1)", exact: true })
      .waitFor();
    // Its long label wraps inside the card (the Play tab is a narrow column beside the scenes).
    expect(await pageProblems(page, { within: '[data-testid="editor-upload"]' })).toEqual([]);
    expect(await outsideCard(page)).toEqual([]);
    await page.getByTestId("editor-undo").click();
    await expect.poll(() => copyText(page)).toBe("The robot holds this motion as motion 12 (remote key 1).");
    await context.close();
  });

  it("refuses while a motion plays, with the busy sentence and a Stop beside it; Escape stops a run started here", async () => {
    const { page, context } = await openOnRobot({ options: FAST }, DEMO, EN);
    // Scene 1 moves servo 0, so that motion 12 moves a servo (and can be caught playing).
    await editServo0End(page, "100");
    await page.getByRole("button", { name: "Upload to robot" }).click();
    const posture = page.getByTestId("editor-posture");
    await posture.getByRole("button", { name: "Run motion 7 (Basic posture)" }).click();
    await page.locator("#confirm-move").click();
    await card(page).getByText("Motion 7 (Basic posture) finished.").waitFor();

    // A motion started in the Motions view (Get up A, 5.5 s), held while it plays; then the Editor.
    await page.getByRole("link", { name: "Motions", exact: true }).click();
    await page.getByRole("tab", { name: "Run" }).click();
    await holdWhenPlaying(page, 1);
    await page.locator('[data-motion="1"]').click();
    await page.getByTestId("running-motion").waitFor();
    await page.getByRole("link", { name: EN.editor, exact: true }).click();
    await card(page).waitFor();
    const busy = page.getByTestId("editor-robot-busy");
    await expectText(
      busy,
      "A motion is playing: the robot ignores everything but Basic posture (7) until it ends. Stop",
    );
    await expect.poll(() => page.getByRole("button", { name: "Upload to robot" }).isDisabled()).toBe(true);
    await expect.poll(() => page.getByTestId("editor-run").isDisabled()).toBe(true);
    await expect
      .poll(() => page.getByRole("button", { name: "Upload to robot" }).getAttribute("aria-describedby"))
      .toBe("editor-upload-why editor-robot-busy");
    expect(await page.evaluate(() => window.__rbcDemoSim?.playingMotion)).toBe(1);
    expect(await axeProblems(page, { within: '[data-testid="editor-upload"]' })).toEqual([]);
    await shot(card(page), "editor-upload-busy");
    await busy.getByRole("button", { name: "Stop" }).click();
    await releaseRobot(page);
    await busy.waitFor({ state: "detached" });
    expect(await page.evaluate(() => window.__rbcDemoSim?.playingMotion)).toBeUndefined();
    await expect.poll(() => page.getByRole("button", { name: "Upload to robot" }).isEnabled()).toBe(true);

    // A run started here shows its own progress (with Stop motion, no second Stop); Escape is Stop still.
    await holdWhenPlaying(page, 12);
    await page.getByTestId("editor-run").click();
    await card(page).getByTestId("running-motion").waitFor();
    expect(await page.getByTestId("editor-robot-stop").count()).toBe(0);
    await expect.poll(() => page.getByRole("button", { name: "Upload to robot" }).isDisabled()).toBe(true);
    expect(await page.evaluate(() => window.__rbcDemoSim?.playingMotion)).toBe(12);
    await page.keyboard.press("Escape");
    await releaseRobot(page);
    await card(page).getByTestId("running-motion").waitFor({ state: "detached" });
    expect(await page.evaluate(() => window.__rbcDemoSim?.playingMotion)).toBeUndefined();
    const passive = await page.evaluate(() => window.__rbcDemoSim?.servos.map((s) => s.passive));
    expect(passive).toEqual(Array(16).fill(false));
    await context.close();
  });

  it("on a real robot (the fake cable) asks first, as the Motions upload does, then stores it", async () => {
    const { page, context } = await openOnRobot({ options: FAST }, CABLE, EN);
    await expectText(
      page.getByTestId("editor-upload-why"),
      "Asks for confirmation first: uploading to a real robot is experimental.",
    );
    await page.getByRole("button", { name: "Upload to robot" }).click();
    const ask = card(page).getByTestId("upload-confirm");
    await ask.waitFor();
    await expectText(ask, "NewMotion.rbm", { contains: true });
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("confirm-upload");
    // Nothing sent before the answer.
    expect(await page.evaluate(() => window.__rbcTest?.sim.motions.length)).toBe(0);
    await page.locator("#confirm-upload").click();
    await page.getByRole("button", { name: "Run on robot: motion 12 (remote key 1)", exact: true }).waitFor();
    expect(await page.evaluate(() => window.__rbcTest?.sim.motions.length)).toBe(1);
    await context.close();
  });
});

async function openEditorTab(page: Page, tab: "pose" | "play"): Promise<void> {
  await page.locator(`#editor-tab-${tab}`).click();
  await page.locator(`#editor-panel-${tab}`).waitFor();
}

describe("in Korean (ko-KR), at phone width", () => {
  it("says it all in Korean, fits and passes axe", async () => {
    const { page, context } = await openOnRobot({ locale: "ko-KR", viewport: PHONE, options: FAST }, DEMO, {
      editor: "편집기",
      addAfter: "뒤에 추가",
    });
    await expectText(card(page).getByRole("heading", { level: 2 }), "로봇에 저장");
    await expectText(
      page.getByTestId("editor-robot-difference"),
      "위의 ‘로봇에서 재생’은 이 컴퓨터에서 모션을 시험해 볼 뿐 아무것도 저장하지 않아요. ‘로봇에 업로드’는 모션을 로봇 메모리에 저장해서 케이블 없이도 번호나 리모컨으로 실행할 수 있어요.",
    );
    await page.getByRole("button", { name: "로봇에 업로드" }).click();
    await page
      .getByRole("button", { name: "로봇에서 실행: 모션 12번(리모컨 1번 키)", exact: true })
      .waitFor();
    await expect
      .poll(() => copyText(page))
      .toBe("로봇에 이 모션이 모션 12번(리모컨 1번 키)으로 저장되어 있어요.");
    await expectPageOk(page, "the Editor's Play tab after an upload, in Korean", {
      lang: "ko",
      within: '[data-testid="editor-upload"]',
    });
    await editServo0End(page, "120");
    await expect
      .poll(() => copyText(page))
      .toBe(
        "로봇에는 이 모션의 이전 버전이 모션 12번(리모컨 1번 키)으로 저장되어 있어요. 업로드한 뒤에 임시 저장본이 바뀌었어요. 화면의 모션을 저장하려면 다시 업로드해 주세요.",
      );
    await page
      .getByRole("button", { name: "이전 버전 실행: 모션 12번(리모컨 1번 키)", exact: true })
      .waitFor();
    await context.close();
  });
});
