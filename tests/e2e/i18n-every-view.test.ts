/**
 * Every view in both languages at both sizes (issue #14, "Done when"): with the demo robot connected, each view
 * of the side navigation is opened in English and in Korean, at 1280×800 and at 390×844, and checked for the
 * page's `lang`, no catalogue key shown in place of its text, no label wider than its button, nothing that
 * scrolls sideways, and no axe violation. The feature files (`i18n-*.test.ts`) check each view's own states and
 * Korean sentences; this one makes sure no view is left out.
 */
import { readdirSync, statSync } from "node:fs";
import { createRequire } from "node:module";
import { join } from "node:path";
import type { BrowserContext, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { type AppHarness, buildOnce, ROOT, startHarness } from "./harness.ts";
import "./rbc-test-globals.ts";

const require = createRequire(import.meta.url);
const AXE_PATH = require.resolve("axe-core/axe.min.js");

const SIZES = [
  { width: 1280, height: 800 },
  { width: 390, height: 844 },
] as const;
const LANGUAGES = [
  { locale: "en-US", lang: "en", demo: "Try the demo robot" },
  { locale: "ko-KR", lang: "ko", demo: "데모 로봇 써 보기" },
] as const;
/** The side navigation's views, by route. */
const VIEWS = ["robot", "zeros", "motions", "editor", "sensors", "servos", "firmware", "log"] as const;

/** Every file named messages.ts under src/: the catalogues (docs/i18n.md). */
function catalogueFiles(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return catalogueFiles(path);
    return name === "messages.ts" ? [path] : [];
  });
}

let app: AppHarness;
let fakeSerial: string;
/** Every key of every catalogue: none may show on a page in place of its text. */
let keys: string[] = [];

beforeAll(async () => {
  app = await startHarness();
  ({ fakeSerial } = await buildOnce());
  for (const file of catalogueFiles(join(ROOT, "src"))) {
    const module = (await import(file)) as Record<string, unknown>;
    for (const value of Object.values(module)) {
      if (value && typeof value === "object") keys.push(...Object.keys(value));
    }
  }
  keys = [...new Set(keys)].filter((k) => k.includes("."));
});

afterAll(async () => {
  await app?.close();
});

async function newPage(
  locale: string,
  viewport: { width: number; height: number },
): Promise<{ context: BrowserContext; page: Page }> {
  const context = await app.browser.newContext({
    locale,
    viewport,
    serviceWorkers: "block",
    reducedMotion: "reduce",
    // axe is added as a script, which the panel's CSP rightly refuses.
    bypassCSP: true,
  });
  await context.addInitScript({ content: `window.__rbcTestOptions = {};\n;\n${fakeSerial}` });
  return { context, page: await context.newPage() };
}

/** What is wrong with the page as shown: keys as text, labels wider than their buttons, sideways scrolling. */
async function problems(page: Page): Promise<string[]> {
  const found = await page.evaluate((keyList) => {
    const out: string[] = [];
    const text = [
      document.title,
      document.body.textContent ?? "",
      ...Array.from(document.querySelectorAll("[aria-label], [title], [placeholder]")).map(
        (e) =>
          `${e.getAttribute("aria-label") ?? ""} ${e.getAttribute("title") ?? ""} ${e.getAttribute("placeholder") ?? ""}`,
      ),
    ].join("\n");
    for (const key of keyList)
      if (new RegExp(`(^|[^\\w.])${key.replace(/\./g, "\\.")}($|[^\\w.])`).test(text))
        out.push(`key shown: ${key}`);
    for (const b of Array.from(
      document.querySelectorAll<HTMLElement>("button, .btn, .side-nav a, select, [role=tab]"),
    )) {
      if (b.offsetParent !== null && b.scrollWidth > b.clientWidth + 1) {
        out.push(
          `overflows: "${(b.textContent ?? "").replace(/\s+/g, " ").trim()}" (${b.scrollWidth} > ${b.clientWidth})`,
        );
      }
    }
    const root = document.documentElement;
    if (root.scrollWidth > root.clientWidth + 1)
      out.push(`scrolls sideways: ${root.scrollWidth} > ${root.clientWidth}`);
    return out;
  }, keys);
  return found;
}

async function axeViolations(page: Page): Promise<string[]> {
  if (!(await page.evaluate(() => "axe" in window))) await page.addScriptTag({ path: AXE_PATH });
  const found = await page.evaluate(async () => {
    type Run = (o: unknown) => Promise<{ violations: unknown[] }>;
    const axe = (window as unknown as { axe: { run: Run } }).axe;
    return (await axe.run({ resultTypes: ["violations"] })).violations as {
      id: string;
      help: string;
      nodes: { target: unknown[] }[];
    }[];
  });
  return found.map((v) => `${v.id}: ${v.help} — ${v.nodes.map((n) => JSON.stringify(n.target)).join(", ")}`);
}

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
        const { page, context } = await newPage(language.locale, size);
        try {
          await page.goto(app.url, { waitUntil: "domcontentloaded" });
          await page.getByRole("button", { name: language.demo }).first().click();
          await page.getByTestId("device-card").waitFor();
          const report: string[] = [];
          for (const view of VIEWS) {
            await openView(page, view);
            expect(await page.evaluate(() => document.documentElement.lang), view).toBe(language.lang);
            // The view speaks the page's language: its heading has Hangul in Korean, none in English.
            const title = await page.evaluate(() => document.querySelector("main h1")?.textContent ?? "");
            expect(/[가-힣]/.test(title), `${view}: "${title}"`).toBe(language.lang === "ko");
            for (const p of await problems(page)) report.push(`${view}: ${p}`);
            for (const v of await axeViolations(page)) report.push(`${view}: axe ${v}`);
          }
          expect(report, report.join("\n")).toEqual([]);
        } finally {
          await context.close();
        }
      });
    });
  }
}
