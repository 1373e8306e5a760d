import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { goldenImage } from "../data/project-data.ts";
import { expectText, FAST, squash, useApp } from "./harness.ts";
import { connectDemo, expectPageOk, newLocalePage } from "./i18n-checks.ts";
import { exampleText, rbmFile, showTab } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

/**
 * The robot's shelf in the panel and the demo robot that keeps its memory (issue 23 item 2): an upload shows one
 * number (the number Run takes) with its remote key and "Run now"; after a page reload and a new connection the
 * demo robot still holds the motion and the panel still knows its name, number and length (Run is judged by the
 * recorded length); "Reset the demo robot" makes it new, and the record is dropped with a sentence.
 */

const app = useApp();

/** tests/data/images/wave.img.hex: the golden image of examples/wave.rbm (624 bytes, 640 in memory). */
const WAVE_HEX = Buffer.from(goldenImage("wave.rbm")).toString("hex");

const demoMotionsHex = (page: Page) =>
  page.evaluate(() =>
    (window.__rbcDemoSim?.motions ?? []).map((m) =>
      Array.from(m.bytes, (b) => b.toString(16).padStart(2, "0")).join(""),
    ),
  );

/** Waits until the demo robot's memory has been saved `count` times in this browser (an event, not a delay). */
const demoSaved = (page: Page, count: number) =>
  page.waitForFunction((n) => (window.__rbcDemoSaves ?? 0) >= n, count);

/** The demo robot from the start card, then Motions, with its free memory read (`free` bytes). */
async function demoMotions(page: Page, free: string): Promise<void> {
  // The start card is on the Robot view (a reload keeps the Motions view, which shows its files without a robot).
  await page.locator('.side-nav a[href$="robot"]').click();
  await connectDemo(page);
  await page.locator('.side-nav a[href$="motions"]').click();
  // "23,936 of 24,576 bytes free"; in Korean the whole area comes first.
  const figures = new RegExp(`${free}\\D+24,576|24,576\\D+${free}`);
  await page.getByTestId("mem-motion-text").filter({ hasText: figures }).waitFor();
}

async function uploadWave(page: Page): Promise<void> {
  await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", exampleText("wave.rbm")));
  await page.getByTestId("motion-file").getByTestId("upload-motion").click();
}

describe("the robot's shelf on the demo robot", () => {
  it("one number with its key and Run now; kept through a reload and a reconnect; forgotten, with a sentence, after a reset", async () => {
    const { page, context } = await newLocalePage(app, "en-US", { options: FAST });
    await demoMotions(page, "24,576");
    await uploadWave(page);
    const card = page.getByTestId("motion-file");
    const result = card.getByText(/^Uploaded wave\.rbm/);
    await result.waitFor();
    await expectText(result, "Stored as motion 12 (key 1): Run takes this number.", { contains: true });
    const said = squash(await result.textContent());
    expect(said).not.toMatch(/downloaded motion 1|slot 1/);
    await card.getByTestId("run-now").filter({ hasText: "Run now" }).waitFor();

    // The Memory tab: one number, its key, the name and length, how it is known, Run now.
    await showTab(page, "Memory");
    await page.locator('[data-testid="shelf-intro"][data-kept="12"]').waitFor();
    const entry = page.locator('[data-testid="shelf-entry"][data-motion="12"]');
    await expectText(
      entry,
      "12 RbcPanel_Wave remote: key 1 · plays 3.2 s uploaded now; the robot's memory accounting showed it stored Run now",
    );
    await expectPageOk(page, "the Memory tab after an upload", { lang: "en" });

    // The Run tab: the same number with the key; the other slots are the 19 the panel has no record of.
    await showTab(page, "Run");
    await expectText(
      page.locator('[data-testid="downloaded-motions"] [data-motion="12"]'),
      "12 RbcPanel_Wave key 1 3.2 s",
    );
    await expectText(page.locator(".other-slots summary"), "Other upload slots (19)");
    await expectText(page.locator('[data-slot-motion="33"]'), "Run motion 33 * then 1");
    // Basic posture first (a new robot ignores the rest until it has run, docs/protocol.md §3.1).
    await page.locator('[data-motion="7"]').click();
    await page.locator("#confirm-move").click();
    await page.getByText("Motion 7 (Basic posture) finished.").waitFor();

    // The demo robot's memory is kept in this browser once it changed (the upload): reload, connect again.
    await demoSaved(page, 1);
    await page.reload({ waitUntil: "domcontentloaded" });
    await demoMotions(page, "23,936");
    expect(await demoMotionsHex(page)).toEqual([WAVE_HEX]);
    await showTab(page, "Memory");
    await page.locator('[data-testid="shelf-intro"][data-kept="12"]').waitFor();
    await page.getByText(/may still be there/).waitFor();
    await expectText(
      entry,
      /^12 RbcPanel_Wave remote: key 1 · plays 3\.2 s uploaded .+; may still be there \(the robot's free memory still has room for it\) Run now$/,
    );
    // Run now: the robot stayed on (its Basic posture had run), and the Run is judged by the recorded 3.2 s.
    await entry.getByTestId("run-now").click();
    await page.locator("#confirm-move").click();
    await page.getByText("Motion 12 (RbcPanel_Wave) finished.").waitFor();
    await expectText(page.locator(".other-slots summary"), "Other upload slots (19)");
    await expectPageOk(page, "the Run tab after a reload", { lang: "en" });
    // The Remote card names key 1 from the shelf too (not only from this connection's uploads).
    await page.getByRole("link", { name: "Sensors", exact: true }).click();
    await page.getByTestId("remote-fold").locator("summary").click();
    await page
      .locator('[data-testid="remote-key"][data-code="12"]')
      .filter({ hasText: "RbcPanel_Wave" })
      .waitFor();
    await page.getByRole("link", { name: "Motions", exact: true }).click();

    // Reset the demo robot: asked once, connected again as new; the record goes, and the panel says so.
    await showTab(page, "Memory");
    await page.getByTestId("demo-reset").locator("summary").click();
    await page.getByTestId("demo-reset-confirm").click();
    await page
      .getByTestId("demo-reset-result")
      .getByText(/was reset and connected again as new/)
      .waitFor();
    const dropped = page.getByTestId("shelf-dropped");
    await dropped.getByText(/^Forgotten: motion 12 \(RbcPanel_Wave\)/).waitFor();
    await expectText(
      dropped,
      "Forgotten: motion 12 (RbcPanel_Wave). The robot's free memory (0 of 24,576 bytes in use) has no room for what was recorded: its memory was reset, or another program uploaded to it.",
    );
    // Kept as a message, so a language switch rewords it (issue 21 item 6).
    await page.getByLabel(/Language/).selectOption("ko");
    await dropped
      .filter({
        hasText:
          "기록에서 지웠어요: 모션 12번(RbcPanel_Wave). 로봇의 남은 메모리(24,576바이트 중 0바이트 사용)에는 기록된 모션이 들어갈 자리가 없어요.",
      })
      .waitFor();
    await page.getByLabel(/언어|Language/).selectOption("en");
    await dropped.getByText(/^Forgotten: motion 12 \(RbcPanel_Wave\)/).waitFor();
    await page.getByTestId("shelf-none").waitFor();
    expect(await demoMotionsHex(page)).toEqual([]);
    expect(await page.evaluate(() => window.__rbcDemoSim?.basicPostureDone)).toBe(false);
    await expectPageOk(page, "the Memory tab after a reset", { lang: "en" });
    // A reload now finds a new robot: the reset was kept, not only the page's robot.
    await page.reload({ waitUntil: "domcontentloaded" });
    await demoMotions(page, "24,576");
    expect(await demoMotionsHex(page)).toEqual([]);
    await context.close();
  });

  it("in Korean: the stored motion's number, key and Run now", async () => {
    const { page, context } = await newLocalePage(app, "ko-KR", { options: FAST });
    await demoMotions(page, "24,576");
    await uploadWave(page);
    const result = page.getByTestId("motion-file").getByText(/^wave\.rbm/);
    await result.filter({ hasText: "모션 12번(1번 키)으로 저장했어요. 실행할 때 이 번호를 써요." }).waitFor();
    await page.locator('.motions-tab[id="motions-tab-uploads"]').click();
    await page.locator('[data-testid="shelf-intro"][data-kept="12"]').waitFor();
    await expectText(
      page.locator('[data-testid="shelf-entry"][data-motion="12"]'),
      "12 RbcPanel_Wave 리모컨: 1번 키 · 재생 시간 3.2초 방금 업로드했고, 로봇의 메모리 계산에서 저장된 게 확인됐어요 지금 실행",
    );
    await page.getByTestId("demo-reset").locator("summary").click();
    await expectPageOk(page, "the Memory tab in Korean", { lang: "ko" });
    await context.close();
  });
});
