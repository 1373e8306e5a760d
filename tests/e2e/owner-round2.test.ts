/**
 * Issue 21, items 1, 2, 3 and 9, as a new owner meets them, in the built panel:
 * 1. servos are named from the robot's own point of view (docs/protocol.md §4: 0-4 left leg, 5-9 right leg,
 *    10-12 left arm, 13-15 right arm), said once per view, in English and Korean; the mirror's "Left → right"
 *    copies 10-12 onto 13-15; the 3D robot, facing the viewer, has its left arm on the viewer's right;
 * 2. the 3D robot's drawing buffer is its box × devicePixelRatio (on load and after a resize), and the Editor
 *    and Servos show it at a working size beside the sliders at 1280×800;
 * 3. Escape is Stop on a slider, a number field, a button and in an open <details>; only a text field being
 *    edited (and dialogs, open menus and lists) keep it;
 * 4. (item 9) at 390 px the menu is one row, and names break only between words.
 * With RBC_SHOTS=<dir>, screenshots of every view changed, at both sizes, light and dark, English and Korean.
 */
import type { Locator, Page } from "playwright-core";
import { describe, expect, it, vi } from "vitest";
import { mirrorPosition } from "../../src/motion/index.ts";
import { STANDARD_ZEROS } from "../../src/protocol/zeros.ts";
import { openConnected } from "./connected-page.ts";
import { expectText, squash, useApp } from "./harness.ts";
import {
  axeProblems,
  connectDemo,
  DESKTOP,
  newLocalePage,
  PHONE,
  type Size,
  scrollsSideways,
  shot,
  sizeName,
} from "./i18n-checks.ts";
import { exampleText, rbmFile } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

const app = useApp();

// Each test walks several views in a real browser; on a machine shared with other builds that can take minutes.
vi.setConfig({ testTimeout: 240_000 });

const SIDES = {
  en: "Left and right are the robot's own: its left arm is on your right when it faces you.",
  ko: "왼쪽과 오른쪽은 로봇 기준이에요. 로봇이 나를 마주 보고 있으면 로봇의 왼팔은 내 오른쪽에 있어요.",
} as const;

/** Goes to a view by its address (the same page, so a connection stays). */
async function go(page: Page, view: string): Promise<void> {
  await page.evaluate((v) => {
    location.hash = `#/${v}`;
  }, view);
}

const nameOf = (row: Locator) => row.locator("th").first().textContent().then(squash);

/** Accepts the Servos view's safety notice (whatever the language) and starts servo control. */
async function startServoControl(page: Page): Promise<void> {
  await page.getByTestId("servo-safety").locator(".btn--primary").click();
  await page.getByTestId("enter-direct").click();
  await page.locator("#servo-3:not([disabled])").waitFor();
}

async function openEditor(page: Page): Promise<void> {
  await go(page, "editor");
  await page.getByTestId("pose-table").waitFor();
  await page.locator('[data-testid="editor-robot3d"][data-state="ready"]').waitFor({ timeout: 20_000 });
}

/** Types a value into a field and leaves it (a `change`). */
async function typeInto(page: Page, testId: string, value: string): Promise<void> {
  const field = page.getByTestId(testId);
  await field.fill(value);
  await field.press("Tab");
}

async function showTab(page: Page, tab: "pose" | "tools" | "teach"): Promise<void> {
  await page.locator(`#editor-tab-${tab}`).click();
  await page.locator(`#editor-panel-${tab}`).waitFor();
}

/** The editor's 3D robot has drawn servo `id` at `position` (data-pose lists the positions drawn). */
async function drawn(page: Page, id: number, position: number): Promise<void> {
  await expect
    .poll(async () => {
      const pose = await page.getByTestId("editor-robot3d").getAttribute("data-pose");
      return pose?.split(" ")[id];
    })
    .toBe(String(position));
  // The drawing happens in the same animation frame as data-pose; one more frame to be sure it is on screen.
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r(null))));
}

/** The editor canvas's pixels (it is drawn with preserveDrawingBuffer), as RGB bytes, and its size. */
async function pixels(page: Page): Promise<{ width: number; height: number; data: number[] }> {
  return page.locator('[data-testid="editor-robot3d"] canvas').evaluate((canvas: HTMLCanvasElement) => {
    const copy = document.createElement("canvas");
    copy.width = canvas.width;
    copy.height = canvas.height;
    const ctx = copy.getContext("2d");
    if (!ctx) throw new Error("no 2D context");
    ctx.drawImage(canvas, 0, 0);
    const d = ctx.getImageData(0, 0, copy.width, copy.height).data;
    const data: number[] = [];
    for (let i = 0; i < d.length; i += 4) data.push(d[i]! + d[i + 1]! + d[i + 2]!);
    return { width: copy.width, height: copy.height, data };
  });
}

/** The mean x (0 = left edge, 1 = right edge) of the pixels that differ between two pictures, and how many. */
function changedCentre(
  a: { width: number; data: number[] },
  b: { data: number[] },
): { x: number; count: number } {
  let sum = 0;
  let count = 0;
  for (let i = 0; i < a.data.length; i++) {
    if (Math.abs(a.data[i]! - b.data[i]!) > 30) {
      sum += (i % a.width) / a.width;
      count++;
    }
  }
  return { x: count ? sum / count : Number.NaN, count };
}

describe("item 1: left and right are the robot's own (docs/protocol.md §4)", () => {
  for (const [lang, locale] of [
    ["en", "en-US"],
    ["ko", "ko-KR"],
  ] as const) {
    it(`names the servos from the robot's point of view in Zeros, Servos and the Editor, once per view (${lang})`, async () => {
      const { page, context } = await openConnected(app, { robot: "cable", locale });
      const expected =
        lang === "en"
          ? { 0: "Left hip roll", 5: "Right hip roll", 10: "Left shoulder pitch", 15: "Right elbow" }
          : { 0: "왼쪽 엉덩이 좌우", 5: "오른쪽 엉덩이 좌우", 10: "왼쪽 어깨 앞뒤", 15: "오른쪽 팔꿈치" };

      await go(page, "zeros");
      await page.locator("#zero-0").waitFor();
      for (const [id, name] of Object.entries(expected))
        await expect
          .poll(() => nameOf(page.locator(`[data-testid="zeros-card"] tr[data-servo="${id}"]`)))
          .toBe(name);
      await expect.poll(() => page.getByTestId("sides-note").allTextContents()).toEqual([SIDES[lang]]);

      await go(page, "servos");
      await page.getByTestId("servo-card").waitFor();
      for (const [id, name] of Object.entries(expected))
        await expect.poll(() => nameOf(page.locator(`.servo-table tr[data-servo="${id}"]`))).toBe(name);
      await expect.poll(() => page.getByTestId("sides-note").allTextContents()).toEqual([SIDES[lang]]);

      await openEditor(page);
      const pose = page.getByTestId("pose-table");
      for (const [id, name] of Object.entries(expected))
        await expectText(pose.locator(`tr[data-servo="${id}"]`), name, { contains: true });
      await expect.poll(() => page.getByTestId("sides-note").allTextContents()).toEqual([SIDES[lang]]);
      await showTab(page, "teach");
      await expect.poll(() => page.getByTestId("sides-note").allTextContents()).toEqual([SIDES[lang]]);
      expect(await axeProblems(page)).toEqual([]);
      await context.close();
    });
  }

  it("mirrors the left arm (10-12) onto the right arm (13-15) with “Left → right”", async () => {
    const { page, context } = await newLocalePage(app, "en-US", { hash: "#/editor" });
    await page.getByTestId("pose-table").waitFor();
    await typeInto(page, "end-10", "141");
    await showTab(page, "tools");
    await page.getByTestId("mirror-left-to-right").click();
    await page.getByTestId("editor-undo").filter({ hasText: "mirror" }).waitFor();
    await showTab(page, "pose");
    const mirrored = mirrorPosition(141, STANDARD_ZEROS[10]!, STANDARD_ZEROS[13]!);
    expect(mirrored).toBe(110);
    await expect.poll(() => page.getByTestId("end-13").inputValue()).toBe("110");
    await expect.poll(() => page.getByTestId("end-10").inputValue()).toBe("141");
    await context.close();
  });

  it("draws the robot facing the viewer with its left arm (10-12) on the viewer's right", async () => {
    const { page, context } = await newLocalePage(app, "en-US", { hash: "#/editor" });
    await page.getByTestId("pose-table").waitFor();
    await page.locator('[data-testid="editor-robot3d"][data-state="ready"]').waitFor({ timeout: 20_000 });
    await drawn(page, 10, 51);
    const basic = await pixels(page);
    // The left arm forward (10: 51 → 141), then instead the right arm in the mirror pose (13: 199 → 110).
    await typeInto(page, "end-10", "141");
    await drawn(page, 10, 141);
    const left = changedCentre(basic, await pixels(page));
    await typeInto(page, "end-10", "51");
    await typeInto(page, "end-13", "110");
    await drawn(page, 13, 110);
    await drawn(page, 10, 51);
    const right = changedCentre(basic, await pixels(page));
    expect(left.count).toBeGreaterThan(200);
    expect(right.count).toBeGreaterThan(200);
    // The robot faces the viewer: its left arm appears to the right of its right arm.
    expect(left.x).toBeGreaterThan(right.x + 0.1);
    await context.close();
  });
});

/** The canvas's drawing buffer and its box (CSS pixels) × devicePixelRatio. */
async function canvasSize(canvas: Locator) {
  return canvas.evaluate((c: HTMLCanvasElement) => {
    const box = c.getBoundingClientRect();
    const ratio = window.devicePixelRatio;
    return {
      buffer: [c.width, c.height],
      box: [Math.round(box.width * ratio), Math.round(box.height * ratio)],
    };
  });
}

function expectSharp(size: { buffer: number[]; box: number[] }): void {
  expect(Math.abs(size.buffer[0]! - size.box[0]!), JSON.stringify(size)).toBeLessThanOrEqual(1);
  expect(Math.abs(size.buffer[1]! - size.box[1]!), JSON.stringify(size)).toBeLessThanOrEqual(1);
}

describe("item 2: the 3D robot drawn true, at a working size", () => {
  for (const ratio of [1, 2]) {
    it(`has a drawing buffer of its box × devicePixelRatio (${ratio}) on load and after every resize`, async () => {
      const context = await app.browser.newContext({
        viewport: { ...DESKTOP },
        deviceScaleFactor: ratio,
        reducedMotion: "reduce",
      });
      const page = await context.newPage();
      await page.goto(`${app.url}#/editor`, { waitUntil: "domcontentloaded" });
      await page.locator('[data-testid="editor-robot3d"][data-state="ready"]').waitFor({ timeout: 20_000 });
      const canvas = page.locator('[data-testid="editor-robot3d"] canvas');
      await expect.poll(() => canvasSize(canvas).then((s) => s.buffer[0] === s.box[0])).toBe(true);
      const first = await canvasSize(canvas);
      expectSharp(first);
      expect(first.buffer[0]).not.toBe(300);
      await page.setViewportSize({ width: 1000, height: 700 });
      await expect.poll(() => canvasSize(canvas).then((s) => s.box[0] !== first.box[0])).toBe(true);
      await expect.poll(() => canvasSize(canvas).then((s) => s.buffer[0] === s.box[0])).toBe(true);
      expectSharp(await canvasSize(canvas));
      await context.close();
    });
  }

  it("shows the Editor's and the Servos' robot beside the sliders at 1280×800, at least 300×400", async () => {
    const { page, context } = await openConnected(app, { view: "editor" });
    await openEditor(page);
    const robot = await page.getByTestId("editor-robot3d").locator("canvas").boundingBox();
    const table = await page.getByTestId("pose-table").boundingBox();
    expect(robot && table).toBeTruthy();
    expect(robot!.width).toBeGreaterThanOrEqual(320);
    expect(robot!.height).toBeGreaterThanOrEqual(400);
    expect(robot!.x).toBeGreaterThanOrEqual(table!.x + table!.width - 1);
    expect(robot!.y + robot!.height).toBeLessThanOrEqual(DESKTOP.height);
    expectSharp(await canvasSize(page.getByTestId("editor-robot3d").locator("canvas")));

    await go(page, "servos");
    await page.getByTestId("live-robot-toggle").click();
    const live = page.locator('[data-testid="live-robot-view"][data-state="ready"]');
    await live.waitFor({ timeout: 20_000 });
    const servoRobot = await live.locator("canvas").boundingBox();
    const sliders = await page.locator(".servo-table").boundingBox();
    // Beside a 16-row table with sliders: narrower than the Editor's, still a working size (not 192 × 320).
    expect(servoRobot!.width).toBeGreaterThanOrEqual(300);
    expect(servoRobot!.height).toBeGreaterThanOrEqual(400);
    expect(servoRobot!.x).toBeGreaterThanOrEqual(sliders!.x + sliders!.width - 1);
    expect(servoRobot!.y).toBeLessThan(DESKTOP.height);
    expectSharp(await canvasSize(live.locator("canvas")));
    expect(await axeProblems(page)).toEqual([]);
    await context.close();
  });
});

describe("item 3: Escape is Stop everywhere but a text field, a dialog or an open menu/list", () => {
  it("stops from a servo slider, a number field, a button and an open <details>; not from a text field", async () => {
    const { page, context } = await openConnected(app, { robot: "cable" });
    // Whether the panel took each Escape as Stop (it calls preventDefault before the event reaches window).
    await page.evaluate(() => {
      const w = window as unknown as { escapes: boolean[] };
      w.escapes = [];
      window.addEventListener("keydown", (e) => {
        if (e.key === "Escape") w.escapes.push(e.defaultPrevented);
      });
    });
    const escapes = () => page.evaluate(() => (window as unknown as { escapes: boolean[] }).escapes);
    const banner = page.getByTestId("stop-banner");
    const dismiss = async () => {
      await banner.getByRole("button").click();
      await banner
        .filter({ hasText: /\S/ })
        .waitFor({ state: "detached" })
        .catch(() => {});
    };

    await go(page, "servos");
    await startServoControl(page);
    const slider = page.locator('tr[data-servo="3"] input[type="range"]');
    await slider.focus();
    await page.keyboard.press("ArrowRight");
    await page.keyboard.press("Escape");
    await banner.filter({ hasText: /keeps|holds|hold their|stopped|ended|Nothing/ }).waitFor();
    expect(await escapes()).toEqual([true]);
    // Stop ended servo control (issue 22 item 6: it leaves direct mode, the servos hold): start it again for
    // the number field and the button below.
    await page.getByTestId("enter-direct").click();
    await page.locator("#servo-3:not([disabled])").waitFor();

    await page.locator("#servo-3").focus();
    await page.keyboard.press("Escape");
    await page
      .getByTestId("enter-direct")
      .focus()
      .catch(() => {});
    await page.locator('[data-testid="servo-card"] button').first().focus();
    await page.keyboard.press("Escape");
    // An open <details> (a fold of the page): Escape from its summary is Stop too.
    await page.evaluate(() => {
      const d = document.createElement("details");
      d.open = true;
      d.id = "fold";
      d.innerHTML = "<summary>More</summary><p>Text</p>";
      document.querySelector("main")?.append(d);
    });
    await page.locator("#fold summary").focus();
    await page.keyboard.press("Escape");
    expect(await escapes()).toEqual([true, true, true, true]);
    await dismiss();

    // A text field being edited keeps Escape (the Editor's motion name).
    await go(page, "editor");
    await page.getByTestId("motion-name").focus();
    await page.keyboard.press("Escape");
    expect(await escapes()).toEqual([true, true, true, true, false]);
    await context.close();
  });
});

/**
 * For each element `locator` matches: its text, and the line breaks inside it, as the two characters either side
 * of each ("l|o"), found from the layout (a new line where a character's top moves down). One call for all of
 * them: the long walk has 284 scene names.
 */
async function breaksOfEach(locator: Locator): Promise<{ text: string; found: string[] }[]> {
  const all = await locator.evaluateAll((elements) =>
    elements.map((el) => {
      const chars: { c: string; top: number }[] = [];
      const walker = document.createTreeWalker(el, NodeFilter.SHOW_TEXT);
      for (let n = walker.nextNode(); n; n = walker.nextNode()) {
        const text = n.textContent ?? "";
        for (let i = 0; i < text.length; i++) {
          const range = document.createRange();
          range.setStart(n, i);
          range.setEnd(n, i + 1);
          const rect = range.getClientRects()[0];
          if (rect && text[i]!.trim()) chars.push({ c: text[i]!, top: rect.top });
        }
      }
      const found: string[] = [];
      for (let i = 1; i < chars.length; i++)
        if (chars[i]!.top > chars[i - 1]!.top + 2) found.push(`${chars[i - 1]!.c}|${chars[i]!.c}`);
      return { text: el.textContent, found };
    }),
  );
  return all.map(({ text, found }) => ({ text: squash(text), found }));
}

/** A break between words: after a space (not seen here), after "_" before a letter, or at a lower→Upper hump. */
const atWordEnd = (pair: string) => /^(_\|\p{L}|\p{Ll}\|\p{Lu}|[^\p{L}\p{N}_]\|.)$/u.test(pair);

describe("item 9: at phone width", () => {
  it("shows the menu in one row and breaks names only between words", async () => {
    const { page, context } = await openConnected(app, { size: PHONE });
    const tops = await page
      .locator(".side-nav li")
      .evaluateAll((items) => items.map((li) => Math.round(li.getBoundingClientRect().top)));
    expect(tops.length).toBeGreaterThan(5);
    expect(new Set(tops).size).toBe(1);
    expect(await scrollsSideways(page)).toEqual([]);
    // The current view's tab is in sight in the row.
    await go(page, "log");
    await page.locator('.side-nav a[aria-current="page"]').waitFor();
    const inRow = () =>
      page.locator('.side-nav a[aria-current="page"]').evaluate((a) => {
        const row = a.closest("ul")!.getBoundingClientRect();
        const box = a.getBoundingClientRect();
        return box.left >= row.left - 1 && box.right <= row.right + 1;
      });
    await expect.poll(inRow).toBe(true);

    // The long walk in the Editor: its name and scene names.
    await go(page, "editor");
    await page
      .getByTestId("editor-file")
      .setInputFiles(rbmFile("long-walk.rbm", exampleText("long-walk.rbm")));
    await page.getByText(/^Opened long-walk\.rbm: RbcPanel_LongWalk, 284 scenes\.$/).waitFor();
    for (const { text, found } of await breaksOfEach(page.locator(".scene-option .scene-name")))
      expect(
        found.filter((b) => !atWordEnd(b)),
        text,
      ).toEqual([]);
    // In Motions: the opened file's heading. The Editor's file is the Editor's own, so the file is opened in
    // Motions too (the Motions view once showed no file here, and the check below looked at no heading).
    await go(page, "motions");
    await page.getByTestId("rbm-files").setInputFiles(rbmFile("long-walk.rbm", exampleText("long-walk.rbm")));
    await page.getByTestId("motion-file").first().waitFor();
    for (const { text, found } of await breaksOfEach(page.locator('[data-testid="motion-file"] h3')))
      expect(
        found.filter((b) => !atWordEnd(b)),
        text,
      ).toEqual([]);
    expect(await axeProblems(page)).toEqual([]);
    await context.close();
  });
});

/** Screenshots for people (RBC_SHOTS only): every view changed, at both sizes, light and dark, both languages. */
describe("screenshots", () => {
  it.runIf(process.env.RBC_SHOTS !== undefined)(
    "of Zeros, Servos, Editor (pose, teach-in, tools) and the menu",
    async () => {
      for (const size of [DESKTOP, PHONE] as Size[]) {
        for (const scheme of ["light", "dark"] as const) {
          for (const [lang, locale] of [
            ["en", "en-US"],
            ["ko", "ko-KR"],
          ] as const) {
            const { page, context } = await newLocalePage(app, locale, { size });
            await page.emulateMedia({ colorScheme: scheme });
            await connectDemo(page);
            const name = (view: string) => `issue21-${view}-${sizeName(size)}-${scheme}-${lang}`;
            await go(page, "zeros");
            await page.locator("#zero-0").waitFor();
            await shot(page, name("zeros"), { fullPage: false });
            await go(page, "servos");
            await page.getByTestId("servo-card").waitFor();
            await startServoControl(page);
            await page.getByTestId("live-robot-toggle").click();
            await page
              .locator('[data-testid="live-robot-view"][data-state="ready"]')
              .waitFor({ timeout: 20_000 });
            await shot(page, name("servos"), { fullPage: false });
            await openEditor(page);
            await page
              .getByTestId("editor-file")
              .setInputFiles(rbmFile("long-walk.rbm", exampleText("long-walk.rbm")));
            await page.locator(".scene-option").nth(100).waitFor();
            await shot(page, name("editor-pose"), { fullPage: false });
            await showTab(page, "teach");
            await shot(page, name("editor-teach"), { fullPage: false });
            await showTab(page, "tools");
            await shot(page, name("editor-tools"), { fullPage: false });
            await context.close();
          }
        }
      }
    },
    1_200_000,
  );
});
