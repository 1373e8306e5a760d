import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { CABLE, loadMotions } from "./connected-page.ts";
import { expectText, FAST, holdRobotWhenShown, releaseRobot, squash, useApp } from "./harness.ts";
import { DESKTOP, overflowing, PHONE, scrollsSideways } from "./i18n-checks.ts";
import "./rbc-test-globals.ts";

// Issue 33 item 6: Stop contradicted itself. The question said Stop "ends the motion and keeps the robot
// standing"; after it the panel said "The robot holds the pose it stopped in; run Basic posture (7) to bring it
// back to standing". The firmware ends a motion at the end of its current scene and holds that pose with the
// servos on (docs/protocol.md §3.6): the robot does not fall, but it is not necessarily standing. The question,
// the top bar's Stop (its Esc hint), Limp's question, the running motion's note and both Stop results now say
// that, with the one sentence, in English and in Korean (the language switched on the same page).

const app = useApp();

const HOLDS_EN =
  "The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing.";
const HOLDS_KO =
  "로봇은 서보에 힘이 들어간 채로 멈춘 자세를 유지해요. 넘어지지는 않지만, 꼭 서 있는 자세는 아니에요.";

/** The old claims, in either language. */
const STANDING = /keeps? (the robot |it )?standing|stands in that pose|선 채로|그 자세로 서 있/;

const RUNNING_CONFIRMED = '[data-testid="running-motion"][data-confirmed="yes"]';

const switchLanguage = async (page: Page, to: "en" | "ko") => {
  await page.getByTestId("language-switch").selectOption(to);
  await expect.poll(() => page.evaluate(() => document.documentElement.lang)).toBe(to);
};

/** The top bar's Stop button (its name is "Stop" or "정지"; the Esc hint is its title). */
const stopButton = (page: Page) => page.locator(".top-bar button.stop");

async function expectStopTitle(page: Page, lead: string, holds: string): Promise<void> {
  await expect.poll(() => stopButton(page).getAttribute("title")).toBe(`${lead} ${holds}`);
}

describe("Stop says the same everywhere: the robot holds the pose it stopped in, not necessarily standing", () => {
  it("the question, the Esc hint, Limp's question, the running note and Stop's results, in English and Korean", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await loadMotions(page, app.url);
    await page.locator("#motions-tab-run").click();
    await page.locator("#motions-panel-run").waitFor();

    // The top bar's Stop: its hint (title) says what Stop leaves.
    await expectStopTitle(page, "End what the robot is doing (Escape).", HOLDS_EN);

    // Limp's question sets Stop beside Limp with the same sentence.
    await page.locator("#limp-button").click();
    const limpText = page.locator("#limp-text");
    await expectText(
      limpText,
      `Stop (Esc) ends a motion at the end of its current scene. ${HOLDS_EN} Limp is for when the robot must go slack.`,
    );
    await switchLanguage(page, "ko");
    await expectText(
      limpText,
      `정지(Esc)를 누르면 모션이 지금 장면이 끝날 때 멈춰요. ${HOLDS_KO} 힘 빼기는 로봇의 힘을 완전히 빼야 할 때 써요.`,
    );
    await expectStopTitle(page, "로봇이 하던 일을 끝내요 (Esc).", HOLDS_KO);
    // The longer question still fits a phone: nothing sticks out of the top bar, the page never scrolls sideways.
    await page.setViewportSize({ ...PHONE });
    await expect.poll(() => page.locator("#limp-confirm").isVisible()).toBe(true);
    expect(await overflowing(page, ".top-bar")).toEqual([]);
    expect(await scrollsSideways(page)).toEqual([]);
    await page.setViewportSize({ ...DESKTOP });
    await page.locator("#cancel-limp").click();
    await switchLanguage(page, "en");

    // The question before the first motion: what Stop (Esc) does and what it leaves.
    await page.locator('[data-motion="7"]').click();
    const question = page.locator("#move-stop");
    await expectText(
      question,
      `The panel asks this once per connection. Stop (Esc) ends a motion at the end of its current scene. ${HOLDS_EN}`,
    );
    await switchLanguage(page, "ko");
    await expectText(
      question,
      `패널은 연결할 때마다 한 번만 물어봐요. 정지(Esc)를 누르면 모션이 지금 장면이 끝날 때 멈춰요. ${HOLDS_KO}`,
    );
    expect(squash(await question.textContent())).not.toMatch(STANDING);
    await switchLanguage(page, "en");
    await page.locator("#confirm-move").click();
    await page.getByText("Motion 7 (Basic posture) finished.", { exact: false }).waitFor({ timeout: 8000 });

    // Motion 2, held at the moment it shows as running: its note says what Stop motion leaves.
    await page.locator('[data-motion="2"]').click();
    await holdRobotWhenShown(page, RUNNING_CONFIRMED, /Get up B/);
    const running = page.getByTestId("running-motion");
    await expectText(running, HOLDS_EN, { contains: true });
    expect(squash(await running.textContent())).not.toMatch(STANDING);
    await switchLanguage(page, "ko");
    await expectText(running, HOLDS_KO, { contains: true });
    await switchLanguage(page, "en");
    // Stop motion's result: stopped at the end of its scene, the same sentence, then how to stand it up.
    await page.getByTestId("stop-motion").click();
    await releaseRobot(page);
    const stoppedEn = `Motion 2 (Get up B (from back)) stopped at the end of its scene. ${HOLDS_EN} Basic posture (7) brings it back to standing.`;
    await page.getByText(stoppedEn).waitFor({ timeout: 8000 });
    await switchLanguage(page, "ko");
    const stoppedKo = page.getByText(/^모션 2번\(.+\)이 장면 끝에서 멈췄어요\./);
    await expectText(stoppedKo, `${HOLDS_KO} 기본 자세(7)로 다시 세울 수 있어요.`, { contains: true });
    await switchLanguage(page, "en");

    // The page's Stop (Escape) during motion 1: the top bar says what the robot confirmed, with the same sentence.
    await expect.poll(() => page.locator('[data-motion="1"]').isEnabled()).toBe(true);
    await page.locator('[data-motion="1"]').click();
    await holdRobotWhenShown(page, RUNNING_CONFIRMED, /Get up A/);
    await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
    await page.keyboard.press("Escape");
    await releaseRobot(page);
    const banner = page.getByTestId("stop-banner").locator(".banner-text > p");
    await page
      .getByTestId("stop-banner")
      .filter({ hasText: "The robot took Stop" })
      .waitFor({ timeout: 8000 });
    await expectText(
      banner,
      `The robot took Stop: the motion ended at the end of the scene it was in. ${HOLDS_EN} Basic posture (7) brings it back to standing.`,
    );
    await switchLanguage(page, "ko");
    await expectText(
      banner,
      `로봇이 정지를 받았어요. 모션은 하던 장면이 끝날 때 멈췄어요. ${HOLDS_KO} 기본 자세(7)로 다시 세울 수 있어요.`,
    );
    // Stop left the servos holding: none passive, no direct mode.
    expect(
      await page.evaluate(() => ({
        passive: window.__rbcTest?.sim.servos.slice(0, 16).some((s) => s.passive),
        direct: window.__rbcTest?.sim.directMode,
      })),
    ).toEqual({ passive: false, direct: false });
    await context.close();
  });
});
