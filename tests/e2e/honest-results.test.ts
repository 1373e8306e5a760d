import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { FACTORY_ZEROS } from "../../src/protocol/index.ts";
import { CABLE, loadConnected } from "./connected-page.ts";
import { expectText, squash, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";

// Issue 21 items 5 and 6: nothing the panel says is more certain than what happened, and results appear where
// the eyes are, in the language of the moment.

const app = useApp();

/** The Zeros view with the robot on the cable connected (a page opened with the start option `CABLE`). */
async function openZeros(page: Page): Promise<void> {
  await loadConnected(page, app.url, "zeros");
  await page.locator("#zero-0").waitFor();
}

/** A browser without the Save dialog (File System Access API): backups are offered as downloads. */
async function withoutSavePicker(page: Page): Promise<void> {
  await page.addInitScript(() => {
    Reflect.deleteProperty(window, "showSaveFilePicker");
  });
}

/** A Save dialog where the person names the file `name` (what was written is kept in window.__saved). */
async function withSavePicker(page: Page, name: string | "cancel"): Promise<void> {
  await page.addInitScript((chosen) => {
    const w = window as unknown as { __saved?: string[]; showSaveFilePicker?: unknown };
    w.__saved = [];
    w.showSaveFilePicker = async () => {
      if (chosen === "cancel") throw new DOMException("The user aborted a request.", "AbortError");
      return {
        name: chosen,
        createWritable: async () => ({
          // Text or a Blob: the panel's save paths write either (src/ui/save-file.ts writes a Blob).
          write: async (data: string | Blob) => {
            w.__saved?.push(typeof data === "string" ? data : await data.text());
          },
          close: async () => {},
        }),
      };
    };
  }, name);
}

const zerosResult = (page: Page) => page.getByTestId("zeros-write").locator(".notice");

describe("zero backups say where they went, and are kept in this browser", () => {
  it("without a Save dialog: 'offered as a download', never 'saved as', and the backup is listed with Restore", async () => {
    const { page, context } = await app.newPage({ start: CABLE });
    await withoutSavePicker(page);
    await openZeros(page);
    await page.getByTestId("kept-backups").locator("summary").filter({ hasText: "(0)" }).waitFor();

    await page.locator("#zero-3").fill("70");
    await page.getByTestId("write-zeros").click();
    const download = page.waitForEvent("download");
    await page.getByRole("button", { name: "Save backup and write" }).click();
    const name = (await download).suggestedFilename();
    await zerosResult(page).filter({ hasText: "Zeros written and verified" }).waitFor();
    await expectText(
      zerosResult(page),
      `Zeros written and verified (read back 16/16). Backup file offered as a download (${name}): the browser decides where it goes and may rename it. It is kept in this browser (Backups kept in this browser, below).`,
    );
    const text = squash(await zerosResult(page).textContent());
    expect(text).not.toContain("saved as");

    // The list holds the backup: the robot's zeros before the write, its serial number, and Restore.
    const list = page.getByTestId("kept-backups");
    await list.locator("summary").filter({ hasText: "(1)" }).click();
    const row = list.locator("tbody tr");
    await expect.poll(() => row.count()).toBe(1);
    await expectText(row.locator("td").nth(1), "8958899989309");
    await expectText(row.locator("td").nth(2), FACTORY_ZEROS.join(" "));

    // Restore puts the backup into the zero table; nothing is written until Write.
    const written = await page.evaluate(() => window.__rbcTest?.port.written.length);
    await row.getByRole("button", { name: "Restore" }).click();
    await page.getByText(/Loaded the backup kept in this browser/).waitFor();
    await expect.poll(() => page.locator("#zero-3").inputValue()).toBe(String(FACTORY_ZEROS[3]));
    expect(await page.evaluate(() => window.__rbcTest?.port.written.length)).toBe(written);
    await context.close();
  });

  it("with a Save dialog: reports the name actually written; closing the dialog writes nothing", async () => {
    const { page, context } = await app.newPage({ start: CABLE });
    await withSavePicker(page, "my-zeros.json");
    await openZeros(page);
    await page.getByTestId("backup-zeros").click();
    await page.getByText(/Backup file written: my-zeros\.json\./).waitFor();
    const saved = await page.evaluate(() => (window as unknown as { __saved: string[] }).__saved);
    expect(saved).toHaveLength(1);
    expect(JSON.parse(saved[0] ?? "{}").zeros).toEqual([...FACTORY_ZEROS]);
    await context.close();

    const second = await app.newPage({ start: CABLE });
    await withSavePicker(second.page, "cancel");
    await openZeros(second.page);
    const before = await second.page.evaluate(() => window.__rbcTest?.sim.zeros);
    await second.page.locator("#zero-3").fill("70");
    await second.page.getByTestId("write-zeros").click();
    await second.page.getByRole("button", { name: "Save backup and write" }).click();
    await zerosResult(second.page)
      .filter({ hasText: "Nothing was written: the Save dialog for the backup file was closed." })
      .waitFor();
    expect(await second.page.evaluate(() => window.__rbcTest?.sim.zeros)).toEqual(before);
    await second.context.close();
  });

  it("never says 'the editor matches the robot' next to a value that cannot be written", async () => {
    const { page, context } = await app.newPage({ start: CABLE });
    await withoutSavePicker(page);
    await openZeros(page);
    await page.locator("#zero-3").fill("200");
    await page.getByTestId("write-why").filter({ hasText: "Cannot write" }).waitFor();
    const summary = page.getByTestId("change-summary");
    await expectText(summary, "The 15 values that can be written match the robot's zeros.");
    expect(squash(await summary.textContent())).not.toContain("matches");
    await context.close();
  });
});

describe("Stop's result is where the eyes are, in the language of the moment", () => {
  it("shows Stop's result inside the top bar while the page is scrolled down, and rewords it after a language switch", async () => {
    const { page, context } = await app.newPage({ start: CABLE });
    await withoutSavePicker(page);
    await openZeros(page);
    await page.evaluate(() => window.scrollTo(0, document.documentElement.scrollHeight));
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    const banner = page.getByTestId("stop-banner");
    await banner.filter({ hasText: "it is idle, nothing to stop" }).waitFor();
    // The result is inside the top bar and within the window, however far down the page is.
    expect(await banner.evaluate((el) => el.closest(".top-bar") !== null)).toBe(true);
    await expect
      .poll(() => banner.boundingBox())
      .toSatisfy(
        (box: { y: number; height: number } | null) =>
          box !== null && box.y >= 0 && box.y + box.height <= 800,
      );
    expect(await page.evaluate(() => window.scrollY)).toBeGreaterThan(0);

    // Made in English; after the switch it reads in Korean.
    await page.getByLabel("Language / 언어").selectOption("ko");
    await banner.filter({ hasText: "쉬고 있어서 멈출 것이 없어요" }).waitFor();
    expect(squash(await banner.textContent())).not.toContain("it is idle, nothing to stop");
    await context.close();
  });
});
