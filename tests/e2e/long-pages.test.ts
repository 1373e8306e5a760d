import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { CABLE, loadMotions } from "./connected-page.ts";
import { connectRobot, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";

// Issue 21 item 7: long pages. With long-walk.rbm (284 scenes) open, Motions was 10,592 px tall; Zeros put Write
// 1,355 px down the page. Each task fits one screen at 1280×800.

const app = useApp();

const VIEWPORT = { width: 1280, height: 800 };

const pageHeight = (page: Page) => page.evaluate(() => document.documentElement.scrollHeight);

/** An element's box against the window (after any scrolling). */
async function boxOf(page: Page, selector: string) {
  return page
    .locator(selector)
    .first()
    .evaluate((el) => {
      const r = el.getBoundingClientRect();
      return { top: r.top, bottom: r.bottom, height: r.height };
    });
}

describe("long pages fit a screen at 1280×800", () => {
  it("Motions with long-walk.rbm: the 284 scenes scroll in a box about twelve rows tall, Upload is on the first screen", async () => {
    const { page, context } = await app.newPage({ start: CABLE, viewport: VIEWPORT });
    await loadMotions(page, app.url);
    await page.getByTestId("examples").locator("summary").click();
    await page.locator('[data-example="long-walk.rbm"]').click();
    await page.getByTestId("scene-table-box").waitFor();
    await expect.poll(() => page.locator('[data-testid="scene-table-box"] tbody tr').count()).toBe(284);

    const box = await boxOf(page, '[data-testid="scene-table-box"]');
    // 24rem: the header and about twelve rows; the rest scroll inside.
    expect(box.height).toBeLessThanOrEqual(24 * 16 + 1);
    const inside = await page
      .getByTestId("scene-table-box")
      .evaluate((el) => ({ scroll: el.scrollHeight, client: el.clientHeight }));
    expect(inside.scroll).toBeGreaterThan(inside.client * 10);
    // The header stays when the box is scrolled.
    await page.getByTestId("scene-table-box").evaluate((el) => el.scrollTo(0, el.scrollHeight));
    const head = await boxOf(page, '[data-testid="scene-table-box"] thead th');
    const after = await boxOf(page, '[data-testid="scene-table-box"]');
    expect(Math.abs(head.top - after.top)).toBeLessThanOrEqual(2);

    await page.evaluate(() => window.scrollTo(0, 0));
    const upload = await boxOf(page, '[data-testid="upload-motion"]');
    expect(upload.bottom).toBeLessThanOrEqual(VIEWPORT.height);
    // Was 10,592 px: now the page is at most two screens (the file's facts, the chart and the bounded table).
    expect(await pageHeight(page)).toBeLessThanOrEqual(2 * VIEWPORT.height);
    await context.close();
  });

  it("Zeros: the table fits the screen and Write stays beside the changed value, even the last servo's", async () => {
    const { page, context } = await app.newPage({ viewport: VIEWPORT });
    await connectRobot(page, app.url);
    await page.getByRole("link", { name: "Zeros" }).click();
    await page.locator("#zero-15").waitFor();
    // Was 1,355 px. The editor (16 rows and the Write panel) fits under the top bar.
    const editor = await boxOf(page, ".zeros-editor");
    const bar = await boxOf(page, ".top-bar");
    expect(editor.height).toBeLessThanOrEqual(VIEWPORT.height - bar.height);
    expect(await pageHeight(page)).toBeLessThanOrEqual(VIEWPORT.height + 200);

    await page.locator("#zero-15").fill(String(Number(await page.locator("#zero-15").inputValue()) + 1));
    // Write moves beside the changed value on the panel's next render: polled, then looked at.
    await expect.poll(() => page.getByTestId("write-zeros").isEnabled()).toBe(true);
    await page.locator("#zero-15").scrollIntoViewIfNeeded();
    for (const selector of ["#zero-15", '[data-testid="write-zeros"]']) {
      await expect
        .poll(() => boxOf(page, selector), { message: selector })
        .toSatisfy((b: { top: number; bottom: number }) => b.top >= 0 && b.bottom <= VIEWPORT.height);
    }
    await context.close();
  });
});
