import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { CABLE, loadMotions } from "./connected-page.ts";
import { connectRobot, expectText, FAST, squash, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";

// Stop and Limp are two things (issue #11 item 1): Stop ends what the robot is doing
// and the servos hold the pose it stopped in (a motion ends with 7); Limp makes every servo passive, only after asking. Escape keeps
// its meaning in a text field, a dialog or an open menu/list, and otherwise (a number field too) means Stop, never Limp.

const app = useApp();

/** The simulated robot as the test sees it: servo torque, direct mode, what it plays. */
const robot = (page: Page) =>
  page.evaluate(() => {
    const sim = window.__rbcTest?.sim;
    return {
      passive: sim?.servos.slice(0, 16).map((s) => s.passive),
      direct: sim?.directMode,
      playing: sim?.playingMotion,
    };
  });

const NONE_PASSIVE = Array(16).fill(false);
const ALL_PASSIVE = Array(16).fill(true);

const stopButton = (page: Page) => page.getByRole("button", { name: "Stop", exact: true });

/** Nothing focused: Escape then reaches the page itself. */
async function blur(page: Page): Promise<void> {
  await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
}

/** Runs motion `n` from the Motions view (the movement question is asked once per connection). */
async function startMotion(page: Page, n: number, name: string): Promise<void> {
  await page.locator(`[data-motion="${n}"]`).click();
  const confirm = page.locator("#confirm-move");
  // Running once the robot was seen busy with it (docs/protocol.md §3.1): the Run and its busy check have gone out.
  const running = page
    .locator('[data-testid="running-motion"][data-confirmed="yes"]')
    .filter({ hasText: name });
  // The click's own effect first: the question or the motion running (a count read at once sees neither).
  await confirm.or(running).first().waitFor();
  if (await confirm.count()) await confirm.click();
  await running.waitFor();
  await expect.poll(() => robot(page).then((r) => r.playing)).toBe(n);
}

describe("Stop leaves the servos holding; Limp asks first", () => {
  it("Escape in a zero field (a number stepper, not a text field) is Stop: no servo passive, the robot stays in packet mode", async () => {
    const { page, context } = await app.newPage();
    await connectRobot(page, app.url);
    await page.getByRole("link", { name: "Zeros" }).click();
    await page.locator("#zero-0").waitFor();
    await page.locator("#zero-3").focus();
    await page.keyboard.press("Escape");
    // Escape in a number field is Stop (docs/ui.md "Keyboard"): nothing was running, and no servo went passive.
    const banner = page.getByTestId("stop-banner");
    await banner
      .filter({ hasText: "The robot answered at once: it is idle, nothing to stop. Nothing was sent." })
      .waitFor();
    await expectText(
      banner,
      "The robot answered at once: it is idle, nothing to stop. Nothing was sent. Dismiss",
    );
    expect(await robot(page)).toMatchObject({ passive: NONE_PASSIVE, direct: false });
    expect(await page.getByTestId("connection-status").textContent().then(squash)).not.toContain("limp");
    await context.close();
  });

  it("Escape with nothing focused, and the Stop button, end a motion with 7: the servos hold, the mode stays packet", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await loadMotions(page, app.url);
    // The Run tab, where the Motions view has tabs (it loads lazily: wait for it first).
    await page.locator('[role="tablist"][aria-label="Motions"], [data-motion="7"]').first().waitFor();
    const runTab = page.getByRole("tab", { name: "Run" });
    if (await runTab.count()) await runTab.click();
    await page.locator('[data-motion="7"]').click();
    await page.locator("#confirm-move").click();
    await page.getByText("Motion 7 (Basic posture) finished.", { exact: false }).waitFor({ timeout: 8000 });

    // Escape during motion 2 (6.6 s): Stop sends 7 and the robot confirms with 07 (said in plain words; the 07
    // is the technical detail).
    await startMotion(page, 2, "Get up B");
    const sentBefore = await page.evaluate(() => window.__rbcTest?.sim.stats.packetsReceived ?? 0);
    await blur(page);
    await page.keyboard.press("Escape");
    const banner = page.getByTestId("stop-banner");
    await banner.filter({ hasText: "The robot took Stop" }).waitFor({ timeout: 8000 });
    await expectText(
      banner.locator(".banner-text > p"),
      "The robot took Stop: the motion ended at the end of the scene it was in. The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing.",
      { contains: true },
    );
    await expectText(
      banner.getByTestId("notice-more"),
      "Stop sent 7 while motion 2, started here, was playing, and the robot answered 07.",
      { contains: true },
    );
    expect(await robot(page)).toEqual({ passive: NONE_PASSIVE, direct: false, playing: undefined });
    // One packet: the 7 (no direct-mode switch, no passive command to any servo).
    expect(await page.evaluate(() => window.__rbcTest?.sim.stats.packetsReceived ?? 0)).toBe(sentBefore + 1);
    await page.getByText(/Motion 2 \(Get up B \(from back\)\) did not finish\. Stopped by Stop/).waitFor();
    expect(await page.getByTestId("connection-status").textContent().then(squash)).not.toMatch(
      /servo control|limp/,
    );

    // The red Stop button during motion 1 does the same.
    await startMotion(page, 1, "Get up A");
    await stopButton(page).click();
    await banner
      .getByTestId("notice-more")
      .filter({ hasText: "while motion 1, started here" })
      .waitFor({ state: "attached", timeout: 8000 });
    expect(await robot(page)).toEqual({ passive: NONE_PASSIVE, direct: false, playing: undefined });
    // Nothing stays in the way of the next motion.
    await expect.poll(() => page.locator('[data-motion="4"]').isEnabled()).toBe(true);
    await context.close();
  });

  it("Limp asks first: Cancel and Escape change nothing; confirmed, every servo goes passive and the status says so", async () => {
    const { page, context } = await app.newPage();
    await connectRobot(page, app.url);
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    const limp = page.getByRole("button", { name: "Limp…" });
    // Not the red primary button, and no keyboard shortcut of its own.
    expect(await limp.getAttribute("class")).not.toContain("btn--danger");
    await expect.poll(() => limp.getAttribute("aria-keyshortcuts")).toBeNull();

    await limp.click();
    const question = page.getByRole("alertdialog");
    await question.waitFor();
    await expectText(
      question,
      "Hold the robot: every servo will go passive and it will fall if nobody holds it.",
      { contains: true },
    );
    // The safe choice has the focus: Enter right away would cancel.
    await expect.poll(() => page.evaluate(() => document.activeElement?.textContent?.trim())).toBe("Cancel");
    await question.getByRole("button", { name: "Cancel" }).click();
    await expect.poll(() => question.count()).toBe(0);
    expect(await robot(page)).toMatchObject({ passive: NONE_PASSIVE, direct: false });

    // Escape inside the question closes it: it is neither Limp nor Stop. (Pressed once the focus is in it, as a
    // person would: before that, the focus is still on "Limp…", where Escape is the page's Stop.)
    await limp.click();
    await question.waitFor();
    await expect.poll(() => page.evaluate(() => document.activeElement?.textContent?.trim())).toBe("Cancel");
    await page.keyboard.press("Escape");
    await expect.poll(() => question.count()).toBe(0);
    await expectText(page.getByTestId("stop-banner"), "");
    expect(await robot(page)).toMatchObject({ passive: NONE_PASSIVE, direct: false });

    await limp.click();
    await question.getByRole("button", { name: "Limp", exact: true }).click();
    await page
      .locator(".stop-banner")
      .filter({ hasText: "Limp: all 16 servos confirmed passive. Hold the robot" })
      .waitFor();
    expect(await robot(page)).toMatchObject({ passive: ALL_PASSIVE, direct: true });
    await expectText(page.getByTestId("connection-status"), "servos limp", { contains: true });

    // Escape afterwards is Stop: it does not undo Limp, and says the servos stay limp.
    await blur(page);
    await page.keyboard.press("Escape");
    await page.getByTestId("stop-banner").filter({ hasText: "the servos stay limp" }).waitFor();
    expect(await robot(page)).toMatchObject({ passive: ALL_PASSIVE });
    await context.close();
  });
});
