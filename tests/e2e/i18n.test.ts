/**
 * The panel in Korean and English (issue #14 item 1): a browser set to Korean gets the panel in Korean with
 * `lang="ko"`; the language switch changes it and the choice survives a reload; no label overflows its button
 * at 1280×800 and 390×844 in either language; no catalogue key shows instead of its text; axe finds nothing in
 * either language. Covers the shell and the Robot view (the other views follow as they are translated).
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { expectText, useApp } from "./harness.ts";
import {
  axeProblems,
  connectCable,
  DESKTOP,
  expectPageOk,
  keysShown,
  pageLang as lang,
  newLocalePage,
  SIZES,
} from "./i18n-checks.ts";
import "./rbc-test-globals.ts";

const app = useApp();

const navLabels = (page: Page) =>
  page.locator(".side-nav a").evaluateAll((links) => links.map((a) => (a.textContent ?? "").trim()));

describe("the panel in Korean", () => {
  it("follows a Korean browser: lang, navigation, title, footer and the Robot view", async () => {
    const { page, context } = await newLocalePage(app, "ko-KR");
    await page.getByTestId("connect-card").waitFor();
    await expect.poll(() => lang(page)).toBe("ko");
    await expect
      .poll(() => navLabels(page))
      .toEqual(["로봇", "영점", "모션", "편집기", "센서", "서보", "서보 점검", "펌웨어", "로그", "교실"]);
    await expect.poll(() => page.getByRole("navigation", { name: "화면" }).isVisible()).toBe(true);
    await expect.poll(() => page.title()).toBe("로봇 · RBC 패널");
    await expectText(page.getByTestId("panel-version"), /^RBC 패널 · 버전 \d+\.\d+\.\d+/);
    await expect.poll(() => page.getByLabel("언어 / Language").inputValue()).toBe("ko");

    await connectCable(page);
    const card = page.getByTestId("device-card");
    await expectText(card.getByRole("heading", { level: 1 }), "로봇");
    await card.getByRole("button", { name: "다시 읽기" }).waitFor();
    await card.getByRole("button", { name: "연결 끊기" }).waitFor();
    await expect
      .poll(() => card.locator("dt").allTextContents())
      .toEqual(["연결된 로봇", "펌웨어", "시리얼 번호", "플랫폼", "오류 코드"]);
    await expectText(page.getByTestId("error-code"), "오류 없음");
    await expectText(page.getByTestId("memory-motion-text"), "24,576바이트 중 0바이트 사용");
    await expectText(page.getByTestId("memory-action-note"), "저장된 것이 없어요 (8,192바이트 남음).");
    await expectText(card.getByText(/에 로봇에서 읽었어요\.$/), /^\d\d:\d\d:\d\d에 로봇에서 읽었어요\.$/);
    await expectText(card.getByRole("heading", { level: 2 }), "로봇의 메모리");
    expect(await keysShown(page)).toEqual([]);
    await context.close();
  });

  it("switches to English and back, sets lang, and remembers the choice across a reload", async () => {
    const { page, context } = await newLocalePage(app, "ko-KR");
    await connectCable(page);

    await page.getByLabel("언어 / Language").selectOption("en");
    await expect.poll(() => lang(page)).toBe("en");
    await expect
      .poll(() => navLabels(page))
      .toEqual([
        "Robot",
        "Zeros",
        "Motions",
        "Editor",
        "Sensors",
        "Servos",
        "Servo check",
        "Firmware",
        "Log",
        "Class",
      ]);
    await expectText(page.getByTestId("device-card").getByRole("heading", { level: 1 }), "Robot");
    await expectText(page.getByTestId("memory-motion-text"), "0 of 24,576 bytes used");
    await expectText(page.getByTestId("error-code"), "No error");
    await expect.poll(() => page.title()).toBe("Robot · RBC Panel");
    expect(await keysShown(page)).toEqual([]);

    // The choice is kept: a Korean browser, but English after a reload.
    await page.reload({ waitUntil: "domcontentloaded" });
    await page.getByTestId("connect-card").waitFor();
    await expect.poll(() => lang(page)).toBe("en");
    await expect.poll(async () => (await navLabels(page))[0]).toBe("Robot");

    // And back to Korean from the focused switch.
    const select = page.getByLabel("Language / 언어");
    await select.focus();
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("language-switch");
    await select.selectOption("ko");
    await expect.poll(() => lang(page)).toBe("ko");
    await expect.poll(async () => (await navLabels(page))[0]).toBe("로봇");
    await page.reload({ waitUntil: "domcontentloaded" });
    await page.getByTestId("connect-card").waitFor();
    await expect.poll(() => lang(page)).toBe("ko");
    expect(await page.evaluate(() => localStorage.getItem("rbc-panel-locale"))).toBe("ko");
    await context.close();
  });

  it("is reached with Tab from the navigation", async () => {
    const { page, context } = await newLocalePage(app, "en-US");
    await page.getByTestId("connect-card").waitFor();
    await expect.poll(() => lang(page)).toBe("en");
    await page.locator(".side-nav a").last().focus();
    await page.keyboard.press("Tab");
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("language-switch");
    await context.close();
  });
});

describe("layout and accessibility in both languages", () => {
  // One page per language: the start card, then the Robot view, each at both sizes (setViewportSize) and with axe
  // (once six tests, a page each: "no label overflows and nothing scrolls sideways, <locale> at 1280×800" and
  // "… at 390×844", and "axe finds no violation on the start card and the Robot view, <locale>").
  for (const locale of ["ko-KR", "en-US"]) {
    it(`no label overflows, nothing scrolls sideways at ${SIZES.map((s) => `${s.width}×${s.height}`).join(" and ")}, and axe finds no violation, on the start card and the Robot view, ${locale}`, async () => {
      const { page, context } = await newLocalePage(app, locale);
      const check = { lang: locale.slice(0, 2), axe: false };
      await page.getByTestId("connect-card").waitFor();
      for (const size of SIZES) {
        await page.setViewportSize({ ...size });
        await expectPageOk(page, `the start card at ${size.width}×${size.height}`, check);
      }
      await page.setViewportSize({ ...DESKTOP });
      expect(await axeProblems(page), "the start card").toEqual([]);
      await connectCable(page);
      for (const size of SIZES) {
        await page.setViewportSize({ ...size });
        await expectPageOk(page, `the Robot view at ${size.width}×${size.height}`, check);
      }
      await page.setViewportSize({ ...DESKTOP });
      expect(await axeProblems(page), "the Robot view").toEqual([]);
      await context.close();
    });
  }
});
