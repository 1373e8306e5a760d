import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { openConnected } from "./connected-page.ts";
import { expectText, squash, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";
import { PHONE, type Size, text } from "./i18n-checks.ts";

/**
 * Issue 33 item 11: the guided id fix ends with the steps left (plug back in the servo it had asked to unplug,
 * named, then scan again, with a button to scan now), and the scan taken before the id change is cleared, so
 * its findings ("id 7 does not answer: check its cable") no longer stand beside the fix. Walked on the demo
 * robot with a replacement servo still at id 0 (as tests/e2e/servo-doctor.test.ts drives it).
 */

const app = useApp();

/** The robot's clock at a quarter of real speed (see servo-doctor.test.ts: a starved page must not miss a reply). */
const QUARTER = { timeScale: 0.25 };

/** Scans with `button` and waits for this scan's summary (the clock is held until the scan shows under way). */
async function scanWith(page: Page, button: string, done: RegExp): Promise<string> {
  await page.evaluate(() => window.__rbcTest?.clock.hold());
  await page.getByTestId(button).click();
  await page.getByTestId("doctor-cancel").waitFor();
  await page.evaluate(() => window.__rbcTest?.clock.release());
  const status = page.getByTestId("doctor-scan-status").filter({ hasText: done });
  await status.waitFor();
  return text(status);
}

interface Words {
  locale: string;
  size?: Size;
  fault: string;
  scanned: RegExp;
  refused: string;
  done: string;
  question: string;
  left: string[];
  cleared: string;
  scanNow: string;
  clean: string;
}

const EN: Words = {
  locale: "en-US",
  fault: "replacement servo (still id 0), servo 7",
  scanned: /Scanned 16 ids/,
  refused: "Not changed",
  question: "Give it id 7?",
  done: "Done",
  left: [
    "Plug back in the servos you unplugged for the fix: Servo 0 (Left hip roll).",
    "Then scan again: every servo should answer, the fixed one at id 7.",
  ],
  cleared:
    "The scan from before the id change (id 0 → id 7) was cleared: it no longer shows the servos as they are. Scan again.",
  scanNow: "Scan now",
  clean:
    "Scanned 16 ids: 16 answered, 0 silent, 0 garbled. Every servo 0-15 answered, with no high load at rest.",
};

const KO: Words = {
  locale: "ko-KR",
  // Korean on a phone: the steps left fit the narrow screen.
  size: PHONE,
  fault: "교체한 서보 (아직 ID 0), 서보 7번",
  scanned: /ID 16개를 검사했어요/,
  refused: "바꾸지 않았어요",
  question: "ID 7을 줄까요?",
  done: "다 됐어요",
  left: [
    "ID 고치기 때문에 뺀 서보를 다시 꽂아 주세요: 서보 0번(왼쪽 엉덩이 좌우).",
    "그다음 다시 검사해 주세요. 모든 서보가 응답해야 하고, 고친 서보는 ID 7에서 응답해야 해요.",
  ],
  cleared:
    "ID 바꾸기(ID 0 → ID 7) 전에 한 검사 결과는 지웠어요. 지금의 서보 상태가 아니에요. 다시 검사해 주세요.",
  scanNow: "지금 검사",
  clean:
    "ID 16개를 검사했어요. 응답함 16, 응답 없음 0, 깨진 응답 0. 서보 0-15가 모두 응답했고, 쉬는 동안 부하가 높은 서보도 없어요.",
};

describe("The guided id fix ends with the steps left and a fresh scan (issue 33 item 11)", () => {
  for (const w of [EN, KO]) {
    it(`${w.locale}: names the servo to plug back in, clears the old scan, and scans again from its own button`, async () => {
      const { page, context } = await openConnected(app, {
        view: "doctor",
        locale: w.locale,
        options: QUARTER,
      });
      await page.getByTestId("doctor-scan-card").waitFor();
      await page.getByTestId("doctor-demo-kind").selectOption("replacement");
      await page.getByTestId("doctor-demo-servo").selectOption("7");
      await page.getByTestId("doctor-demo-apply").click();
      await page.getByTestId("doctor-demo-now").filter({ hasText: w.fault }).waitFor();
      await page.getByTestId("doctor-scan").and(page.locator(":enabled")).waitFor();

      await scanWith(page, "doctor-scan", w.scanned);
      // Id 0 answered by two servos: the fix refuses and asks to unplug the other one; the demo robot does it.
      await page.getByTestId("doctor-fix").click();
      const result = page.getByTestId("doctor-fix-result");
      await result.filter({ hasText: w.refused }).waitFor();
      await page.getByTestId("doctor-demo-unplug").click();
      await scanWith(page, "doctor-scan", w.scanned);
      // The scan before the fix blames id 7's cable (it has no servo yet).
      await expect.poll(() => page.getByTestId("doctor-findings").count()).toBe(1);

      await page.getByTestId("doctor-fix").click();
      await page.getByRole("alertdialog").filter({ hasText: w.question }).waitFor();
      await page.getByTestId("doctor-fix-confirm").click();
      await result.filter({ hasText: w.done }).waitFor();

      // The steps left, the unplugged servo named; the scan from before the fix is gone and says so.
      const left = page.getByTestId("doctor-fix-left");
      await expect.poll(async () => (await left.locator("li").allTextContents()).map(squash)).toEqual(w.left);
      await expectText(page.getByTestId("doctor-scan-status"), w.cleared);
      expect(await page.getByTestId("doctor-findings").count()).toBe(0);
      expect(await page.getByTestId("doctor-table").count()).toBe(0);
      expect(await page.getByTestId("doctor-fix-suggested").count()).toBe(0);
      await expectText(page.getByTestId("doctor-fix-scan"), w.scanNow);
      expect(await page.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth)).toBe(true);

      // Servo 0 plugged back in, then the guide's own button scans: every servo answers.
      await page.getByTestId("doctor-demo-plug-back").click();
      await scanWith(page, "doctor-fix-scan", w.scanned);
      await expectText(page.getByTestId("doctor-scan-status"), w.clean);
      await expect.poll(() => page.getByTestId("doctor-findings").count()).toBe(0);
      // The fresh scan ends the guide: its steps are done.
      await expect.poll(() => left.count()).toBe(0);
      await context.close();
    });
  }
});
