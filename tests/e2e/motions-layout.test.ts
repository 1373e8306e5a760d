import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { parseRbm } from "../../src/protocol/rbm.ts";
import { validateRbm } from "../../src/protocol/rbm-validate.ts";
import { CABLE, loadMotions } from "./connected-page.ts";
import { expectText, FAST, useApp } from "./harness.ts";
import {
  exampleText,
  longMotion,
  rbmFile,
  showTab,
  withJumps,
  withName,
  withUnsafePosition,
} from "./motion-fixtures.ts";
import type { RbcTestOptions } from "./rbc-test-globals.ts";
import "./rbc-test-globals.ts";

// Issue #11: the Motions view in tabs that fit a screen, progress and results where the action started,
// labels that never overflow, warnings grouped by kind, memory shown as used.

const app = useApp();

const TABS = ["Files", "Memory", "Run", "Sounds"] as const;
const PHONE = { width: 390, height: 844 };
const DESKTOP = { width: 1280, height: 800 };

/** Opens a file in the Motions view and waits for its card. */
async function openFile(page: Page, name: string, text: string): Promise<void> {
  await page.getByTestId("rbm-files").setInputFiles(rbmFile(name, text));
  await page.getByTestId("motion-file").filter({ hasText: name }).waitFor();
}

/** Uploads the shown file to the fake (real-robot) port, through the experimental notice. */
async function uploadShown(page: Page, fileName: string): Promise<void> {
  await page.getByTestId("upload-motion").click();
  await page.getByRole("button", { name: "Upload (experimental)" }).click();
  await page.getByText(new RegExp(`^Uploaded ${fileName.replace(".", "\\.")}`)).waitFor({ timeout: 15_000 });
}

/** Where an element lies against the viewport, or undefined when it is not in the page. */
async function placement(page: Page, selector: string) {
  return page.evaluate((sel) => {
    const el = document.querySelector(sel);
    if (!el) return undefined;
    const r = el.getBoundingClientRect();
    return { top: r.top, bottom: r.bottom, viewport: window.innerHeight };
  }, selector);
}

/** The placement's element lies wholly inside the viewport. */
const inView = (p: Awaited<ReturnType<typeof placement>>) =>
  p !== undefined && p.top >= 0 && p.bottom <= p.viewport;

/** Buttons (and tabs) whose label is wider than the button, as "label (scroll > client)". */
async function overflowingButtons(page: Page): Promise<string[]> {
  return page.evaluate(() =>
    Array.from(document.querySelectorAll<HTMLElement>("button, [role=button], .btn"))
      .filter((b) => b.offsetParent !== null && b.scrollWidth > b.clientWidth)
      .map(
        (b) => `${(b.textContent ?? "").replace(/\s+/g, " ").trim()} (${b.scrollWidth} > ${b.clientWidth})`,
      ),
  );
}

describe("motions view layout", () => {
  it("splits the view into tabs that each fit about one screen at 1280×800 with wave.rbm open", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST, viewport: DESKTOP });
    await loadMotions(page, app.url);
    await openFile(page, "wave.rbm", exampleText("wave.rbm"));
    await page.locator('[data-testid="motion-chart"][data-chart="drawn"]').waitFor();
    const heights: Record<string, number> = {};
    for (const tab of TABS) {
      await showTab(page, tab);
      // Where the view ends on the page (the version line below it is the same on every view).
      heights[tab] = await page.evaluate(() => {
        const main = document.querySelector("main");
        return main ? Math.round(main.getBoundingClientRect().bottom + window.scrollY) : Number.NaN;
      });
    }
    // The single page was 2,606 px here; no tab is more than 1.5 screens now.
    for (const tab of TABS) expect(heights[tab], tab).toBeLessThanOrEqual(1.5 * DESKTOP.height);

    // The tab list follows the tabs pattern: one tab in the Tab order, arrows move and select.
    await showTab(page, "Files");
    const files = page.getByRole("tab", { name: "Files" });
    await expect.poll(() => files.getAttribute("aria-selected")).toBe("true");
    await expect.poll(() => files.getAttribute("aria-controls")).toBe("motions-panel-files");
    await expect.poll(() => page.getByRole("tab", { name: "Run" }).getAttribute("tabindex")).toBe("-1");
    await files.focus();
    await page.keyboard.press("ArrowRight");
    await page.locator("#motions-panel-uploads").waitFor();
    const memory = page.getByRole("tab", { name: "Memory" });
    await expect.poll(() => memory.getAttribute("aria-selected")).toBe("true");
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("motions-tab-uploads");
    await page.keyboard.press("End");
    await page.locator("#motions-panel-sounds").waitFor();
    // The focus follows the tab on the next frame: the next key goes to the tab that has it.
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("motions-tab-sounds");
    await page.keyboard.press("ArrowRight");
    await page.locator("#motions-panel-files").waitFor();
    await context.close();
  });

  it("shows an upload's progress, Cancel and result in the file card, in view, where Upload was pressed", async () => {
    // The paced link in real time: a long motion's upload lasts long enough to look at its progress.
    const paced: RbcTestOptions = { baudPacing: true, latencyMs: 16 };
    const { page, context } = await app.newPage({ start: CABLE, options: paced, viewport: DESKTOP });
    await loadMotions(page, app.url);
    await openFile(page, "Long.rbm", longMotion(exampleText("wave.rbm"), 40));
    const card = page.getByTestId("motion-file");
    await card.getByTestId("upload-motion").click();
    await card.getByTestId("upload-confirm").waitFor();
    await card.getByRole("button", { name: "Upload (experimental)" }).click();
    const progress = card.getByTestId("upload-progress");
    await progress.waitFor();
    // In the card, under its button, wholly inside the viewport: bar, figures and Cancel.
    await expect
      .poll(() => placement(page, '[data-testid="motion-file"] [data-testid="upload-progress"]'))
      .toSatisfy(inView);
    await expect.poll(() => progress.locator("progress").count()).toBe(1);
    await progress.getByRole("button", { name: "Cancel upload" }).click();
    const result = card.getByRole("status", { name: "Upload result" }).locator(".notice");
    await result.waitFor({ timeout: 10_000 });
    await expectText(result, /^Upload cancelled|^Uploaded Long\.rbm/);
    await expect
      .poll(() => placement(page, '[data-testid="motion-file"] .upload-in-place .notice'))
      .toSatisfy(inView);
    await context.close();
  });

  it("never lets a label overflow its button, at 390 and 1280 px, with a long motion name uploaded", async () => {
    const long = withName(exampleText("wave.rbm"), "HunoDemo_WalkJump_WithAVeryLongNameIndeed");
    for (const viewport of [PHONE, DESKTOP]) {
      const { page, context } = await app.newPage({ start: CABLE, options: FAST, viewport });
      await loadMotions(page, app.url);
      await openFile(page, "HunoDemo_WalkJump_WithAVeryLongNameIndeed.rbm", long);
      await page.getByTestId("reset-first").check();
      await uploadShown(page, "HunoDemo_WalkJump_WithAVeryLongNameIndeed.rbm");
      for (const tab of TABS) {
        await showTab(page, tab);
        if (tab === "Run") {
          await page.locator('[data-testid="downloaded-motions"] [data-motion="12"]').waitFor();
          await page.getByText(/Other upload slots/).click();
        }
        expect(await overflowingButtons(page), `${tab} at ${viewport.width} px`).toEqual([]);
        // Nor does the page scroll sideways.
        expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(
          viewport.width,
        );
      }
      await context.close();
    }
  });

  it("groups warnings by kind with a count and a weight, the single warnings on demand", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await loadMotions(page, app.url);
    // Small jumps only: one minor kind, not 16 alarming lines.
    const small = withJumps(exampleText("wave.rbm"), 2);
    const smallCount = validateRbm(parseRbm(small)).warnings.length;
    expect(smallCount).toBe(16);
    await openFile(page, "Small.rbm", small);
    let groups = page.getByTestId("warning-group");
    await expect.poll(() => groups.count()).toBe(1);
    await expectText(groups.first(), /^Minor Servos jump between scenes \(16\)/);
    await expectText(groups.first(), "The largest jump is 2 steps", { contains: true });
    await expect.poll(() => groups.first().locator("details").getAttribute("open")).toBeNull();
    await expectText(groups.first().locator("details summary"), "Show all 16");
    await expectText(
      page.getByTestId("check-summary"),
      "Checked: 0 errors, 16 warnings of 1 kind, none serious.",
    );

    // A position outside a safe range comes first and is called serious; large jumps ask for a check.
    const risky = withUnsafePosition(withJumps(exampleText("wave.rbm"), 40));
    const warnings = validateRbm(parseRbm(risky)).warnings;
    const count = (code: string) => warnings.filter((w) => w.code === code).length;
    await openFile(page, "Risky.rbm", risky);
    const card = page.getByTestId("motion-file").filter({ hasText: "Risky.rbm" });
    groups = card.getByTestId("warning-group");
    await expect
      .poll(() => groups.evaluateAll((els) => els.map((e) => e.getAttribute("data-code"))))
      .toEqual(["rbm-unsafe-position", "rbm-scene-jump"]);
    await expectText(
      groups.nth(0),
      new RegExp(`^Serious Positions outside a joint's safe range \\(${count("rbm-unsafe-position")}\\)`),
    );
    await expectText(
      groups.nth(1),
      new RegExp(`^Check Servos jump between scenes \\(${count("rbm-scene-jump")}\\)`),
    );
    // Details on demand: the single warnings, where they are.
    await groups.nth(1).locator("summary").click();
    await expect.poll(() => groups.nth(1).locator("li.issue").count()).toBe(count("rbm-scene-jump"));
    await context.close();
  });

  it("shows memory as used (an empty bar when nothing is stored) and the scenes toggle by its action", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await loadMotions(page, app.url);
    const meter = page.locator("#mem-motion");
    await expect.poll(() => meter.getAttribute("value")).toBe("0");
    await expectText(page.getByTestId("mem-motion-used"), "0 bytes used");
    await openFile(page, "wave.rbm", exampleText("wave.rbm"));

    // The toggle names its action and says whether the scenes are expanded.
    const toggle = page.getByTestId("scenes-toggle");
    await expectText(toggle, "Hide scenes and chart");
    await expect.poll(() => toggle.getAttribute("aria-expanded")).toBe("true");
    await expect.poll(() => toggle.getAttribute("aria-controls")).toBe("scene-section");
    await toggle.click();
    await page.getByTestId("scene-section").waitFor({ state: "detached" });
    await expectText(toggle, "Show scenes and chart");
    await expect.poll(() => toggle.getAttribute("aria-expanded")).toBe("false");

    await uploadShown(page, "wave.rbm");
    // wave.rbm takes 640 bytes of the motion area.
    await expect.poll(() => meter.getAttribute("value")).toBe("640");
    await showTab(page, "Memory");
    await expect.poll(() => page.locator("#mem-motion").getAttribute("value")).toBe("640");
    await expect.poll(() => page.locator("#mem-action").getAttribute("value")).toBe("0");
    await context.close();
  });
});
