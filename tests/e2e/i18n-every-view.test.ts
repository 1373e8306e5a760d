/**
 * Every view in both languages at both sizes (issue #14, "Done when"): with the demo robot connected, each view
 * of the side navigation is opened in English and in Korean, at 1280×800 and at 390×844, and checked for the
 * page's `lang`, no catalogue key shown in place of its text, no label wider than its button, nothing that
 * scrolls sideways, and no axe violation. The feature files (`i18n-*.test.ts`) check each view's own states and
 * Korean sentences; this one makes sure no view is left out. One page walks them all, in order: English, then
 * Korean from the language switch, each at both sizes (a Korean browser is i18n.test.ts's; the start card's
 * Korean demo button, connect.test.ts's).
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { sharedConnectedPage } from "./connected-page.ts";
import { pageLang, pageProblems, SIZES } from "./i18n-checks.ts";
import "./rbc-test-globals.ts";
import { useApp } from "./harness.ts";

const LANGUAGES = [
  { locale: "en-US", lang: "en" },
  { locale: "ko-KR", lang: "ko" },
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
  const from = await page.evaluate(() => location.hash);
  await page.locator(`.side-nav a[href="#/${view}"]`).click();
  await page.waitForFunction((v) => location.hash === `#/${v}`, view);
  // Views load lazily: wait for this view's own heading, not the one before it (unless the view was already
  // shown: the Robot view at the start).
  if (from !== `#/${view}` && !(from === "" && view === "robot")) {
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

describe("every view, on one page with the demo robot", () => {
  const page = sharedConnectedPage(app);

  for (const language of LANGUAGES) {
    for (const size of SIZES) {
      it(`in ${language.locale} at ${size.width}×${size.height}: has its lang, shows no key, fits its labels, never scrolls sideways and passes axe`, {
        timeout: 120_000,
      }, async () => {
        await page().locator("#language-switch").selectOption(language.lang);
        // The switch takes effect on the next render, which sets lang too: the walk starts from there.
        await expect.poll(() => pageLang(page())).toBe(language.lang);
        await page().setViewportSize({ ...size });
        const report: string[] = [];
        for (const view of VIEWS) {
          await openView(page(), view);
          await expect.poll(() => pageLang(page()), { message: view }).toBe(language.lang);
          // The view speaks the page's language: its heading has Hangul in Korean, none in English.
          const title = await page().evaluate(() => document.querySelector("main h1")?.textContent ?? "");
          expect(/[가-힣]/.test(title), `${view}: "${title}"`).toBe(language.lang === "ko");
          for (const p of await pageProblems(page())) report.push(`${view}: ${p}`);
        }
        expect(report, report.join("\n")).toEqual([]);
      });
    }
  }
});
