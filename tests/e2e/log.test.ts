import { readFileSync } from "node:fs";
import { createRequire } from "node:module";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import {
  type AppHarness,
  connectRobot,
  cspViolations,
  FAST,
  squash,
  startHarness,
  watchPage,
} from "./harness.ts";
import "./rbc-test-globals.ts";

/** The packet log view: coalesced garbage, raw bytes, and a scroll area the keyboard can reach (issue #11 item 11). */

let app: AppHarness;

beforeAll(async () => {
  app = await startHarness();
});

afterAll(async () => {
  await app?.close();
});

const AXE_SOURCE = readFileSync(createRequire(import.meta.url).resolve("axe-core/axe.min.js"), "utf8");

describe("packet log view", () => {
  it("shows a run of garbage as one row with its byte count, and its scroll area is focusable and named", async () => {
    // A short window, so that the log's rows overflow its scroll area.
    const { page, context } = await app.newPage({ options: FAST, viewport: { width: 1280, height: 600 } });
    const seen = watchPage(page, app.origin);
    await connectRobot(page, app.url);
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    // 3,000 stray bytes and a frame too long for its type arrive before the next reply.
    await page.evaluate(() => {
      const stray = Array.from({ length: 3000 }, (_, i) => (i * 13 + 1) & 0x7f);
      const oversize = [0xff, 0xff, 0xaa, 0x55, 0xaa, 0x55, 0x37, 0xba, 0x11, 0x01, 0x00, 0x00, 0x0f, 0x00];
      window.__rbcTest?.port.faults.garbageBeforeReply([...stray, ...oversize, 0, 0]);
    });
    for (let i = 0; i < 4; i++) {
      await page.getByRole("button", { name: "Refresh" }).click();
      await page.getByRole("button", { name: "Refresh" }).waitFor();
    }
    await page.getByRole("link", { name: "Log" }).click();
    const log = page.getByTestId("log-card");
    const discards = log.locator("tr.log-discard");
    await discards.first().waitFor();
    expect(await discards.count()).toBe(1);
    const row = squash(await discards.first().textContent());
    expect(row).toContain("(3,016 bytes)");
    expect(row).toContain("1 frame too long for its type, stray bytes");
    expect(row).toContain("01 0E 1B 28"); // the first stray bytes as they arrived
    expect(squash(await log.textContent())).toContain("FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01");

    // The scroll area is a named region in the tab order, and the keyboard scrolls it.
    const region = page.getByRole("region", { name: "Packets, newest first" });
    expect(await region.getAttribute("tabindex")).toBe("0");
    await region.focus();
    expect(await page.evaluate(() => document.activeElement?.getAttribute("data-testid"))).toBe("log-scroll");
    expect(await region.evaluate((el) => el.scrollHeight > el.clientHeight)).toBe(true);
    await page.keyboard.press("End");
    await expect.poll(() => region.evaluate((el) => el.scrollTop)).toBeGreaterThan(0);

    await page.evaluate(AXE_SOURCE);
    const violations = await page.evaluate(async () => {
      const axe = (
        window as unknown as { axe: { run(el: Element): Promise<{ violations: { id: string }[] }> } }
      ).axe;
      const card = document.querySelector('[data-testid="log-card"]');
      if (!card) return ["no log card"];
      return (await axe.run(card)).violations.map((v) => v.id);
    });
    expect(violations).toEqual([]);

    expect(seen.errors).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("pauses without losing capture, pages back through older rows, and copies the whole log", async () => {
    const { page, context } = await app.newPage({ options: FAST });
    await connectRobot(page, app.url);
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    await page.getByRole("link", { name: "Log" }).click();
    const log = page.getByTestId("log-card");
    await log.locator("tbody tr").first().waitFor();
    const rows = () => log.locator("tbody tr").count();
    const entries = async () =>
      Number(squash(await log.getByTestId("log-count").textContent()).split(" ")[0]);
    const before = await rows();
    const total = await entries();
    await page.getByRole("button", { name: "Pause" }).click();
    await log.getByText("Paused:").waitFor();
    await page.getByRole("link", { name: "Robot" }).click();
    for (let i = 0; i < 20; i++) {
      await page.getByRole("button", { name: "Refresh" }).click();
      await page.getByRole("button", { name: "Refresh" }).waitFor();
    }
    await page.getByRole("link", { name: "Log" }).click();
    await expect.poll(entries).toBeGreaterThan(total + 100);
    expect(await rows()).toBe(before);

    await page.getByRole("button", { name: "Resume" }).click();
    await expect.poll(rows).toBe(100);
    const all = await entries();
    expect(squash(await log.getByTestId("log-page").textContent())).toBe(
      `Rows 1–100 of ${all}, newest first`,
    );
    const newestTime = await log.locator("tbody tr").first().locator(".log-time").textContent();
    await page.getByRole("button", { name: "Older" }).click();
    await expect
      .poll(() => log.getByTestId("log-page").textContent().then(squash))
      .toBe(`Rows 101–${Math.min(200, all)} of ${all}, newest first`);
    await page.getByRole("button", { name: "Newer" }).click();
    await expect
      .poll(() => log.locator("tbody tr").first().locator(".log-time").textContent())
      .toBe(newestTime);

    await context.grantPermissions(["clipboard-read", "clipboard-write"], { origin: app.origin });
    await page.getByRole("button", { name: "Copy" }).click();
    await page.getByText(`Copied ${all} lines to the clipboard.`).waitFor();
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    expect(copied.trim().split("\n")).toHaveLength(all + 1);
    expect(copied).toContain(
      "PC → RBC  Read firmware version (16 bytes)  FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01",
    );
    await context.close();
  });
});
