import { readFileSync } from "node:fs";
import { join } from "node:path";
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { expectText, ROOT, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";

/**
 * The version at the foot of the page links to what changed (issue 33, item 13): the changelog shipped with the
 * build (changelog.html beside the hosted panel, made from CHANGELOG.md), which opens in a tab of its own and
 * shows the changelog's headings. In English and in Korean. (Offline: tests/e2e/subpath.test.ts; the one-file
 * panel: tests/e2e/single-file.test.ts.)
 */

const app = useApp();

const CHANGELOG = readFileSync(join(ROOT, "CHANGELOG.md"), "utf8");
/** The changelog's first heading ("Changelog") and its first section's ("Unreleased" or a version). */
const FIRST_HEADING = /^# (.+)$/m.exec(CHANGELOG)?.[1] ?? "";
const FIRST_SECTION = /^## (.+)$/m.exec(CHANGELOG)?.[1] ?? "";

async function openChangelog(page: Page, linkName: string): Promise<Page> {
  const footer = page.getByTestId("panel-version");
  const link = footer.getByRole("link", { name: linkName, exact: true });
  await link.waitFor();
  const [tab] = await Promise.all([page.waitForEvent("popup"), link.click()]);
  await tab.waitForLoadState("domcontentloaded");
  return tab;
}

describe("the version's link to what changed", () => {
  for (const [locale, version, linkName] of [
    ["en-US", /^RBC Panel · Version \d+\.\d+\.\d+/, "What changed"],
    ["ko-KR", /^RBC 패널 · 버전 \d+\.\d+\.\d+/, "변경 사항"],
  ] as const) {
    it(`opens the changelog shipped with the panel (${locale})`, async () => {
      expect(FIRST_HEADING).not.toBe("");
      const { page, context } = await app.newPage({ locale });
      await page.goto(app.url);
      await expectText(page.getByTestId("panel-version"), version);
      const tab = await openChangelog(page, linkName);
      // Beside the panel, from the same server: nothing from elsewhere (the build knows no repository).
      expect(tab.url()).toBe(`${app.url}changelog.html`);
      expect(await tab.evaluate(() => document.title)).toBe("Changelog · RBC Panel");
      await tab.getByRole("heading", { level: 1, name: FIRST_HEADING, exact: true }).waitFor();
      await tab.getByRole("heading", { level: 2, name: FIRST_SECTION, exact: true }).first().waitFor();
      // The panel stayed where it was.
      expect(page.url()).toBe(app.url);
      await tab.close();
      await context.close();
    });
  }
});
