import { readFile } from "node:fs/promises";
import { createRequire } from "node:module";
import type { Download, Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { mirrorPosition } from "../../src/motion/index.ts";
import { HUNO_BASIC_POSTURE, parseRbm, STANDARD_ZEROS } from "../../src/protocol/index.ts";
import { DEMO, loadConnected } from "./connected-page.ts";
import { cspViolations, expectText, FAST, squash, useApp, watchPage } from "./harness.ts";
import { rbmFile } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";
import { DESKTOP, expectPageOkAtSizes, pageLang as lang, PHONE, resizeTo } from "./i18n-checks.ts";

/**
 * The motion editor in the browser, without a robot (editing needs none): a three-scene motion made from the
 * template by typing and sliding, undo and redo (buttons and keys), mirror, save, reopen unchanged, drafts
 * across a reload, and the layout at desktop and phone widths. The selected scene's work is in tabs (Pose,
 * Scene, Tools, Teach-in, Play, Check); editor-layout.test.ts checks the layout itself.
 */

const app = useApp();

const VIEWPORTS = [
  { name: "1280×800", width: 1280, height: 800 },
  { name: "390×844", width: 390, height: 844 },
];

async function openEditor(page: Page): Promise<void> {
  await page.goto(`${app.url}#/editor`, { waitUntil: "domcontentloaded" });
  await page.getByTestId("editor").waitFor();
}

/** Types a value into a field and leaves it (a `change`, as a person pressing Tab). */
async function typeInto(page: Page, testId: string, value: string): Promise<void> {
  const field = page.getByTestId(testId);
  await field.fill(value);
  await field.press("Tab");
}

const fieldValue = (page: Page, testId: string) => page.getByTestId(testId).inputValue();

type EditorTab = "pose" | "scene" | "tools" | "teach" | "play" | "check";

/** Shows a tab of the selected scene's work and waits for its panel. */
async function showTab(page: Page, tab: EditorTab): Promise<void> {
  await page.locator(`#editor-tab-${tab}`).click();
  await page.locator(`#editor-panel-${tab}`).waitFor();
}

/**
 * Shows the Pose tab with the pose table's `columns`: at phone width a servo has one line, its end pose (with
 * the slider) or its start, torque and port; wider, every column is shown and there is nothing to choose.
 */
async function showPose(page: Page, columns: "end" | "more" = "end"): Promise<void> {
  await showTab(page, "pose");
  const choice = page.getByTestId("pose-columns");
  if (await choice.isVisible()) await choice.locator(`input[value="${columns}"]`).check();
}

/** Waits until the field `testId` shows `value` (the panel redraws on the next animation frame). */
async function expectValue(page: Page, testId: string, value: string | number): Promise<void> {
  await expect.poll(() => fieldValue(page, testId)).toBe(String(value));
}
const sceneCount = (page: Page) => page.locator('[data-testid="scene-list"] .scene-option').count();

async function bytesOf(download: Download): Promise<Buffer> {
  return readFile(await download.path());
}

async function saveFile(page: Page): Promise<Download> {
  const downloading = page.waitForEvent("download");
  await page.getByTestId("editor-save").click();
  return downloading;
}

/** Drags a slider with the mouse from its middle to `fraction` of its width, in several moves. */
async function dragSlider(page: Page, testId: string, fraction: number): Promise<void> {
  const slider = page.getByTestId(testId);
  await slider.scrollIntoViewIfNeeded();
  const box = await slider.boundingBox();
  if (!box) throw new Error(`${testId} is not visible`);
  const y = box.y + box.height / 2;
  await page.mouse.move(box.x + box.width / 2, y);
  await page.mouse.down();
  for (let i = 1; i <= 5; i++) {
    await page.mouse.move(box.x + box.width * (0.5 + ((fraction - 0.5) * i) / 5), y);
  }
  await page.mouse.up();
}

async function noSidewaysScroll(page: Page): Promise<void> {
  const overflow = await page.evaluate(
    () => document.documentElement.scrollWidth - document.documentElement.clientWidth,
  );
  expect(overflow).toBeLessThanOrEqual(0);
}

/** What the 3D canvas shows: how many pixels differ from its corner (the background), and a digest of all. */
async function canvasPicture(page: Page): Promise<{ drawn: number; total: number; digest: string }> {
  return page.evaluate(() => {
    const canvas = document.querySelector('[data-testid="editor-robot3d"] canvas') as HTMLCanvasElement;
    const copy = document.createElement("canvas");
    copy.width = canvas.width;
    copy.height = canvas.height;
    const g = copy.getContext("2d") as CanvasRenderingContext2D;
    g.drawImage(canvas, 0, 0);
    const { data } = g.getImageData(0, 0, copy.width, copy.height);
    let drawn = 0;
    let hash = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (
        Math.abs(data[i]! - data[0]!) +
          Math.abs(data[i + 1]! - data[1]!) +
          Math.abs(data[i + 2]! - data[2]!) >
        24
      )
        drawn++;
      hash = (hash * 31 + data[i]! + data[i + 1]! * 7 + data[i + 2]! * 13) >>> 0;
    }
    return { drawn, total: data.length / 4, digest: hash.toString(16) };
  });
}

const AXE_PATH = createRequire(import.meta.url).resolve("axe-core/axe.min.js");

/** axe-core's violations on the page, one line each (axe needs the page's CSP bypassed to be added). */
async function axeViolations(page: Page): Promise<string[]> {
  if (!(await page.evaluate(() => "axe" in window))) await page.addScriptTag({ path: AXE_PATH });
  return page.evaluate(async () => {
    type Result = { violations: { id: string; help: string; nodes: { target: unknown[] }[] }[] };
    const axe = (window as unknown as { axe: { run(): Promise<Result> } }).axe;
    const { violations } = await axe.run();
    return violations.map(
      (v) => `${v.id}: ${v.help} — ${v.nodes.map((n) => JSON.stringify(n.target)).join(", ")}`,
    );
  });
}

describe("motion editor accessibility", () => {
  it.each(["light", "dark"] as const)(
    "has no axe violations in %s mode, in every tab, with the demo robot and a refused value shown",
    async (scheme) => {
      const context = await app.browser.newContext({
        viewport: { width: 1280, height: 800 },
        serviceWorkers: "block",
        reducedMotion: "reduce",
        colorScheme: scheme,
        bypassCSP: true,
      });
      const page = await context.newPage();
      await page.goto(app.url, { waitUntil: "domcontentloaded" });
      await page.getByRole("button", { name: "Try the demo robot" }).click();
      await page.getByTestId("device-card").waitFor();
      await page.getByRole("link", { name: "Editor", exact: true }).click();
      await page.getByTestId("editor").waitFor();
      await page.getByTestId("scene-add").click();
      await page.locator("#scene-opt-1[aria-current=true]").waitFor();
      await typeInto(page, "end-3", "300");
      await page.getByTestId("field-problem").waitFor();
      await page.getByTestId("draft").waitFor();
      await page.locator('[data-testid="editor-robot3d"][data-state="ready"]').waitFor({ timeout: 20_000 });
      expect(await axeViolations(page)).toEqual([]);
      for (const tab of ["scene", "tools", "teach", "play", "check"] as const) {
        await showTab(page, tab);
        expect(await axeViolations(page), tab).toEqual([]);
      }
      await context.close();
    },
  );
});

describe.each(VIEWPORTS)("motion editor at $name", ({ width, height }) => {
  it("makes a three-scene motion from the template, undoes and redoes, mirrors, saves and reopens it unchanged", async () => {
    const { page, context } = await app.newPage({ viewport: { width, height } });
    const seen = watchPage(page, app.origin);
    await openEditor(page);

    // No drafts yet: the template, one scene in the basic posture.
    await expect.poll(() => sceneCount(page)).toBe(1);
    await expectValue(page, "end-10", String(HUNO_BASIC_POSTURE[10]));
    await expect.poll(() => page.getByTestId("editor-undo").isDisabled()).toBe(true);

    await typeInto(page, "motion-name", "Wave test");
    await expectText(page.getByTestId("editor-save-as"), "as Wave-test.rbm");

    // Scene 0: raise the left shoulder (servo 10, the robot's own left arm) by typing.
    await typeInto(page, "end-10", "100");
    await expectText(page.getByTestId("editor-undo"), "Undo: set Left shoulder pitch (end of scene 0)");

    // Scene 1 starts where scene 0 ends (continuity); its end is set with the slider, one undo step per drag.
    await page.getByTestId("scene-add").click();
    await page.locator("#scene-opt-1[aria-current=true]").waitFor();
    await expectValue(page, "start-10", "100");
    await dragSlider(page, "slider-10", 0.85);
    // The slider's own value is the browser's as the mouse left it; the field follows on the next render.
    const dragged = Number(await page.getByTestId("slider-10").inputValue());
    expect(dragged).toBeGreaterThan(100);
    await expectValue(page, "end-10", dragged);
    await page.getByTestId("editor-undo").click();
    await expectValue(page, "end-10", "100");
    await expectText(page.getByTestId("editor-undo"), "Undo: add scene 1");
    await page.getByTestId("editor-redo").click();
    await expectValue(page, "end-10", String(dragged));

    // Keys: Ctrl+Z and Ctrl+Shift+Z outside a text field; inside one they belong to the field.
    await page.getByTestId("scene-add").focus();
    await page.keyboard.press("Control+z");
    await expectValue(page, "end-10", "100");
    await page.keyboard.press("Control+Shift+z");
    await expectValue(page, "end-10", String(dragged));
    await page.getByTestId("motion-name").focus();
    await page.keyboard.press("Control+z");
    await expectValue(page, "end-10", String(dragged));

    // A refused value stays in its field with the reason; the document does not change.
    await typeInto(page, "end-3", "300");
    const problem = page.getByTestId("field-problem");
    await problem.waitFor();
    await expectText(problem, "0 to 254", { contains: true });
    await expect.poll(() => page.getByTestId("end-3").getAttribute("aria-invalid")).toBe("true");
    await expectText(page.getByTestId("editor-undo"), "Undo: set Left shoulder pitch (end of scene 1)");
    await typeInto(page, "end-3", String(HUNO_BASIC_POSTURE[3]));
    await page.getByTestId("field-problem").waitFor({ state: "detached" });
    await expect.poll(() => page.getByTestId("end-3").getAttribute("aria-invalid")).toBe("false");

    // Scene 2: a duplicate of scene 1, mirrored left to right (the right shoulder, 13, takes the left's pose, 10).
    await page.getByTestId("scene-duplicate").click();
    await page.locator("#scene-opt-2[aria-current=true]").waitFor();
    await showTab(page, "tools");
    await page.getByTestId("mirror-left-to-right").click();
    await page.getByTestId("editor-undo").filter({ hasText: "mirror" }).waitFor();
    await showPose(page);
    const mirrored = mirrorPosition(dragged, STANDARD_ZEROS[10]!, STANDARD_ZEROS[13]!);
    await expectValue(page, "end-13", String(mirrored));
    await expectValue(page, "end-10", String(dragged));
    await expect.poll(() => sceneCount(page)).toBe(3);

    // Save: Motionbuilder's format, what was made.
    const first = await saveFile(page);
    expect(first.suggestedFilename()).toBe("Wave-test.rbm");
    const saved = await bytesOf(first);
    const motion = parseRbm(saved.toString("latin1"));
    expect(motion.name).toBe("Wave test");
    expect(motion.scenes.map((s) => s.servos[10]!.end)).toEqual([100, dragged, dragged]);
    expect(motion.scenes.map((s) => s.servos[10]!.start)).toEqual([HUNO_BASIC_POSTURE[10], 100, dragged]);
    expect(motion.scenes[2]!.servos[13]!.end).toBe(mirrored);

    // A corrupt file is refused in words and changes nothing.
    await page.getByTestId("editor-file").setInputFiles(rbmFile("broken.rbm", "1:13:not a motion:"));
    await page.getByText(/broken\.rbm was not opened/).waitFor();
    await expect.poll(() => sceneCount(page)).toBe(3);

    // Reopen the saved file and save it again: byte for byte the same.
    await page.getByTestId("editor-new").click();
    await page.waitForFunction(
      () => document.querySelectorAll('[data-testid="scene-list"] .scene-option').length === 1,
    );
    await page.getByTestId("editor-file").setInputFiles(rbmFile("Wave-test.rbm", saved.toString("latin1")));
    await page.getByText(/Opened Wave-test\.rbm: Wave test, 3 scenes/).waitFor();
    await expect.poll(() => page.getByTestId("editor-undo").isDisabled()).toBe(true);
    const again = await bytesOf(await saveFile(page));
    expect(again.equals(saved)).toBe(true);

    // The scene list by keyboard: one Tab stop, the arrows move the selection and the focus.
    await page.locator("#scene-opt-0").focus();
    await page.keyboard.press("ArrowDown");
    await page.locator("#scene-opt-1[aria-current=true]").waitFor();
    await page.waitForFunction(() => document.activeElement?.id === "scene-opt-1");

    // Continuity: joined, a start follows the end before it (no jump); detached, a jump and its warning; Join.
    await showPose(page, "more");
    await typeInto(page, "start-0", "130");
    expect(await page.getByTestId("jump-0").count()).toBe(0);
    await showTab(page, "scene");
    await page.getByTestId("detach-1").check();
    await showPose(page, "more");
    await typeInto(page, "start-0", "135");
    await page.getByTestId("jump-0").waitFor();
    await expectText(page.getByTestId("jump-0"), "130", { contains: true });
    await showTab(page, "check");
    await page.locator('[data-testid="editor-warning"][data-code="rbm-scene-jump"]').waitFor();
    await showTab(page, "scene");
    await page.getByTestId("join-scene").click();
    await page.getByTestId("join-scene").waitFor({ state: "detached" });
    await showPose(page, "more");
    expect(await page.getByTestId("jump-0").count()).toBe(0);
    await expectValue(page, "start-0", "130");
    await showTab(page, "check");
    await page.getByTestId("editor-check").filter({ hasText: "No errors, no warnings" }).waitFor();
    expect(await page.locator('[data-testid="editor-warning"][data-code="rbm-scene-jump"]').count()).toBe(0);

    // Copy scene 0's pose into scene 2, then retime the whole motion to 3 s; a factor that is no number is refused.
    await page.locator("#scene-opt-2").click();
    await showTab(page, "tools");
    await page.getByTestId("copy-pose").filter({ hasText: "Copy into scene 2" }).waitFor();
    await page.getByTestId("copy-from").selectOption("0");
    await page.getByTestId("copy-pose").click();
    await page.getByTestId("editor-undo").filter({ hasText: "copy" }).waitFor();
    await showPose(page);
    await expectValue(page, "end-10", "100");
    await showTab(page, "tools");
    await page.getByTestId("retime-scope").selectOption("motion");
    await page.getByTestId("retime-mode").selectOption("duration");
    await page.getByTestId("retime-value").fill("3000");
    await page.getByTestId("retime-apply").click();
    await expectText(page.getByTestId("scene-total"), "3 scenes · 3.0 s");
    await page.getByTestId("retime-mode").selectOption("factor");
    await page.getByTestId("retime-value").fill("fast");
    await page.getByTestId("retime-apply").click();
    await page.getByTestId("field-problem").filter({ hasText: "A time factor" }).waitFor();
    await expectText(page.getByTestId("scene-total"), "3 scenes · 3.0 s");

    await noSidewaysScroll(page);
    expect(seen.errors).toEqual([]);
    expect(seen.foreignRequests).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("restores the draft after a reload, and lists, renames and deletes drafts", async () => {
    const { page, context } = await app.newPage({ viewport: { width, height } });
    await openEditor(page);
    await typeInto(page, "motion-name", "Kept");
    await typeInto(page, "end-0", "120");
    await page.getByTestId("draft-status").filter({ hasText: "saved" }).waitFor();

    await page.reload({ waitUntil: "domcontentloaded" });
    await page.getByTestId("editor").waitFor();
    const restored = page.getByText(/^Draft restored: Kept, saved \d\d:\d\d\.$/);
    await restored.waitFor();
    await expectValue(page, "end-0", "120");
    await expectValue(page, "motion-name", "Kept");

    // A second motion: the first stays in the Drafts list.
    await page.getByTestId("editor-new").click();
    await typeInto(page, "end-0", "121");
    const drafts = page.getByTestId("draft");
    await page.waitForFunction(() => document.querySelectorAll('[data-testid="draft"]').length === 2);
    const kept = drafts.filter({ hasText: "Kept" });
    await expectText(kept, /1 scene · saved \d\d:\d\d/);

    // Export it: its .rbm file.
    const exporting = page.waitForEvent("download");
    await kept.getByRole("button", { name: "Export Kept as .rbm" }).click();
    const exported = await exporting;
    expect(exported.suggestedFilename()).toBe("Kept.rbm");
    const keptMotion = parseRbm((await bytesOf(exported)).toString("latin1"));
    expect(keptMotion.name).toBe("Kept");
    expect(keptMotion.scenes[0]!.servos[0]!.end).toBe(120);

    // Rename it, then delete it (asked once).
    await kept.getByRole("button", { name: "Rename Kept" }).click();
    const name = page.getByLabel("New name");
    await name.fill("Kept twice");
    await name.press("Enter");
    await page.getByText("Renamed the draft to Kept twice.").waitFor();
    await drafts.filter({ hasText: "Kept twice" }).getByRole("button", { name: "Delete Kept twice" }).click();
    await page.getByRole("alertdialog").waitFor();
    await page.locator("#confirm-delete-draft").click();
    await page.getByText("Deleted the draft Kept twice.").waitFor();
    await expect.poll(() => drafts.count()).toBe(1);

    // A change made just before the page goes away (inside the autosave's 300 ms) is kept too.
    await typeInto(page, "end-0", "122");
    await page.reload({ waitUntil: "domcontentloaded" });
    await page.getByText(/^Draft restored: NewMotion, saved/).waitFor();
    await expectValue(page, "end-0", "122");
    await noSidewaysScroll(page);
    await context.close();
  });

  it("draws the scene's pose in 3D, and draws it again when the pose changes", async () => {
    const { page, context } = await app.newPage({ viewport: { width, height } });
    const seen = watchPage(page, app.origin);
    await openEditor(page);
    const view = page.locator('[data-testid="editor-robot3d"][data-state="ready"]');
    await view.waitFor({ timeout: 20_000 });
    await page.waitForFunction(
      () => Number(document.querySelector('[data-testid="editor-robot3d"]')?.getAttribute("data-frames")) > 0,
    );
    await expect.poll(() => view.getAttribute("data-pose")).toBe(HUNO_BASIC_POSTURE.join(" "));
    const before = await canvasPicture(page);
    expect(before.drawn / before.total).toBeGreaterThan(0.01);

    // Raise the left arm (10): the robot is drawn again, differently.
    await typeInto(page, "end-10", "20");
    await page.waitForFunction(() =>
      document
        .querySelector('[data-testid="editor-robot3d"]')
        ?.getAttribute("data-pose")
        ?.startsWith("125 179 199 88 108 126 72 49 163 141 20 "),
    );
    const after = await canvasPicture(page);
    expect(after.drawn / after.total).toBeGreaterThan(0.01);
    expect(after.digest).not.toBe(before.digest);
    await expect
      .poll(() => page.getByRole("img", { name: /3D view of the end pose of scene 0/ }).count())
      .toBe(1);
    expect(seen.errors).toEqual([]);
    await context.close();
  });
});

/**
 * The motion editor in Korean (issue #14 item 1), with the demo robot connected: a Korean browser gets the
 * Editor in Korean with `lang="ko"`, every tab (Pose with a refused value, Scene with refused frames, Tools
 * with a refused factor, Teach-in with a limb limp, Play with its question and result, Check with a warning)
 * and the Drafts list with its question; the sentences the actions make are Korean too. No catalogue key
 * shows, no button's label overflows it and nothing scrolls sideways at 1280×800 and 390×844, and axe finds no
 * violation (tests/e2e/i18n-checks.ts). Screenshots of every tab at both sizes with RBC_SHOTS=<dir>.
 */
describe("in Korean (ko-KR)", () => {
  const size = (viewport: { width: number; height: number }) => `${viewport.width}x${viewport.height}`;

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

  /**
   * Opens the Editor with the demo robot connected (a page opened with the start option `DEMO`; the Korean demo
   * button is connect.test.ts's) and a second scene added.
   */
  async function openEditor(page: Page): Promise<void> {
    await loadConnected(page, app.url, "editor");
    await page.getByTestId("editor").waitFor();
    await page.getByRole("button", { name: "뒤에 추가" }).click();
    await page.locator("#scene-opt-1[aria-current=true]").waitFor();
    await page.getByTestId("draft").waitFor();
    await page.locator('[data-testid="editor-robot3d"][data-state="ready"]').waitFor({ timeout: 20_000 });
  }

  /**
   * The layout checks of one state of the Editor (tests/e2e/i18n-checks.ts), its screenshot, and axe, at both
   * sizes on the same page (the window resized, then put back).
   */
  async function expectTidy(page: Page, where: string, ready?: () => Promise<void>): Promise<void> {
    await expectPageOkAtSizes(page, where, {
      lang: "ko",
      shot: (viewport) => `editor-${where}-ko-${size(viewport)}`,
      ...(ready ? { ready } : {}),
    });
  }

  // One page for both sizes: the flow once at 390×844 (the phone, where Korean labels are tightest), each
  // state's checks at 1280×800 and at 390×844 (`expectTidy`).
  describe("the Editor in Korean", () => {
    it("is in Korean in every tab, fits and passes axe at 1280×800 and at 390×844", async () => {
      const { page, context } = await app.newPage({
        locale: "ko-KR",
        start: DEMO,
        viewport: PHONE,
        options: FAST,
      });
      await openEditor(page);
      await expect.poll(() => lang(page)).toBe("ko");
      await expectText(page.getByRole("heading", { level: 1 }), "모션 편집기");
      await expect
        .poll(() =>
          page
            .getByRole("tab")
            .allTextContents()
            .then((t) => t.map(squash)),
        )
        .toEqual(["자세", "장면", "도구", "티칭", "재생", "검사"]);
      await page.getByRole("tablist", { name: "선택한 장면 작업" }).waitFor();
      await expect.poll(() => notice(page, "editor-toolbar")).toBe("완료: 장면 1 추가.");
      await expectText(page.getByTestId("editor-undo"), "실행 취소: 장면 1 추가");
      await expectText(page.getByTestId("scene-total"), "장면 2개 · 1.0초");
      await page.getByRole("img", { name: /^장면 1의 끝 자세를 보여 주는 3D 화면/ }).waitFor();

      // Pose: the table in Korean, and a value the motion file cannot hold, refused beside its field.
      await expect
        .poll(() => page.getByRole("heading", { level: 2, name: "장면 1: 장면_1" }).count())
        .toBe(1);
      await typeInto(page, "end-3", "300");
      const problem = page.getByTestId("field-problem");
      await problem.waitFor();
      await expectText(
        problem,
        "왼쪽 발목 앞뒤(서보 3)의 끝 위치에는 0에서 254 사이의 정수만 쓸 수 있어요. 입력한 값: 300.",
      );
      await expect
        .poll(() => page.getByLabel("왼쪽 발목 앞뒤 (서보 3), 끝 위치", { exact: true }).inputValue())
        .toBe("300");
      // The table's head is shown on a wide window.
      await resizeTo(page, DESKTOP);
      await expect
        .poll(() => page.locator('[data-testid="pose-table"] thead th').allTextContents())
        .toEqual(["ID", "관절", "시작", "끝", "끝 위치 슬라이더", "토크", "출력"]);
      await resizeTo(page, PHONE);
      await expectTidy(page, "pose");
      await typeInto(page, "end-3", "");
      await problem.filter({ hasText: "써 주세요" }).waitFor();
      await expectText(problem, "왼쪽 발목 앞뒤(서보 3)의 끝 위치에는 0에서 254 사이의 정수를 써 주세요.");

      // Scene: its fields, continuity, and frames closer than the RBC plays them.
      await showTab(page, "scene");
      await page.getByRole("heading", { level: 3, name: "장면 사이 이어짐" }).waitFor();
      await expectText(
        page.getByTestId("boundary-start"),
        "장면 0의 끝에서 시작해요. 서보 16개 모두 부드럽게 이어져요.",
      );
      const time = Number(await page.getByTestId("scene-time").inputValue());
      await typeInto(page, "scene-frames", String(time));
      await page.locator("#frames-problem").waitFor();
      await expectText(
        page.locator("#frames-problem"),
        /^프레임 [\d,]+개를 [\d,]+ms에 재생하면 프레임 사이가 1\.0ms예요\. RBC는 20ms 이상이 필요해요\. 프레임을 \d+개 이하로 하거나 시간을 [\d,]+ms 이상으로 해 주세요\.$/,
      );
      await expectTidy(page, "scene");

      // Tools: mirror, copy and retime, and a factor that is not a number.
      await showTab(page, "tools");
      await page.getByRole("button", { name: "좌우 바꾸기" }).waitFor();
      await page.getByRole("button", { name: "장면 1에 복사" }).waitFor();
      await page.getByTestId("retime-value").fill("빠르게");
      await page.getByTestId("retime-apply").click();
      await page.locator("#retime-problem").waitFor();
      await expectText(
        page.locator("#retime-problem"),
        '시간 배수는 0보다 큰 수여야 해요 (2 = 절반 속도, 0.5 = 두 배 속도). 입력한 값: "빠르게".',
      );
      await expectTidy(page, "tools");

      // Teach-in: the question, a limb made limp, its slider, the pose read into the scene, the end.
      await showTab(page, "teach");
      await page.getByRole("button", { name: "티칭 시작…" }).click();
      const question = page.getByTestId("teach-in-confirm");
      await expectText(
        question.locator("#teach-in-question"),
        "로봇을 잡아 주세요. 고른 서보의 힘이 빠져요.",
      );
      await question.getByRole("button", { name: "티칭 시작", exact: true }).click();
      await page.getByTestId("teach-in-status").waitFor();
      await expectText(
        page.getByTestId("teach-in-status"),
        "모든 서보가 제자리를 유지해요. 팔다리를 고르고 힘 빼기를 눌러 주세요.",
      );
      await page.getByRole("checkbox", { name: "왼쪽 팔 (서보 10–12)" }).check();
      await page.getByRole("button", { name: "왼쪽 팔 힘 빼기" }).click();
      await page.getByTestId("teach-in").getByText("서보 10–12의 힘이 빠졌어요 (확인함).").waitFor();
      await expectText(
        page.getByTestId("teach-in-status"),
        "힘 빠짐: 서보 10–12. 나머지 서보는 제자리를 유지해요.",
      );
      await page.getByRole("tab", { name: "티칭 (켜짐)", exact: true }).waitFor();
      await page.getByRole("heading", { level: 3, name: "손으로 자세 잡기 (데모 로봇)" }).waitFor();
      await page.getByLabel("왼쪽 팔꿈치 (서보 12)").fill("120");
      await page.getByTestId("teach-pos-12").filter({ hasText: "120" }).waitFor();
      await expectTidy(page, "teach");
      await page.getByRole("button", { name: "장면 1에 자세 읽기" }).click();
      await page
        .getByTestId("teach-in")
        .getByText("서보 0–15의 위치를 장면 1의 끝 자세로 읽어 넣었어요")
        .waitFor();
      await page.getByRole("button", { name: "티칭 끝내기" }).click();
      await page.getByTestId("teach-in").getByText("티칭을 끝냈어요.").waitFor();
      await expect
        .poll(() => notice(page, "teach-in"))
        .toBe(
          "서보 10–12을(를) 자세를 잡은 자리에 고정했어요 (토크 켜짐, 확인함). 티칭을 끝냈어요. 로봇이 일반 모드로 돌아왔고, 모든 서보가 제자리를 유지해요.",
        );

      // Play: the choice, the question before the robot moves, and what the robot confirmed.
      await showTab(page, "play");
      await page.getByRole("radio", { name: "선택한 장면 (1)" }).waitFor();
      await page.getByRole("radio", { name: "모션 전체 (장면 2개)" }).waitFor();
      await expectText(page.getByTestId("play-summary"), /^장면 1: 프레임 \d+개, [\d.]+초\.$/);
      await page.getByRole("button", { name: "로봇에서 재생…" }).click();
      const ask = page.getByTestId("play-confirm");
      await ask.waitFor();
      await expectText(
        ask.locator("#play-question"),
        /^로봇이 장면 1을\(를\) 따라 움직여요 \([\d.]+초\)\. 로봇을 잡거나 혼자 설 수 있는지 확인해 주세요\.$/,
      );
      await ask.getByRole("button", { name: "취소" }).waitFor();
      await expectTidy(page, "play");
      await ask.getByRole("button", { name: "장면 1 재생" }).click();
      await page.getByTestId("play-panel").getByText("재생했어요").waitFor({ timeout: 20_000 });
      await expect
        .poll(() => notice(page, "play-panel"))
        .toMatch(
          /^장면 1을\(를\) 재생했어요 \(프레임 \d+개, [\d.]+초\)\. 서보는 마지막 프레임 자세를 유지해요\.$/,
        );

      // Check: a position outside the joint's safe range is a warning, counted on the tab, worded in Korean.
      await showTab(page, "pose");
      await typeInto(page, "end-3", "254");
      const check = page.getByRole("tab", { name: /^검사 \(경고 \d+개\)$/ });
      await check.waitFor();
      await check.click();
      await expectText(page.getByTestId("editor-check"), /^오류 0개, 경고 \d+개\.$/);
      const warning = page.locator('[data-testid="editor-warning"][data-code="rbm-unsafe-position"]');
      await expectText(warning.locator(".warning-head"), /^심각 관절의 안전 범위를 벗어난 위치 \(\d+\)$/);
      await warning.locator("summary").click();
      await warning.getByRole("button", { name: "장면 1, 서보 3" }).waitFor();
      // The checker's own sentence is Korean too (motions/issue-text.ts), with the value typed.
      expect(await warning.locator('.issue span[lang="en"]').count()).toBe(0);
      await expectText(warning.locator(".issue").first(), /[가-힣].*254/);
      await expectTidy(page, "check");

      // Drafts: the list and the question before a draft is deleted.
      const drafts = page.getByTestId("drafts-card");
      await drafts.getByRole("heading", { level: 2, name: "임시 저장본" }).waitFor();
      const draft = drafts.getByTestId("draft");
      await expectText(draft.locator(".draft-open"), "편집기에서 열려 있음");
      await expectText(draft.locator("p.num"), /^장면 2개 · \d\d:\d\d 저장$/);
      await draft.getByRole("button", { name: "NewMotion 지우기" }).click();
      const confirm = drafts.getByRole("alertdialog");
      await expectText(confirm, "임시 저장본 NewMotion을(를) 지울까요?", { contains: true });
      await confirm.getByRole("button", { name: "임시 저장본 지우기" }).waitFor();
      await expectTidy(page, "drafts", () => drafts.scrollIntoViewIfNeeded());
      await confirm.getByRole("button", { name: "취소" }).click();
      await context.close();
    });
  });
});
