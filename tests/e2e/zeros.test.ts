import { readFile } from "node:fs/promises";
import type { Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { FACTORY_ZEROS, STANDARD_ZEROS } from "../../src/protocol/index.ts";
import { parseZerosBackup } from "../../src/protocol/zeros-backup.ts";
import { type AppHarness, connectRobot, cspViolations, robotTime, squash, startHarness } from "./harness.ts";
import "./rbc-test-globals.ts";

let app: AppHarness;

beforeAll(async () => {
  app = await startHarness();
});

afterAll(async () => {
  await app?.close();
});

async function openZeros(page: Page): Promise<void> {
  // This file tests the download path: a browser without the Save dialog (honest-results.test.ts has both).
  await page.addInitScript(() => {
    Reflect.deleteProperty(window, "showSaveFilePicker");
  });
  await connectRobot(page, app.url);
  await page.getByRole("link", { name: "Zeros" }).click();
  await page.getByTestId("zeros-card").waitFor();
  await page.locator("#zero-0").waitFor();
}

const simZeros = (page: Page) => page.evaluate(() => window.__rbcTest?.sim.zeros);

describe("zeros editor", () => {
  it("reads the robot's zeros, writes an edit after saving a backup, and verifies it", async () => {
    const { page, context } = await app.newPage();
    await openZeros(page);
    expect(await page.locator("#zero-3").inputValue()).toBe(String(FACTORY_ZEROS[3]));

    // Every input is labelled with its joint.
    expect(await page.getByLabel("Left ankle pitch", { exact: true }).inputValue()).toBe("65");

    await page.locator("#zero-3").fill("70");
    await page.getByTestId("change-summary").filter({ hasText: "servo 3 65 → 70" }).waitFor();
    expect(await page.locator('tr[data-servo="3"] .zero-diff').textContent().then(squash)).toBe("+5");

    await page.getByTestId("write-zeros").click();
    const downloadPromise = page.waitForEvent("download");
    await page.getByRole("button", { name: "Save backup and write" }).click();
    const download = await downloadPromise;
    const name = download.suggestedFilename();
    expect(name).toMatch(/^rbc-zeros-8958899989309-\d{4}-\d{2}-\d{2}\.json$/);

    const result = page.getByText(/Zeros written and verified/);
    await result.waitFor();
    expect(await result.textContent().then(squash)).toBe(
      `Zeros written and verified (read back 16/16). Backup file offered as a download (${name}): the browser decides where it goes and may rename it. It is kept in this browser (Backups kept in this browser, below).`,
    );
    const expected = [...FACTORY_ZEROS];
    expected[3] = 70;
    expect(await simZeros(page)).toEqual(expected);

    // The backup holds what the robot had before the write, and loads back.
    const path = await download.path();
    const parsed = parseZerosBackup(await readFile(path, "utf8"));
    expect(parsed.ok).toBe(true);
    if (parsed.ok) {
      expect(parsed.backup.zeros).toEqual([...FACTORY_ZEROS]);
      expect(parsed.backup.serialNumber).toBe("8958899989309");
      expect(parsed.backup.firmware).toBe("2.23");
    }
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("refuses an out-of-range value: Write is disabled and says why, nothing is sent", async () => {
    const { page, context } = await app.newPage();
    await openZeros(page);
    const before = await simZeros(page);
    const written = await page.evaluate(() => window.__rbcTest?.port.written.length);

    await page.locator("#zero-3").fill("200");
    const why = page.getByTestId("write-why");
    await why.filter({ hasText: "outside the accepted range" }).waitFor();
    expect(await page.getByTestId("write-zeros").isDisabled()).toBe(true);
    expect(await page.locator("#zero-3").getAttribute("aria-invalid")).toBe("true");
    expect(await page.locator("#zero-3-hint").textContent().then(squash)).toBe("Must be 51–81");

    // The slider cannot go outside the window either.
    const slider = page.getByLabel(/Left ankle pitch \(servo 3\), slider/);
    expect(await slider.getAttribute("min")).toBe("51");
    expect(await slider.getAttribute("max")).toBe("81");

    // Nothing can go out: a moment of the robot's time shows that nothing did.
    await robotTime(page, 100);
    expect(await page.evaluate(() => window.__rbcTest?.port.written.length)).toBe(written);
    expect(await simZeros(page)).toEqual(before);
    await context.close();
  });

  it("refuses a corrupt or wrong backup file with a clear message", async () => {
    const { page, context } = await app.newPage();
    await openZeros(page);
    const file = page.getByTestId("zeros-file");
    const cases: Array<[string, string, RegExp]> = [
      ["broken.json", "{ not json", /not JSON/],
      ["other.json", JSON.stringify({ format: "something-else" }), /not an RBC zero backup/],
      [
        "short.json",
        JSON.stringify({
          format: "rbc-zeros",
          version: 1,
          serialNumber: "x",
          firmware: "2.23",
          savedAt: new Date().toISOString(),
          zeros: [1, 2, 3],
        }),
        /holds 3 values; a zero table has exactly 16/,
      ],
      [
        "range.json",
        JSON.stringify({
          format: "rbc-zeros",
          version: 1,
          serialNumber: "8958899989309",
          firmware: "2.23",
          savedAt: new Date().toISOString(),
          zeros: FACTORY_ZEROS.map((v, i) => (i === 5 ? 250 : v)),
        }),
        /would refuse.*Servo 5: 250 is outside/,
      ],
    ];
    for (const [name, text, message] of cases) {
      await file.setInputFiles({ name, mimeType: "application/json", buffer: Buffer.from(text) });
      const notice = page.getByText(`"${name}" was not loaded.`);
      await notice.waitFor();
      expect(await notice.textContent().then(squash)).toMatch(message);
    }
    // The editor still holds the robot's values.
    expect(await page.locator("#zero-5").inputValue()).toBe(String(FACTORY_ZEROS[5]));
    await context.close();
  });

  it("restores a backup into the editor, warning when it comes from another robot; the factory zeros fill it", async () => {
    const { page, context } = await app.newPage();
    await openZeros(page);
    const zeros = FACTORY_ZEROS.map((v, i) => (i === 0 ? v + 3 : v));
    const backup = {
      format: "rbc-zeros",
      version: 1,
      serialNumber: "1111111111111",
      firmware: "2.23",
      savedAt: "2026-11-21T10:00:00.000Z",
      zeros,
    };
    await page.getByTestId("zeros-file").setInputFiles({
      name: "rbc-zeros-1111111111111-2026-11-21.json",
      mimeType: "application/json",
      buffer: Buffer.from(JSON.stringify(backup)),
    });
    await page.getByText(/saved from robot 1111111111111, not the connected robot 8958899989309/).waitFor();
    expect(await page.locator("#zero-0").inputValue()).toBe(String(zeros[0]));
    // Loaded, not written.
    expect(await simZeros(page)).toEqual([...FACTORY_ZEROS]);

    await page.locator("#zero-0").fill("130");
    await page.getByRole("button", { name: "Load factory zeros" }).click();
    await page.getByText(/The factory zeros are in the editor/).waitFor();
    expect(await page.locator("#zero-0").inputValue()).toBe(String(FACTORY_ZEROS[0]));
    await context.close();
  });

  it("backs up the robot's zeros on their own, in the write path's format and name, writing nothing", async () => {
    const { page, context } = await app.newPage();
    await openZeros(page);
    // The editor has an unsaved edit: the backup holds what the robot holds, not the editor.
    const onRobot = [...FACTORY_ZEROS];
    await page.locator("#zero-7").fill("90");
    const written = await page.evaluate(() => window.__rbcTest?.port.written.length ?? 0);

    const downloadPromise = page.waitForEvent("download");
    await page.getByRole("button", { name: "Back up zeros" }).click();
    const download = await downloadPromise;
    const name = download.suggestedFilename();
    expect(name).toMatch(/^rbc-zeros-8958899989309-\d{4}-\d{2}-\d{2}\.json$/);
    const saved = page.getByText(/^Backup made/);
    await saved.waitFor();
    expect(await saved.textContent().then(squash)).toBe(
      `Backup made: 16 zeros read from the robot. To put them back later: Restore from backup. Backup file offered as a download (${name}): the browser decides where it goes and may rename it. It is kept in this browser (Backups kept in this browser, below).`,
    );
    const parsed = parseZerosBackup(await readFile(await download.path(), "utf8"));
    expect(parsed.ok && parsed.backup).toMatchObject({
      format: "rbc-zeros",
      version: 1,
      serialNumber: "8958899989309",
      firmware: "2.23",
      zeros: onRobot,
    });

    // Only the read went out (one request): nothing was written, and the edit is still in the editor.
    expect(await simZeros(page)).toEqual(onRobot);
    const sent = await page.evaluate((from) => window.__rbcTest?.port.written.slice(from), written);
    expect(sent?.map((bytes) => bytes[8])).toEqual([0x0b]);
    expect(await page.locator("#zero-7").inputValue()).toBe("90");
    await context.close();
  });

  it("names the factory and reference zeros and says which is which", async () => {
    const { page, context } = await app.newPage();
    await openZeros(page);
    const tables = await page.getByTestId("zero-tables").textContent().then(squash);
    expect(tables).toContain(
      `Factory zeros The values the robot's firmware holds when it is new: ${FACTORY_ZEROS.join(" ")}.`,
    );
    expect(tables).toContain(
      `Reference zeros The table the robot checks every write against: ${STANDARD_ZEROS.join(" ")}. Each zero must stay within ±15 of it`,
    );
    // The button's description is the explanation beside it.
    const button = page.getByRole("button", { name: "Load factory zeros" });
    expect(await button.getAttribute("aria-describedby")).toBe("factory-zeros-why");
    // An unchanged row says so to a screen reader with text, not with a label on a plain span.
    const unchanged = page.locator('tr[data-servo="1"] .zero-diff');
    expect(await unchanged.locator("[aria-label]").count()).toBe(0);
    expect(await unchanged.locator(".sr-only").textContent()).toBe("unchanged");
    await context.close();
  });

  it("works with the keyboard alone", async () => {
    const { page, context } = await app.newPage();
    await openZeros(page);
    await page.locator("#zero-1").focus();
    await page.keyboard.press("ArrowUp");
    await page.keyboard.press("ArrowUp");
    await page.getByTestId("change-summary").filter({ hasText: "servo 1 202 → 204" }).waitFor();
    // Tab moves on to the slider of the same servo; arrows move it within its window.
    await page.keyboard.press("Tab");
    await page.keyboard.press("ArrowLeft");
    await page.getByTestId("change-summary").filter({ hasText: "servo 1 202 → 203" }).waitFor();
    await page.getByTestId("write-zeros").focus();
    await page.keyboard.press("Enter");
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("confirm-write");
    const downloadPromise = page.waitForEvent("download");
    await page.keyboard.press("Enter");
    await downloadPromise;
    await page.getByText(/Zeros written and verified/).waitFor();
    expect((await simZeros(page))?.[1]).toBe(203);
    await context.close();
  });
});
