import { mkdir } from "node:fs/promises";
import { join } from "node:path";
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { firmwareHex, firmwareHexWithBadChecksum } from "../support/hex.ts";
import { DEMO, loadConnected } from "./connected-page.ts";
import { expectText, ROOT, squash, useApp, watchPage } from "./harness.ts";
import "./rbc-test-globals.ts";
import { DESKTOP, expectPageOk, keysShown, pageLang as lang, newLocalePage, PHONE } from "./i18n-checks.ts";

/**
 * The Firmware view on the demo robot (its bootloader in front of the simulated RBC; the panel switches it off
 * and on itself): open the demo file or a .hex, see its summary, confirm, watch the progress in place, and see
 * the version the robot reports change; Cancel mid-way says what the robot holds. Robot time runs faster.
 */

const app = useApp();

/** Screenshots for people to look at (not compared): SCREENSHOTS=dir. */
const SHOTS = process.env.FIRMWARE_SCREENSHOTS;

async function shot(page: Page, name: string): Promise<void> {
  if (!SHOTS) return;
  const dir = join(ROOT, SHOTS);
  await mkdir(dir, { recursive: true });
  await page.screenshot({ path: join(dir, `${name}.png`), fullPage: true });
}

/** The Firmware view with the demo robot connected (a page opened with the start option `DEMO`). */
async function openFirmwareOnDemo(page: Page): Promise<void> {
  await loadConnected(page, app.url, "firmware");
  await page.getByTestId("firmware-view").waitFor();
}

describe("Firmware view on the demo robot", () => {
  for (const variant of [
    { name: "desktop-light", viewport: { width: 1280, height: 800 }, dark: false },
    { name: "phone-dark", viewport: { width: 390, height: 844 }, dark: true },
  ]) {
    it(`flashes the demo file and the version shown changes to 2.50 (${variant.name})`, {
      timeout: 60_000,
    }, async () => {
      const { page } = await app.newPage({
        start: DEMO,
        viewport: variant.viewport,
        options: { timeScale: 4 },
      });
      await page.emulateMedia({ colorScheme: variant.dark ? "dark" : "light" });
      const seen = watchPage(page, app.origin);
      await openFirmwareOnDemo(page);
      await expectText(page.getByTestId("fw-version"), "2.23");
      await expectText(
        page.getByTestId("fw-notice"),
        "The bootloader itself is never written, so a failed or interrupted update is fixed by running the update again.",
        { contains: true },
      );
      await expect.poll(() => page.getByTestId("flash-start").isDisabled()).toBe(true);

      await page.getByTestId("fw-demo-file").click();
      await page.getByTestId("fw-summary").waitFor();
      await expectText(page.getByTestId("fw-size"), "16,384 bytes");
      await expectText(page.getByTestId("fw-range"), "0x00000–0x03FFF");
      await expectText(page.getByTestId("fw-pages"), "64 of 256 bytes");
      await expectText(page.getByTestId("fw-lines"), "1,025 (46,093 bytes to send)");
      await shot(page, `before-${variant.name}`);

      await page.getByTestId("flash-start").click();
      const confirm = page.getByTestId("flash-confirm");
      await confirm.waitFor();
      await expectText(confirm, "Replace the robot's firmware with demo-2.50.hex?", { contains: true });
      await page.getByRole("button", { name: "Update firmware", exact: true }).click();

      // The power-cycle step, then progress in place.
      const progress = page.getByTestId("flash-progress");
      await progress.waitFor();
      await expectText(progress, "Switch the robot off and on now.", { contains: true });
      const figures = page.getByTestId("flash-figures");
      await figures.filter({ hasText: /bytes\/s/ }).waitFor({ timeout: 20_000 });
      await expectText(
        figures,
        /^[\d,]+ of 1,025 lines · [\d,]+ of 46,093 bytes \(\d+%\) · [\d,]+ bytes\/s · /,
      );
      await shot(page, `during-${variant.name}`);

      const result = page.getByTestId("flash-result").getByText(/Firmware updated/);
      await result.waitFor({ timeout: 40_000 });
      await expectText(
        result,
        /^Firmware updated: the robot now reports 2\.50 \(was 2\.23\)\. 1,025 lines in [\d.]+ s\. The robot was restarted/,
      );
      await expectText(page.getByTestId("fw-version"), "2.50");
      // The top bar and the Robot view show what the robot reported too.
      await page.getByRole("link", { name: "Robot" }).click();
      await expectText(page.getByTestId("firmware"), "2.50");
      await page.getByRole("link", { name: "Firmware" }).click();
      await page.getByTestId("firmware-view").waitFor();
      // No sideways scrolling on a phone.
      const overflow = await page.evaluate(
        () => document.documentElement.scrollWidth - document.documentElement.clientWidth,
      );
      expect(overflow).toBeLessThanOrEqual(0);
      await shot(page, `after-${variant.name}`);
      expect(seen.errors).toEqual([]);
    });
  }

  it("Cancel mid-way says the firmware may be incomplete; a bad file names its line", {
    timeout: 60_000,
  }, async () => {
    const { page } = await app.newPage({ start: DEMO, options: { timeScale: 2 } });
    await openFirmwareOnDemo(page);

    // A bad file first: refused with the line to blame, nothing opened.
    await page.getByTestId("fw-file-input").setInputFiles({
      name: "broken.hex",
      mimeType: "text/plain",
      buffer: Buffer.from(firmwareHexWithBadChecksum(3)),
    });
    const problem = page.getByText(/broken\.hex is not a firmware file/);
    await problem.waitFor();
    await expectText(problem, /Line 3: the checksum is 00/);
    expect(await page.getByTestId("fw-summary").count()).toBe(0);

    // A good file of this computer (64 KiB: long enough to cancel).
    await page.getByTestId("fw-file-input").setInputFiles({
      name: "big-2.60.hex",
      mimeType: "text/plain",
      buffer: Buffer.from(firmwareHex("2.60", 64 * 1024)),
    });
    await page.getByTestId("fw-summary").waitFor();
    await expectText(page.getByTestId("fw-lines"), "4,097 (184,333 bytes to send)");
    await page.getByTestId("flash-start").click();
    await page.getByRole("button", { name: "Update firmware", exact: true }).click();
    await page
      .getByTestId("flash-figures")
      .filter({ hasText: /bytes\/s/ })
      .waitFor({ timeout: 20_000 });
    await expectText(
      page.getByTestId("flash-progress"),
      "Cancel now and the robot's firmware may be incomplete",
      { contains: true },
    );
    await page.getByTestId("flash-cancel").click();
    // The notice's sentence (the updater's English sentence is its technical detail, one click away).
    const result = page
      .getByTestId("flash-result")
      .locator("p")
      .filter({ hasText: /The firmware update was cancelled/ });
    await result.waitFor({ timeout: 20_000 });
    await expectText(
      result,
      "The firmware update was cancelled. The robot's firmware may now be incomplete, and the robot may not work until an update succeeds. The bootloader is never overwritten: switch the robot off and on and run the update again.",
    );
    await expect.poll(() => page.getByTestId("flash-progress").count()).toBe(0);
    await expectText(page.getByTestId("fw-version"), "2.23");
  });
});

describe("a robot waiting in its bootloader (issue 20 item 11)", () => {
  it("connecting says so, and the notice's link opens the Firmware view's Recover", {
    timeout: 60_000,
  }, async () => {
    const { page } = await app.newPage({ options: { inBootloader: true, timeScale: 4 } });
    const seen = watchPage(page, app.origin);
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByRole("button", { name: "Connect robot" }).click();
    const go = page.getByRole("link", { name: "Go to the firmware recovery" });
    await go.waitFor({ timeout: 30_000 });
    await expectText(
      page.getByTestId("connect-card"),
      /The robot is waiting in its bootloader: it sent the bootloader's prompt \(\^\) \d+ times and answered no request\./,
    );
    await expectText(page.getByTestId("connect-card"), "Run the firmware update again, in recovery mode", {
      contains: true,
    });
    const text = await page.getByTestId("connect-card").textContent().then(squash);
    expect(text).not.toContain("no robot answered");
    await go.click();
    await page.getByTestId("firmware-view").waitFor();
    await expect
      .poll(() =>
        page.getByRole("heading", { name: "Recover: update a robot that does not answer" }).isVisible(),
      )
      .toBe(true);
    await expect.poll(() => page.getByTestId("recover-start").isVisible()).toBe(true);
    expect(seen.errors).toEqual([]);
  });

  it("another failed connect (no port chosen) gets no such link", { timeout: 30_000 }, async () => {
    const { page } = await app.newPage({ options: { userCancels: true } });
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByRole("button", { name: "Connect robot" }).click();
    await page.getByText("No port was chosen").waitFor();
    expect(await page.getByTestId("open-recovery").count()).toBe(0);
  });
});

/**
 * The Firmware view in Korean (issue #14 item 1): on the demo robot at 1280×800 and 390×844, the view with the
 * demo file opened, the confirmation, the progress and the result sentence are Korean, with `lang="ko"`, no
 * catalogue key shown, no button label overflowing and nothing scrolling sideways; axe finds no violation. The
 * device's words are Korean too: a refused file names its line, a cancelled update says what the robot holds,
 * and the device's English sentence stays in the technical detail. Recover (no robot connected) in Korean.
 * With RBC_SHOTS=<dir>, screenshots go there.
 */
describe("in Korean (ko-KR)", () => {
  /**
   * No label overflows, nothing scrolls sideways, no key shows: at `where` (axe has a test of its own); the
   * screenshot `shotName` with RBC_SHOTS.
   */
  const expectLaidOut = (page: Page, where: string, shotName?: string) =>
    expectPageOk(page, where, { axe: false, shot: shotName });

  /** The Firmware view with the demo robot connected, in a browser in Korean (the start option `DEMO`). */
  async function openFirmwareOnDemo(page: Page): Promise<void> {
    await loadConnected(page, app.url, "firmware");
    await page.getByTestId("firmware-view").waitFor();
  }

  /** Opens the demo file and asks to update: the confirmation is shown. */
  async function confirmDemoFile(page: Page): Promise<void> {
    await page.getByTestId("fw-demo-file").click();
    await page.getByTestId("fw-summary").waitFor();
    await page.getByTestId("flash-start").click();
    await page.getByTestId("flash-confirm").waitFor();
  }

  const RESULT =
    /^펌웨어를 업데이트했어요\. 로봇이 알려 준 버전: 2\.50 \(이전: 2\.23\)\. [\d.]+초 동안 1,025줄을 썼어요\. 로봇이 다시 시작했어요\. 다른 모션을 실행하기 전에 기본 자세를 실행해 주세요\.$/;

  describe("the Firmware view in Korean", () => {
    for (const [name, viewport] of [
      ["desktop", DESKTOP],
      ["phone", PHONE],
    ] as const) {
      it(`shows the file, the confirmation, progress and the result in Korean (${name})`, {
        timeout: 60_000,
      }, async () => {
        const { page, context } = await app.newPage({
          locale: "ko-KR",
          start: DEMO,
          viewport,
          options: { timeScale: 4 },
        });
        const seen = watchPage(page, app.origin);
        await openFirmwareOnDemo(page);
        await expect.poll(() => lang(page)).toBe("ko");
        const view = page.getByTestId("firmware-view");
        await expectText(view.getByRole("heading", { level: 1 }), "펌웨어");
        await expect
          .poll(() => view.getByRole("heading", { level: 2 }).allTextContents())
          .toEqual(["펌웨어 파일", "로봇 업데이트"]);
        await expectText(page.getByTestId("fw-current"), "데모 로봇이 알려 준 펌웨어 버전: 2.23");
        await expectText(
          page.getByTestId("fw-notice"),
          "실제 로봇에서는 실험 단계예요. 부트로더 자체는 절대 덮어쓰지 않아요. 그래서 업데이트가 실패하거나 중간에 끊겨도 업데이트를 다시 하면 고쳐져요. " +
            "업데이트가 끝날 때까지 로봇의 전원을 켜 둔 채(충전된 배터리나 어댑터) 로봇을 눕혀 두고, 케이블도 꽂아 두세요.",
        );
        await page.getByText("먼저 펌웨어 파일을 열어 주세요.").waitFor();
        await page.getByRole("button", { name: "데모 펌웨어 파일 사용 (2.50)" }).waitFor();
        await expectLaidOut(page, "the view");

        await page.getByTestId("fw-demo-file").click();
        await page.getByTestId("fw-summary").waitFor();
        await expectText(page.getByTestId("fw-size"), "16,384바이트");
        await expectText(page.getByTestId("fw-pages"), "256바이트 페이지 64개");
        await expectText(page.getByTestId("fw-lines"), "1,025줄 (보낼 데이터 46,093바이트)");
        // Plain facts first; the address range, pages and lines under "기술 정보" (technical detail).
        await expect
          .poll(() => page.getByTestId("fw-summary").locator("dt").allTextContents())
          .toEqual(["크기", "파일에 적힌 버전", "주소 범위", "플래시 페이지", "줄 수"]);
        await page.getByRole("button", { name: "파일 닫기" }).waitFor();
        await expectLaidOut(page, "the file opened", `firmware-ko-file-${name}`);

        await page.getByRole("button", { name: "펌웨어 업데이트…" }).click();
        const confirm = page.getByTestId("flash-confirm");
        await confirm.waitFor();
        await expectText(
          confirm,
          "로봇의 펌웨어를 demo-2.50.hex(으)로 바꿀까요? 데모 로봇은 요청하면 스스로 다시 시작해요. " +
            "다음으로 로봇을 껐다가 켜 달라는 안내가 나오고, 그다음 파일을 한 줄씩 써요. 펌웨어 업데이트 취소",
        );
        await expectLaidOut(page, "the confirmation", `firmware-ko-confirm-${name}`);
        await page.getByRole("button", { name: "펌웨어 업데이트", exact: true }).click();

        const progress = page.getByTestId("flash-progress");
        await progress.waitFor();
        await expectText(progress, "지금 로봇을 껐다가 다시 켜 주세요.", { contains: true });
        const figures = page.getByTestId("flash-figures");
        await figures.filter({ hasText: /초당/ }).waitFor({ timeout: 20_000 });
        await expectText(
          figures,
          /^1,025줄 중 [\d,]+줄 · 46,093바이트 중 [\d,]+바이트 \(\d+%\) · 초당 [\d,]+바이트 · (약 \d+초 남음|약 \d+분 \d+초 남음)$/,
        );
        await expect
          .poll(() => progress.locator("progress").getAttribute("aria-label"))
          .toBe("demo-2.50.hex(으)로 펌웨어 업데이트");
        await expectText(progress, "demo-2.50.hex 쓰기", { contains: true });
        await expectLaidOut(page, "the progress", `firmware-ko-progress-${name}`);

        const result = page.getByTestId("flash-result").getByText(/펌웨어를 업데이트했어요/);
        await result.waitFor({ timeout: 40_000 });
        await expectText(result, RESULT);
        await expectText(page.getByTestId("fw-version"), "2.50");
        await expect
          .poll(() => page.getByTestId("flash-result").getByRole("status").getAttribute("aria-label"))
          .toBe("펌웨어 업데이트 결과");
        await expectLaidOut(page, "the result", `firmware-ko-result-${name}`);
        expect(seen.errors).toEqual([]);
        await context.close();
      });
    }

    it("says in Korean why a file is refused and what a cancelled update leaves, with the device's technical line in the detail", {
      timeout: 60_000,
    }, async () => {
      const { page, context } = await app.newPage({
        locale: "ko-KR",
        start: DEMO,
        options: { timeScale: 2 },
      });
      await openFirmwareOnDemo(page);

      await page.getByTestId("fw-file-input").setInputFiles({
        name: "broken.hex",
        mimeType: "text/plain",
        buffer: Buffer.from(firmwareHexWithBadChecksum(3)),
      });
      const problem = page.locator(".fw-file .notice");
      await problem.waitFor();
      await expectText(
        problem.locator("p"),
        "broken.hex은(는) 로봇의 부트로더가 받을 수 있는 펌웨어 파일이 아니에요. 3번째 줄: 체크섬이 00인데, 레코드의 바이트를 더하면 58이어야 해요.",
      );
      await expectText(problem.locator("summary"), "기술 정보");
      // The technical detail: the parser's code and facts.
      await expectText(problem.locator("pre"), "IntelHexError: hex line 3: checksum (got 00, expected 58)");
      await expect.poll(() => problem.locator("pre").getAttribute("lang")).toBe("en");
      expect(await page.getByTestId("fw-summary").count()).toBe(0);

      await page.getByTestId("fw-file-input").setInputFiles({
        name: "big-2.60.hex",
        mimeType: "text/plain",
        buffer: Buffer.from(firmwareHex("2.60", 64 * 1024)),
      });
      await page.getByTestId("fw-summary").waitFor();
      await page.getByTestId("flash-start").click();
      await page.getByRole("button", { name: "펌웨어 업데이트", exact: true }).click();
      await page.getByTestId("flash-figures").filter({ hasText: /초당/ }).waitFor({ timeout: 20_000 });
      await expectText(
        page.getByTestId("flash-progress"),
        "지금 취소하면 업데이트가 성공할 때까지 로봇의 펌웨어가 불완전할 수 있어요.",
        { contains: true },
      );
      await page.getByRole("button", { name: "취소", exact: true }).click();
      const result = page.getByTestId("flash-result").locator(".notice");
      await result.getByText(/업데이트를 취소했어요/).waitFor({ timeout: 20_000 });
      await expectText(
        result.locator("p"),
        "펌웨어 업데이트를 취소했어요. 로봇의 펌웨어가 불완전할 수 있고, 업데이트가 성공할 때까지 로봇이 작동하지 않을 수 있어요. " +
          "부트로더는 절대 덮어쓰지 않아요. 로봇을 껐다가 다시 켜고 업데이트를 다시 해 주세요.",
      );
      await expectText(
        result.locator("pre"),
        // The technical detail is the device's own technical line (its code and facts); the sentence above is the
        // outcome catalogue's (docs/architecture.md: the words of outcomes stand above the device).
        "FirmwareUpdateError (cancelled): firmware update cancelled; robot holds incomplete-firmware",
      );
      await expectText(page.getByTestId("fw-version"), "2.23");
      await expectLaidOut(page, "the cancelled update");
      await context.close();
    });

    for (const [name, viewport] of [
      ["desktop", DESKTOP],
      ["phone", PHONE],
    ] as const) {
      it(`offers Recover in Korean while no robot is connected (${name})`, async () => {
        const { page, context } = await newLocalePage(app, "ko-KR", { size: viewport });
        await page.getByTestId("connect-card").waitFor();
        await page.getByRole("link", { name: "펌웨어" }).click();
        await page.getByTestId("firmware-view").waitFor();
        await expect.poll(() => lang(page)).toBe("ko");
        await page.getByRole("heading", { level: 2, name: "복구: 응답하지 않는 로봇 업데이트" }).waitFor();
        await expectText(page.getByTestId("recover-start"), "복구…");
        await expect.poll(() => page.getByTestId("recover-start").isDisabled()).toBe(true);
        // A real file opens here too; Recover's confirmation asks for the port first.
        await page.getByTestId("fw-file-input").setInputFiles({
          name: "firmware-2.60.hex",
          mimeType: "text/plain",
          buffer: Buffer.from(firmwareHex("2.60", 1024)),
        });
        await page.getByTestId("fw-summary").waitFor();
        await page.getByTestId("recover-start").click();
        const confirm = page.getByTestId("flash-confirm");
        await confirm.waitFor();
        await expectText(confirm, "응답하지 않는 로봇에 firmware-2.60.hex을(를) 쓸까요?", { contains: true });
        await expectText(confirm, "먼저 브라우저가 로봇의 포트를 물어봐요.", { contains: true });
        await page.getByRole("button", { name: "포트 선택 후 업데이트" }).waitFor();
        await expectLaidOut(page, "Recover", `firmware-ko-recover-${name}`);
        await context.close();
      });
    }

    it("says in Korean that a browser without Web Serial cannot Recover", async () => {
      const { page, context } = await newLocalePage(app, "ko-KR", { noSerial: true, hash: "#/firmware" });
      await page.getByTestId("firmware-view").waitFor();
      const note = page.getByText(/Web Serial을 지원하지 않아요/);
      await expectText(
        note,
        "이 브라우저는 Web Serial을 지원하지 않아요. 컴퓨터에서 Chrome이나 Edge를 쓰거나 rbc flash --recover 명령을 써 주세요.",
      );
      await expectText(note.locator("code"), "rbc flash --recover");
      expect(await keysShown(page)).toEqual([]);
      await context.close();
    });

    it("axe finds no violation: the file, the confirmation, the progress and the result", {
      timeout: 60_000,
    }, async () => {
      const { page, context } = await app.newPage({
        locale: "ko-KR",
        start: DEMO,
        options: { timeScale: 4 },
      });
      await openFirmwareOnDemo(page);
      await expect.poll(() => lang(page)).toBe("ko");
      await expectPageOk(page, "the Firmware view", { lang: "ko" });
      await confirmDemoFile(page);
      await expectPageOk(page, "the confirmation", { lang: "ko" });
      await page.getByRole("button", { name: "펌웨어 업데이트", exact: true }).click();
      await page.getByTestId("flash-progress").waitFor();
      await expectPageOk(page, "the progress", { lang: "ko" });
      await page
        .getByTestId("flash-result")
        .getByText(/펌웨어를 업데이트했어요/)
        .waitFor({ timeout: 40_000 });
      await expectPageOk(page, "the result", { lang: "ko" });
      await context.close();
    });
  });
});
