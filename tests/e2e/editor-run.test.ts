/**
 * Issue 33 items 3 and 4, on the demo robot.
 *
 * Item 3: "Run now" under the Editor's upload result opened its question in Motions → Run (another view, not on
 * screen), sent nothing and greyed out the Editor's other Run buttons. Now it asks right under the button, in the
 * Editor (the Motions view's own question and words, with "Basic posture first" while the robot is not known to
 * be in it); Cancel sends nothing; confirmed, the Run goes out and the Editor shows it as the Run tab does: "sent:
 * checking" until the robot is seen busy (docs/protocol.md §3.1), then the verdict.
 *
 * Item 4: after "Play on robot" (tethered play, docs/protocol.md §10) the robot stays in direct mode; Upload said
 * "end teach-in, or servo control in the Servos view, first" though neither was used. Now the refusal beside the
 * disabled control names tethered play and Stop (from the device's activity), with Stop beside it, in English
 * and Korean.
 *
 * The robot runs on the paced virtual clock (FAST); the moment a Run was sent and not yet seen busy is held by
 * an event in the page (`watchText` with `hold`), never by waiting a while.
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { DEMO, loadConnected } from "./connected-page.ts";
import { expectText, FAST, releaseRobot, squash, type TestContext, useApp, watchText } from "./harness.ts";
import { axeProblems, PHONE, pageProblems } from "./i18n-checks.ts";
import "./rbc-test-globals.ts";

const app = useApp();

const card = (page: Page) => page.getByTestId("editor-upload");
const switchLanguage = (page: Page, to: "en" | "ko") => page.getByLabel(/Language|언어/).selectOption(to);

/** A page with the demo robot connected, its motion memory read, showing the Editor's Play tab. */
async function openEditorPlay(): Promise<{ page: Page; context: TestContext }> {
  const { page, context } = await app.newPage({ options: FAST, start: DEMO });
  await loadConnected(page, app.url);
  await page.getByTestId("device-card").waitFor();
  await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
  await page.getByRole("link", { name: "Editor", exact: true }).click();
  await page.getByTestId("editor").waitFor();
  await page.locator("#editor-tab-play").click();
  await page.locator("#editor-panel-play").waitFor();
  await card(page).waitFor();
  return { page, context };
}

/**
 * Counts the Run motion packets (type 0x14, docs/protocol.md §2: `… 37 BA 14 …`) the demo robot receives from
 * now on (`runsSent`).
 */
async function countRuns(page: Page): Promise<void> {
  await page.evaluate(() => {
    const sim = window.__rbcDemoSim;
    if (!sim) throw new Error("no demo robot in this page");
    const w = window as unknown as { __runsSent: number };
    w.__runsSent = 0;
    let tail: number[] = [];
    const receive = sim.receive.bind(sim);
    sim.receive = (bytes: Uint8Array) => {
      const seen = [...tail, ...bytes];
      for (let i = 0; i + 2 < seen.length; i++) {
        if (i + 2 >= tail.length && seen[i] === 0x37 && seen[i + 1] === 0xba && seen[i + 2] === 0x14)
          w.__runsSent++;
      }
      tail = seen.slice(-2);
      receive(bytes);
    };
  });
}

const runsSent = (page: Page) =>
  page.evaluate(() => (window as unknown as { __runsSent: number }).__runsSent);

describe("the Editor's Run now (issue 33 item 3)", () => {
  it("asks in the Editor under the button, Cancel sends nothing, confirmed it shows 'sent: checking' then the verdict", async () => {
    const { page, context } = await openEditorPlay();
    await page.getByRole("button", { name: "Upload to robot" }).click();
    const runNow = card(page).getByTestId("run-now");
    await runNow.waitFor();
    await countRuns(page);
    const url = page.url();

    // The question, right under "Run now", in the Editor: the Motions view's words, Basic posture first.
    await runNow.click();
    const place = card(page).getByTestId("editor-run-place-result");
    const ask = place.getByTestId("move-confirm");
    await ask.waitFor();
    await expectText(ask, "The robot will move. Hold it or give it room.", { contains: true });
    await expectText(
      ask.getByTestId("move-posture-first"),
      "After switching on, the robot only accepts Basic posture (7). Run it first. Until then it silently ignores every other motion.",
    );
    await expectText(ask, "The panel asks this once per connection.", { contains: true });
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("confirm-move");
    expect(page.url()).toBe(url);
    await page.getByTestId("editor").waitFor();
    // Under the button, and on screen (the focus brought it there).
    const [button, question] = [await runNow.boundingBox(), await ask.boundingBox()];
    expect(question && button && question.y >= button.y + button.height).toBe(true);
    await expect
      .poll(async () => {
        const box = await ask.boundingBox();
        const size = page.viewportSize();
        return box !== null && size !== null && box.y >= 0 && box.y + box.height <= size.height;
      })
      .toBe(true);
    expect(await axeProblems(page, { within: '[data-testid="editor-upload"]' })).toEqual([]);
    // At phone width it fits its card.
    await page.setViewportSize(PHONE);
    expect(await pageProblems(page, { within: '[data-testid="editor-upload"]', axe: false })).toEqual([]);
    await page.setViewportSize({ width: 1280, height: 800 });

    // Cancel: nothing sent, nothing running, the Run buttons back.
    await ask.getByRole("button", { name: "Cancel" }).click();
    await ask.waitFor({ state: "detached" });
    expect(await runsSent(page)).toBe(0);
    expect(await page.evaluate(() => window.__rbcDemoSim?.playingMotion)).toBeUndefined();
    await expect.poll(() => runNow.isEnabled()).toBe(true);
    await expect.poll(() => page.getByTestId("editor-run").isEnabled()).toBe(true);

    // Confirmed: sent, then checked (no "Running", no bar) until the robot is seen busy or its reply comes.
    const running = place.getByTestId("running-motion");
    const checking = await watchText(
      page,
      '[data-testid="editor-run-place-result"] [data-testid="running-motion"]',
      /sent: checking that the robot plays it/,
      { hold: true },
    );
    await runNow.click();
    await ask.waitFor();
    await page.locator("#confirm-move").click();
    await checking.moment();
    await expectText(running, "Motion 12 — NewMotion sent: checking that the robot plays it", {
      contains: true,
    });
    expect(await running.locator("progress").count()).toBe(0);
    expect(squash(await running.textContent())).not.toContain("Running");
    expect(page.url()).toBe(url);
    await releaseRobot(page);

    // The verdict, under the same button: before Basic posture the robot ignores motion 12 (§3.1).
    const verdict = place.locator(".notice");
    await expectText(verdict, /The robot ignored motion 12/);
    await expectText(verdict, "Run it first.", { contains: true });
    await running.waitFor({ state: "detached" });
    expect(await runsSent(page)).toBe(1);
    expect(page.url()).toBe(url);
    await context.close();
  });
});

describe("the Editor's Upload after Play on robot (issue 33 item 4)", () => {
  it("names tethered play and Stop beside the disabled control, in English and Korean; Stop ends it", async () => {
    const { page, context } = await openEditorPlay();
    await page.locator("#play-button").click();
    await page.locator("#confirm-play").click();
    await page.getByTestId("play-panel").getByText("the servos hold the last frame").waitFor();

    const upload = page.getByTestId("editor-upload-button");
    const busy = page.getByTestId("editor-robot-busy");
    await expect.poll(() => upload.isDisabled()).toBe(true);
    await expectText(
      busy,
      "Tethered play (Play on robot) keeps the robot in direct mode: press Stop to end it. The servos keep their pose. Stop",
    );
    await expect
      .poll(() => upload.getAttribute("aria-describedby"))
      .toBe("editor-upload-why editor-robot-busy");
    expect(await axeProblems(page, { within: '[data-testid="editor-upload"]' })).toEqual([]);

    await switchLanguage(page, "ko");
    await expectText(
      busy,
      "로봇에서 재생 때문에 로봇이 직접 모드에 있어요. 끝내려면 정지를 눌러 주세요. 서보는 자세를 그대로 유지해요. 정지",
    );
    await expect.poll(() => upload.isDisabled()).toBe(true);

    // Its Stop ends tethered play's direct mode: Upload is back.
    await busy.getByRole("button", { name: "정지" }).click();
    await busy.waitFor({ state: "detached" });
    await expect.poll(() => upload.isEnabled()).toBe(true);
    expect(await page.evaluate(() => window.__rbcDemoSim?.directMode)).toBe(false);
    await context.close();
  });
});
