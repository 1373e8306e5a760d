/**
 * The motion editor in Korean (issue #14 item 1), with the demo robot connected: a Korean browser gets the
 * Editor in Korean with `lang="ko"`, every tab (Pose with a refused value, Scene with refused frames, Tools
 * with a refused factor, Teach-in with a limb limp, Play with its question and result, Check with a warning)
 * and the Drafts list with its question; the sentences the actions make are Korean too. No catalogue key
 * shows, no button's label overflows it and nothing scrolls sideways at 1280×800 and 390×844, and axe finds no
 * violation (tests/e2e/i18n-checks.ts). Screenshots of every tab at both sizes with RBC_SHOTS=<dir>.
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { type AppHarness, FAST, squash } from "./harness.ts";
import { DESKTOP, expectPageOk, pageLang as lang, PHONE, useApp } from "./i18n-checks.ts";
import "./rbc-test-globals.ts";

const VIEWPORTS = [DESKTOP, PHONE] as const;

const app: AppHarness = useApp();

const size = (viewport: { width: number; height: number }) => `${viewport.width}x${viewport.height}`;
const text = async (page: Page, testId: string) => squash(await page.getByTestId(testId).textContent());

type Tab = "pose" | "scene" | "tools" | "teach" | "play" | "check";

async function showTab(page: Page, tab: Tab): Promise<void> {
  await page.locator(`#editor-tab-${tab}`).click();
  await page.locator(`#editor-panel-${tab}`).waitFor();
}

/** Types a value into a field and leaves it (a `change`, as a person pressing Tab). */
async function typeInto(page: Page, testId: string, value: string): Promise<void> {
  const field = page.getByTestId(testId);
  await field.fill(value);
  await field.press("Tab");
}

/** The editor's result line (the toolbar's live region), or a panel's (teach-in, play). */
async function notice(page: Page, where: "editor-toolbar" | "teach-in" | "play-panel"): Promise<string> {
  return squash(await page.getByTestId(where).locator(".live .notice p").first().textContent());
}

/** Connects the demo robot from the Korean start card and opens the Editor with a second scene added. */
async function openEditor(page: Page): Promise<void> {
  await page.goto(app.url, { waitUntil: "domcontentloaded" });
  await page.getByRole("button", { name: "데모 로봇 써 보기", exact: true }).click();
  await page.getByTestId("device-card").waitFor();
  await page.getByRole("link", { name: "편집기", exact: true }).click();
  await page.getByTestId("editor").waitFor();
  await page.getByRole("button", { name: "뒤에 추가" }).click();
  await page.locator("#scene-opt-1[aria-current=true]").waitFor();
  await page.getByTestId("draft").waitFor();
  await page.locator('[data-testid="editor-robot3d"][data-state="ready"]').waitFor({ timeout: 20_000 });
}

/** The layout checks of one state of the Editor (tests/e2e/i18n-checks.ts), its screenshot, and axe. */
async function expectTidy(
  page: Page,
  where: string,
  viewport: { width: number; height: number },
): Promise<void> {
  await expectPageOk(page, where, { lang: "ko", shot: `editor-${where}-ko-${size(viewport)}` });
}

describe("the Editor in Korean", () => {
  for (const viewport of VIEWPORTS) {
    it(`is in Korean in every tab, fits and passes axe at ${viewport.width}×${viewport.height}`, async () => {
      const { page, context } = await app.newPage({ locale: "ko-KR", viewport, options: FAST });
      await openEditor(page);
      expect(await lang(page)).toBe("ko");
      expect(await page.getByRole("heading", { level: 1 }).textContent()).toBe("모션 편집기");
      expect(
        await page
          .getByRole("tab")
          .allTextContents()
          .then((t) => t.map(squash)),
      ).toEqual(["자세", "장면", "도구", "티칭", "재생", "검사"]);
      await page.getByRole("tablist", { name: "선택한 장면 작업" }).waitFor();
      expect(await notice(page, "editor-toolbar")).toBe("완료: 장면 1 추가.");
      expect(await text(page, "editor-undo")).toBe("실행 취소: 장면 1 추가");
      expect(await text(page, "scene-total")).toBe("장면 2개 · 1.0초");
      await page.getByRole("img", { name: /^장면 1의 끝 자세를 보여 주는 3D 화면/ }).waitFor();

      // Pose: the table in Korean, and a value the motion file cannot hold, refused beside its field.
      expect(await page.getByRole("heading", { level: 2, name: "장면 1: Scene_1" }).count()).toBe(1);
      await typeInto(page, "end-3", "300");
      const problem = page.getByTestId("field-problem");
      await problem.waitFor();
      expect(squash(await problem.textContent())).toBe(
        "오른쪽 발목 피치(서보 3)의 끝 위치에는 0에서 254 사이의 정수만 쓸 수 있어요. 입력한 값: 300.",
      );
      expect(await page.getByLabel("오른쪽 발목 피치 (서보 3), 끝 위치", { exact: true }).inputValue()).toBe(
        "300",
      );
      if (viewport === DESKTOP) {
        expect(await page.locator('[data-testid="pose-table"] thead th').allTextContents()).toEqual([
          "ID",
          "관절",
          "시작",
          "끝",
          "끝 위치 슬라이더",
          "토크",
          "포트",
        ]);
      }
      await expectTidy(page, "pose", viewport);
      await typeInto(page, "end-3", "");
      await problem.filter({ hasText: "써 주세요" }).waitFor();
      expect(squash(await problem.textContent())).toBe(
        "오른쪽 발목 피치(서보 3)의 끝 위치에는 0에서 254 사이의 정수를 써 주세요.",
      );

      // Scene: its fields, continuity, and frames closer than the RBC plays them.
      await showTab(page, "scene");
      await page.getByRole("heading", { level: 3, name: "장면 사이 이어짐" }).waitFor();
      expect(await text(page, "boundary-start")).toBe("장면 0의 끝에서 시작해요 (서보 16개 모두 이어짐).");
      const time = Number(await page.getByTestId("scene-time").inputValue());
      await typeInto(page, "scene-frames", String(time));
      await page.locator("#frames-problem").waitFor();
      expect(squash(await page.locator("#frames-problem").textContent())).toMatch(
        /^프레임 [\d,]+개를 [\d,]+ms에 재생하면 프레임 사이가 1\.0ms예요\. RBC는 20ms 이상이 필요해요\. 프레임을 \d+개 이하로 하거나 시간을 [\d,]+ms 이상으로 해 주세요\.$/,
      );
      await expectTidy(page, "scene", viewport);

      // Tools: mirror, copy and retime, and a factor that is not a number.
      await showTab(page, "tools");
      await page.getByRole("button", { name: "좌우 바꾸기" }).waitFor();
      await page.getByRole("button", { name: "장면 1에 복사" }).waitFor();
      await page.getByTestId("retime-value").fill("빠르게");
      await page.getByTestId("retime-apply").click();
      await page.locator("#retime-problem").waitFor();
      expect(squash(await page.locator("#retime-problem").textContent())).toBe(
        '시간 배수는 0보다 큰 수여야 해요 (2 = 절반 속도, 0.5 = 두 배 속도). 입력한 값: "빠르게".',
      );
      await expectTidy(page, "tools", viewport);

      // Teach-in: the question, a limb made limp, its slider, the pose read into the scene, the end.
      await showTab(page, "teach");
      await page.getByRole("button", { name: "티칭 시작…" }).click();
      const question = page.getByTestId("teach-in-confirm");
      expect(squash(await question.locator("#teach-in-question").textContent())).toBe(
        "로봇을 잡아 주세요. 고른 서보의 힘이 빠져요.",
      );
      await question.getByRole("button", { name: "티칭 시작", exact: true }).click();
      await page.getByTestId("teach-in-status").waitFor();
      expect(await text(page, "teach-in-status")).toBe(
        "모든 서보가 제자리를 유지해요. 팔다리를 고르고 힘 빼기를 눌러 주세요.",
      );
      await page.getByRole("checkbox", { name: "오른쪽 팔 (서보 10–12)" }).check();
      await page.getByRole("button", { name: "오른쪽 팔 힘 빼기" }).click();
      await page.getByTestId("teach-in").getByText("서보 10–12의 힘이 빠졌어요 (확인함).").waitFor();
      expect(await text(page, "teach-in-status")).toBe(
        "힘 빠짐: 서보 10–12. 나머지 서보는 제자리를 유지해요.",
      );
      await page.getByRole("tab", { name: "티칭 (켜짐)", exact: true }).waitFor();
      await page.getByRole("heading", { level: 3, name: "손으로 자세 잡기 (데모 로봇)" }).waitFor();
      await page.getByLabel("오른쪽 팔꿈치 (서보 12)").fill("120");
      await page.getByTestId("teach-pos-12").filter({ hasText: "120" }).waitFor();
      await expectTidy(page, "teach", viewport);
      await page.getByRole("button", { name: "장면 1에 자세 읽기" }).click();
      await page
        .getByTestId("teach-in")
        .getByText("서보 0–15의 위치를 장면 1의 끝 자세로 읽어 넣었어요")
        .waitFor();
      await page.getByRole("button", { name: "티칭 끝내기" }).click();
      await page.getByTestId("teach-in").getByText("티칭을 끝냈어요.").waitFor();
      expect(await notice(page, "teach-in")).toBe(
        "서보 10–12을(를) 자세를 잡은 자리에 고정했어요 (토크 켜짐, 확인함). 티칭을 끝냈어요. 로봇이 일반 모드로 돌아왔고, 모든 서보가 제자리를 유지해요.",
      );

      // Play: the choice, the question before the robot moves, and what the robot confirmed.
      await showTab(page, "play");
      await page.getByRole("radio", { name: "선택한 장면 (1)" }).waitFor();
      await page.getByRole("radio", { name: "모션 전체 (장면 2개)" }).waitFor();
      expect(await text(page, "play-summary")).toMatch(/^장면 1: 프레임 \d+개, [\d.]+초\.$/);
      await page.getByRole("button", { name: "로봇에서 재생…" }).click();
      const ask = page.getByTestId("play-confirm");
      await ask.waitFor();
      expect(squash(await ask.locator("#play-question").textContent())).toMatch(
        /^로봇이 장면 1을\(를\) 따라 움직여요 \([\d.]+초\)\. 로봇을 잡거나 혼자 설 수 있는지 확인해 주세요\.$/,
      );
      await ask.getByRole("button", { name: "취소" }).waitFor();
      await expectTidy(page, "play", viewport);
      await ask.getByRole("button", { name: "장면 1 재생" }).click();
      await page.getByTestId("play-panel").getByText("재생했어요").waitFor({ timeout: 20_000 });
      expect(await notice(page, "play-panel")).toMatch(
        /^장면 1을\(를\) 재생했어요 \(프레임 \d+개, [\d.]+초\)\. 서보는 마지막 프레임 자세를 유지해요\.$/,
      );

      // Check: a position outside the joint's safe range is a warning, counted on the tab, worded in Korean.
      await showTab(page, "pose");
      await typeInto(page, "end-3", "254");
      const check = page.getByRole("tab", { name: /^검사 \(경고 \d+개\)$/ });
      await check.waitFor();
      await check.click();
      expect(await text(page, "editor-check")).toMatch(/^오류 0개, 경고 \d+개\.$/);
      const warning = page.locator('[data-testid="editor-warning"][data-code="rbm-unsafe-position"]');
      expect(squash(await warning.locator(".warning-head").textContent())).toMatch(
        /^심각 관절의 안전 범위를 벗어난 위치 \(\d+\)$/,
      );
      await warning.locator("summary").click();
      await warning.getByRole("button", { name: "장면 1, 서보 3" }).waitFor();
      // The checker's own sentence is Korean too (motions/issue-text.ts), with the value typed.
      expect(await warning.locator('.issue span[lang="en"]').count()).toBe(0);
      expect(squash(await warning.locator(".issue").first().textContent())).toMatch(/[가-힣].*254/);
      await expectTidy(page, "check", viewport);

      // Drafts: the list and the question before a draft is deleted.
      const drafts = page.getByTestId("drafts-card");
      await drafts.getByRole("heading", { level: 2, name: "임시 저장본" }).waitFor();
      const draft = drafts.getByTestId("draft");
      expect(squash(await draft.locator(".draft-open").textContent())).toBe("편집기에서 열려 있음");
      expect(squash(await draft.locator("p.num").textContent())).toMatch(/^장면 2개 · \d\d:\d\d 저장$/);
      await draft.getByRole("button", { name: "NewMotion 지우기" }).click();
      const confirm = drafts.getByRole("alertdialog");
      expect(squash(await confirm.textContent())).toContain("임시 저장본 NewMotion을(를) 지울까요?");
      await confirm.getByRole("button", { name: "임시 저장본 지우기" }).waitFor();
      await drafts.scrollIntoViewIfNeeded();
      await expectTidy(page, "drafts", viewport);
      await confirm.getByRole("button", { name: "취소" }).click();
      await context.close();
    });
  }
});
