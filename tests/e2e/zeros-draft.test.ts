import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { FACTORY_ZEROS } from "../../src/protocol/index.ts";
import { openConnected } from "./connected-page.ts";
import { expectText, squash, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";
import { axeProblems, connectDemo, PHONE, type Size } from "./i18n-checks.ts";

/**
 * Issue 33 item 7: unwritten zero changes are not lost without a word. Read from robot (and every load that
 * replaces the table) asks first, naming the servos; Keep editing keeps the value; the browser's leave question
 * is asked while there are unwritten changes; and a reload offers them back, marked as changed, with Discard.
 */

const app = useApp();

/** Opens the Zeros view with the robot on the cable connected, once its zeros are read. */
async function openZeros(
  locale: string,
  robot: "cable" | "demo" = "cable",
  size?: Size,
): Promise<{ page: Page; close: () => Promise<void> }> {
  const { page, context } = await openConnected(app, { robot, view: "zeros", locale, size });
  // The robot on the cable holds the factory zeros; the demo robot its own.
  if (robot === "cable")
    await expect.poll(() => page.locator("#zero-0").inputValue()).toBe(String(FACTORY_ZEROS[0]));
  else await expect.poll(() => page.locator("#zero-0").inputValue()).not.toBe("");
  return { page, close: () => context.close() };
}

/** Whether the page asks the browser's leave question now (a cancelled beforeunload event). */
const asksBeforeLeaving = (page: Page) =>
  page.evaluate(() => {
    const e = new Event("beforeunload", { cancelable: true });
    window.dispatchEvent(e);
    return e.defaultPrevented;
  });

/** Reloads the page; the start option connects the robot on the cable again, and the view reads its zeros. */
async function reload(page: Page): Promise<void> {
  await page.reload({ waitUntil: "domcontentloaded" });
  await page.locator("#limp-button").waitFor();
  await page.locator("#zero-0").waitFor();
}

const changed = String((FACTORY_ZEROS[0] ?? 0) + 3);
const stored = String(FACTORY_ZEROS[0]);

describe("Unwritten zeros (issue 33 item 7)", () => {
  it("asks before Read from robot discards a change, keeps it on Keep editing, and across a reload", async () => {
    const { page, close } = await openZeros("en-US");
    expect(await asksBeforeLeaving(page)).toBe(false);
    await page.locator("#zero-0").fill(changed);
    await page.getByTestId("change-summary").filter({ hasText: "not yet written" }).waitFor();
    expect(await asksBeforeLeaving(page)).toBe(true);

    // Read from robot asks, naming how many servos (and which) have unwritten changes.
    await page.getByRole("button", { name: "Read from robot" }).click();
    const question = page.getByTestId("zeros-discard");
    await expectText(
      question.locator("p"),
      "1 servo has a change not yet written to the robot (servo 0). Discard it? Reading from the robot puts the robot's zeros in their place.",
    );
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("keep-editing");
    expect(await axeProblems(page, { within: "[data-testid=zeros-card]" })).toEqual([]);
    await question.getByRole("button", { name: "Keep editing" }).click();
    await expect.poll(() => question.count()).toBe(0);
    expect(await page.locator("#zero-0").inputValue()).toBe(changed);

    // Load factory zeros asks the same way.
    await page.getByRole("button", { name: "Load factory zeros" }).click();
    await question.getByRole("button", { name: "Discard and load" }).waitFor();
    await question.getByRole("button", { name: "Keep editing" }).click();
    expect(await page.locator("#zero-0").inputValue()).toBe(changed);

    // A reload: the change is back in the table, marked as changed and not written, with Discard beside it.
    await reload(page);
    await expect.poll(() => page.locator("#zero-0").inputValue()).toBe(changed);
    await expect.poll(() => page.locator('tr[data-servo="0"]').getAttribute("class")).toContain("is-changed");
    await expectText(page.locator('tr[data-servo="0"] .zero-stored'), stored);
    await expectText(
      page.getByTestId("change-summary"),
      `1 change not yet written: servo 0 ${stored} → ${changed}.`,
    );
    const back = page.getByTestId("zeros-draft-back");
    await expectText(
      back.locator("p"),
      /^1 change not yet written, kept in this browser since .+, is back in the table \(servo 0, marked as changed\)\. The robot does not hold it until you write it\.$/,
    );
    expect(await asksBeforeLeaving(page)).toBe(true);
    expect(await axeProblems(page, { within: "[data-testid=zeros-card]" })).toEqual([]);

    // Discard and read: the robot's value, nothing kept, no leave question; a reload shows the robot's zeros.
    await page.getByRole("button", { name: "Read from robot" }).click();
    await question.getByRole("button", { name: "Discard and read" }).click();
    await expect.poll(() => page.locator("#zero-0").inputValue()).toBe(stored);
    await expect.poll(() => asksBeforeLeaving(page)).toBe(false);
    await reload(page);
    await expect.poll(() => page.locator("#zero-0").inputValue()).toBe(stored);
    expect(await back.count()).toBe(0);
    // Nothing unwritten is said (whatever words another item gives the matching table).
    expect(squash(await page.getByTestId("change-summary").textContent())).not.toContain("not yet written");
    await close();
  });

  it("speaks Korean on a phone: the question (inside its card), the changes offered back after a reload, and their Discard", async () => {
    const { page, close } = await openZeros("ko-KR", "cable", PHONE);
    await page.locator("#zero-0").fill(changed);
    await page.getByRole("button", { name: "로봇에서 읽기" }).click();
    const question = page.getByTestId("zeros-discard");
    await expectText(
      question.locator("p"),
      "로봇에 아직 쓰지 않은 변경이 있는 서보가 1개 있어요(서보 0). 버릴까요? 로봇에서 읽으면 그 자리에 로봇의 영점이 들어가요.",
    );
    await question.getByRole("button", { name: "버리고 읽기" }).waitFor();
    // On a phone the question stays inside the Zeros card, and the page does not scroll sideways.
    const inside = await page.evaluate(() => {
      const q = document.querySelector("[data-testid=zeros-discard]")?.getBoundingClientRect();
      const card = document.querySelector("[data-testid=zeros-card]")?.getBoundingClientRect();
      return (
        q !== undefined &&
        card !== undefined &&
        q.left >= card.left &&
        q.right <= card.right &&
        document.documentElement.scrollWidth <= window.innerWidth
      );
    });
    expect(inside).toBe(true);
    await question.getByRole("button", { name: "계속 편집하기" }).click();
    expect(await page.locator("#zero-0").inputValue()).toBe(changed);

    await reload(page);
    await expect.poll(() => page.locator("#zero-0").inputValue()).toBe(changed);
    const back = page.getByTestId("zeros-draft-back");
    await expectText(
      back.locator("p"),
      /^이 브라우저에 .+부터 보관한, 아직 쓰지 않은 변경 1개를 표에 다시 넣었어요\(서보 0, 바뀐 것으로 표시\)\. 쓰기 전에는 로봇에 들어 있지 않아요\.$/,
    );
    await back.getByRole("button", { name: "쓰지 않은 변경 버리기" }).click();
    await expect.poll(() => page.locator("#zero-0").inputValue()).toBe(stored);
    await expect.poll(() => back.count()).toBe(0);
    expect(await asksBeforeLeaving(page)).toBe(false);
    await close();
  });

  it("keeps unwritten changes across a disconnect: the same robot, connected again, gets them back", async () => {
    const { page, close } = await openZeros("en-US", "demo");
    const demoStored = await page.locator("#zero-0").inputValue();
    const demoChanged = String(Number(demoStored) + 2);
    await page.locator("#zero-0").fill(demoChanged);
    await page.getByTestId("change-summary").filter({ hasText: "not yet written" }).waitFor();
    await page.getByRole("link", { name: "Robot", exact: true }).click();
    await page.getByRole("button", { name: "Disconnect" }).click();
    await connectDemo(page);
    await page.getByRole("link", { name: "Zeros", exact: true }).click();
    await expect.poll(() => page.locator("#zero-0").inputValue()).toBe(demoChanged);
    await expectText(page.locator('tr[data-servo="0"] .zero-stored'), demoStored);
    await page.getByTestId("zeros-draft-back").waitFor();
    await close();
  });
});
