import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { DEMO } from "./connected-page.ts";
import { openEditorOnDemo } from "./editor-fixtures.ts";
import { expectText, FAST, squash, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";

// Issue 21 item 5: the Editor's questions say what the robot will actually do.

const app = useApp();

async function showTab(page: Page, tab: "pose" | "teach" | "play"): Promise<void> {
  await page.locator(`#editor-tab-${tab}`).click();
  await page.locator(`#editor-panel-${tab}`).waitFor();
}

describe("the Editor's questions match what the robot will do", () => {
  it("Play on robot names the servos it will hold at the edge of their safe range, with the values", async () => {
    const { page, context } = await app.newPage({ start: DEMO, options: FAST });
    await openEditorOnDemo(page, app.url);
    // docs/protocol.md §5: servo 0's safe range ends at 174; the motion asks for 200.
    await showTab(page, "pose");
    await page.getByTestId("end-0").fill("200");
    await page.getByTestId("end-0").press("Tab");
    const robot = page.locator('[data-testid="editor-robot3d"][data-state="ready"]');
    await robot.waitFor({ timeout: 20_000 });
    const servo0 = async () => (await robot.getAttribute("data-pose"))?.split(" ")[0];
    // The scene as the file has it: 200.
    await expect.poll(servo0).toBe("200");
    await showTab(page, "play");
    await page.locator("#play-button").click();
    const clamped = page.getByTestId("play-clamped");
    await clamped.waitFor();
    await expectText(clamped, /^1 servo is outside its safe range in these scenes/);
    await expectText(clamped, /servo 0 \([^)]+\) 200 → 174/);
    // While it asks, the 3D shows what the robot will do: servo 0 at 174, not the file's 200.
    await expect.poll(servo0).toBe("174");
    await expect
      .poll(() => page.getByTestId("editor-robot3d").locator("canvas").getAttribute("aria-label"))
      .toContain("as the robot will take it");
    await page.locator("#cancel-play").click();
    await expect.poll(servo0).toBe("200");
    await context.close();
  });

  it("Teach-in after Limp says every servo stays limp, not that every servo holds", async () => {
    const { page, context } = await app.newPage({ start: DEMO, options: FAST });
    await openEditorOnDemo(page, app.url);
    await page.locator("#limp-button").click();
    await page.locator("#confirm-limp").click();
    await page.getByTestId("stop-banner").filter({ hasText: "limp" }).waitFor();
    await showTab(page, "teach");
    await page.locator("#start-teach-in").click();
    await expectText(
      page.getByTestId("teach-in-detail"),
      "Every servo is limp now (Limp was pressed) and stays limp until you press Hold",
      { contains: true },
    );
    const detail = squash(await page.getByTestId("teach-in-detail").textContent());
    expect(detail).not.toContain("every servo holds");
    await context.close();
  });

  it("Teach-in after Limp and then Stop (which leaves servo control and moves no servo) still says every servo is limp", async () => {
    const { page, context } = await app.newPage({ start: DEMO, options: FAST });
    await openEditorOnDemo(page, app.url);
    await page.locator("#limp-button").click();
    await page.locator("#confirm-limp").click();
    await page.getByTestId("stop-banner").filter({ hasText: "limp" }).waitFor();
    const allPassive = () =>
      page.evaluate(() => window.__rbcDemoSim?.servos.slice(0, 16).every((s) => s.passive));
    await expect.poll(allPassive).toBe(true);
    await page.getByTestId("stop-banner").filter({ hasText: "all 16 servos confirmed passive" }).waitFor();
    // Stop leaves direct mode (docs/protocol.md §5's leave sequence): no servo is commanded, so all stay limp.
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    await expect.poll(() => page.evaluate(() => window.__rbcDemoSim?.directMode)).toBe(false);
    expect(await allPassive()).toBe(true);
    await showTab(page, "teach");
    await page.locator("#start-teach-in").click();
    const detail = page.getByTestId("teach-in-detail");
    await expect
      .poll(async () => squash(await detail.textContent()))
      .toContain("Every servo is still limp from Limp (leaving servo control moved none of them)");
    expect(squash(await detail.textContent())).not.toContain("hold their position");
    await context.close();
  });
});
