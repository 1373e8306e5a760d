import { readFileSync } from "node:fs";
import { createRequire } from "node:module";
import { describe, expect, it } from "vitest";
import { CABLE, loadConnected } from "./connected-page.ts";
import { cspViolations, expectText, FAST, squash, useApp, watchPage } from "./harness.ts";
import "./rbc-test-globals.ts";
import type { Page } from "playwright-core";
import {
  connectCable,
  expectPageOkAtSizes,
  keysShown,
  pageLang as lang,
  newLocalePage,
  PHONE,
  sizeName as size,
} from "./i18n-checks.ts";

/** The packet log view: coalesced garbage, raw bytes, and a scroll area the keyboard can reach (issue #11 item 11). */

const app = useApp();

const AXE_SOURCE = readFileSync(createRequire(import.meta.url).resolve("axe-core/axe.min.js"), "utf8");

describe("packet log view", () => {
  it("shows a run of garbage as one row with its byte count, and its scroll area is focusable and named", async () => {
    // A short window, so that the log's rows overflow its scroll area.
    const { page, context } = await app.newPage({
      start: CABLE,
      options: FAST,
      viewport: { width: 1280, height: 600 },
    });
    const seen = watchPage(page, app.origin);
    await loadConnected(page, app.url);
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    // 3,000 stray bytes and a frame too long for its type arrive before the next reply.
    await page.evaluate(() => {
      const stray = Array.from({ length: 3000 }, (_, i) => (i * 13 + 1) & 0x7f);
      const oversize = [0xff, 0xff, 0xaa, 0x55, 0xaa, 0x55, 0x37, 0xba, 0x11, 0x01, 0x00, 0x00, 0x0f, 0x00];
      window.__rbcTest?.port.faults.garbageBeforeReply([...stray, ...oversize, 0, 0]);
    });
    for (let i = 0; i < 4; i++) {
      await page.getByRole("button", { name: "Refresh" }).click();
      await page.getByRole("button", { name: "Refresh" }).waitFor();
    }
    await page.getByRole("link", { name: "Log" }).click();
    const log = page.getByTestId("log-card");
    const discards = log.locator("tr.log-discard");
    await discards.first().waitFor();
    await expect.poll(() => discards.count()).toBe(1);
    await expectText(discards.first(), "(3,016 bytes)", { contains: true });
    await expectText(discards.first(), "1 frame too long for its type, stray bytes", { contains: true });
    await expectText(discards.first(), "01 0E 1B 28", { contains: true }); // the first stray bytes as they arrived
    await expectText(log, "FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01", { contains: true });

    // The scroll area is a named region in the tab order, and the keyboard scrolls it.
    const region = page.getByRole("region", { name: "Packets, newest first" });
    await expect.poll(() => region.getAttribute("tabindex")).toBe("0");
    await region.focus();
    await expect
      .poll(() => page.evaluate(() => document.activeElement?.getAttribute("data-testid")))
      .toBe("log-scroll");
    await expect.poll(() => region.evaluate((el) => el.scrollHeight > el.clientHeight)).toBe(true);
    await page.keyboard.press("End");
    await expect.poll(() => region.evaluate((el) => el.scrollTop)).toBeGreaterThan(0);

    await page.evaluate(AXE_SOURCE);
    const violations = await page.evaluate(async () => {
      const axe = (
        window as unknown as { axe: { run(el: Element): Promise<{ violations: { id: string }[] }> } }
      ).axe;
      const card = document.querySelector('[data-testid="log-card"]');
      if (!card) return ["no log card"];
      return (await axe.run(card)).violations.map((v) => v.id);
    });
    expect(violations).toEqual([]);

    expect(seen.errors).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("pauses without losing capture, pages back through older rows, and copies the whole log", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await loadConnected(page, app.url);
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    await page.getByRole("link", { name: "Log" }).click();
    const log = page.getByTestId("log-card");
    await log.locator("tbody tr").first().waitFor();
    const rows = () => log.locator("tbody tr").count();
    const entries = async () =>
      Number(squash(await log.getByTestId("log-count").textContent()).split(" ")[0]);
    const before = await rows();
    const total = await entries();
    await page.getByRole("button", { name: "Pause" }).click();
    await log.getByText("Paused:").waitFor();
    await page.getByRole("link", { name: "Robot" }).click();
    for (let i = 0; i < 20; i++) {
      await page.getByRole("button", { name: "Refresh" }).click();
      await page.getByRole("button", { name: "Refresh" }).waitFor();
    }
    await page.getByRole("link", { name: "Log" }).click();
    await expect.poll(entries).toBeGreaterThan(total + 100);
    expect(await rows()).toBe(before);

    await page.getByRole("button", { name: "Resume" }).click();
    await expect.poll(rows).toBe(100);
    const all = await entries();
    await expectText(log.getByTestId("log-page"), `Rows 1–100 of ${all}, newest first`);
    const newestTime = await log.locator("tbody tr").first().locator(".log-time").textContent();
    await page.getByRole("button", { name: "Older" }).click();
    await expectText(log.getByTestId("log-page"), `Rows 101–${Math.min(200, all)} of ${all}, newest first`);
    await page.getByRole("button", { name: "Newer" }).click();
    await expect
      .poll(() => log.locator("tbody tr").first().locator(".log-time").textContent())
      .toBe(newestTime);

    await context.grantPermissions(["clipboard-read", "clipboard-write"], { origin: app.origin });
    await page.getByRole("button", { name: "Copy" }).click();
    await page.getByText(`Copied ${all} lines to the clipboard.`).waitFor();
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    expect(copied.trim().split("\n")).toHaveLength(all + 1);
    expect(copied).toContain(
      "PC → RBC  Read firmware version (16 bytes)  FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01",
    );
    await context.close();
  });
});

/**
 * The Zeros and Log views in Korean (issue #14 item 1): a Korean browser gets both views in Korean with
 * `lang="ko"`, their sentences from the actions too (write, backup files, copy); no catalogue key shows; no
 * button's label overflows it and nothing scrolls sideways at 1280×800 and 390×844; axe finds no violation.
 * With RBC_SHOTS=<dir>, screenshots of both views at both sizes go there to be looked at.
 */
describe("in Korean (ko-KR)", () => {
  /** Adds packets to the log: every "다시 읽기" on the Robot view reads the robot's details again. */
  async function refreshTimes(page: Page, times: number): Promise<void> {
    const refresh = page.getByTestId("device-card").getByRole("button", { name: "다시 읽기" });
    for (let i = 0; i < times; i++) {
      await refresh.click();
      await refresh.waitFor();
    }
  }

  const entries = async (page: Page) =>
    Number(
      squash(await page.getByTestId("log-count").textContent())
        .match(/^항목 ([\d,]+)개/)?.[1]
        ?.replace(/,/g, ""),
    );

  describe("the Log view in Korean", () => {
    it("says in Korean that there is nothing yet, before a robot is connected", async () => {
      const { page, context } = await newLocalePage(app, "ko-KR");
      await page.getByRole("link", { name: "로그", exact: true }).click();
      const card = page.getByTestId("log-card");
      await card.waitFor();
      await expectText(card.getByRole("heading", { level: 1 }), "패킷 로그");
      await expectText(
        card.locator(".empty"),
        "아직 패킷이 없어요. 로봇(또는 데모 로봇)을 연결하면 주고받는 모든 패킷이 여기에 나와요.",
      );
      await expectText(
        page.getByTestId("log-count"),
        "항목 0개 (최근 항목 5,000개까지, 바이트는 최대 1,024KB까지 보관해요). 연달아 버린 바이트는 한 항목으로 묶어요.",
      );
      await expect.poll(() => card.getByRole("button", { name: "지우기" }).isDisabled()).toBe(true);
      await context.close();
    });

    // One page for both sizes: the flow once at 390×844, each page check at 1280×800 and at 390×844 (`expectPageOkAtSizes`).
    it("is in Korean, fits and passes axe at 1280×800 and at 390×844", async () => {
      const { page, context } = await newLocalePage(app, "ko-KR", { size: PHONE, options: FAST });
      await connectCable(page);
      // Stray bytes and a frame too long for its type before the next reply: one row of discarded bytes.
      await page.evaluate(() => {
        const stray = Array.from({ length: 3000 }, (_, i) => (i * 13 + 1) & 0x7f);
        const oversize = [0xff, 0xff, 0xaa, 0x55, 0xaa, 0x55, 0x37, 0xba, 0x11, 0x01, 0x00, 0x00, 0x0f, 0x00];
        window.__rbcTest?.port.faults.garbageBeforeReply([...stray, ...oversize, 0, 0]);
      });
      await refreshTimes(page, 20);
      await page.getByRole("link", { name: "로그", exact: true }).click();
      const card = page.getByTestId("log-card");
      await card.locator("tbody tr").first().waitFor();
      await expect.poll(() => lang(page)).toBe("ko");

      await expectText(card.getByRole("heading", { level: 1 }), "패킷 로그");
      for (const name of ["일시 정지", "지우기", "복사", "다운로드 (.txt)"]) {
        await card.getByRole("button", { name, exact: true }).waitFor();
      }
      await expect
        .poll(() => card.locator("thead th").allTextContents())
        .toEqual(["시간", "방향", "종류", "바이트 (16진수)"]);
      await expect.poll(() => entries(page)).toBeGreaterThan(100);
      const total = await entries(page);
      await expectText(
        page.getByTestId("log-count"),
        `항목 ${total.toLocaleString("ko")}개 (최근 항목 5,000개까지, 바이트는 최대 1,024KB까지 보관해요). 연달아 버린 바이트는 한 항목으로 묶어요. 한 쪽에 100개씩 보여요. '복사'와 '다운로드'는 전체를 가져가요.`,
      );
      await expectText(page.getByTestId("log-page"), `${total.toLocaleString("ko")}개 중 1–100번째 (최신순)`);
      const pages = page.getByRole("navigation", { name: "로그 쪽" });
      await pages.getByRole("button", { name: "더 최근" }).waitFor();
      await pages.getByRole("button", { name: "더 이전" }).waitFor();
      await page.getByRole("region", { name: "패킷 (최신순)" }).waitFor();

      // The view's words are Korean, the packets' names too (issue 33); the copied log stays English.
      const directions = async () =>
        new Set((await card.locator("tbody .log-dir").allTextContents()).map(squash));
      await expect.poll(directions).toEqual(new Set(["→ 보냄", "← 받음"]));
      const named = card.locator("tbody tr.log-packet .log-name").first();
      await expectText(named, /^[가-힣 ]+$/);
      expect(await card.locator("tbody tr.log-packet .log-name span[lang='en']").count()).toBe(0);
      await expectPageOkAtSizes(page, "the Log view", { shot: (viewport) => `log-ko-${size(viewport)}` });

      // The run of discarded bytes is on an older page.
      await pages.getByRole("button", { name: "더 이전" }).click();
      const discard = card.locator("tr.log-discard");
      await discard.first().waitFor();
      await expectText(discard.first(), "버린 바이트 종류에 비해 너무 긴 프레임 1개, 프레임이 아닌 바이트", {
        contains: true,
      });
      await expectText(discard.first(), "(3,016바이트)", { contains: true });
      await expectText(discard.first(), "01 0E 1B 28", { contains: true });

      // Paused: the button says what it will do, and the line says what happens meanwhile.
      await card.getByRole("button", { name: "일시 정지", exact: true }).click();
      const resume = card.getByRole("button", { name: "계속", exact: true });
      await resume.waitFor();
      await expect.poll(() => resume.getAttribute("aria-pressed")).toBe("true");
      await expectText(
        page.getByTestId("log-count"),
        /일시 정지됨: 새 패킷은 계속 기록하지만 화면에는 보여 주지 않아요\.$/,
      );
      await expectPageOkAtSizes(page, "the Log view, paused", { axe: false });
      await context.close();
    });

    it("says in Korean what Copy did; the copied log stays a packet trace in English", async () => {
      const { page, context } = await newLocalePage(app, "ko-KR", { options: FAST });
      await connectCable(page);
      await page.getByRole("link", { name: "로그", exact: true }).click();
      const card = page.getByTestId("log-card");
      await card.locator("tbody tr").first().waitFor();
      const total = await entries(page);
      await context.grantPermissions(["clipboard-read", "clipboard-write"], { origin: app.origin });
      await card.getByRole("button", { name: "복사", exact: true }).click();
      await page.getByText(`${total}줄을 클립보드에 복사했어요.`).waitFor();
      const copied = await page.evaluate(() => navigator.clipboard.readText());
      expect(copied).toMatch(/^RBC Panel packet log, /);
      expect(copied).toContain(
        "PC → RBC  Read firmware version (16 bytes)  FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01",
      );
      expect(await keysShown(page)).toEqual([]);
      await context.close();
    });
  });
});
