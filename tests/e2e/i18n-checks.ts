/**
 * The checks every page of the panel gets in both languages (issue #14, "Done when"), once for all the browser
 * tests: the feature files' "in Korean (ko-KR)" blocks, `i18n.test.ts` and `i18n-every-view.test.ts`. The page's `lang`, no catalogue key shown in place of its text, no label wider than
 * its button, nothing that scrolls sideways, no axe violation (nor an unreviewed "needs review"), and
 * screenshots on demand (`RBC_SHOTS=<dir>`). Also the pages themselves: a browser in a given language at a
 * given size, connected to the fake robot on a cable or to the demo robot.
 */
import { readdirSync, readFileSync, statSync } from "node:fs";
import { mkdir } from "node:fs/promises";
import { createRequire } from "node:module";
import { join, resolve } from "node:path";
import type { Locator, Page } from "playwright-core";
import { expect } from "vitest";
import { type AppHarness, ROOT, squash, type TestContext } from "./harness.ts";
import type { RbcTestOptions } from "./rbc-test-globals.ts";

/** A browser window's size in CSS pixels. */
export interface Size {
  readonly width: number;
  readonly height: number;
}

/** The two sizes the issue asks for: a laptop and a phone. */
export const DESKTOP: Size = { width: 1280, height: 800 };
export const PHONE: Size = { width: 390, height: 844 };
export const SIZES: readonly Size[] = [DESKTOP, PHONE];

/** A size as it goes into a file name: "1280x800". */
export const sizeName = (size: Size) => `${size.width}x${size.height}`;

/** The page's language, as the panel set it on `<html lang>`. */
export const pageLang = (page: Page) => page.evaluate(() => document.documentElement.lang);

/** An element's text with runs of white space collapsed (templates indent their text). */
export const text = async (locator: Locator) => squash(await locator.textContent());

/** The texts of every element a locator matches, each with its white space collapsed. */
export const texts = async (locator: Locator) => (await locator.allTextContents()).map(squash);

/**
 * Opens the panel in a browser whose language is `locale` (`navigator.languages`, Accept-Language), at `size`
 * (1280×800 by default), with the fake serial port (`options`) or, with `noSerial`, without Web Serial, at
 * `hash` (e.g. "#/firmware"). The page is the harness's: the panel's Content Security Policy stays in force,
 * and axe is added through DevTools (`axeProblems`), which that policy does not govern.
 */
export async function newLocalePage(
  app: AppHarness,
  locale: string,
  setup: { size?: Size; options?: RbcTestOptions; noSerial?: boolean; hash?: string } = {},
): Promise<{ context: TestContext; page: Page }> {
  const { context, page } = await app.newPage({
    locale,
    viewport: { ...(setup.size ?? DESKTOP) },
    ...(setup.options ? { options: setup.options } : {}),
    ...(setup.noSerial ? { noSerial: true } : {}),
  });
  await page.goto(`${app.url}${setup.hash ?? ""}`, { waitUntil: "domcontentloaded" });
  return { context, page };
}

/**
 * Connects the fake robot on a cable from the start card's main button (whatever its language), and waits
 * until the Robot view has read the memory figures.
 */
export async function connectCable(page: Page): Promise<void> {
  await page.getByTestId("connect-card").locator(".actions .btn--primary").click();
  await page.getByTestId("device-card").waitFor();
  await page.getByTestId("memory-action-note").filter({ hasText: /8,192/ }).waitFor();
}

/** Connects the demo robot from the start card's second button (whatever its language). */
export async function connectDemo(page: Page): Promise<void> {
  await page.getByTestId("connect-card").locator(".actions .btn").nth(1).click();
  await page.getByTestId("device-card").waitFor();
}

/** What carries a label that must fit: buttons and what looks or acts like one, tabs, links, selects. */
export const LABELLED = "button, [role=button], [role=tab], .btn, .side-nav a, select, .skip-link, summary";

/**
 * The visible elements with a label (`LABELLED`) in `within` (the whole page by default) whose label is wider
 * than they are, as "label (scroll width > client width)". No pixel of slack.
 */
export async function overflowing(page: Page, within = "body"): Promise<string[]> {
  return page.evaluate(
    ([root, selector]) =>
      Array.from(document.querySelector(root)?.querySelectorAll<HTMLElement>(selector) ?? [])
        .filter((b) => b.offsetParent !== null && b.scrollWidth > b.clientWidth)
        .map(
          (b) => `${(b.textContent ?? "").replace(/\s+/g, " ").trim()} (${b.scrollWidth} > ${b.clientWidth})`,
        ),
    [within, LABELLED] as const,
  );
}

/**
 * Whether the page scrolls sideways (wider than its window, scroll bar excluded): none, or one line that
 * names the widths and the first elements sticking out.
 */
export async function scrollsSideways(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const root = document.documentElement;
    if (root.scrollWidth <= root.clientWidth) return [];
    const out = Array.from(document.querySelectorAll<HTMLElement>("body *"))
      .filter((e) => e.getBoundingClientRect().right > root.clientWidth + 0.5)
      .slice(0, 8)
      .map((e) => `${e.tagName.toLowerCase()}.${e.className} ${Math.round(e.getBoundingClientRect().right)}`);
    return [`${root.scrollWidth} > ${root.clientWidth}: ${out.join("; ")}`];
  });
}

/** Every file named messages.ts under `dir`: the catalogues (docs/i18n.md). */
function catalogueFiles(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return catalogueFiles(path);
    return name === "messages.ts" ? [path] : [];
  });
}

/** A catalogue entry: a text in each language. */
const isMessage = (value: unknown) =>
  typeof value === "object" && value !== null && "en" in value && "ko" in value;

let allKeys: Promise<readonly string[]> | undefined;

/**
 * Every key of every catalogue of the project (each `messages.ts` under src/, the panel's and the command
 * line's), found by reading the folders, so a new catalogue is checked without a test naming it.
 */
export function allCatalogueKeys(): Promise<readonly string[]> {
  allKeys ??= (async () => {
    const keys = new Set<string>();
    for (const file of catalogueFiles(join(ROOT, "src"))) {
      const module = (await import(file)) as Record<string, unknown>;
      for (const value of Object.values(module)) {
        if (typeof value !== "object" || value === null) continue;
        for (const [key, message] of Object.entries(value)) if (isMessage(message)) keys.add(key);
      }
    }
    if (keys.size === 0) throw new Error(`no catalogue found under ${join(ROOT, "src")}`);
    return [...keys];
  })();
  return allKeys;
}

/**
 * The catalogue keys (`keys`, every key of the project by default) that the page shows in place of their text:
 * in its title, its text, or a label, title, placeholder, value text or prefix of any element.
 */
export async function keysShown(page: Page, keys?: readonly string[]): Promise<string[]> {
  const shown = await page.evaluate(() => {
    const attributes = ["aria-label", "title", "placeholder", "aria-valuetext", "data-prefix"];
    const selector = attributes.map((a) => `[${a}]`).join(", ");
    return [
      document.title,
      document.body.textContent ?? "",
      ...Array.from(document.querySelectorAll(selector)).map((e) =>
        attributes.map((a) => e.getAttribute(a) ?? "").join(" "),
      ),
    ].join("\n");
  });
  return (keys ?? (await allCatalogueKeys())).filter((key) => shown.includes(key));
}

const AXE_SOURCE = readFileSync(createRequire(import.meta.url).resolve("axe-core/axe.min.js"), "utf8");

/**
 * axe's "needs review" results that are accepted, each with the reason (as in a11y.test.ts). Every other one
 * fails like a violation: axe reports `aria-label` on a plain span as needing review, not as a violation.
 */
export const REVIEWED: Readonly<Record<string, string>> = {
  "color-contrast":
    "axe cannot measure text it cannot see the background of (aria-hidden icons, text over other elements); " +
    "the colour tokens are chosen for 4.5:1, and the chart lines are measured in sensors.test.ts",
};

interface AxeResult {
  id: string;
  impact: string | null;
  help: string;
  nodes: { target: unknown[]; failureSummary?: string }[];
}

/**
 * axe-core on the page (or only on `within`, a selector): one line per violation and per "needs review" not in
 * `reviewed` (`REVIEWED` by default), as "rule (impact): help — element summary, …". axe is added through
 * DevTools, so it runs on pages that keep the panel's CSP.
 */
export async function axeProblems(
  page: Page,
  { within, reviewed = REVIEWED }: { within?: string; reviewed?: Readonly<Record<string, string>> } = {},
): Promise<string[]> {
  if (!(await page.evaluate(() => "axe" in window))) await page.evaluate(AXE_SOURCE);
  const found = await page.evaluate(async (include) => {
    type Run = (context: unknown, o: unknown) => Promise<{ violations: unknown[]; incomplete: unknown[] }>;
    const axe = (window as unknown as { axe: { run: Run } }).axe;
    const result = await axe.run(include ? { include: [include] } : document, {
      resultTypes: ["violations", "incomplete"],
    });
    return { violations: result.violations, incomplete: result.incomplete };
  }, within ?? null);
  const line = (v: AxeResult, kind: string) =>
    `${v.id} (${v.impact ?? "?"}${kind}): ${v.help} — ${v.nodes.map((n) => `${JSON.stringify(n.target)} ${(n.failureSummary ?? "").replace(/\s+/g, " ")}`).join(", ")}`;
  return [
    ...(found.violations as AxeResult[]).map((v) => line(v, "")),
    ...(found.incomplete as AxeResult[])
      .filter((v) => !(v.id in reviewed))
      .map((v) => line(v, ", needs review")),
  ];
}

/**
 * A screenshot for people to look at (never compared), written only when `RBC_SHOTS` names a folder (relative
 * to the repository): `<name>.png` there, of the whole page, or of one element for a locator.
 */
export async function shot(target: Page | Locator, name: string, { fullPage = true } = {}): Promise<void> {
  const folder = process.env.RBC_SHOTS;
  if (!folder) return;
  const dir = resolve(ROOT, folder);
  await mkdir(dir, { recursive: true });
  const path = join(dir, `${name}.png`);
  if ("goto" in target) await target.screenshot({ path, fullPage });
  else await target.screenshot({ path });
}

/** What `pageProblems` checks beyond keys, labels and sideways scrolling. */
export interface PageCheck {
  /** The page's expected `lang` ("ko", "en"). */
  lang?: string;
  /** Run axe too (default true). */
  axe?: boolean;
  /** Check labels and axe only inside this element (a selector); keys and scrolling are the whole page's. */
  within?: string;
}

/**
 * Everything wrong with the page as shown, one line each: its `lang`, catalogue keys shown, labels wider than
 * their buttons, sideways scrolling, and (unless `axe: false`) axe's violations and unreviewed "needs review".
 */
export async function pageProblems(page: Page, check: PageCheck = {}): Promise<string[]> {
  const out: string[] = [];
  if (check.lang !== undefined) {
    const lang = await pageLang(page);
    if (lang !== check.lang) out.push(`lang is "${lang}", not "${check.lang}"`);
  }
  for (const key of await keysShown(page)) out.push(`key shown: ${key}`);
  for (const label of await overflowing(page, check.within)) out.push(`label overflows: ${label}`);
  for (const line of await scrollsSideways(page)) out.push(`scrolls sideways: ${line}`);
  if (check.axe ?? true) for (const line of await axeProblems(page, check)) out.push(`axe: ${line}`);
  return out;
}

/**
 * Fails, listing them all, if `pageProblems` finds anything on the page at `where`; first takes the screenshot
 * `shot` (with `RBC_SHOTS`), so that a failure can be looked at.
 */
export async function expectPageOk(page: Page, where: string, check: PageCheck & { shot?: string } = {}) {
  if (check.shot) await shot(page, check.shot);
  const found = await pageProblems(page, check);
  expect(found, `${found.length} problem(s) on ${where}:\n${found.join("\n")}\n`).toEqual([]);
}

/**
 * The window at `size` on the page as it is (`setViewportSize`), once the panel has drawn at that size (two
 * animation frames: resize listeners run before the first). The Korean/size tables switch sizes this way on one
 * page instead of opening a page per size.
 */
export async function resizeTo(page: Page, size: Size): Promise<void> {
  await page.setViewportSize({ ...size });
  await page.evaluate(
    () => new Promise<void>((r) => requestAnimationFrame(() => requestAnimationFrame(() => r()))),
  );
}

/**
 * `expectPageOk` at each of `sizes` (1280×800 and 390×844 by default) on the same page, the window resized for
 * each (`resizeTo`) and put back to the size it had afterwards. `where` and the screenshot's name (`shot`, given
 * the size) name the size; `ready` runs after each resize, before the checks (e.g. scrolls a card into view, takes
 * close-ups).
 */
export async function expectPageOkAtSizes(
  page: Page,
  where: string,
  check: PageCheck & { shot?: (size: Size) => string; ready?: (size: Size) => Promise<unknown> } = {},
  sizes: readonly Size[] = SIZES,
): Promise<void> {
  const before = page.viewportSize();
  const { shot: shotName, ready, ...rest } = check;
  for (const size of sizes) {
    await resizeTo(page, size);
    await ready?.(size);
    await expectPageOk(page, `${where} at ${size.width}×${size.height}`, {
      ...rest,
      ...(shotName ? { shot: shotName(size) } : {}),
    });
  }
  if (before) await resizeTo(page, before);
}
