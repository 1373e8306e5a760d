import { describe, expect, it } from "vitest";
import { cspViolations, expectText, useApp, watchPage } from "./harness.ts";
import "./rbc-test-globals.ts";

const app = useApp();

describe("demo robot, browsers without Web Serial, offline", () => {
  it("without navigator.serial shows which browsers work, and the demo robot still works", async () => {
    const { page, context } = await app.newPage({ noSerial: true });
    const seen = watchPage(page, app.origin);
    await page.goto(app.url);
    const card = page.getByTestId("unsupported-card");
    await card.waitFor();
    await expectText(card, /Chrome, Edge and Opera \(version 89 or later\)/);
    await expectText(card, /Firefox, Safari/);
    expect(await page.getByRole("button", { name: "Connect robot" }).count()).toBe(0);
    expect(await page.evaluate(() => "serial" in navigator)).toBe(false);

    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await expectText(page.getByTestId("connection-status"), /Demo robot\s*·\s*Connected/);
    await expectText(page.getByTestId("firmware"), "2.23");
    expect(seen.foreignRequests).toEqual([]);
    expect(seen.errors).toEqual([]);
    await context.close();
  });

  it("the in-app demo robot drives the same UI, and the packet log records its packets", async () => {
    const { page, context } = await app.newPage();
    const seen = watchPage(page, app.origin);
    const scripts: string[] = [];
    page.on("request", (r) => {
      if (r.resourceType() === "script") scripts.push(new URL(r.url()).pathname);
    });
    await page.goto(app.url);
    await page.waitForLoadState("networkidle");
    // The simulator is not part of the initial load.
    expect(scripts.some((s) => s.includes("demo-robot"))).toBe(false);

    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    expect(scripts.some((s) => s.includes("demo-robot"))).toBe(true);
    await expectText(
      page.getByTestId("connection-status"),
      /Demo robot\s*·\s*Connected\s*·\s*HUNO\s*·\s*fw 2\.23\s*·\s*SN 8958899989309/,
    );
    // Free of total, or (the Robot view being reworded) used of total: either way nothing is used yet.
    await expectText(page.getByTestId("memory-action-text"), /8,192 of 8,192|\b0 of 8,192 bytes used/);
    await expectText(page.getByRole("heading", { level: 1 }), "Demo robot");
    // The page's fake port was never touched: this was the built-in demo.
    expect(await page.evaluate(() => window.__rbcTest?.port.stats.opens)).toBe(0);

    await page.getByRole("link", { name: "Log" }).click();
    const log = page.getByTestId("log-card");
    await log.waitFor();
    await log.getByText("Read firmware version").first().waitFor();
    await expectText(log, "FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01", { contains: true });
    // Pause freezes the view while capture goes on.
    const rowsBefore = await log.locator("tbody tr").count();
    // Refresh reads the error code and both free memories (3 requests, 3 replies); firmware and serial number
    // were read when connecting and are not read again.
    const refreshRows = 6;
    await page.getByRole("button", { name: "Pause" }).click();
    await page.getByRole("link", { name: "Robot" }).click();
    await page.getByRole("button", { name: "Refresh" }).click();
    await page.getByRole("button", { name: "Refresh" }).waitFor();
    await page.getByRole("link", { name: "Log" }).click();
    await log.getByText("Paused:").waitFor();
    expect(await log.locator("tbody tr").count()).toBe(rowsBefore);
    await expectText(log.getByTestId("log-count"), new RegExp(`^${rowsBefore + refreshRows} entries`));
    expect(await log.locator("tbody tr").count()).toBe(rowsBefore);
    await page.getByRole("button", { name: "Resume" }).click();
    await expect.poll(() => log.locator("tbody tr").count()).toBe(rowsBefore + refreshRows);

    await context.grantPermissions(["clipboard-read", "clipboard-write"], { origin: app.origin });
    await page.getByRole("button", { name: "Copy" }).click();
    await page.getByText(/Copied \d+ lines to the clipboard/).waitFor();
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    expect(copied).toContain(
      "PC → RBC  Read firmware version (16 bytes)  FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01",
    );

    const download = page.waitForEvent("download");
    await page.getByRole("button", { name: "Download .txt" }).click();
    expect((await download).suggestedFilename()).toMatch(/^rbc-packet-log-\d{4}-\d{2}-\d{2}\.txt$/);
    await page.getByRole("button", { name: "Clear" }).click();
    await log.getByText("No packets yet").waitFor();

    expect(seen.foreignRequests).toEqual([]);
    expect(seen.errors).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("works offline after the first visit (service worker precache), demo robot included", async () => {
    const { page, context } = await app.newPage({ serviceWorkers: "allow" });
    const seen = watchPage(page, app.origin);
    await page.goto(app.url);
    await page.waitForFunction(() => navigator.serviceWorker.controller !== null, undefined, {
      timeout: 30_000,
    });

    await context.setOffline(true);
    await page.reload();
    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await expectText(page.getByTestId("firmware"), "2.23");
    // Lazily loaded views come from the cache too.
    await page.getByRole("link", { name: "Zeros" }).click();
    await page.locator("#zero-0").waitFor();
    await page.getByRole("link", { name: "Log" }).click();
    await page.getByTestId("log-card").waitFor();

    expect(seen.foreignRequests).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.setOffline(false);
    await context.close();
  });
});
