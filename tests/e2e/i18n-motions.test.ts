/**
 * The Motions view in Korean (issue #14 item 1): a Korean browser gets every tab in Korean with `lang="ko"`
 * (Files with an example open and its scenes shown, a file's warnings and errors, an upload; Memory; Run with
 * its confirmation and result; Sounds), the sentences made by the actions too; no catalogue key shows; no
 * button's label overflows it and nothing scrolls sideways at 1280×800 and 390×844; axe finds no violation.
 * With RBC_SHOTS=<dir>, screenshots of every tab at both sizes go there to be looked at.
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { FAST, squash } from "./harness.ts";
import {
  connectCable,
  expectPageOk,
  newLocalePage,
  SIZES,
  type Size,
  sizeName,
  text,
  texts,
  useApp,
} from "./i18n-checks.ts";
import { exampleText, rbmFile, withJumps, withShortFrames } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

const TABS = { files: "파일", uploads: "메모리", run: "실행", sounds: "소리" } as const;

const app = useApp();

/** Connects the fake robot from the connect card and opens the Motions view once its memory has been read. */
async function openMotions(page: Page): Promise<void> {
  await connectCable(page);
  await page.getByRole("link", { name: "모션", exact: true }).click();
  await page
    .getByTestId("mem-motion-text")
    .filter({ hasText: "24,576바이트 중 24,576바이트 남음" })
    .waitFor();
}

/** Chooses a tab by its Korean name and waits until its panel is shown. */
async function showTab(page: Page, tab: keyof typeof TABS): Promise<void> {
  await page.getByRole("tab", { name: TABS[tab], exact: true }).click();
  await page.locator(`#motions-panel-${tab}`).waitFor();
}

/**
 * One state of the view: Korean, no overflowing label, no sideways scroll, no key shown, nothing for axe; and a
 * screenshot of the whole page (with RBC_SHOTS).
 */
const expectGood = (page: Page, where: string, size: Size) =>
  expectPageOk(page, where, { lang: "ko", shot: `motions-${where}-ko-${sizeName(size)}` });

describe("the Motions view in Korean", () => {
  for (const viewport of SIZES) {
    it(`shows the Files tab in Korean with an example open, fitting at ${viewport.width}×${viewport.height}`, async () => {
      const { page, context } = await newLocalePage(app, "ko-KR", { size: viewport, options: FAST });
      await openMotions(page);
      expect(await page.getByRole("heading", { level: 1 }).textContent()).toBe("모션");
      expect(await texts(page.getByRole("tab"))).toEqual(["파일", "메모리", "실행", "소리"]);
      expect(await page.getByRole("tablist").getAttribute("aria-label")).toBe("모션");
      const files = page.getByTestId("motion-files");
      expect(await text(files.getByRole("heading", { level: 2 }))).toBe("모션 파일");
      expect(await text(files.locator(".drop-title"))).toBe("모션 파일 열기 (.rbm)");
      expect(await text(page.getByTestId("mem-motion-used"))).toBe("0바이트 사용");
      await page.getByLabel("먼저 모션 메모리 초기화", { exact: false }).waitFor();

      // An example, opened from the disclosure: its facts, its check, its scenes and chart.
      await page.getByText("예제 모션 열기").click();
      await page.getByRole("button", { name: "wave.rbm 열기" }).click();
      await page.getByText("예제 wave.rbm을(를) 열었어요.").waitFor();
      const card = page.getByTestId("motion-file").filter({ hasText: "wave.rbm" });
      expect(await texts(card.locator(".file-facts dt"))).toEqual([
        "장면",
        "서보",
        "재생 시간",
        "이미지",
        "로봇에서",
      ]);
      expect(await texts(card.locator(".file-facts dd"))).toEqual([
        "6",
        "16",
        "3.2초",
        "624바이트",
        "640바이트",
      ]);
      expect(await text(card.locator(".check-ok"))).toBe("확인함: 오류 없음, 경고 없음.");
      expect(await text(card.getByTestId("scenes-toggle"))).toBe("장면과 차트 숨기기");
      expect(await text(card.getByTestId("preview-toggle"))).toBe("3D 미리 보기");
      expect(await card.getByRole("button", { name: "wave.rbm 닫기" }).textContent().then(squash)).toBe(
        "닫기",
      );
      expect(await text(card.getByTestId("upload-why"))).toBe(
        "먼저 확인을 받아요. 실제 로봇에 업로드하는 기능은 실험 단계예요.",
      );
      const scenes = page.getByTestId("scene-section");
      expect(await text(scenes.getByRole("heading"))).toBe("RbcPanel_Wave의 장면");
      expect(await texts(scenes.locator(".scene-table th"))).toEqual([
        "#",
        "이름",
        "프레임",
        "시작",
        "길이",
        "프레임 간격",
      ]);
      expect(await texts(scenes.locator(".scene-table tbody tr").nth(1).locator("td"))).toEqual([
        "1",
        expect.any(String),
        "10",
        "0.8초",
        "0.4초",
        "40ms",
      ]);
      await page.locator('[data-testid="motion-chart"][data-chart="drawn"]').waitFor();
      expect(await text(page.locator('[data-testid="motion-chart"] .u-legend'))).toContain("2 오른쪽 무릎");
      await expectGood(page, "files", viewport);

      // A file with warnings and one with an error: the panel's words and the checker's sentences in Korean
      // (tests/e2e/i18n-motion-issues.test.ts has more of them).
      await page
        .getByTestId("rbm-files")
        .setInputFiles([
          rbmFile("Jumpy.rbm", withJumps(exampleText("wave.rbm"), 2)),
          rbmFile("Edited.rbm", withShortFrames(exampleText("wave.rbm"))),
        ]);
      await page.getByText("파일 2개를 열었어요.").waitFor();
      const jumpy = page.getByTestId("motion-file").filter({ hasText: "Jumpy.rbm" });
      expect(await text(jumpy.getByTestId("check-summary"))).toBe(
        "확인함: 오류 0개, 경고 16개 (1종류, 심각한 경고 없음).",
      );
      const group = jumpy.getByTestId("warning-group");
      expect(await text(group.locator(".weight"))).toBe("사소함");
      expect(await text(group.locator("strong"))).toBe("장면 사이에서 서보가 튐");
      expect(await text(group.locator(".warning-meaning"))).toContain(
        "가장 크게 튀는 폭은 2단계로, 거의 보이지 않는 작은 떨림이에요.",
      );
      await group.getByText("16개 모두 보기").click();
      const first = group.locator(".issues li").first();
      expect(await text(first)).toBe(
        "장면 0에서 서보 0번(오른쪽 엉덩이 롤)의 끝 위치는 125인데, 장면 1에서는 127에서 시작해서 서보가 튀어요.",
      );
      expect(await first.locator('[lang="en"]').count()).toBe(0);
      const edited = page.getByTestId("motion-file").filter({ hasText: "Edited.rbm" });
      expect(await text(edited.getByTestId("check-summary"))).toMatch(/^확인함: 오류 1개, 경고 0개\.$/);
      expect(await text(edited.locator(".issue--error .issue-kind"))).toBe("오류");
      expect(await text(edited.locator(".issue--error"))).toMatch(/^오류 장면 0의 프레임 간격이 10ms예요 /);
      expect(await text(edited.getByTestId("upload-why"))).toBe(
        "업로드할 수 없어요. 파일에 오류가 1개 있어요 (위 목록). 아무것도 보내지 않아요.",
      );
      await expectGood(page, "files-checked", viewport);

      // The upload: its question and its result, in Korean.
      await card.getByTestId("upload-motion").click();
      const confirm = card.getByTestId("upload-confirm");
      expect(await text(confirm.locator("#upload-confirm-title"))).toBe(
        "wave.rbm을(를) 로봇에 업로드할까요?",
      );
      await confirm.getByRole("button", { name: "취소" }).waitFor();
      await confirm.scrollIntoViewIfNeeded();
      await expectGood(page, "upload-confirm", viewport);
      await confirm.getByRole("button", { name: "업로드 (실험 기능)" }).click();
      const result = card.getByText(/^wave\.rbm을\(를\) 업로드했어요\./);
      await result.waitFor({ timeout: 15_000 });
      const sentence = await text(result);
      expect(sentence).toMatch(
        /^wave\.rbm을\(를\) 업로드했어요\. 624바이트를 조각 \d+개로 [\d.]+초 동안 보냈고 \([\d,]+바이트\/초\), 로봇이 모든 조각을 받았다고 확인했어요\./,
      );
      expect(sentence).toContain(
        "다운로드된 모션 1번이에요. 실행 탭에서 모션 번호 12번으로 실행할 수 있어요.",
      );
      expect(sentence).toContain("남은 모션 메모리: 24,576바이트 중 23,936바이트 (전에는 24,576바이트");
      expect(sentence).toContain("업로드 후 오류 코드: 오류 없음.");
      await expectGood(page, "uploaded", viewport);
      await context.close();
    });

    it(`shows Memory, Run and Sounds in Korean, fitting at ${viewport.width}×${viewport.height}`, async () => {
      const { page, context } = await newLocalePage(app, "ko-KR", { size: viewport, options: FAST });
      await openMotions(page);
      await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", exampleText("wave.rbm")));
      await page.getByTestId("upload-motion").click();
      await page.getByRole("button", { name: "업로드 (실험 기능)" }).click();
      await page.getByText(/^wave\.rbm을\(를\) 업로드했어요\./).waitFor({ timeout: 15_000 });

      // Memory: the areas as used, the uploads of this connection, an action file.
      await showTab(page, "uploads");
      const memory = page.getByTestId("memory-card");
      expect(await text(memory.getByRole("heading"))).toBe("로봇 메모리");
      expect(await text(page.getByTestId("mem-motion-used"))).toBe("24,576바이트 중 640바이트 사용");
      expect(await text(page.getByTestId("mem-motion-text"))).toBe("24,576바이트 중 23,936바이트 남음");
      expect(await text(page.getByTestId("mem-motion-count"))).toBe(
        "마지막 초기화나 전원을 켠 뒤로 모션 20개 중 1개 저장됨",
      );
      expect(await text(page.getByTestId("uploaded-list"))).toBe(
        "RbcPanel_Wave wave.rbm — 슬롯 1 → 모션 번호 12, 재생 시간 3.2초",
      );
      expect(await text(page.getByTestId("uploads-card").locator("summary"))).toBe("메모리를 세는 방법");
      await page.getByTestId("action-file").setInputFiles({
        name: "wave.act",
        mimeType: "application/octet-stream",
        buffer: Buffer.alloc(100, 1),
      });
      const action = page.getByTestId("action-card");
      await action.getByText("wave.act, 100바이트").waitFor();
      await action.getByRole("button", { name: "액션 파일 업로드" }).waitFor();
      await action.getByLabel("먼저 액션 메모리 초기화 (다운로드한 액션을 모두 지워요)").waitFor();
      expect(await text(action.locator("label.file-button"))).toBe("액션 파일 고르기…");
      await expectGood(page, "memory", viewport);

      // Run: the basic-posture guidance, the built-in and downloaded motions, the other slots, the question
      // before the robot moves, and the result.
      await showTab(page, "run");
      const run = page.getByTestId("run-card");
      expect(await text(run.getByRole("heading", { level: 2 }))).toBe("모션 실행");
      expect(await texts(run.getByRole("heading", { level: 3 }))).toEqual(["내장 모션", "다운로드한 모션"]);
      expect(await text(page.getByTestId("posture-guidance"))).toBe(
        "로봇을 켠 뒤에는 기본 자세(7)만 받아들여요. 먼저 기본 자세를 실행해 주세요. 그 전까지는 다른 모션을 모두 아무 말 없이 무시해요.",
      );
      expect(await text(run.locator('[data-motion="7"]'))).toBe("7 기본 자세 1.8초 먼저 실행");
      expect(await text(run.locator('[data-motion="12"]'))).toBe("12 RbcPanel_Wave 3.2초");
      await run.getByText("다른 다운로드 슬롯 (19)").click();
      // The slot button shows its number; a screen reader hears "모션 13번 실행" and its slot.
      await run.getByRole("button", { name: /^모션 13\s?번 실행 슬롯 2$/ }).waitFor();
      await run.locator('[data-motion="7"]').click();
      const ask = page.getByTestId("move-confirm");
      expect(await text(ask)).toBe(
        "로봇이 움직여요. 로봇을 잡거나 주변에 공간을 비워 주세요. 패널은 연결할 때마다 한 번만 물어봐요. 정지(Esc)는 모션을 끝내고 로봇을 선 채로 유지해요. 모션 7번(기본 자세) 실행 취소",
      );
      await expectGood(page, "run-confirm", viewport);
      await page.locator("#confirm-move").click();
      await page.getByText("모션 7번(기본 자세)을 마쳤어요. 이제 로봇이 모든 모션을 받아들여요.").waitFor();
      await expectGood(page, "run", viewport);

      // Sounds: the buttons' names, and what a sound did.
      await showTab(page, "sounds");
      const sounds = page.getByTestId("sound-card");
      expect(await text(sounds.getByRole("heading"))).toBe("소리");
      await sounds.getByRole("button", { name: "소리 4, 0.4초" }).click();
      await sounds.getByText("소리 4번을 재생했어요 (0.4초).").waitFor();
      await expectGood(page, "sounds", viewport);
      await context.close();
    });
  }
});
