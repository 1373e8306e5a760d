/**
 * The panel in Korean and English (issue #14 item 1): a browser set to Korean gets the panel in Korean with
 * `lang="ko"`; the language switch changes it and the choice survives a reload; no label overflows its button
 * at 1280×800 and 390×844 in either language; no catalogue key shows instead of its text; axe finds nothing in
 * either language. Covers the shell and the Robot view (the other views follow as they are translated).
 */
import { createRequire } from "node:module";
import type { BrowserContext, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { unitMessages } from "../../src/i18n/messages.ts";
import { robotMessages } from "../../src/ui/features/robot/messages.ts";
import { uiMessages } from "../../src/ui/messages.ts";
import { shellMessages } from "../../src/ui/shell/messages.ts";
import { type AppHarness, buildOnce, squash, startHarness } from "./harness.ts";
import "./rbc-test-globals.ts";

const require = createRequire(import.meta.url);
const AXE_PATH = require.resolve("axe-core/axe.min.js");

const PHONE = { width: 390, height: 844 };
const DESKTOP = { width: 1280, height: 800 };

/** Every key of the catalogues these pages use: none may show on the page in place of its text. */
const KEYS = [shellMessages, robotMessages, uiMessages, unitMessages].flatMap((m) => Object.keys(m));

let app: AppHarness;
let fakeSerial: string;

beforeAll(async () => {
  app = await startHarness();
  ({ fakeSerial } = await buildOnce());
});

afterAll(async () => {
  await app?.close();
});

/**
 * A page whose browser prefers `locale` (navigator.languages), with the fake serial port. `bypassCSP` lets axe
 * be added as a script (the panel's CSP rightly refuses it).
 */
async function newLocalePage(
  locale: string,
  viewport = DESKTOP,
  bypassCSP = false,
): Promise<{ context: BrowserContext; page: Page }> {
  const context = await app.browser.newContext({
    locale,
    viewport,
    serviceWorkers: "block",
    reducedMotion: "reduce",
    bypassCSP,
  });
  await context.addInitScript({ content: `window.__rbcTestOptions = {};\n;\n${fakeSerial}` });
  const page = await context.newPage();
  return { context, page };
}

/** Connects the fake robot from the connect card (its main button, whatever its language). */
async function connect(page: Page): Promise<void> {
  await page.getByTestId("connect-card").locator(".btn--primary").click();
  await page.getByTestId("device-card").waitFor();
  // The memory figures have been read.
  await page.getByTestId("memory-action-note").filter({ hasText: /8,192/ }).waitFor();
}

const lang = (page: Page) => page.evaluate(() => document.documentElement.lang);
const navLabels = (page: Page) =>
  page.locator(".side-nav a").evaluateAll((links) => links.map((a) => (a.textContent ?? "").trim()));

/** Buttons, navigation links and selects whose label is wider than they are, as "label (scroll > client)". */
async function overflowing(page: Page): Promise<string[]> {
  return page.evaluate(() =>
    Array.from(document.querySelectorAll<HTMLElement>("button, .btn, .side-nav a, select, .skip-link"))
      .filter((b) => b.offsetParent !== null && b.scrollWidth > b.clientWidth)
      .map(
        (b) => `${(b.textContent ?? "").replace(/\s+/g, " ").trim()} (${b.scrollWidth} > ${b.clientWidth})`,
      ),
  );
}

/** Catalogue keys shown as text or in a label (a message the page could not find). */
async function keysShown(page: Page): Promise<string[]> {
  const text = await page.evaluate(() =>
    [
      document.title,
      document.body.textContent ?? "",
      ...Array.from(document.querySelectorAll("[aria-label], [title]")).map(
        (e) => `${e.getAttribute("aria-label") ?? ""} ${e.getAttribute("title") ?? ""}`,
      ),
    ].join("\n"),
  );
  return KEYS.filter((key) => text.includes(key));
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

describe("the panel in Korean", () => {
  it("follows a Korean browser: lang, navigation, title, footer and the Robot view", async () => {
    const { page, context } = await newLocalePage("ko-KR");
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByTestId("connect-card").waitFor();
    expect(await lang(page)).toBe("ko");
    expect(await navLabels(page)).toEqual([
      "로봇",
      "영점",
      "모션",
      "편집기",
      "센서",
      "서보",
      "펌웨어",
      "로그",
    ]);
    expect(await page.getByRole("navigation", { name: "화면" }).isVisible()).toBe(true);
    await expect.poll(() => page.title()).toBe("로봇 · RBC 패널");
    expect(squash(await page.getByTestId("panel-version").textContent())).toMatch(
      /^RBC 패널 · 버전 \d+\.\d+\.\d+/,
    );
    expect(await page.getByLabel("언어 / Language").inputValue()).toBe("ko");

    await connect(page);
    const card = page.getByTestId("device-card");
    expect(await card.getByRole("heading", { level: 1 }).textContent()).toBe("로봇");
    await card.getByRole("button", { name: "다시 읽기" }).waitFor();
    await card.getByRole("button", { name: "연결 끊기" }).waitFor();
    expect(await card.locator("dt").allTextContents()).toEqual([
      "연결된 로봇",
      "펌웨어",
      "시리얼 번호",
      "플랫폼",
      "오류 코드",
    ]);
    expect(squash(await page.getByTestId("error-code").textContent())).toBe("오류 없음 (0xFF)");
    expect(squash(await page.getByTestId("memory-motion-text").textContent())).toBe(
      "24,576바이트 중 0바이트 사용",
    );
    expect(squash(await page.getByTestId("memory-action-note").textContent())).toBe(
      "저장된 것이 없어요 (8,192바이트 남음).",
    );
    expect(squash(await card.getByText(/에 로봇에서 읽었어요\.$/).textContent())).toMatch(
      /^\d\d:\d\d:\d\d에 로봇에서 읽었어요\.$/,
    );
    expect(await card.getByRole("heading", { level: 2 }).textContent()).toBe("로봇의 메모리");
    expect(await keysShown(page)).toEqual([]);
    await context.close();
  });

  it("switches to English and back, sets lang, and remembers the choice across a reload", async () => {
    const { page, context } = await newLocalePage("ko-KR");
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await connect(page);

    await page.getByLabel("언어 / Language").selectOption("en");
    await expect.poll(() => lang(page)).toBe("en");
    expect(await navLabels(page)).toEqual([
      "Robot",
      "Zeros",
      "Motions",
      "Editor",
      "Sensors",
      "Servos",
      "Firmware",
      "Log",
    ]);
    expect(await page.getByTestId("device-card").getByRole("heading", { level: 1 }).textContent()).toBe(
      "Robot",
    );
    expect(squash(await page.getByTestId("memory-motion-text").textContent())).toBe("0 of 24,576 bytes used");
    expect(squash(await page.getByTestId("error-code").textContent())).toBe("No error (0xFF)");
    await expect.poll(() => page.title()).toBe("Robot · RBC Panel");
    expect(await keysShown(page)).toEqual([]);

    // The choice is kept: a Korean browser, but English after a reload.
    await page.reload({ waitUntil: "domcontentloaded" });
    await page.getByTestId("connect-card").waitFor();
    expect(await lang(page)).toBe("en");
    expect((await navLabels(page))[0]).toBe("Robot");

    // And back to Korean from the focused switch.
    const select = page.getByLabel("Language / 언어");
    await select.focus();
    expect(await page.evaluate(() => document.activeElement?.id)).toBe("language-switch");
    await select.selectOption("ko");
    await expect.poll(() => lang(page)).toBe("ko");
    expect((await navLabels(page))[0]).toBe("로봇");
    await page.reload({ waitUntil: "domcontentloaded" });
    await page.getByTestId("connect-card").waitFor();
    expect(await lang(page)).toBe("ko");
    expect(await page.evaluate(() => localStorage.getItem("rbc-panel-locale"))).toBe("ko");
    await context.close();
  });

  it("is reached with Tab from the navigation", async () => {
    const { page, context } = await newLocalePage("en-US");
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByTestId("connect-card").waitFor();
    expect(await lang(page)).toBe("en");
    await page.locator(".side-nav a").last().focus();
    await page.keyboard.press("Tab");
    expect(await page.evaluate(() => document.activeElement?.id)).toBe("language-switch");
    await context.close();
  });
});

describe("layout and accessibility in both languages", () => {
  for (const locale of ["ko-KR", "en-US"]) {
    for (const viewport of [DESKTOP, PHONE]) {
      it(`no label overflows and nothing scrolls sideways, ${locale} at ${viewport.width}×${viewport.height}`, async () => {
        const { page, context } = await newLocalePage(locale, viewport);
        await page.goto(app.url, { waitUntil: "domcontentloaded" });
        await page.getByTestId("connect-card").waitFor();
        expect(await overflowing(page), "the start card").toEqual([]);
        await connect(page);
        expect(await overflowing(page), "the Robot view").toEqual([]);
        expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(
          viewport.width,
        );
        expect(await keysShown(page)).toEqual([]);
        await context.close();
      });
    }

    it(`axe finds no violation on the start card and the Robot view, ${locale}`, async () => {
      const { page, context } = await newLocalePage(locale, DESKTOP, true);
      await page.goto(app.url, { waitUntil: "domcontentloaded" });
      await page.getByTestId("connect-card").waitFor();
      expect(await axeViolations(page), "the start card").toEqual([]);
      await connect(page);
      expect(await axeViolations(page), "the Robot view").toEqual([]);
      await context.close();
    });
  }
});
