import { readFile } from "node:fs/promises";
import { createRequire } from "node:module";
import type { Download, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { mirrorPosition } from "../../src/motion/index.ts";
import { HUNO_BASIC_POSTURE, parseRbm, STANDARD_ZEROS } from "../../src/protocol/index.ts";
import { type AppHarness, cspViolations, squash, startHarness, watchPage } from "./harness.ts";
import { rbmFile } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

/**
 * The motion editor in the browser, without a robot (editing needs none): a three-scene motion made from the
 * template by typing and sliding, undo and redo (buttons and keys), mirror, save, reopen unchanged, drafts
 * across a reload, and the layout at desktop and phone widths. The selected scene's work is in tabs (Pose,
 * Scene, Tools, Teach-in, Play, Check); editor-layout.test.ts checks the layout itself.
 */

let app: AppHarness;

beforeAll(async () => {
  app = await startHarness();
});

afterAll(async () => {
  await app?.close();
});

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
  const want = String(value);
  await page
    .waitForFunction(
      ([id, v]) => (document.querySelector(`[data-testid="${id}"]`) as HTMLInputElement | null)?.value === v,
      [testId, want] as const,
      { timeout: 5000 },
    )
    .catch(() => undefined);
  expect(await fieldValue(page, testId)).toBe(want);
}

/** Waits until the element `testId` reads `text` (white space collapsed). */
async function expectText(page: Page, testId: string, text: string): Promise<void> {
  await page
    .getByTestId(testId)
    .filter({ hasText: text })
    .waitFor({ timeout: 5000 })
    .catch(() => undefined);
  expect(await page.getByTestId(testId).textContent().then(squash)).toBe(text);
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
    expect(await sceneCount(page)).toBe(1);
    await expectValue(page, "end-10", String(HUNO_BASIC_POSTURE[10]));
    expect(await page.getByTestId("editor-undo").isDisabled()).toBe(true);

    await typeInto(page, "motion-name", "Wave test");
    await expectText(page, "editor-save-as", "as Wave-test.rbm");

    // Scene 0: raise the right shoulder by typing.
    await typeInto(page, "end-10", "100");
    await expectText(page, "editor-undo", "Undo: set Left shoulder pitch (end of scene 0)");

    // Scene 1 starts where scene 0 ends (continuity); its end is set with the slider, one undo step per drag.
    await page.getByTestId("scene-add").click();
    await page.locator("#scene-opt-1[aria-current=true]").waitFor();
    await expectValue(page, "start-10", "100");
    await dragSlider(page, "slider-10", 0.85);
    const dragged = Number(await fieldValue(page, "end-10"));
    expect(dragged).toBeGreaterThan(100);
    await page.getByTestId("editor-undo").click();
    await expectValue(page, "end-10", "100");
    await expectText(page, "editor-undo", "Undo: add scene 1");
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
    expect(await problem.textContent().then(squash)).toContain("0 to 254");
    expect(await page.getByTestId("end-3").getAttribute("aria-invalid")).toBe("true");
    await expectText(page, "editor-undo", "Undo: set Left shoulder pitch (end of scene 1)");
    await typeInto(page, "end-3", String(HUNO_BASIC_POSTURE[3]));
    await page.getByTestId("field-problem").waitFor({ state: "detached" });
    expect(await page.getByTestId("end-3").getAttribute("aria-invalid")).toBe("false");

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
    expect(await sceneCount(page)).toBe(3);

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
    expect(await sceneCount(page)).toBe(3);

    // Reopen the saved file and save it again: byte for byte the same.
    await page.getByTestId("editor-new").click();
    await page.waitForFunction(
      () => document.querySelectorAll('[data-testid="scene-list"] .scene-option').length === 1,
    );
    await page.getByTestId("editor-file").setInputFiles(rbmFile("Wave-test.rbm", saved.toString("latin1")));
    await page.getByText(/Opened Wave-test\.rbm: Wave test, 3 scenes/).waitFor();
    expect(await page.getByTestId("editor-undo").isDisabled()).toBe(true);
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
    expect(await page.getByTestId("jump-0").textContent().then(squash)).toContain("130");
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
    await expectText(page, "scene-total", "3 scenes · 3.0 s");
    await page.getByTestId("retime-mode").selectOption("factor");
    await page.getByTestId("retime-value").fill("fast");
    await page.getByTestId("retime-apply").click();
    await page.getByTestId("field-problem").filter({ hasText: "A time factor" }).waitFor();
    await expectText(page, "scene-total", "3 scenes · 3.0 s");

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
    expect(await kept.textContent().then(squash)).toMatch(/1 scene · saved \d\d:\d\d/);

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
    expect(await drafts.count()).toBe(1);

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
    expect(await view.getAttribute("data-pose")).toBe(HUNO_BASIC_POSTURE.join(" "));
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
    expect(await page.getByRole("img", { name: /3D view of the end pose of scene 0/ }).count()).toBe(1);
    expect(seen.errors).toEqual([]);
    await context.close();
  });
});
