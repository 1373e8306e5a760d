import { readFile } from "node:fs/promises";
import { describe, expect, it } from "vitest";
import { storeDraft } from "./editor-fixtures.ts";
import { useApp, watchPage } from "./harness.ts";
import "./rbc-test-globals.ts";

/**
 * Issue 20 item 9 in the browser: a stored draft whose motion has no scenes (docs/protocol.md §7: S = 0 is an
 * error) once kept the Editor on "Opening the last draft…" for good. Now the Editor opens with the template,
 * says in one sentence that the draft was set aside, and exports the stored text as it is on request.
 */

const app = useApp();

/** One servo, zero scenes. */
const ZERO_SCENES =
  "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:6:Broken:0:1:0:2:1:4:00:020:030:000:0:125:";
const KEY = "d-broken-1";

describe("a stored draft with no scenes", () => {
  it("the Editor opens after a reload, with the sentence, and exports the draft as it is", async () => {
    const { page, context } = await app.newPage();
    const seen = watchPage(page, app.origin);
    await page.goto(`${app.url}#/editor`, { waitUntil: "domcontentloaded" });
    await page.getByTestId("editor").waitFor();
    await storeDraft(page, KEY, {
      version: 1,
      id: KEY,
      name: "Broken",
      savedAt: Date.now(),
      rbm: ZERO_SCENES,
    });

    await page.reload({ waitUntil: "domcontentloaded" });
    await page.getByTestId("editor").waitFor();
    const sentence = page.getByText(
      "The last draft, Broken, could not be opened and was set aside: Its motion cannot be read: The motion has no scenes; a motion needs at least one. It stays in Drafts, where you can export it as it is or delete it.",
    );
    await sentence.waitFor({ timeout: 10_000 });
    await expect.poll(() => page.getByTestId("editor-starting").count()).toBe(0);
    // The Editor works: the template motion is open, with its one scene.
    await expect.poll(() => page.getByTestId("motion-name").inputValue()).toBe("NewMotion");

    // Set aside, not lost: listed with why, and exported unchanged on request.
    const aside = page.getByTestId("broken-drafts");
    await aside.locator("summary").click();
    const exporting = page.waitForEvent("download");
    await aside.getByRole("button", { name: `Export the stored text of ${KEY} as it is` }).click();
    const download = await exporting;
    expect(download.suggestedFilename()).toBe("Broken.rbm");
    const path = await download.path();
    expect(await readFile(path, "latin1")).toBe(ZERO_SCENES);
    expect(seen.errors).toEqual([]);
    await context.close();
  });
});
