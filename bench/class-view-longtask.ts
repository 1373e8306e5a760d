import { readFileSync } from "node:fs";
import { join } from "node:path";
import { preview } from "vite";
import { launchChromium } from "../tests/support/chromium.ts";
import { PROJECT_ROOT } from "./bundle-size.ts";

/**
 * The panel's responsiveness with a class of robots (issue 24 item 5): in headless Chromium, against `vite
 * preview` of a production build, the Class view connects 12 demo robots (each its own simulated RBC and mock
 * port in the page, on real time) and uploads examples/wave.rbm to all of them at once. A `longtask`
 * PerformanceObserver (tasks of 50 ms or more, the browser's own definition), registered before the page's
 * scripts, records every long task; the figures are those that start between the Upload click and the class
 * summary appearing: the longest one, how many there were, and their total. The upload's wall time and the
 * number of robots that stored the motion are reported beside them, so a run that did not upload is seen.
 *
 * Not wired into bench/run.ts. Run: `npx vite build && npx tsx bench/class-view-longtask.ts [outDir]`
 * (prints one JSON object).
 */

export interface ClassLongtaskFigures {
  robots: number;
  stored: number;
  uploadMs: number;
  longestTaskMs: number;
  longTasks: number;
  longTaskTotalMs: number;
  /** The longest task of the whole visit (loading, 12 connections, upload): shows the observer works. */
  longestTaskOfVisitMs: number;
}

const WATCH_LONG_TASKS = `(() => {
  window.__rbcLongTasks = [];
  new PerformanceObserver((list) => {
    for (const e of list.getEntries()) window.__rbcLongTasks.push({ start: e.startTime, duration: e.duration });
  }).observe({ type: "longtask", buffered: true });
})();`;

interface PageWindow {
  __rbcLongTasks: { start: number; duration: number }[];
}

export async function measureClassViewLongtask(
  outDir = join(PROJECT_ROOT, "dist"),
  robots = 12,
): Promise<ClassLongtaskFigures> {
  const wave = readFileSync(join(PROJECT_ROOT, "examples/wave.rbm"));
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
      viewport: { width: 1280, height: 800 },
    });
    const page = await context.newPage();
    await page.addInitScript({ content: WATCH_LONG_TASKS });
    await page.goto(`http://127.0.0.1:${address.port}/#/class`);
    const add = page.getByRole("button", { name: "Add demo robot", exact: true });
    for (let i = 0; i < robots; i++) await add.click();
    await page.waitForFunction(
      (n) => document.querySelectorAll(".class-phase--connected").length === n,
      robots,
      { timeout: 60_000 },
    );
    await page
      .getByTestId("class-rbm-input")
      .setInputFiles([{ name: "wave.rbm", mimeType: "text/plain", buffer: wave }]);
    await page.getByRole("button", { name: `Upload to ${robots} robots` }).waitFor();
    const start = await page.evaluate(() => performance.now());
    await page.getByRole("button", { name: `Upload to ${robots} robots` }).click();
    await page
      .getByTestId("class-summary")
      .filter({ hasText: "Pack upload finished" })
      .waitFor({ timeout: 120_000 });
    const end = await page.evaluate(() => performance.now());
    // Let the observer deliver the last entries.
    await page.waitForTimeout(200);
    const tasks = await page.evaluate(() => (window as unknown as PageWindow).__rbcLongTasks);
    const summary = (await page.getByTestId("class-summary").textContent()) ?? "";
    const stored = Number(/(\d+) stored/.exec(summary)?.[1] ?? 0);
    const during = tasks.filter((t) => t.start + t.duration >= start && t.start <= end);
    await context.close();
    const round = (ms: number) => Math.round(ms * 10) / 10;
    return {
      robots,
      stored,
      uploadMs: Math.round(end - start),
      longestTaskMs: round(Math.max(0, ...during.map((t) => t.duration))),
      longTasks: during.length,
      longTaskTotalMs: round(during.reduce((sum, t) => sum + t.duration, 0)),
      longestTaskOfVisitMs: round(Math.max(0, ...tasks.map((t) => t.duration))),
    };
  } finally {
    await browser.close();
    await server.close();
  }
}

if (import.meta.url === `file://${process.argv[1]}`) {
  measureClassViewLongtask(process.argv[2]).then((f) => console.log(JSON.stringify(f)));
}
