import type { Locator, Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { expectText, squash, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";

/**
 * One Stop for every robot of the page (issue 31 item 2): with only Class view robots connected (no robot in the
 * top bar), the top bar still offers Stop; the Stop button and Escape (from a button) stop each class robot, and
 * the top bar says each robot's outcome on a line of its own; with a robot in the top bar as well, its outcome is
 * named too. Stop never makes a servo passive.
 */

const app = useApp();

/** The class demo robots' simulators, as the test sees them (as class-view.test.ts reads them). */
const sims = (page: Page) =>
  page.evaluate(() => {
    const demos =
      (
        window as unknown as {
          __rbcClassDemos?: { sim: { playingMotion?: number; servos: { passive: boolean }[] } }[];
        }
      ).__rbcClassDemos ?? [];
    return demos.map((d) => ({
      playing: d.sim.playingMotion,
      passive: d.sim.servos.slice(0, 16).filter((s) => s.passive).length,
    }));
  });

const rows = (page: Page) => page.getByTestId("class-robot");
const row = (page: Page, i: number): Locator => rows(page).nth(i);
const runButton = (page: Page) => page.getByRole("button", { name: "Run on all 2 robots" });

/** Runs motion `n` on both class robots, and waits until both simulators play it. */
async function runOnBoth(page: Page, n: number): Promise<void> {
  await page.getByLabel("Motion", { exact: true }).selectOption(String(n));
  await runButton(page).click();
  // Run on all asks once for the class first (issue 33 item 2).
  await page.getByTestId("class-confirm").click();
  await expect.poll(async () => (await sims(page)).map((s) => s.playing)).toEqual([n, n]);
}

/** Waits until the top bar's lines, one per class robot, say `expected` (a line still shown from before does not). */
async function expectStopLines(page: Page, expected: string[]): Promise<void> {
  const lines = page.getByTestId("robot-stop");
  await expect
    .poll(async () => (await lines.allTextContents()).map(squash), { timeout: 20_000 })
    .toEqual(expected);
}

const STOPPED =
  "The robot took Stop: the motion ended at the end of the scene it was in. The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing. Basic posture (7) brings it back to standing.";

describe("Stop reaches every robot of the page, also with no robot in the top bar", () => {
  it("the top bar's Stop and Escape stop both class robots and say each one's outcome", async () => {
    const { page, context } = await app.newPage();
    await page.goto(`${app.url}#/class`, { waitUntil: "domcontentloaded" });
    await page.getByRole("heading", { level: 1, name: "Class: several robots at once" }).waitFor();
    const stop = page.getByRole("button", { name: "Stop", exact: true });
    expect(await stop.count()).toBe(0);
    for (let i = 0; i < 2; i++)
      await page.getByRole("button", { name: "Add demo robot", exact: true }).click();
    await expect.poll(() => rows(page).count()).toBe(2);
    for (let i = 0; i < 2; i++)
      await row(page, i).getByTestId("class-phase").filter({ hasText: "Connected" }).waitFor();

    // The top bar's robot is not connected, yet the robots of the page can move: the top bar offers Stop.
    await expectText(page.getByTestId("connection-status"), "Not connected");
    await stop.waitFor();
    expect(await page.locator("#limp-button").count()).toBe(0);

    // Basic posture first (a robot ignores other motions until 7 has run), then motion 2 (6.6 s).
    await runButton(page).click();
    await page.getByTestId("class-confirm").click();
    for (let i = 0; i < 2; i++)
      await row(page, i)
        .getByTestId("class-result")
        .filter({ hasText: "Motion 7 played" })
        .waitFor({ timeout: 20_000 });
    await runOnBoth(page, 2);
    await stop.click();
    await expectStopLines(page, [`Demo robot 1: ${STOPPED}`, `Demo robot 2: ${STOPPED}`]);
    await expect.poll(async () => (await sims(page)).map((s) => s.playing)).toEqual([undefined, undefined]);
    expect((await sims(page)).map((s) => s.passive)).toEqual([0, 0]);

    // Dismiss clears the lines; Escape from a button (a robot's Name) stops both again.
    await page.getByTestId("stop-banner").getByRole("button", { name: "Dismiss" }).click();
    await expect.poll(() => page.getByTestId("robot-stop").count()).toBe(0);
    await runOnBoth(page, 2);
    await row(page, 0).getByRole("button", { name: /^Name/ }).focus();
    await page.keyboard.press("Escape");
    await expectStopLines(page, [`Demo robot 1: ${STOPPED}`, `Demo robot 2: ${STOPPED}`]);
    await expect.poll(async () => (await sims(page)).map((s) => s.playing)).toEqual([undefined, undefined]);
    expect((await sims(page)).map((s) => s.passive)).toEqual([0, 0]);

    // With a robot in the top bar too, Stop reaches all three, and the top bar names each one's outcome.
    await page.getByRole("link", { name: "Robot", exact: true }).click();
    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await stop.click();
    const idle = "The robot answered at once: it is idle, nothing to stop. Nothing was sent.";
    await expectStopLines(page, [`Demo robot 1: ${idle}`, `Demo robot 2: ${idle}`]);
    await expectText(page.getByTestId("stop-banner").locator("p").first(), `Demo robot: ${idle}`);
    await context.close();
  });
});
