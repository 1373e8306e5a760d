/**
 * The 3D robot (issue #12 item 5) in headless Chromium, whose WebGL 2 is SwiftShader's (software): an opened
 * file's "Preview in 3D" loads the 3D module only when pressed, draws a robot (pixels that are not the
 * background), draws another picture when the pose changes (scrubbing to another time), plays on Play, keeps
 * its WebGL context across the app's re-renders, frees it when closed, and with prefers-reduced-motion never
 * animates by itself (Play shows one scene at a time).
 */
import { createRequire } from "node:module";
import type { Locator, Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { TEST_START_NAME } from "../../src/ui/test-start.ts";
import { CABLE, loadMotions } from "./connected-page.ts";
import { buildOnce, cspViolations, expectText, useApp, watchPage } from "./harness.ts";
import { exampleText, rbmFile } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

const app = useApp();

const BASIC = "125 179 199 88 108 126 72 49 163 141 51 47 49 199 205 205";
/** wave.rbm at 800 ms, the end of its first scene (RaiseArm): the left arm up (examples/README.md). */
const ARM_RAISED = "125 179 199 88 108 126 72 49 163 141 160 80 90 199 205 205";

interface Picture {
  /** Pixels whose colour differs from the top-left corner's (the background) by more than 24 in sum. */
  robotPixels: number;
  total: number;
  dataUrl: string;
}

/** Reads the preview's canvas (drawn with preserveDrawingBuffer) through a 2D canvas. */
async function picture(preview: Locator): Promise<Picture> {
  return preview.locator("canvas.robot3d-canvas").evaluate((canvas: HTMLCanvasElement) => {
    const copy = document.createElement("canvas");
    copy.width = canvas.width;
    copy.height = canvas.height;
    const ctx = copy.getContext("2d");
    if (!ctx) throw new Error("no 2D context");
    ctx.drawImage(canvas, 0, 0);
    const { data } = ctx.getImageData(0, 0, copy.width, copy.height);
    const [r, g, b] = [data[0]!, data[1]!, data[2]!];
    let robotPixels = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (Math.abs(data[i]! - r) + Math.abs(data[i + 1]! - g) + Math.abs(data[i + 2]! - b) > 24)
        robotPixels++;
    }
    return { robotPixels, total: copy.width * copy.height, dataUrl: canvas.toDataURL() };
  });
}

/** How many pixels two pictures of the same size differ in. */
async function pixelsChanged(page: Page, a: string, b: string): Promise<number> {
  return page.evaluate(
    async ([first, second]) => {
      const load = async (url: string) => {
        const img = new Image();
        img.src = url;
        await img.decode();
        const c = document.createElement("canvas");
        c.width = img.width;
        c.height = img.height;
        const ctx = c.getContext("2d")!;
        ctx.drawImage(img, 0, 0);
        return ctx.getImageData(0, 0, c.width, c.height).data;
      };
      const [x, y] = await Promise.all([load(first), load(second)]);
      let n = 0;
      for (let i = 0; i < x.length; i += 4) {
        if (Math.abs(x[i]! - y[i]!) + Math.abs(x[i + 1]! - y[i + 1]!) + Math.abs(x[i + 2]! - y[i + 2]!) > 24)
          n++;
      }
      return n;
    },
    [a, b] as const,
  );
}

/** Waits `n` animation frames of the page: long enough for anything that animates to have moved. */
async function animationFrames(page: Page, n: number): Promise<void> {
  await page.evaluate(
    (count) =>
      new Promise<void>((resolve) => {
        let seen = 0;
        const step = () => (++seen >= count ? resolve() : requestAnimationFrame(step));
        requestAnimationFrame(step);
      }),
    n,
  );
}

const attr = (locator: Locator, name: string) => locator.getAttribute(name).then((v) => v ?? "");
const frames = (view: Locator) => attr(view, "data-frames").then(Number);

/**
 * Opens wave.rbm on the Motions view (a page opened with the start option `CABLE`) and returns its card; records
 * requests for the 3D module.
 */
async function openWave(page: Page): Promise<{ card: Locator; sceneRequests: string[] }> {
  const sceneRequests: string[] = [];
  page.on("request", (r) => {
    if (/robot-scene-[\w-]+\.js$/.test(r.url())) sceneRequests.push(r.url());
  });
  await loadMotions(page, app.url);
  await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", exampleText("wave.rbm")));
  const card = page.getByTestId("motion-file");
  await card.waitFor();
  return { card, sceneRequests };
}

describe("3D preview of an opened motion file", () => {
  it("loads on demand, draws the robot, draws it anew for another time, and frees its context when closed", async () => {
    // The harness's pages prefer reduced motion: the preview does not start by itself.
    const { page } = await app.newPage({ start: CABLE });
    const seen = watchPage(page, app.origin);
    const { card, sceneRequests } = await openWave(page);
    await animationFrames(page, 5);
    expect(sceneRequests).toEqual([]);
    expect(await card.locator("canvas.robot3d-canvas").count()).toBe(0);

    const toggle = card.getByTestId("preview-toggle");
    await expect.poll(() => toggle.getAttribute("aria-expanded")).toBe("false");
    await toggle.click();
    const preview = card.getByTestId("motion-preview");
    const view = preview.getByTestId("robot3d-view");
    await preview.locator('[data-state="ready"]').waitFor();
    await expect.poll(() => frames(view)).toBeGreaterThan(0);
    expect(sceneRequests).toHaveLength(1);
    await expect.poll(() => toggle.getAttribute("aria-expanded")).toBe("true");

    const canvas = preview.locator("canvas.robot3d-canvas");
    await expect.poll(() => canvas.getAttribute("role")).toBe("img");
    await expect.poll(() => canvas.getAttribute("aria-label")).toContain("3D preview of RbcPanel_Wave");
    await expect.poll(() => canvas.getAttribute("aria-label")).toContain("scene table");
    await expect.poll(() => attr(view, "data-pose")).toBe(BASIC);
    await expect.poll(() => attr(preview, "data-time")).toBe("0");
    await expect.poll(() => attr(preview, "data-duration")).toBe("3200");
    await expectText(preview.getByTestId("preview-clock"), "0.0 s / 3.2 s");

    const first = await picture(preview);
    // Not blank: the robot covers a good part of the picture (about 5-15 %; the grid adds a little).
    expect(first.robotPixels).toBeGreaterThan(first.total * 0.02);
    // A blank canvas of the same size is a different picture.
    const blank = await canvas.evaluate((c: HTMLCanvasElement) => {
      const b = document.createElement("canvas");
      b.width = c.width;
      b.height = c.height;
      return b.toDataURL();
    });
    expect(first.dataUrl).not.toBe(blank);

    // Scrub to 0.8 s: the left arm is up, and the picture changes where it moved.
    const drawn = await frames(view);
    await preview.getByTestId("preview-time").fill("800");
    await expect.poll(() => attr(view, "data-pose")).toBe(ARM_RAISED);
    await expect.poll(() => frames(view)).toBeGreaterThan(drawn);
    await expectText(preview.getByTestId("preview-clock"), "0.8 s / 3.2 s");
    const raised = await picture(preview);
    expect(raised.dataUrl).not.toBe(first.dataUrl);
    expect(await pixelsChanged(page, first.dataUrl, raised.dataUrl)).toBeGreaterThan(200);

    // The keyboard turns the robot: a new picture of the same pose.
    await canvas.focus();
    const beforeTurn = await frames(view);
    await page.keyboard.press("ArrowLeft");
    await expect.poll(() => frames(view)).toBeGreaterThan(beforeTurn);
    await expect.poll(() => attr(view, "data-pose")).toBe(ARM_RAISED);
    expect((await picture(preview)).dataUrl).not.toBe(raised.dataUrl);

    // The app re-renders the view (scenes and chart shown or hidden): the same canvas and context go on drawing.
    await canvas.evaluate((c) => {
      (c as HTMLCanvasElement & { __kept?: boolean }).__kept = true;
    });
    const kept = await frames(view);
    const scenesToggle = card.getByTestId("scenes-toggle");
    const expanded = await scenesToggle.getAttribute("aria-expanded");
    await scenesToggle.click();
    await expect.poll(() => scenesToggle.getAttribute("aria-expanded")).not.toBe(expanded);
    await preview.getByTestId("preview-time").fill("1600");
    await expect.poll(() => frames(view)).toBeGreaterThan(kept);
    expect(await canvas.evaluate((c) => (c as HTMLCanvasElement & { __kept?: boolean }).__kept)).toBe(true);
    await expect.poll(() => card.locator("canvas.robot3d-canvas").count()).toBe(1);

    // Closing the preview frees the context.
    await canvas.evaluate((c) => {
      (window as unknown as { __previewCanvas: HTMLCanvasElement }).__previewCanvas = c as HTMLCanvasElement;
    });
    await toggle.click();
    await preview.waitFor({ state: "detached" });
    await expect
      .poll(() =>
        page.evaluate(() =>
          (window as unknown as { __previewCanvas: HTMLCanvasElement }).__previewCanvas
            .getContext("webgl2")
            ?.isContextLost(),
        ),
      )
      .toBe(true);

    expect(seen.errors).toEqual([]);
    expect(seen.foreignRequests).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
  });

  it("plays on the motion's timing when motion is welcome, and pauses where it is", async () => {
    const { page } = await app.newPage({ start: CABLE });
    await page.emulateMedia({ reducedMotion: "no-preference" });
    const seen = watchPage(page, app.origin);
    // The preview plays on the page's own clock (performance.now, animation frames), not the robot's: a fake
    // one (Playwright's), stepped 400 ms at a time, samples it at known times however loaded the machine is.
    await page.clock.install();
    const { card } = await openWave(page);
    await page.clock.pauseAt((await page.evaluate(() => Date.now())) + 1_000);
    await card.getByTestId("preview-toggle").click();
    const preview = card.getByTestId("motion-preview");
    const view = preview.getByTestId("robot3d-view");
    // Loading the 3D module takes real time; the page's clock moves one animation frame per look until it is ready.
    await expect
      .poll(async () => {
        await page.clock.runFor(16);
        return preview.locator('[data-state="ready"]').count();
      })
      .toBe(1);

    // It starts by itself: time runs, the robot moves through the scenes and stops at the end (3.2 s).
    const poses = new Set<string>();
    const pictures = new Set<string>();
    for (let step = 0; step < 20 && (await attr(preview, "data-playing")) !== "false"; step++) {
      await page.clock.runFor(400);
      poses.add(await attr(view, "data-pose"));
      if (pictures.size < 3) pictures.add((await picture(preview)).dataUrl);
    }
    await expect.poll(() => attr(preview, "data-playing")).toBe("false");
    await expect.poll(() => attr(preview, "data-time")).toBe("3200");
    await page.clock.resume();
    // The last pose is drawn at the next animation frame.
    await expect.poll(() => attr(view, "data-pose")).toBe(BASIC);
    expect(poses.size).toBeGreaterThan(3);
    expect(pictures.size).toBeGreaterThan(1);
    const play = preview.getByTestId("preview-play");
    await expectText(play, "Play again");

    // Play again starts from the beginning; Pause stops where it is.
    await play.click();
    await expect.poll(() => attr(preview, "data-time").then(Number)).toBeGreaterThan(0);
    await expectText(play, "Pause");
    await play.click();
    await expect.poll(() => attr(preview, "data-playing")).toBe("false");
    const stoppedAt = await attr(preview, "data-time");
    // The pose reached as Pause was pressed may still be drawn at the next animation frame; nothing after it.
    await animationFrames(page, 2);
    const drawn = await frames(view);
    await animationFrames(page, 30);
    await expect.poll(() => attr(preview, "data-time")).toBe(stoppedAt);
    await expect.poll(() => frames(view)).toBe(drawn);
    await expectText(play, "Play");

    expect(seen.errors).toEqual([]);
  });

  it("with reduced motion never animates by itself; Play shows the next scene's pose at once", async () => {
    const { page } = await app.newPage({ start: CABLE });
    await page.emulateMedia({ reducedMotion: "reduce" });
    const { card } = await openWave(page);
    await card.getByTestId("preview-toggle").click();
    const preview = card.getByTestId("motion-preview");
    const view = preview.getByTestId("robot3d-view");
    await preview.locator('[data-state="ready"]').waitFor();
    await expect.poll(() => frames(view)).toBeGreaterThan(0);

    const drawn = await frames(view);
    await animationFrames(page, 30);
    await expect.poll(() => attr(preview, "data-playing")).toBe("false");
    await expect.poll(() => attr(preview, "data-time")).toBe("0");
    await expect.poll(() => frames(view)).toBe(drawn);
    await expectText(preview, "Reduced motion is on", { contains: true });

    const next = preview.getByTestId("preview-play");
    await expectText(next, "Next scene");
    await next.click();
    await expect.poll(() => attr(preview, "data-time")).toBe("800");
    await expect.poll(() => attr(preview, "data-playing")).toBe("false");
    await expect.poll(() => attr(view, "data-pose")).toBe(ARM_RAISED);
    await next.click();
    // Scene 1 (WaveOut) ends at 1.2 s.
    await expect.poll(() => attr(preview, "data-time")).toBe("1200");
    await animationFrames(page, 30);
    await expect.poll(() => attr(preview, "data-time")).toBe("1200");

    // The scrub bar's keys: a tenth of a second, and a scene with Page Up.
    const time = preview.getByTestId("preview-time");
    await time.focus();
    await page.keyboard.press("ArrowRight");
    await expect.poll(() => attr(preview, "data-time")).toBe("1300");
    await page.keyboard.press("PageUp");
    await expect.poll(() => attr(preview, "data-time")).toBe("1600");
    await expect
      .poll(() => time.getAttribute("aria-valuetext"))
      .toBe("1.6 s / 3.2 s, end of scene 2, WaveIn");
  });

  it("says so in place of the picture when the browser has no WebGL 2, and loads no 3D code", async () => {
    const { page } = await app.newPage({ start: CABLE });
    const seen = watchPage(page, app.origin);
    await page.addInitScript({
      content: `const getContext = HTMLCanvasElement.prototype.getContext;
HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
  return type === "webgl2" || type === "webgl" ? null : getContext.call(this, type, ...rest);
};`,
    });
    const { card, sceneRequests } = await openWave(page);
    await card.getByTestId("preview-toggle").click();
    const view = card.getByTestId("robot3d-view");
    await view.locator(".robot3d-status").filter({ hasText: "needs WebGL 2" }).waitFor();
    await expect.poll(() => attr(view, "data-state")).toBe("no-webgl");
    expect(await view.locator("canvas").count()).toBe(0);
    await expectText(view.locator(".robot3d-status"), "scene table", { contains: true });
    // The controls still work: the time moves, nothing is drawn.
    await card.getByTestId("preview-time").fill("800");
    await expect.poll(() => attr(card.getByTestId("motion-preview"), "data-time")).toBe("800");
    await expect.poll(() => attr(view, "data-frames")).toBe("0");
    expect(sceneRequests).toEqual([]);
    expect(seen.errors).toEqual([]);
  });

  it("passes axe with the preview open, in light and dark mode", async () => {
    const { fakeSerial } = await buildOnce();
    const axePath = createRequire(import.meta.url).resolve("axe-core/axe.min.js");
    for (const colorScheme of ["light", "dark"] as const) {
      // The page's CSP rightly refuses axe's script tag: this page bypasses it (as tests/e2e/a11y.test.ts does).
      const context = await app.browser.newContext({
        viewport: { width: 1280, height: 800 },
        serviceWorkers: "block",
        reducedMotion: "reduce",
        colorScheme,
        bypassCSP: true,
      });
      await context.addInitScript({
        content: `window.__rbcTestOptions = {};\n;\n${fakeSerial}\n;\nwindow.${TEST_START_NAME} = ${JSON.stringify(CABLE)};`,
      });
      const page = await context.newPage();
      const { card } = await openWave(page);
      await card.getByTestId("preview-toggle").click();
      await card.locator('[data-testid="motion-preview"] [data-state="ready"]').waitFor();
      await page.addScriptTag({ path: axePath });
      const found = await page.evaluate(async () => {
        type Result = { id: string; nodes: { target: unknown[] }[] };
        type Run = (context: unknown, o: unknown) => Promise<{ violations: Result[]; incomplete: Result[] }>;
        const axe = (window as unknown as { axe: { run: Run } }).axe;
        const result = await axe.run('[data-testid="motion-file"]', {
          resultTypes: ["violations", "incomplete"],
        });
        return [...result.violations, ...result.incomplete.filter((r) => r.id !== "color-contrast")].map(
          (r) => `${r.id}: ${r.nodes.map((n) => JSON.stringify(n.target)).join(", ")}`,
        );
      });
      expect(found, `${colorScheme}: ${found.join("\n")}`).toEqual([]);
      await context.close();
    }
  });
});
