/**
 * Every view in both languages at both sizes (issue #14, "Done when"): with the demo robot connected, each view
 * of the side navigation is opened in English and in Korean, at 1280×800 and at 390×844, and checked for the
 * page's `lang`, no catalogue key shown in place of its text, no label wider than its button, nothing that
 * scrolls sideways, and no axe violation. The feature files (`i18n-*.test.ts`) check each view's own states and
 * Korean sentences; this one makes sure no view is left out.
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { newLocalePage, pageLang, pageProblems, SIZES } from "./i18n-checks.ts";
import "./rbc-test-globals.ts";
import { useApp } from "./harness.ts";

const LANGUAGES = [
  { locale: "en-US", lang: "en", demo: "Try the demo robot" },
  { locale: "ko-KR", lang: "ko", demo: "데모 로봇 써 보기" },
] as const;
/** The side navigation's views, by route. */
const VIEWS = [
  "robot",
  "zeros",
  "motions",
  "editor",
  "sensors",
  "servos",
  "doctor",
  "firmware",
  "log",
  "class",
] as const;

const app = useApp();

/** Opens a view from the side navigation and waits until it has drawn and read what it reads on arrival. */
async function openView(page: Page, view: string): Promise<void> {
  const heading = () => page.evaluate(() => document.querySelector("main h1")?.textContent ?? "");
  const before = await heading();
  await page.locator(`.side-nav a[href="#/${view}"]`).click();
  await page.waitForFunction((v) => location.hash === `#/${v}`, view);
  // Views load lazily: wait for this view's own heading, not the one before it (the Robot view is first).
  if (view !== "robot") {
    await page.waitForFunction((old) => {
      const text = document.querySelector("main h1")?.textContent ?? "";
      return text !== "" && text !== old;
    }, before);
  }
  // Views read the robot when they open (zeros, memory, sensors): wait until nothing runs and nothing is busy.
  await page
    .waitForFunction(
      () => document.querySelector('[aria-busy="true"], .is-running, progress:not([value])') === null,
      undefined,
      { timeout: 10_000 },
    )
    .catch(() => {});
  if (view === "zeros") {
    await page.waitForFunction(
      () => (document.querySelector<HTMLInputElement>("#zero-15")?.value ?? "") !== "",
    );
  }
  await page.waitForLoadState("networkidle");
}

for (const language of LANGUAGES) {
  for (const size of SIZES) {
    describe(`every view in ${language.locale} at ${size.width}×${size.height}`, () => {
      it("has its lang, shows no key, fits its labels, never scrolls sideways and passes axe", {
        timeout: 120_000,
      }, async () => {
        const { page, context } = await newLocalePage(app, language.locale, { size });
        try {
          await page.getByRole("button", { name: language.demo }).first().click();
          await page.getByTestId("device-card").waitFor();
          const report: string[] = [];
          for (const view of VIEWS) {
            await openView(page, view);
            await expect.poll(() => pageLang(page), { message: view }).toBe(language.lang);
            // The view speaks the page's language: its heading has Hangul in Korean, none in English.
            const title = await page.evaluate(() => document.querySelector("main h1")?.textContent ?? "");
            expect(/[가-힣]/.test(title), `${view}: "${title}"`).toBe(language.lang === "ko");
            for (const p of await pageProblems(page)) report.push(`${view}: ${p}`);
          }
          expect(report, report.join("\n")).toEqual([]);
        } finally {
          await context.close();
        }
      });
    });
  }
}
