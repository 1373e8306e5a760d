/**
 * The 3D robot in headless Chromium (issue #12: "3D frame rate in headless Chromium (report it)"), against
 * `vite preview` of a production build, with Chromium's software WebGL 2 (SwiftShader; the launch flags of the
 * browser tests, --disable-gpu included):
 *
 * - play: the Motions view's "Preview in 3D" of examples/long-walk.rbm (284 scenes, a new pose every 30 ms)
 *   playing on its own timing; pictures drawn per second. The view draws only when the pose changes, so this is
 *   at most the motion's rate of new poses (about 33 per second), less when the machine cannot keep up.
 * - orbit: the same view turned by one arrow key press on every animation frame, so that every frame needs a
 *   new picture; pictures drawn per second: the most the renderer manages on this machine.
 * - the gzip size (level 9) of the lazily loaded 3D chunk (assets/robot-scene-*.js, three.js and the scene),
 *   which the first page load does not carry (bench/bundle-size.ts).
 *
 *   npx tsx bench/robot3d-fps.ts                 builds into a temporary folder, measures, deletes it
 *   npx tsx bench/robot3d-fps.ts --dist <dir>    measures an existing build
 */
import { mkdtempSync, readdirSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { fileURLToPath } from "node:url";
import { gzipSync } from "node:zlib";
import { preview } from "vite";
import { launchChromium } from "../tests/support/chromium.ts";
import { PROJECT_ROOT, viteBuild } from "./bundle-size.ts";
import { round } from "./stats.ts";

export interface Robot3dFigures {
  /** Pictures per second while long-walk.rbm plays. */
  playFps: number;
  /** Pictures per second with the camera turned on every animation frame. */
  orbitFps: number;
  /** Animation frames per second the page had meanwhile (the ceiling for both). */
  animationFps: number;
  seconds: number;
  chunkFile: string;
  chunkBytes: number;
  chunkGzipBytes: number;
  /** The WebGL renderer Chromium reports (SwiftShader here). */
  webgl: string;
}

/** The lazily loaded 3D chunk of a build and its gzip size. */
export function robot3dChunk(outDir: string): { file: string; bytes: number; gzipBytes: number } {
  const assets = join(outDir, "assets");
  const file = readdirSync(assets).find((f) => /^robot-scene-[\w-]+\.js$/.test(f));
  if (!file) throw new Error(`no robot-scene-*.js in ${assets}: is the 3D view still loaded with import()?`);
  const code = readFileSync(join(assets, file));
  return { file: `assets/${file}`, bytes: code.length, gzipBytes: gzipSync(code, { level: 9 }).length };
}

/** Counts, in the page, pictures drawn and animation frames over `ms`, optionally turning the view each frame. */
const COUNT_FRAMES = `async ([ms, turn]) => {
  const view = document.querySelector('[data-testid="motion-preview"] .robot3d');
  const canvas = view.querySelector("canvas");
  const drawn = () => Number(view.dataset.frames);
  const start = performance.now();
  const first = drawn();
  let frames = 0;
  await new Promise((resolve) => {
    const step = (now) => {
      frames++;
      if (turn) canvas.dispatchEvent(new KeyboardEvent("keydown", { key: "ArrowRight", bubbles: true }));
      if (now - start >= ms) resolve(undefined);
      else requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  });
  const seconds = (performance.now() - start) / 1000;
  return { pictures: (drawn() - first) / seconds, frames: frames / seconds };
}`;

export async function measureRobot3d(outDir: string, seconds = 4): Promise<Robot3dFigures> {
  const chunk = robot3dChunk(outDir);
  const server = await preview({
    root: PROJECT_ROOT,
    logLevel: "silent",
    build: { outDir },
    preview: { host: "127.0.0.1", port: 0, strictPort: true, open: false },
  });
  const browser = await launchChromium();
  try {
    const address = server.httpServer.address();
    if (!address || typeof address === "string") throw new Error("vite preview did not report its port");
    const context = await browser.newContext({
      serviceWorkers: "block",
      reducedMotion: "no-preference",
      viewport: { width: 1280, height: 800 },
    });
    const page = await context.newPage();
    await page.goto(`http://127.0.0.1:${address.port}/`, { waitUntil: "domcontentloaded" });
    await page.getByRole("link", { name: "Motions" }).click();
    const text = readFileSync(join(PROJECT_ROOT, "examples/long-walk.rbm"));
    await page
      .getByTestId("rbm-files")
      .setInputFiles({ name: "long-walk.rbm", mimeType: "text/plain", buffer: text });
    const card = page.getByTestId("motion-file");
    await card.getByTestId("preview-toggle").click();
    const preview3d = card.getByTestId("motion-preview");
    await preview3d.locator('[data-state="ready"]').waitFor({ timeout: 30_000 });
    await page.waitForFunction(
      () => document.querySelector('[data-testid="motion-preview"]')?.getAttribute("data-playing") === "true",
    );
    const webgl = await page.evaluate(() => {
      const gl = document.createElement("canvas").getContext("webgl2");
      const info = gl?.getExtension("WEBGL_debug_renderer_info");
      return gl ? String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER)) : "none";
    });
    type Counted = { pictures: number; frames: number };
    const count = (turn: boolean) =>
      page.evaluate(`(${COUNT_FRAMES})([${seconds * 1000}, ${turn}])`) as Promise<Counted>;
    const play = await count(false);
    // Stop the motion, then turn the view on every frame.
    await page.getByTestId("preview-play").click();
    const orbit = await count(true);
    await context.close();
    return {
      playFps: play.pictures,
      orbitFps: orbit.pictures,
      animationFps: Math.min(play.frames, orbit.frames),
      seconds,
      chunkFile: chunk.file,
      chunkBytes: chunk.bytes,
      chunkGzipBytes: chunk.gzipBytes,
      webgl,
    };
  } finally {
    await browser.close();
    await server.close();
  }
}

export function describeRobot3d(f: Robot3dFigures): string {
  return [
    `3D preview (headless Chromium, ${f.webgl}):`,
    `  playing long-walk.rbm: ${round(f.playFps, 1)} pictures/s (new poses at most every 30 ms)`,
    `  turning the view every frame: ${round(f.orbitFps, 1)} pictures/s (animation frames: ${round(f.animationFps, 1)}/s)`,
    `  3D chunk ${f.chunkFile}: ${(f.chunkGzipBytes / 1000).toFixed(1)} KB gzip (${(f.chunkBytes / 1000).toFixed(1)} KB), loaded only when a 3D view opens`,
  ].join("\n");
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  const distIndex = args.indexOf("--dist");
  let outDir = distIndex >= 0 ? args[distIndex + 1] : undefined;
  let temporary: string | undefined;
  if (!outDir) {
    temporary = mkdtempSync(join(tmpdir(), "rbc-bench-3d-"));
    outDir = temporary;
    process.stderr.write(`robot3d-fps: building into ${outDir}\n`);
    await viteBuild(outDir);
  }
  try {
    process.stdout.write(`${describeRobot3d(await measureRobot3d(outDir))}\n`);
  } finally {
    if (temporary) rmSync(temporary, { recursive: true, force: true });
  }
}
