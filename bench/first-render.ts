import { preview } from "vite";
import { launchChromium } from "../tests/support/chromium.ts";
import { PROJECT_ROOT } from "./bundle-size.ts";
import { median } from "./stats.ts";

/**
 * Time from navigation to the connect button being usable, in headless Chromium against `vite preview` of a
 * production build. "Usable": a <button> whose text is "Connect robot" or "Try the demo robot" is visible (it
 * has a layout box and `checkVisibility()` says so) and not disabled.
 *
 * Each load gets a fresh browser context (empty HTTP cache, no service worker: a first visit). A script
 * injected before the page's own (`addInitScript`) watches DOM mutations and animation frames and records
 * `performance.now()` when the button first becomes usable; `performance.now()` counts from the navigation's
 * start (the page's time origin), so the figure covers request, parse, script load and first render.
 * Playwright then waits for the same button to be visible and enabled, as a cross-check.
 */

const BUTTON_TEXT = /^(Connect robot|Try the demo robot)$/;

declare global {
  interface Window {
    __rbcFirstUsable?: number;
    __rbcFirstUsableText?: string;
  }
}

/**
 * Runs in the page before any of its scripts. A plain string, not a function: tsx would wrap a function's
 * source in helpers (`__name`) that do not exist in the page.
 */
const WATCH_FOR_CONNECT_BUTTON = `(() => {
  const pattern = /^(Connect robot|Try the demo robot)$/;
  const usable = (b) => {
    if (b.disabled || !pattern.test((b.textContent || "").trim())) return false;
    const box = b.getBoundingClientRect();
    if (box.width === 0 || box.height === 0) return false;
    return typeof b.checkVisibility === "function"
      ? b.checkVisibility({ opacityProperty: true, visibilityProperty: true })
      : true;
  };
  const look = () => {
    if (window.__rbcFirstUsable !== undefined) return true;
    for (const b of document.querySelectorAll("button")) {
      if (usable(b)) {
        window.__rbcFirstUsable = performance.now();
        window.__rbcFirstUsableText = (b.textContent || "").trim();
        return true;
      }
    }
    return false;
  };
  const observer = new MutationObserver(() => {
    if (look()) observer.disconnect();
  });
  observer.observe(document, { childList: true, subtree: true, attributes: true, characterData: true });
  const frame = () => {
    if (!look()) requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
})();`;

export interface FirstRenderFigures {
  medianMs: number;
  loadsMs: number[];
  button: string;
  url: string;
}

/** Serves `outDir` with vite preview on 127.0.0.1 (random free port) and times `loads` first visits. */
export async function measureFirstRender(outDir: string, loads = 5): Promise<FirstRenderFigures> {
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
    const url = `http://127.0.0.1:${address.port}/`;
    const loadsMs: number[] = [];
    let button = "";
    // One untimed load so that the first measured one does not pay for starting the renderer process pool.
    for (let i = 0; i <= loads; i++) {
      const context = await browser.newContext({ serviceWorkers: "block" });
      try {
        const page = await context.newPage();
        await page.addInitScript({ content: WATCH_FOR_CONNECT_BUTTON });
        await page.goto(url, { waitUntil: "commit" });
        const locator = page.getByRole("button", { name: BUTTON_TEXT }).first();
        await locator.waitFor({ state: "visible", timeout: 15_000 });
        if (!(await locator.isEnabled())) {
          await page.waitForFunction(() => window.__rbcFirstUsable !== undefined, undefined, {
            timeout: 15_000,
          });
        }
        const at = await page.evaluate(() => [window.__rbcFirstUsable, window.__rbcFirstUsableText] as const);
        if (at[0] === undefined) throw new Error("the connect button never became usable");
        if (i > 0) loadsMs.push(at[0]);
        button = at[1] ?? "";
      } finally {
        await context.close();
      }
    }
    return { medianMs: median(loadsMs), loadsMs, button, url };
  } finally {
    await browser.close();
    await server.close();
  }
}
