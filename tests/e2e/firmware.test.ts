import { mkdir } from "node:fs/promises";
import { join } from "node:path";
import type { Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { firmwareHex } from "../support/hex.ts";
import { type AppHarness, ROOT, squash, startHarness, watchPage } from "./harness.ts";
import "./rbc-test-globals.ts";

/**
 * The Firmware view on the demo robot (its bootloader in front of the simulated RBC; the panel switches it off
 * and on itself): open the demo file or a .hex, see its summary, confirm, watch the progress in place, and see
 * the version the robot reports change; Cancel mid-way says what the robot holds. Robot time runs faster.
 */

let app: AppHarness;

beforeAll(async () => {
  app = await startHarness();
});

afterAll(async () => {
  await app?.close();
});

/** Screenshots for people to look at (not compared): SCREENSHOTS=dir. */
const SHOTS = process.env.FIRMWARE_SCREENSHOTS;

async function shot(page: Page, name: string): Promise<void> {
  if (!SHOTS) return;
  const dir = join(ROOT, SHOTS);
  await mkdir(dir, { recursive: true });
  await page.screenshot({ path: join(dir, `${name}.png`), fullPage: true });
}

async function openFirmwareOnDemo(page: Page): Promise<void> {
  await page.goto(app.url, { waitUntil: "domcontentloaded" });
  await page.getByRole("button", { name: "Try the demo robot" }).click();
  await page.getByTestId("device-card").waitFor();
  await page.getByRole("link", { name: "Firmware" }).click();
  await page.getByTestId("firmware-view").waitFor();
}

describe("Firmware view on the demo robot", () => {
  for (const variant of [
    { name: "desktop-light", viewport: { width: 1280, height: 800 }, dark: false },
    { name: "phone-dark", viewport: { width: 390, height: 844 }, dark: true },
  ]) {
    it(`flashes the demo file and the version shown changes to 2.50 (${variant.name})`, {
      timeout: 60_000,
    }, async () => {
      const { page } = await app.newPage({ viewport: variant.viewport, options: { timeScale: 4 } });
      await page.emulateMedia({ colorScheme: variant.dark ? "dark" : "light" });
      const seen = watchPage(page, app.origin);
      await openFirmwareOnDemo(page);
      expect(await page.getByTestId("fw-version").textContent().then(squash)).toBe("2.23");
      expect(await page.getByTestId("fw-notice").textContent().then(squash)).toContain(
        "The bootloader itself is never written, so a failed or interrupted update is fixed by running the update again.",
      );
      expect(await page.getByTestId("flash-start").isDisabled()).toBe(true);

      await page.getByTestId("fw-demo-file").click();
      await page.getByTestId("fw-summary").waitFor();
      expect(await page.getByTestId("fw-size").textContent().then(squash)).toBe("16,384 bytes");
      expect(await page.getByTestId("fw-range").textContent().then(squash)).toBe("0x00000–0x03FFF");
      expect(await page.getByTestId("fw-pages").textContent().then(squash)).toBe("64 of 256 bytes");
      expect(await page.getByTestId("fw-lines").textContent().then(squash)).toBe(
        "1,025 (46,093 bytes to send)",
      );
      await shot(page, `before-${variant.name}`);

      await page.getByTestId("flash-start").click();
      const confirm = page.getByTestId("flash-confirm");
      await confirm.waitFor();
      expect(await confirm.textContent().then(squash)).toContain(
        "Replace the robot's firmware with demo-2.50.hex?",
      );
      await page.getByRole("button", { name: "Update firmware", exact: true }).click();

      // The power-cycle step, then progress in place.
      const progress = page.getByTestId("flash-progress");
      await progress.waitFor();
      expect(await progress.textContent().then(squash)).toContain("Switch the robot off and on now.");
      const figures = page.getByTestId("flash-figures");
      await figures.filter({ hasText: /bytes\/s/ }).waitFor({ timeout: 20_000 });
      const text = squash(await figures.textContent());
      expect(text).toMatch(/^[\d,]+ of 1,025 lines · [\d,]+ of 46,093 bytes \(\d+%\) · [\d,]+ bytes\/s · /);
      await shot(page, `during-${variant.name}`);

      const result = page.getByTestId("flash-result").getByText(/Firmware updated/);
      await result.waitFor({ timeout: 40_000 });
      expect(squash(await result.textContent())).toMatch(
        /^Firmware updated: the robot now reports 2\.50 \(was 2\.23\)\. 1,025 lines in [\d.]+ s\. The robot was restarted/,
      );
      expect(await page.getByTestId("fw-version").textContent().then(squash)).toBe("2.50");
      // The top bar and the Robot view show what the robot reported too.
      await page.getByRole("link", { name: "Robot" }).click();
      expect(await page.getByTestId("firmware").textContent().then(squash)).toBe("2.50");
      await page.getByRole("link", { name: "Firmware" }).click();
      await page.getByTestId("firmware-view").waitFor();
      // No sideways scrolling on a phone.
      const overflow = await page.evaluate(
        () => document.documentElement.scrollWidth - document.documentElement.clientWidth,
      );
      expect(overflow).toBeLessThanOrEqual(0);
      await shot(page, `after-${variant.name}`);
      expect(seen.errors).toEqual([]);
    });
  }

  it("Cancel mid-way says the firmware may be incomplete; a bad file names its line", {
    timeout: 60_000,
  }, async () => {
    const { page } = await app.newPage({ options: { timeScale: 2 } });
    await openFirmwareOnDemo(page);

    // A bad file first: refused with the line to blame, nothing opened.
    const lines = firmwareHex("2.50", 512).split("\r\n");
    lines[2] = `${lines[2]!.slice(0, -2)}00`;
    await page.getByTestId("fw-file-input").setInputFiles({
      name: "broken.hex",
      mimeType: "text/plain",
      buffer: Buffer.from(lines.join("\r\n")),
    });
    const problem = page.getByText(/broken\.hex is not a firmware file/);
    await problem.waitFor();
    expect(squash(await problem.textContent())).toMatch(/Line 3: the checksum is 00/);
    expect(await page.getByTestId("fw-summary").count()).toBe(0);

    // A good file of this computer (64 KiB: long enough to cancel).
    await page.getByTestId("fw-file-input").setInputFiles({
      name: "big-2.60.hex",
      mimeType: "text/plain",
      buffer: Buffer.from(firmwareHex("2.60", 64 * 1024)),
    });
    await page.getByTestId("fw-summary").waitFor();
    expect(await page.getByTestId("fw-lines").textContent().then(squash)).toBe(
      "4,097 (184,333 bytes to send)",
    );
    await page.getByTestId("flash-start").click();
    await page.getByRole("button", { name: "Update firmware", exact: true }).click();
    await page
      .getByTestId("flash-figures")
      .filter({ hasText: /bytes\/s/ })
      .waitFor({ timeout: 20_000 });
    expect(await page.getByTestId("flash-progress").textContent().then(squash)).toContain(
      "Cancel now and the robot's firmware may be incomplete",
    );
    await page.getByTestId("flash-cancel").click();
    const result = page.getByTestId("flash-result").getByText(/The firmware update was cancelled/);
    await result.waitFor({ timeout: 20_000 });
    expect(squash(await result.textContent())).toBe(
      "The firmware update was cancelled. The robot's firmware may now be incomplete, and the robot may not work until an update succeeds. The bootloader is never overwritten: switch the robot off and on and run the update again.",
    );
    expect(await page.getByTestId("flash-progress").count()).toBe(0);
    expect(await page.getByTestId("fw-version").textContent().then(squash)).toBe("2.23");
  });
});

describe("a robot waiting in its bootloader (issue 20 item 11)", () => {
  it("connecting says so, and the notice's link opens the Firmware view's Recover", {
    timeout: 60_000,
  }, async () => {
    const { page } = await app.newPage({ options: { inBootloader: true, timeScale: 4 } });
    const seen = watchPage(page, app.origin);
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByRole("button", { name: "Connect robot" }).click();
    const go = page.getByRole("link", { name: "Go to the firmware recovery" });
    await go.waitFor({ timeout: 30_000 });
    const text = await page.getByTestId("connect-card").textContent().then(squash);
    expect(text).toMatch(
      /The robot is waiting in its bootloader: it sent the bootloader's prompt \(\^\) \d+ times and answered no request\./,
    );
    expect(text).toContain("Run the firmware update again, in recovery mode");
    expect(text).not.toContain("no robot answered");
    await go.click();
    await page.getByTestId("firmware-view").waitFor();
    expect(
      await page.getByRole("heading", { name: "Recover: update a robot that does not answer" }).isVisible(),
    ).toBe(true);
    expect(await page.getByTestId("recover-start").isVisible()).toBe(true);
    expect(seen.errors).toEqual([]);
  });

  it("another failed connect (no port chosen) gets no such link", { timeout: 30_000 }, async () => {
    const { page } = await app.newPage({ options: { userCancels: true } });
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByRole("button", { name: "Connect robot" }).click();
    await page.getByText("No port was chosen").waitFor();
    expect(await page.getByTestId("open-recovery").count()).toBe(0);
  });
});
