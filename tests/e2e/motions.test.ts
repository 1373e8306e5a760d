import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { memoryFootprint } from "../../src/protocol/catalog.ts";
import { motionImage } from "../../src/protocol/motion-image.ts";
import { motionDurationMs, parseRbm } from "../../src/protocol/rbm.ts";
import { formatSeconds } from "../../src/ui/features/motions/plot-data.ts";
import { CABLE, loadMotions, openConnected } from "./connected-page.ts";
import {
  cspViolations,
  expectText,
  FAST,
  robotTime,
  squash,
  type TestContext,
  useApp,
  watchPage,
} from "./harness.ts";
import {
  exampleText,
  imageHex,
  longMotion,
  rbmFile,
  showTab,
  withJumps,
  withSerial,
  withShortFrames,
  withUnsafePosition,
} from "./motion-fixtures.ts";
import type { RbcTestOptions } from "./rbc-test-globals.ts";
import "./rbc-test-globals.ts";
import {
  expectPageOkAtSizes,
  PHONE,
  type Size,
  shot,
  sizeName as size,
  sizeName,
  texts,
} from "./i18n-checks.ts";

const app = useApp();

/** A paced link (115200 baud, 16 ms FTDI latency), so uploads take as long as on the wire. */
const PACED: RbcTestOptions = { baudPacing: true, latencyMs: 16 };
/** The simulated robot's time (ms of its clock). */
const _robotNow = (page: Page) => page.evaluate(() => window.__rbcTest?.clock.now() ?? Number.NaN);

const bytesFromPc = (page: Page) => page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? -1);
const simMotionsHex = (page: Page) =>
  page.evaluate(() =>
    (window.__rbcTest?.sim.motions ?? []).map((m) =>
      Array.from(m.bytes, (b) => b.toString(16).padStart(2, "0")).join(""),
    ),
  );

/** Records every text the upload figures show, so a test can see the progress that flashed by. */
async function recordFigures(page: Page): Promise<void> {
  await page.evaluate(() => {
    const seen: string[] = [];
    (window as unknown as { __figures: string[] }).__figures = seen;
    new MutationObserver(() => {
      const el = document.querySelector('[data-testid="upload-figures"]');
      const text = el?.textContent?.replace(/\s+/g, " ").trim();
      if (text && seen.at(-1) !== text) seen.push(text);
    }).observe(document.body, { subtree: true, childList: true, characterData: true });
  });
}

describe("motions view", () => {
  it("checks wave.rbm, uploads it after the experimental notice, and the robot holds the exact image", async () => {
    // The paced link 3 times faster: the progress of its 10 chunks still shows (figures, rate, time left).
    const { page, context } = await app.newPage({ start: CABLE, options: { ...PACED, timeScale: 3 } });
    const seen = watchPage(page, app.origin);
    await loadMotions(page, app.url);
    const wave = exampleText("wave.rbm");
    await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", wave));
    const card = page.getByTestId("motion-file");
    await card.waitFor();
    await expectText(card, "RbcPanel_Wave", { contains: true });
    await expectText(card, /Scenes\s*6 Servos\s*16/);
    await expectText(card, /Plays for\s*3\.2 s/);
    await expectText(card, /To send to the robot\s*624 bytes/);
    await expectText(card, /Memory it takes\s*640 bytes/);
    // The scene table and the chart (uPlot, loaded on demand).
    await page.getByTestId("scene-section").waitFor();
    await expect.poll(() => page.locator(".scene-table tbody tr").count()).toBe(6);
    await page.locator('[data-testid="motion-chart"][data-chart="drawn"]').waitFor();
    expect(await page.locator('[data-testid="motion-chart"] canvas').count()).toBeGreaterThan(0);
    await expectText(page.locator('[data-testid="motion-chart"] .u-legend'), "Left knee", { contains: true });

    // A real robot (the fake port is hardware): the panel says it is experimental and asks first.
    const before = await bytesFromPc(page);
    await page.getByTestId("upload-motion").click();
    const confirm = page.getByTestId("upload-confirm");
    await confirm.waitFor();
    await expectText(confirm, "experimental", { contains: true });
    await expectText(confirm, "not been verified on real RBC firmware", { contains: true });
    await expectText(confirm, "held or lying down", { contains: true });
    expect(await bytesFromPc(page)).toBe(before);

    await recordFigures(page);
    await page.getByRole("button", { name: "Upload (experimental)" }).click();
    // The result shows in the file's card, where the upload was started.
    const result = card.getByText(/^Uploaded wave\.rbm/);
    await result.waitFor({ timeout: 15_000 });
    await expectText(result, /624 bytes in 10 chunks/);
    await expectText(result, /bytes\/s/);
    // One number: the one Run takes, with the remote key that plays it (issue 23 item 2).
    await expectText(result, "Stored as motion 12 (key 1): Run takes this number.", { contains: true });
    const text = await result.textContent().then(squash);
    expect(text).not.toContain("downloaded motion 1");
    await expectText(result, "Free motion memory: 23,936 of 24,576 bytes (was 24,576", { contains: true });
    await expectText(result, "Error code after the upload: no error", { contains: true });
    await expectText(result, "held or lying down", { contains: true });
    const figures = await page.evaluate(() => (window as unknown as { __figures: string[] }).__figures);
    // Progress was drawn while the chunks went out. The last acknowledgement and the result can come within one
    // frame, so "624 of 624" need not be drawn before the result replaces it: the result says all 624 were sent.
    expect(figures.some((f) => /\b\d+ of 624 bytes \(\d+%\)/.test(f))).toBe(true);
    expect(figures.some((f) => /bytes\/s/.test(f) && /left/.test(f))).toBe(true);

    expect(await simMotionsHex(page)).toEqual([imageHex(wave)]);
    // Memory figures refreshed: used and free on the Files tab, the counts on the Memory tab, and the device card.
    await expectText(page.getByTestId("mem-motion-used"), "640 bytes used");
    await expectText(page.getByTestId("mem-motion-text"), "23,936 of 24,576 bytes free");
    await showTab(page, "Memory");
    await expectText(page.getByTestId("mem-motion-used"), "640 of 24,576 bytes used");
    await expectText(page.getByTestId("mem-motion-count"), /^1 of 20 motions/);
    await expectText(
      page.locator('[data-testid="shelf-entry"][data-motion="12"]'),
      /^12 RbcPanel_Wave remote: key 1 · plays 3\.2 s /,
    );
    // Run offers it by name and length.
    await showTab(page, "Run");
    const download = page.locator('[data-testid="downloaded-motions"] [data-motion="12"]');
    await expectText(download, "12 RbcPanel_Wave key 1 3.2 s");
    await page.getByRole("link", { name: "Robot" }).click();
    await expectText(
      page.getByTestId("memory-motion-text"),
      /640 of 24,576 bytes used|23,936 of 24,576 bytes free/,
    );

    expect(seen.errors).toEqual([]);
    expect(seen.foreignRequests).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("cancels an upload: sending stops, the robot records nothing, and the panel says how much was acknowledged", async () => {
    // The paced link in real time: the 20 KB upload takes seconds, and every acknowledgement keeps its full
    // timeout (500 ms) on a busy machine (at 4 times the speed, a CI machine once missed one by a few ms).
    const { page, context } = await app.newPage({ start: CABLE, options: PACED });
    await loadMotions(page, app.url);
    const long = longMotion(exampleText("wave.rbm"), 40);
    await page.getByTestId("rbm-files").setInputFiles(rbmFile("Long.rbm", long));
    await page.getByTestId("upload-motion").click();
    await page.getByRole("button", { name: "Upload (experimental)" }).click();
    const midway = page.getByTestId("upload-figures").filter({ hasText: /\((?:[5-9]|[1-9]\d)%\)/ });
    const ended = page.getByRole("status", { name: "Upload result" }).locator(".notice");
    await midway.or(ended).first().waitFor({ timeout: 15_000 });
    // An upload that ended before it could be cancelled says why here, not as a time-out.
    expect(await ended.count().then((n) => (n ? ended.first().textContent() : ""))).toBe("");
    await page.getByRole("button", { name: "Cancel upload" }).click();

    const result = page.getByText(/^Upload cancelled/);
    await result.waitFor({ timeout: 10_000 });
    await expectText(result, /Upload cancelled \([\d,]+ of 20,?748 bytes were acknowledged\)/);
    await expectText(result, "recorded nothing", { contains: true });
    await expect.poll(() => page.getByTestId("upload-progress").count()).toBe(0);
    // Nothing more goes out, and the robot holds no motion.
    const after = await bytesFromPc(page);
    await robotTime(page, 400);
    expect(await bytesFromPc(page)).toBe(after);
    expect(await simMotionsHex(page)).toEqual([]);
    await context.close();
  });

  it("never sends a byte of a file with errors and says why in words", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await loadMotions(page, app.url);
    const before = await bytesFromPc(page);
    await page
      .getByTestId("rbm-files")
      .setInputFiles(rbmFile("Edited.rbm", withShortFrames(exampleText("wave.rbm"))));
    const card = page.getByTestId("motion-file");
    await card.waitFor();
    await expectText(
      page.getByTestId("rbm-issues"),
      /Error Scene 0 has frames 10 ms apart \(200 ms \/ 20 frames\); the RBC needs at least 20 ms/,
    );
    // The file is still shown, so the person can see which scene is wrong.
    await expect.poll(() => page.getByTestId("scene-section").isVisible()).toBe(true);
    const upload = page.getByTestId("upload-motion");
    await expect.poll(() => upload.isDisabled()).toBe(true);
    await expectText(
      page.getByTestId("upload-why"),
      "Cannot upload: the file has 1 error (listed below). Nothing is sent.",
    );
    await upload.click({ force: true }).catch(() => {});
    await robotTime(page, 200);
    expect(await bytesFromPc(page)).toBe(before);
    expect(await simMotionsHex(page)).toEqual([]);
    await context.close();
  });

  it("opens files by drop and by keyboard, and warns about a motion made for another robot", async () => {
    const { page, context } = await app.newPage({ start: CABLE });
    await loadMotions(page, app.url);
    const text = withSerial(exampleText("bow.rbm"), "1234567890123");
    const transfer = await page.evaluateHandle((t) => {
      const dt = new DataTransfer();
      dt.items.add(new File([t], "Other.rbm", { type: "text/plain" }));
      return dt;
    }, text);
    await page.dispatchEvent('[data-testid="rbm-drop"]', "drop", { dataTransfer: transfer });
    const card = page.getByTestId("motion-file");
    await card.waitFor();
    await expectText(
      card,
      "made for the robot with serial number 1234567890123, but the connected robot is 8958899989309",
      { contains: true },
    );
    // Warnings do not block an upload.
    await expect.poll(() => page.getByTestId("upload-motion").isEnabled()).toBe(true);

    // The drop zone is a button for the keyboard too: Enter and Space open the (multiple) file picker.
    expect(await page.getByTestId("rbm-files").getAttribute("multiple")).not.toBeNull();
    await page.evaluate(() => {
      const w = window as unknown as { __picks: number };
      w.__picks = 0;
      document.getElementById("rbm-input")?.addEventListener("click", (e) => {
        w.__picks++;
        e.preventDefault();
      });
    });
    await page.getByTestId("rbm-drop").focus();
    await page.keyboard.press("Enter");
    await page.keyboard.press("Space");
    await expect.poll(() => page.evaluate(() => (window as unknown as { __picks: number }).__picks)).toBe(2);
    await context.close();
  });

  it("opens one of the project's example motions from the keyboard, exactly like a picked file", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    const seen = watchPage(page, app.origin);
    const scripts: string[] = [];
    page.on("request", (r) => {
      if (r.resourceType() === "script") scripts.push(new URL(r.url()).pathname);
    });
    await loadMotions(page, app.url);
    const text = exampleText("squat.rbm");
    const motion = parseRbm(text);
    const image = motionImage(motion);
    // The examples are not loaded until one is opened.
    expect(scripts.some((s) => s.includes("squat"))).toBe(false);

    // A disclosure, then one button per example that says what the motion does.
    const examples = page.getByTestId("examples");
    await examples.locator("summary").focus();
    await page.keyboard.press("Enter");
    const open = page.getByRole("button", { name: "Open squat.rbm" });
    await open.waitFor();
    const description = await open.getAttribute("aria-describedby");
    await expectText(page.locator(`#${description}`), "squats twice", { contains: true });
    await open.focus();
    await page.keyboard.press("Enter");

    const card = page.getByTestId("motion-file");
    await card.waitFor();
    expect(scripts.some((s) => s.includes("squat"))).toBe(true);
    await page.getByText("Opened the example squat.rbm.").waitFor();
    const fact = (label: string, value: string | number) =>
      expectText(card, `${label}${String(value)}`.replace(/\s+/g, " "), { contains: true });
    await expectText(card, `${motion.name} squat.rbm`, { contains: true });
    await fact("Scenes", motion.scenes.length);
    await fact("Servos", motion.servos.length);
    await fact("Plays for", formatSeconds(motionDurationMs(motion)));
    await fact("To send to the robot", `${image.length.toLocaleString("en-US")} bytes`);
    await fact("Memory it takes", `${memoryFootprint(image.length).toLocaleString("en-US")} bytes`);
    await expectText(card, "Checked: no errors, no warnings.", { contains: true });
    await expect.poll(() => page.locator(".scene-table tbody tr").count()).toBe(motion.scenes.length);

    // Uploaded like any other file: the robot holds exactly its image.
    await card.getByTestId("upload-motion").click();
    await page.getByRole("button", { name: "Upload (experimental)" }).click();
    await page.getByText(/^Uploaded squat\.rbm/).waitFor();
    expect(await simMotionsHex(page)).toEqual([imageHex(text)]);

    expect(seen.errors).toEqual([]);
    expect(seen.foreignRequests).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("on the demo robot uploads without asking, and a reset first puts the upload into slot 1", async () => {
    // The in-app demo robot on the faster clock too (its simulator and the panel's client share it).
    const { page, context } = await app.newPage({ options: FAST });
    await page.goto(app.url);
    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await page.getByRole("link", { name: "Motions" }).click();
    await page.getByTestId("mem-motion-text").filter({ hasText: "24,576 of 24,576" }).waitFor();
    await page
      .getByTestId("rbm-files")
      .setInputFiles([
        rbmFile("wave.rbm", exampleText("wave.rbm")),
        rbmFile("bow.rbm", exampleText("bow.rbm")),
      ]);
    const cards = page.getByTestId("motion-file");
    await cards.nth(1).waitFor();
    await cards.nth(0).getByTestId("upload-motion").click();
    await page.getByText(/^Uploaded wave\.rbm/).waitFor();
    // The upload finished without a question (the demo robot is not asked about); read after it, not before
    // the click was drawn.
    expect(await page.getByTestId("upload-confirm").count()).toBe(0);
    await cards.nth(1).getByTestId("upload-motion").click();
    await page.getByText(/^Uploaded bow\.rbm/).waitFor();
    await showTab(page, "Memory");
    await expectText(
      page.getByTestId("shelf-list"),
      /^12 RbcPanel_Wave remote: key 1 · plays 3\.2 s .* 13 RbcPanel_Bow remote: key 2 · plays /,
    );
    await showTab(page, "Files");
    await page.getByTestId("reset-first").check();
    await cards.nth(1).getByTestId("upload-motion").click();
    const result = page.getByText(/^Uploaded bow\.rbm/);
    await result.filter({ hasText: "Free motion memory: 24,064 of" }).waitFor();
    await expectText(page.getByTestId("mem-motion-text"), "24,064 of 24,576 bytes free");
    await showTab(page, "Memory");
    await expectText(page.getByTestId("shelf-list"), /^12 RbcPanel_Bow remote: key 1 · /);
    const list = await page.getByTestId("shelf-list").textContent().then(squash);
    expect(list).not.toContain("RbcPanel_Wave");

    // An action file goes up byte for byte, with the format called unverified; its result shows beside it.
    await expectText(
      page.getByTestId("action-card"),
      "No action file format is known: the file's bytes are sent as they are",
      { contains: true },
    );
    await page.getByTestId("action-file").setInputFiles({
      name: "wave.act",
      mimeType: "application/octet-stream",
      buffer: Buffer.from(Array.from({ length: 100 }, (_, i) => i)),
    });
    await page.getByTestId("upload-action").click();
    await page
      .getByTestId("action-card")
      .getByText(/^Uploaded wave\.act: 100 bytes in 2 chunks/)
      .waitFor();
    await expectText(page.getByTestId("mem-action-text"), "8,064 of 8,192 bytes free");
    await context.close();
  });
});

/**
 * The Motions view in Korean (issue #14 item 1): a Korean browser gets every tab in Korean with `lang="ko"`
 * (Files with an example open and its scenes shown, a file's warnings and errors, an upload; Memory; Run with
 * its confirmation and result; Sounds), the sentences made by the actions too; no catalogue key shows; no
 * button's label overflows it and nothing scrolls sideways at 1280×800 and 390×844; axe finds no violation.
 * With RBC_SHOTS=<dir>, screenshots of every tab at both sizes go there to be looked at.
 */
describe("in Korean (ko-KR)", () => {
  const TABS = { files: "파일", uploads: "메모리", run: "실행", sounds: "소리" } as const;

  /** Opens the Motions view in Korean with the fake robot connected at start, once its memory has been read. */
  async function openMotions(size: Size): Promise<{ page: Page; context: TestContext }> {
    const opened = await openConnected(app, {
      robot: "cable",
      view: "motions",
      locale: "ko-KR",
      size,
      options: FAST,
    });
    const { page } = opened;
    await page
      .getByTestId("mem-motion-text")
      .filter({ hasText: "24,576바이트 중 24,576바이트 남음" })
      .waitFor();
    return opened;
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
  const expectGood = (page: Page, where: string, ready?: () => Promise<void>) =>
    expectPageOkAtSizes(page, where, {
      lang: "ko",
      shot: (size) => `motions-${where}-ko-${sizeName(size)}`,
      ...(ready ? { ready } : {}),
    });

  // One page per test for both sizes: the flow once at 390×844 (the phone, where Korean labels are tightest),
  // each state's checks at 1280×800 and at 390×844 (`expectGood`).
  describe("the Motions view in Korean", () => {
    it("shows the Files tab in Korean with an example open, fitting at 1280×800 and at 390×844", async () => {
      const { page, context } = await openMotions(PHONE);
      await expectText(page.getByRole("heading", { level: 1 }), "모션");
      await expect.poll(() => texts(page.getByRole("tab"))).toEqual(["파일", "메모리", "실행", "소리"]);
      await expect.poll(() => page.getByRole("tablist").getAttribute("aria-label")).toBe("모션");
      const files = page.getByTestId("motion-files");
      await expectText(files.getByRole("heading", { level: 2 }), "모션 파일");
      await expectText(files.locator(".drop-title"), "모션 파일 열기 (.rbm)");
      await expectText(page.getByTestId("mem-motion-used"), "0바이트 사용");
      await page.getByLabel("먼저 모션 메모리 초기화", { exact: false }).waitFor();

      // An example, opened from the disclosure: its facts, its check, its scenes and chart.
      await page.getByText("예제 모션 열기").click();
      await page.getByRole("button", { name: "wave.rbm 열기" }).click();
      await page.getByText("예제 wave.rbm을(를) 열었어요.").waitFor();
      const card = page.getByTestId("motion-file").filter({ hasText: "wave.rbm" });
      await expect
        .poll(() => texts(card.locator(".file-facts dt")))
        .toEqual(["장면", "서보", "재생 시간", "로봇에 보낼 크기", "차지할 메모리"]);
      await expect
        .poll(() => texts(card.locator(".file-facts dd")))
        .toEqual(["6", "16", "3.2초", "624바이트", "640바이트"]);
      await expectText(card.locator(".check-ok"), "확인함: 오류 없음, 경고 없음.");
      await expectText(card.getByTestId("scenes-toggle"), "장면과 차트 숨기기");
      await expectText(card.getByTestId("preview-toggle"), "3D 미리 보기");
      await expectText(card.getByRole("button", { name: "wave.rbm 닫기" }), "닫기");
      await expectText(
        card.getByTestId("upload-why"),
        "먼저 확인을 받아요. 실제 로봇에 업로드하는 기능은 실험 단계예요.",
      );
      const scenes = page.getByTestId("scene-section");
      await expectText(scenes.getByRole("heading"), "RbcPanel_Wave의 장면");
      await expect
        .poll(() => texts(scenes.locator(".scene-table th")))
        .toEqual(["#", "이름", "프레임", "시작", "길이", "프레임 간격"]);
      await expect
        .poll(() => texts(scenes.locator(".scene-table tbody tr").nth(1).locator("td")))
        .toEqual(["1", expect.any(String), "10", "0.8초", "0.4초", "40ms"]);
      await page.locator('[data-testid="motion-chart"][data-chart="drawn"]').waitFor();
      await expectText(page.locator('[data-testid="motion-chart"] .u-legend'), "2 왼쪽 무릎", {
        contains: true,
      });
      await expectGood(page, "files");

      // A file with warnings and one with an error: the panel's words and the checker's sentences in Korean
      // (the motion file checker's Korean block at the end of this file has more of them).
      await page
        .getByTestId("rbm-files")
        .setInputFiles([
          rbmFile("Jumpy.rbm", withJumps(exampleText("wave.rbm"), 2)),
          rbmFile("Edited.rbm", withShortFrames(exampleText("wave.rbm"))),
        ]);
      await page.getByText("파일 2개를 열었어요.").waitFor();
      const jumpy = page.getByTestId("motion-file").filter({ hasText: "Jumpy.rbm" });
      await expectText(
        jumpy.getByTestId("check-summary"),
        "확인함: 오류 0개, 경고 16개 (1종류, 심각한 경고 없음).",
      );
      const group = jumpy.getByTestId("warning-group");
      await expectText(group.locator(".weight"), "사소함");
      await expectText(group.locator("strong"), "장면 사이에서 서보가 튐");
      await expectText(
        group.locator(".warning-meaning"),
        "가장 크게 튀는 폭은 2단계로, 거의 보이지 않는 작은 떨림이에요.",
        { contains: true },
      );
      await group.getByText("16개 모두 보기").click();
      const first = group.locator(".issues li").first();
      await expectText(
        first,
        "장면 0에서 서보 0번(왼쪽 엉덩이 좌우)의 끝 위치는 125인데, 장면 1에서는 127에서 시작해서 서보가 튀어요.",
      );
      expect(await first.locator('[lang="en"]').count()).toBe(0);
      const edited = page.getByTestId("motion-file").filter({ hasText: "Edited.rbm" });
      await expectText(edited.getByTestId("check-summary"), /^확인함: 오류 1개, 경고 0개\.$/);
      await expectText(edited.locator(".issue--error .issue-kind"), "오류");
      await expectText(edited.locator(".issue--error"), /^오류 장면 0의 프레임 간격이 10ms예요 /);
      await expectText(
        edited.getByTestId("upload-why"),
        "업로드할 수 없어요. 파일에 오류가 1개 있어요 (아래 목록). 아무것도 보내지 않아요.",
      );
      await expectGood(page, "files-checked");

      // The upload: its question and its result, in Korean.
      await card.getByTestId("upload-motion").click();
      const confirm = card.getByTestId("upload-confirm");
      await expectText(confirm.locator("#upload-confirm-title"), "wave.rbm을(를) 로봇에 업로드할까요?");
      await confirm.getByRole("button", { name: "취소" }).waitFor();
      await expectGood(page, "upload-confirm", () => confirm.scrollIntoViewIfNeeded());
      await confirm.getByRole("button", { name: "업로드 (실험 기능)" }).click();
      const result = card.getByText(/^wave\.rbm을\(를\) 업로드했어요\./);
      await result.waitFor({ timeout: 15_000 });
      await expectText(
        result,
        /^wave\.rbm을\(를\) 업로드했어요\. 624바이트를 조각 \d+개로 [\d.]+초 동안 보냈고 \(초당 [\d,]+바이트\), 로봇이 모든 조각을 받았다고 확인했어요\./,
      );
      await expectText(result, "모션 12번(1번 키)으로 저장했어요. 실행할 때 이 번호를 써요.", {
        contains: true,
      });
      await expectText(result, "남은 모션 메모리: 24,576바이트 중 23,936바이트 (전에는 24,576바이트", {
        contains: true,
      });
      await expectText(result, "업로드 후 오류 코드: 오류 없음.", { contains: true });
      await expectGood(page, "uploaded");
      await context.close();
    });

    it("shows Memory, Run and Sounds in Korean, fitting at 1280×800 and at 390×844", async () => {
      const { page, context } = await openMotions(PHONE);
      await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", exampleText("wave.rbm")));
      await page.getByTestId("upload-motion").click();
      await page.getByRole("button", { name: "업로드 (실험 기능)" }).click();
      await page.getByText(/^wave\.rbm을\(를\) 업로드했어요\./).waitFor({ timeout: 15_000 });

      // Memory: the areas as used, the uploads of this connection, an action file.
      await showTab(page, "uploads");
      const memory = page.getByTestId("memory-card");
      await expectText(memory.getByRole("heading"), "로봇 메모리");
      await expectText(page.getByTestId("mem-motion-used"), "24,576바이트 중 640바이트 사용");
      await expectText(page.getByTestId("mem-motion-text"), "24,576바이트 중 23,936바이트 남음");
      await expectText(
        page.getByTestId("mem-motion-count"),
        "마지막 초기화나 전원을 켠 뒤로 모션 20개 중 1개 저장됨",
      );
      await expectText(
        page.locator('[data-testid="shelf-entry"][data-motion="12"]'),
        "12 RbcPanel_Wave 리모컨: 1번 키 · 재생 시간 3.2초 방금 업로드했고, 로봇의 메모리 계산에서 저장된 게 확인됐어요 지금 실행",
      );
      await expectText(page.getByTestId("uploads-card").locator("summary"), "메모리를 세는 방법");
      await page.getByTestId("action-file").setInputFiles({
        name: "wave.act",
        mimeType: "application/octet-stream",
        buffer: Buffer.alloc(100, 1),
      });
      const action = page.getByTestId("action-card");
      await action.getByText("wave.act, 100바이트").waitFor();
      await action.getByRole("button", { name: "액션 파일 업로드" }).waitFor();
      await action.getByLabel("먼저 액션 메모리 초기화 (업로드한 액션을 모두 지워요)").waitFor();
      await expectText(action.locator("label.file-button"), "액션 파일 고르기…");
      await expectGood(page, "memory");

      // Run: the basic-posture guidance, the built-in and downloaded motions, the other slots, the question
      // before the robot moves, and the result.
      await showTab(page, "run");
      const run = page.getByTestId("run-card");
      await expectText(run.getByRole("heading", { level: 2 }), "모션 실행");
      await expect
        .poll(() => texts(run.getByRole("heading", { level: 3 })))
        .toEqual(["내장 모션", "업로드한 모션"]);
      await expectText(
        page.getByTestId("posture-guidance"),
        "로봇을 켠 뒤에는 기본 자세(7)만 받아들여요. 먼저 기본 자세를 실행해 주세요. 그 전까지는 다른 모션을 모두 아무 말 없이 무시해요.",
      );
      await expectText(run.locator('[data-motion="7"]'), "7 기본 자세 1.8초 먼저 실행");
      await expectText(run.locator('[data-motion="12"]'), "12 RbcPanel_Wave 1번 키 3.2초");
      await run.getByText("다른 업로드 슬롯 (19)").click();
      // The slot button shows its number and key; a screen reader hears "모션 13번 실행" and the key.
      await run.getByRole("button", { name: /^모션 13\s?번 실행 2번 키$/ }).waitFor();
      await run.locator('[data-motion="7"]').click();
      const ask = page.getByTestId("move-confirm");
      await expectText(
        ask,
        "로봇이 움직여요. 로봇을 잡거나 주변에 공간을 비워 주세요. 패널은 연결할 때마다 한 번만 물어봐요. 정지(Esc)를 누르면 모션이 지금 장면이 끝날 때 멈춰요. 로봇은 서보에 힘이 들어간 채로 멈춘 자세를 유지해요. 넘어지지는 않지만, 꼭 서 있는 자세는 아니에요. 모션 7번(기본 자세) 실행 취소",
      );
      await expectGood(page, "run-confirm");
      await page.locator("#confirm-move").click();
      await page.getByText("모션 7번(기본 자세)을 마쳤어요. 이제 로봇이 모든 모션을 받아들여요.").waitFor();
      await expectGood(page, "run");

      // Sounds: the buttons' names, and what a sound did.
      await showTab(page, "sounds");
      const sounds = page.getByTestId("sound-card");
      await expectText(sounds.getByRole("heading"), "소리");
      await sounds.getByRole("button", { name: "소리 4 아주 짧은 소리 0.4초" }).click();
      await sounds.getByText("소리 4번을 재생했어요 (0.4초).").waitFor();
      await expectGood(page, "sounds");
      await context.close();
    });
  });
});

/**
 * The motion file checker's sentences in Korean (issue #14 item 1): a Korean browser opens files with errors
 * (one the RBC refuses, one that cannot be read) and warnings of every weight; each issue is a Korean sentence
 * with the file's numbers and no English left in it; the page is `lang="ko"`, shows no catalogue key, no
 * button's label overflows it and nothing scrolls sideways at 1280×800 and 390×844; axe finds no violation.
 * With RBC_SHOTS=<dir>, screenshots go there to be looked at.
 */
describe("in Korean (ko-KR): the motion file checker", () => {
  /** The text with some `:`-separated fields replaced: [index, new text]... */
  function edit(source: string, ...changes: [number, string][]): string {
    const fields = source.split(":");
    for (const [i, value] of changes) fields[i] = value;
    return fields.join(":");
  }

  const WAVE = exampleText("wave.rbm");
  /** Field 128 of wave.rbm (16 servos): scene 0, servo record 2, its start position. */
  const SCENE0_RECORD2_START = 13 + 6 * 16 + 5 + 6 * 2 + 2;

  /** The files opened: warnings only; an error the RBC refuses; unreadable; warnings of every weight. */
  const FILES = [
    rbmFile("Jumpy.rbm", withJumps(WAVE, 2)),
    rbmFile("Edited.rbm", withShortFrames(WAVE)),
    rbmFile("Broken.rbm", edit(WAVE, [SCENE0_RECORD2_START, "x1"])),
    rbmFile("Odd.rbm", edit(withSerial(withUnsafePosition(WAVE), "1234567890123"), [10, "5"])),
  ];

  /** Opens the Motions view in Korean with the fake robot connected at start. */
  async function openMotions(size: Size): Promise<{ page: Page; context: TestContext }> {
    const opened = await openConnected(app, {
      robot: "cable",
      view: "motions",
      locale: "ko-KR",
      size,
      options: FAST,
    });
    await opened.page.getByTestId("motion-files").waitFor();
    return opened;
  }

  // One page for both sizes: the files opened once at 390×844, the page checked at 1280×800 and at 390×844.
  describe("the motion file checker's sentences in Korean", () => {
    it("says every problem of the opened files in Korean, fitting at 1280×800 and at 390×844", async () => {
      const { page, context } = await openMotions(PHONE);
      await page.getByTestId("rbm-files").setInputFiles(FILES);
      await page
        .getByText(/^파일 4개를 열었어요\./)
        .first()
        .waitFor();
      const card = (name: string) => page.getByTestId("motion-file").filter({ hasText: name });

      // An error the RBC refuses: the sentence names the scene itself, so no place is said before it.
      await expect
        .poll(() => texts(card("Edited.rbm").locator(".issue--error")))
        .toEqual([
          "오류 장면 0의 프레임 간격이 10ms예요 (200ms / 프레임 20개). RBC에는 20ms 이상이 필요해요. 프레임 수를 줄여 주세요.",
        ]);

      // A file that cannot be read: the field, by its number and what it holds.
      await expect
        .poll(() => texts(card("Broken.rbm").locator(".issue--error")))
        .toEqual(['오류 128번 필드(장면 0, 서보 레코드 2번의 시작 위치)는 정수여야 해요 (지금 값: "x1").']);

      // Warnings, grouped by kind; each single warning in Korean.
      const jumps = card("Jumpy.rbm").getByTestId("warning-group");
      await jumps.getByText("16개 모두 보기").click();
      await expectText(
        jumps.locator(".issues li").first(),
        "장면 0에서 서보 0번(왼쪽 엉덩이 좌우)의 끝 위치는 125인데, 장면 1에서는 127에서 시작해서 서보가 튀어요.",
      );
      const odd = card("Odd.rbm");
      for (const summary of await odd.locator(".warning-details summary").all()) await summary.click();
      const said = () => texts(odd.locator(".warning-details .issues li"));
      await expect
        .poll(said)
        .toContainEqual(
          expect.stringMatching(
            /^장면 0에서 서보 0번\(왼쪽 엉덩이 좌우\)이 안전 범위\(\d+-174\) 밖인 254 위치로 가요\.$/,
          ),
        );
      await expect
        .poll(said)
        .toContainEqual(
          expect.stringMatching(
            /^이 모션은 시리얼 번호 1234567890123 로봇용으로 만들었는데, 지금 연결된 로봇은 시리얼 번호 \d{13} 로봇이에요\. Motionbuilder는 이런 파일을 거부해요\. 이 로봇에 맞는 모션인지 확인해 주세요\.$/,
          ),
        );
      await expect.poll(said).toContain("10번 필드 값이 5인데, Motionbuilder는 항상 2(으)로 써요.");
      await expect
        .poll(said)
        .toContainEqual(
          expect.stringMatching(/^장면 0에서 서보 0번\(왼쪽 엉덩이 좌우\)의 끝 위치는 254인데/),
        );

      // Nothing is left in English: no sentence marked as English, no English sentence unmarked.
      const lists = page.locator('[data-testid="rbm-issues"], [data-testid="rbm-warnings"]');
      expect(await lists.locator('[lang="en"]').count()).toBe(0);
      const all = await texts(page.locator(".issues li"));
      expect(all.length).toBeGreaterThan(20);
      expect(
        all.filter((s) => !/\p{Script=Hangul}/u.test(s) || /\b(Scene|servo|must|the)\b/.test(s)),
      ).toEqual([]);

      await expectPageOkAtSizes(page, "the files", {
        lang: "ko",
        shot: (viewport) => `motion-issues-files-ko-${size(viewport)}`,
        ready: async (viewport) => {
          // Close-ups of each file's check, to be read (the whole page at 390 px is too tall to read).
          for (const name of ["Jumpy", "Edited", "Broken", "Odd"]) {
            await shot(card(`${name}.rbm`), `motion-issues-${name.toLowerCase()}-ko-${size(viewport)}`);
          }
          await card("Jumpy.rbm").scrollIntoViewIfNeeded();
        },
      });
      await context.close();
    });
  });
});
