import type { Locator, Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { CABLE, loadConnected } from "./connected-page.ts";
import { expectText, squash, useApp } from "./harness.ts";
import { axeProblems } from "./i18n-checks.ts";
import "./rbc-test-globals.ts";

// Issue 21 items 6 and 7: messages where the eyes are, worded in the language of the moment; the Servos task on
// one screen at 1280×800.

const app = useApp();

const SIZES = [
  { width: 1280, height: 800 },
  { width: 390, height: 844 },
] as const;

type Size = (typeof SIZES)[number];

/** An element's box against the window. */
const boxOf = (target: Locator) =>
  target.evaluate((el) => {
    const r = el.getBoundingClientRect();
    return { top: r.top, bottom: r.bottom, left: r.left, right: r.right, height: r.height };
  });

/** Waits until `target` is wholly inside the window (and has a size). */
async function expectInWindow(target: Locator, size: Size): Promise<void> {
  await expect
    .poll(() => boxOf(target))
    .toSatisfy(
      (box: Awaited<ReturnType<typeof boxOf>>) =>
        box.height > 0 &&
        box.top >= 0 &&
        box.bottom <= size.height &&
        box.left >= 0 &&
        box.right <= size.width,
    );
}

const scrollY = (page: Page) => page.evaluate(() => Math.round(window.scrollY));

/**
 * The page kept its place: it did not jump back up. (It may scroll further down by as much as the top bar grew:
 * the browser keeps the content in view where it was while the sticky bar above it gets taller.)
 */
async function expectStillAt(page: Page, bottom: number): Promise<void> {
  await expect.poll(() => scrollY(page)).toBeGreaterThanOrEqual(bottom - 1);
}

async function scrollToBottom(page: Page): Promise<number> {
  await page.evaluate(() => window.scrollTo(0, document.documentElement.scrollHeight));
  return scrollY(page);
}

const switchLanguage = (page: Page, to: "en" | "ko") => page.getByLabel(/Language/).selectOption(to);

describe("Stop's and Limp's results are seen and announced however far down the page is", () => {
  for (const size of SIZES) {
    it(`at ${size.width}×${size.height}: Stop, then Limp through its question, at the foot of the Sensors view`, async () => {
      const { page, context } = await app.newPage({ start: CABLE, viewport: size });
      await loadConnected(page, app.url, "sensors");
      await page.getByRole("heading", { level: 1, name: "Sensors" }).waitFor();
      const bottom = await scrollToBottom(page);
      // A long view: the window is well down the page.
      expect(bottom).toBeGreaterThan(size.height / 2);

      await page.getByRole("button", { name: "Stop", exact: true }).click();
      const banner = page.getByTestId("stop-banner");
      const result = banner.locator(".banner-notice");
      await result.filter({ hasText: "it is idle, nothing to stop" }).waitFor();
      await expectInWindow(result, size);
      await expect.poll(() => banner.getAttribute("aria-live")).toMatch(/^(polite|assertive)$/);
      // Beside Stop, not over it: the result sits below the Stop and Limp buttons.
      const stop = await boxOf(page.getByRole("button", { name: "Stop", exact: true }));
      await expect.poll(async () => (await boxOf(result)).top).toBeGreaterThanOrEqual(stop.bottom);
      await expectStillAt(page, bottom);
      expect(await axeProblems(page, { within: ".top-bar" })).toEqual([]);

      // Dismissed, it is gone and the bar is its usual height again.
      await result.getByRole("button", { name: "Dismiss" }).click();
      await result.waitFor({ state: "detached" });

      // Limp asks first, where the eyes are, and the page keeps its place.
      await page.getByRole("button", { name: "Limp…" }).click();
      const question = page.locator("#limp-confirm");
      await question.waitFor();
      await expectInWindow(question, size);
      // Focus moves to the question's Cancel when it is drawn (the next render): polled, not read once.
      await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("cancel-limp");
      await expectStillAt(page, bottom);
      await question.getByRole("button", { name: "Limp", exact: true }).click();
      await result.filter({ hasText: "all 16 servos confirmed passive" }).waitFor();
      await expectInWindow(result, size);
      await expectStillAt(page, bottom);
      await expect.poll(() => banner.getAttribute("aria-live")).toMatch(/^(polite|assertive)$/);
      expect(await axeProblems(page, { within: ".top-bar" })).toEqual([]);
      await context.close();
    });
  }
});

describe("messages made before a language switch follow it", () => {
  it("a Servos result, a refusal under a field and Stop's result: Korean after the switch, English after the switch back", async () => {
    const { page, context } = await app.newPage({ start: CABLE });
    await loadConnected(page, app.url, "servos");
    await page.getByRole("button", { name: "I understand: the robot is supported" }).click();
    await page.getByTestId("enter-direct").click();
    const result = page.getByTestId("servo-card").locator(".live .notice p");
    await result.filter({ hasText: "Read all 16 servos." }).waitFor();
    // A typed target outside servo 12's safe range (1-198): refused, with its sentence under the field.
    await page.locator("#servo-12").fill("300");
    await page.locator("#servo-12").press("Tab");
    const refusal = page.getByTestId("servo-refused-12");
    await refusal.waitFor();
    await expectText(refusal, /300/);
    await expectText(refusal, /1.198/);
    const refusalEn = squash(await refusal.textContent());

    await switchLanguage(page, "ko");
    await page.getByRole("heading", { level: 1, name: "서보" }).waitFor();
    await expectText(refusal, /[가-힣]/);
    const refusalKo = squash(await refusal.textContent());
    expect(refusalKo).not.toBe(refusalEn);
    await expectText(result, refusalKo);

    // Stop ends servo control; its words, and their technical detail, follow the next switch.
    await page.getByRole("button", { name: "정지", exact: true }).click();
    const banner = page.getByTestId("stop-banner").locator(".banner-notice");
    await banner.filter({ hasText: "서보 제어를 끝냈어요" }).waitFor();
    await switchLanguage(page, "en");
    await banner.filter({ hasText: "Servo control ended" }).waitFor();
    expect(squash(await banner.textContent())).not.toMatch(/[가-힣]/);
    await expectText(refusal, refusalEn);
    await context.close();
  });

  it("“Draft restored…” made in English reads in Korean after the switch, and in English again after the switch back", async () => {
    const { page, context } = await app.newPage();
    await page.goto(`${app.url}#/editor`, { waitUntil: "domcontentloaded" });
    await page.getByTestId("editor").waitFor();
    await page.getByTestId("motion-name").fill("Kept");
    await page.getByTestId("motion-name").press("Tab");
    await page.getByTestId("draft-status").filter({ hasText: "saved" }).waitFor();
    await page.reload({ waitUntil: "domcontentloaded" });
    const restored = page.getByTestId("editor-toolbar").locator(".live .notice p");
    await restored.filter({ hasText: /^Draft restored: Kept, saved \d\d:\d\d\.$/ }).waitFor();
    const time = /saved (\d\d:\d\d)\./.exec(squash(await restored.textContent()))?.[1];

    await switchLanguage(page, "ko");
    await restored.filter({ hasText: "임시 저장본을 복원했어요" }).waitFor();
    await expectText(restored, `임시 저장본을 복원했어요: Kept, ${time} 저장.`);
    await switchLanguage(page, "en");
    await restored.filter({ hasText: "Draft restored" }).waitFor();
    await expectText(restored, `Draft restored: Kept, saved ${time}.`);
    await context.close();
  });
});

describe("Servos: the whole task on one screen at 1280×800", () => {
  it("the sixteen servos scroll in a box under a header that stays; Start, Read all, every row, Speed and Basic posture are on the first screen", async () => {
    const size = SIZES[0];
    const { page, context } = await app.newPage({ start: CABLE, viewport: size });
    await loadConnected(page, app.url, "servos");
    await page.getByRole("button", { name: "I understand: the robot is supported" }).click();
    await page.getByTestId("enter-direct").click();
    await page.getByText("Read all 16 servos.").waitFor();

    // The measure: the page is at most one screen and a footer line (it was 1,664 px, then 2,081 px), and every
    // control of the task is inside the window without scrolling the page.
    await expect
      .poll(() => page.evaluate(() => document.documentElement.scrollHeight))
      .toBeLessThanOrEqual(900);
    expect(await scrollY(page)).toBe(0);
    const box = page.getByTestId("servo-table-box");
    for (const control of [
      page.getByTestId("leave-direct"),
      page.getByRole("button", { name: "Read all positions" }),
      box,
      page.getByLabel("Speed"),
      page.getByRole("button", { name: "All to basic posture…" }),
    ]) {
      await expectInWindow(control, size);
    }
    // The rows scroll inside the box, and its header stays at its top.
    await expect
      .poll(() => box.evaluate((el) => ({ scroll: el.scrollHeight, client: el.clientHeight })))
      .toSatisfy(
        (inside: { scroll: number; client: number }) =>
          inside.scroll > inside.client && inside.client >= 8 * 30,
      );

    // The keyboard reaches the last servo: the box scrolls it into view, the page does not move.
    await page.locator("#servo-15").focus();
    const row = await boxOf(page.locator('tr[data-servo="15"]'));
    const frame = await boxOf(box);
    expect(row.top).toBeGreaterThanOrEqual(frame.top);
    expect(row.bottom).toBeLessThanOrEqual(frame.bottom + 1);
    const head = await boxOf(box.locator("thead th").first());
    expect(Math.abs(head.top - frame.top)).toBeLessThanOrEqual(2);
    expect(await scrollY(page)).toBe(0);

    // Keyboard order: the last row's torque, then Basic posture's speed and button.
    await page.getByRole("combobox", { name: /Torque of Right elbow/ }).focus();
    await page.keyboard.press("Tab");
    await expect
      .poll(() =>
        page.evaluate(() => document.activeElement?.closest("[data-testid]")?.getAttribute("data-testid")),
      )
      .toBe("posture-card");
    expect(await axeProblems(page)).toEqual([]);
    await context.close();
  });
});
