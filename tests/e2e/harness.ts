/**
 * Shared set-up of the browser tests: the app built once (cached by a hash of its inputs, so the test files
 * share one build), served by Vite's preview server on 127.0.0.1, the fake `navigator.serial` bundled to an
 * IIFE string, and one Chromium per test file, whose browser contexts are kept across its tests (`startHarness`).
 */
import { createHash } from "node:crypto";
import { existsSync } from "node:fs";
import { mkdir, readdir, readFile, rename, rm, stat, writeFile } from "node:fs/promises";
import { createServer } from "node:net";
import { tmpdir } from "node:os";
import { join, relative } from "node:path";
import { fileURLToPath } from "node:url";
import type { Browser, BrowserContext, Disposable, Locator, Page } from "playwright-core";
import { build, preview } from "vite";
import { afterAll, afterEach, beforeAll, expect } from "vitest";
import { TEST_START_NAME, type TestStart } from "../../src/ui/test-start.ts";
import { launchChromium } from "../support/chromium.ts";
import type { RbcTestOptions } from "./rbc-test-globals.ts";

/**
 * The simulated robot's virtual clock paced at up to 4 times real speed, for tests that wait for motions,
 * sounds, uploads or polling: the panel's client shares the clock, so every duration and timeout keeps its
 * proportions, and a reply always beats its timeout (timers run in due order, and a starved page pauses the
 * robot's time rather than letting it jump).
 */
export const FAST: RbcTestOptions = { timeScale: 4 };

export const ROOT = fileURLToPath(new URL("../..", import.meta.url));
const CACHE_PREFIX = "rbc-panel-e2e-";

/** The files a build depends on. */
const INPUTS = [
  "src",
  "public",
  "index.html",
  "vite.config.ts",
  "scripts/vite-words-per-language.ts",
  "scripts/vite-changelog.ts",
  "CHANGELOG.md",
  "package-lock.json",
  "tests/e2e/fake-serial-entry.ts",
  "tests/e2e/rbc-test-globals.ts",
  "tests/support/paced-clock.ts",
];

async function listFiles(path: string): Promise<string[]> {
  const info = await stat(path).catch(() => undefined);
  if (!info) return [];
  if (info.isFile()) return [path];
  const out: string[] = [];
  for (const entry of await readdir(path)) out.push(...(await listFiles(join(path, entry))));
  return out;
}

/**
 * The mode of the tests' build: like `npm run build`, plus the tests' start option (src/ui/test-start.ts), which
 * only a build in this mode contains.
 */
const TEST_BUILD_MODE = "e2e";

async function inputsHash(): Promise<string> {
  const hash = createHash("sha256");
  hash.update(`mode ${TEST_BUILD_MODE}\n`);
  const files = (await Promise.all(INPUTS.map((p) => listFiles(join(ROOT, p))))).flat().sort();
  for (const file of files) {
    hash.update(relative(ROOT, file));
    hash.update(await readFile(file));
  }
  return hash.digest("hex").slice(0, 16);
}

async function buildFakeSerial(): Promise<string> {
  const result = await build({
    configFile: false,
    root: ROOT,
    publicDir: false,
    logLevel: "warn",
    build: {
      write: false,
      minify: false,
      target: "es2022",
      lib: { entry: join(ROOT, "tests/e2e/fake-serial-entry.ts"), formats: ["iife"], name: "RbcFakeSerial" },
    },
  });
  const outputs = Array.isArray(result) ? result : [result];
  for (const output of outputs) {
    if (!("output" in output)) continue;
    for (const chunk of output.output) if (chunk.type === "chunk" && chunk.isEntry) return chunk.code;
  }
  throw new Error("the fake serial bundle produced no entry chunk");
}

/** A cached build older than this is removed when a new one is made. */
const STALE_BUILD_MS = 6 * 60 * 60 * 1000;

/** Builds the app and the fake serial script once per set of inputs; later calls reuse the build. */
export async function buildOnce(): Promise<{ outDir: string; fakeSerial: string }> {
  const dir = join(tmpdir(), `${CACHE_PREFIX}${await inputsHash()}`);
  const outDir = join(dir, "app");
  const fakeFile = join(dir, "fake-serial.iife.js");
  if (!existsSync(join(dir, ".complete"))) {
    // Clear out stale builds, but not ones another test run (other inputs) may be serving right now.
    for (const entry of await readdir(tmpdir())) {
      if (!entry.startsWith(CACHE_PREFIX)) continue;
      const path = join(tmpdir(), entry);
      // Another test run (another checkout) may be removing the same stale build at this moment.
      const info = await stat(path).catch(() => undefined);
      if (info && Date.now() - info.mtimeMs > STALE_BUILD_MS)
        await rm(path, { recursive: true, force: true });
    }
    const work = `${dir}.tmp-${process.pid}`;
    await mkdir(work, { recursive: true });
    await build({
      root: ROOT,
      configFile: join(ROOT, "vite.config.ts"),
      mode: TEST_BUILD_MODE,
      logLevel: "warn",
      build: { outDir: join(work, "app"), emptyOutDir: true },
    });
    await writeFile(join(work, "fake-serial.iife.js"), await buildFakeSerial());
    await writeFile(join(work, ".complete"), new Date().toISOString());
    try {
      await rename(work, dir);
    } catch (e) {
      // Test files run in parallel: another one finished the same build first. Use that one.
      await rm(work, { recursive: true, force: true });
      if (!existsSync(join(dir, ".complete"))) throw e;
    }
  }
  return { outDir, fakeSerial: await readFile(fakeFile, "utf8") };
}

function freePort(): Promise<number> {
  return new Promise((resolve, reject) => {
    const server = createServer();
    server.unref();
    server.on("error", reject);
    server.listen(0, "127.0.0.1", () => {
      const address = server.address();
      const port = typeof address === "object" && address ? address.port : 0;
      server.close(() => resolve(port));
    });
  });
}

export interface PageOptions {
  /** Install the fake navigator.serial (default true). */
  fakeSerial?: boolean;
  /** Remove navigator.serial entirely (a browser without Web Serial). */
  noSerial?: boolean;
  options?: RbcTestOptions;
  viewport?: { width: number; height: number };
  /** Service workers are blocked unless a test needs one (offline). */
  serviceWorkers?: "allow" | "block";
  /** The browser's language (navigator.language, Accept-Language), e.g. "ko-KR"; English by default. */
  locale?: string;
  /** The tests' start option: the panel connects this robot as it starts (src/ui/test-start.ts). */
  start?: TestStart;
  /**
   * The page stays open after the test that opened it, for the next tests of a describe that look at the same
   * page in order (`sharedConnectedPage`), until its context is closed.
   */
  kept?: boolean;
}

/**
 * The browser context a test's page lives in, as far as a test may touch it. Contexts are kept for the next
 * test of the file (see `startHarness`), so `close` hands it back rather than closing it, and a test changes
 * only what the harness puts back: permissions and the network being offline.
 */
export interface TestContext {
  /** Closes the test's pages and hands the context back for the next test (done after each test anyway). */
  close(): Promise<void>;
  grantPermissions: BrowserContext["grantPermissions"];
  setOffline: BrowserContext["setOffline"];
}

export interface AppHarness {
  url: string;
  origin: string;
  browser: Browser;
  newPage(options?: PageOptions): Promise<{ context: TestContext; page: Page }>;
  /** Hands back every context a test still holds (after each test), but for kept pages (`PageOptions.kept`). */
  releaseAll(): Promise<void>;
  close(): Promise<void>;
}

/** Records CSP violations into window.__cspViolations, from the very start of every page. */
const CSP_WATCH = `window.__cspViolations = [];
document.addEventListener("securitypolicyviolation", (e) => {
  window.__cspViolations.push(e.violatedDirective + " " + (e.blockedURI || "inline") + " " + e.sourceFile + ":" + e.lineNumber);
});`;

const NO_SERIAL = `delete Navigator.prototype.serial; delete navigator.serial;`;

/** A browser context kept across the tests of one file, for pages with the same language and service workers. */
interface PooledContext {
  context: BrowserContext;
  /** What `newPage` options the context was made with: the ones a page cannot change. */
  key: string;
  /** The current test's init script (fake serial port, its options), removed when the context is handed back. */
  script: Disposable | undefined;
  inUse: boolean;
  /** Not handed back after each test (`PageOptions.kept`), only by its `close`. */
  kept: boolean;
}

const DEFAULT_VIEWPORT = { width: 1280, height: 800 };

/**
 * Starts the preview server and one Chromium for a test file.
 *
 * Each test gets a new page, but not a new browser context: opening a page, loading the panel and connecting the
 * demo robot cost 4.7 CPU-seconds in a new context and 2.0 in a kept one (the full Chromium, measured one after
 * the other on a 2-core machine), and setting up pages was most of what the browser tests spent. A context is
 * kept for the next test that asks for the same language and service-worker setting, and starts it as a new one
 * would: the previous test's pages are closed, its init script removed, its permissions and offline state put
 * back, and everything the origin stored (IndexedDB, local storage, caches, cookies, service workers) cleared
 * before the new page loads anything. What a test changes on the page itself (init scripts, a fake clock,
 * listeners) goes with the page.
 */
export async function startHarness(): Promise<AppHarness> {
  const { outDir, fakeSerial } = await buildOnce();
  const port = await freePort();
  const server = await preview({
    root: ROOT,
    configFile: join(ROOT, "vite.config.ts"),
    logLevel: "warn",
    build: { outDir },
    preview: { host: "127.0.0.1", port, strictPort: true, open: false },
  });
  const origin = `http://127.0.0.1:${port}`;
  const browser = await launchChromium();
  const pool = new Set<PooledContext>();

  async function handBack(entry: PooledContext): Promise<void> {
    if (!entry.inUse) return;
    try {
      await entry.script?.dispose();
      entry.script = undefined;
      for (const page of entry.context.pages()) await page.close();
      await entry.context.clearPermissions();
      await entry.context.setOffline(false);
      entry.inUse = false;
      entry.kept = false;
    } catch {
      // A context that cannot be put back (its browser crashed, a test closed it) is not used again.
      pool.delete(entry);
      await entry.context.close().catch(() => {});
    }
  }

  async function takeContext(key: string, options: PageOptions): Promise<PooledContext> {
    for (const entry of pool) {
      if (entry.inUse || entry.key !== key) continue;
      entry.inUse = true;
      return entry;
    }
    const context = await browser.newContext({
      viewport: DEFAULT_VIEWPORT,
      serviceWorkers: options.serviceWorkers ?? "block",
      acceptDownloads: true,
      reducedMotion: "reduce",
      locale: options.locale ?? "en-US",
    });
    const entry: PooledContext = { context, key, script: undefined, inUse: true, kept: false };
    pool.add(entry);
    context.on("close", () => pool.delete(entry));
    return entry;
  }

  return {
    url: `${origin}/`,
    origin,
    browser,
    async newPage(options = {}) {
      const key = JSON.stringify([options.serviceWorkers ?? "block", options.locale ?? "en-US"]);
      const entry = await takeContext(key, options);
      const { context } = entry;
      entry.kept = options.kept ?? false;
      // One init script, so that its parts run in this order (Playwright does not order separate ones).
      const scripts = [CSP_WATCH];
      if (options.noSerial) {
        scripts.push(NO_SERIAL);
      } else if (options.fakeSerial ?? true) {
        scripts.push(`window.__rbcTestOptions = ${JSON.stringify(options.options ?? {})};`, fakeSerial);
      }
      if (options.start) scripts.push(`window.${TEST_START_NAME} = ${JSON.stringify(options.start)};`);
      entry.script = await context.addInitScript({ content: scripts.join("\n;\n") });
      const page = await context.newPage();
      // The page is still blank: nothing of this origin runs while its storage is cleared.
      const cdp = await context.newCDPSession(page);
      await cdp.send("Storage.clearDataForOrigin", { origin, storageTypes: "all" });
      await cdp.detach();
      await page.setViewportSize(options.viewport ?? DEFAULT_VIEWPORT);
      return {
        page,
        context: {
          close: () => handBack(entry),
          grantPermissions: (permissions, grant) => context.grantPermissions(permissions, grant),
          setOffline: (offline) => context.setOffline(offline),
        },
      };
    },
    async releaseAll() {
      for (const entry of pool) if (!entry.kept) await handBack(entry);
    },
    async close() {
      for (const { context } of pool) await context.close().catch(() => {});
      await browser.close().catch(() => {});
      await server.close();
    },
  };
}

/** Collects what a page should never do: requests to other origins, page errors, CSP violations. */
export function watchPage(page: Page, origin: string): { foreignRequests: string[]; errors: string[] } {
  const seen = { foreignRequests: [] as string[], errors: [] as string[] };
  page.on("request", (request) => {
    const url = request.url();
    if (url.startsWith("blob:") || url.startsWith("data:")) return;
    if (new URL(url).origin !== origin) seen.foreignRequests.push(url);
  });
  page.on("pageerror", (error) => seen.errors.push(`pageerror: ${error.message}`));
  page.on("console", (message) => {
    if (message.type() === "error") seen.errors.push(`console: ${message.text()}`);
  });
  return seen;
}

export async function cspViolations(page: Page): Promise<string[]> {
  return page.evaluate(() => window.__cspViolations ?? []);
}

/** Loads the app and connects through "Connect robot" (the fake chooser grants the mock port). */
export async function connectRobot(page: Page, url: string): Promise<void> {
  // The app's module script has run by DOMContentLoaded; the icon and manifest need not be waited for.
  await page.goto(url, { waitUntil: "domcontentloaded" });
  await page.getByRole("button", { name: "Connect robot" }).click();
  await page.getByTestId("device-card").waitFor();
}

/**
 * Waits `ms` of the simulated robot's time (the fake port's virtual clock).
 * For what can only be seen as nothing happening: "no byte goes out for a while".
 */
export async function robotTime(page: Page, ms: number): Promise<void> {
  await page.evaluate(
    (wait) =>
      new Promise<void>((resolve) => {
        const clock = window.__rbcTest?.clock;
        if (!clock) throw new Error("no fake serial port in this page");
        clock.setTimeout(resolve, wait);
      }),
    ms,
  );
}

/** An element's text with runs of white space collapsed (templates indent their text). */
export function squash(text: string | null): string {
  return (text ?? "").replace(/\s+/g, " ").trim();
}

/**
 * Stops the simulated robot's time (the fake port's robot and the demo robot) until `releaseRobot`: the panel
 * still renders and answers, but no reply, motion frame or timeout happens, so a test can look at a motion or
 * a sound in the middle however slowly its own steps run.
 */
export async function holdRobot(page: Page): Promise<void> {
  await page.evaluate(() => window.__rbcTest?.clock.hold());
}

/** Lets the simulated robot's time run again (see `holdRobot`). */
export async function releaseRobot(page: Page): Promise<void> {
  await page.evaluate(() => window.__rbcTest?.clock.release());
}

declare global {
  interface Window {
    /** The robot's time when each of `watchText`'s watches saw its text, by the watch's key. */
    __rbcShownAt?: Record<string, number>;
  }
}

/** Watches started in this test file, each with its own key in the page. */
let watches = 0;

/** A moment the page watches for (`watchText`). */
export interface ShownMoment {
  /** Waits until the text was shown; the robot's time (ms of its clock) at that moment. */
  moment(): Promise<number>;
}

/**
 * Starts watching the page for an element matching `selector` whose text matches `text`, and returns once the
 * watch is in place, so that it can be started before the click that shows the text. The page notes the robot's
 * time in the same task as the change that shows it (a mutation observer), not after the test's next steps:
 * a moment that lasts a few ms of robot time is caught however slowly the test runs. With `hold`, the robot's
 * time also stands still from that moment (`holdRobot`), so the test's next steps (posing the robot by hand, a
 * Cancel, a Stop) happen at the moment it was shown; call `releaseRobot` after them. Text already shown when
 * the watch starts counts as shown then.
 */
export async function watchText(
  page: Page,
  selector: string,
  text: RegExp,
  { hold = false }: { hold?: boolean } = {},
): Promise<ShownMoment> {
  watches += 1;
  const key = `w${watches}`;
  await page.evaluate(
    ({ key, selector, source, flags, hold }) => {
      const pattern = new RegExp(source, flags);
      const shown = () =>
        [...document.querySelectorAll(selector)].some((e) => pattern.test(e.textContent ?? ""));
      const note = () => {
        const clock = window.__rbcTest?.clock;
        if (hold) clock?.hold();
        window.__rbcShownAt = { ...window.__rbcShownAt, [key]: clock?.now() ?? Number.NaN };
      };
      if (shown()) {
        note();
        return;
      }
      const observer = new MutationObserver(() => {
        if (!shown()) return;
        observer.disconnect();
        note();
      });
      observer.observe(document.documentElement, { childList: true, subtree: true, characterData: true });
    },
    { key, selector, source: text.source, flags: text.flags, hold },
  );
  return {
    async moment() {
      const handle = await page.waitForFunction((key) => {
        const at = window.__rbcShownAt?.[key];
        return at === undefined ? false : [at];
      }, key);
      const [at] = (await handle.jsonValue()) as [number];
      return at;
    },
  };
}

/**
 * Waits until `selector`'s text matches `text` and holds the robot's time from that moment (`watchText` with
 * `hold`). Call `releaseRobot` after the steps that must happen at that moment.
 */
export async function holdRobotWhenShown(page: Page, selector: string, text: RegExp): Promise<void> {
  await (await watchText(page, selector, text, { hold: true })).moment();
}

/** The simulated robot's time (ms of its clock). */
export const robotNow = (page: Page) => page.evaluate(() => window.__rbcTest?.clock.now() ?? Number.NaN);

/** How long one read of a text may wait for its element before the poll reads again (ms). */
const READ_MS = 2000;

/**
 * Waits until `locator`'s text, white space collapsed (`squash`), is `expected`, or contains it with
 * `contains`, or matches it when it is a RegExp. The panel draws what an action changed on its next render,
 * so a text read once right after a click can still be the old one on a starved machine; this reads it again
 * until it is right, and fails after the browser project's poll timeout (10 s, vitest.config.ts) with the
 * last text read.
 */
export async function expectText(
  locator: Locator,
  expected: string | RegExp,
  { contains = false }: { contains?: boolean } = {},
): Promise<void> {
  const shown = expect.poll(async () => squash(await locator.textContent({ timeout: READ_MS })), {
    message: `the text of ${locator}`,
  });
  if (typeof expected !== "string") await shown.toMatch(expected);
  else if (contains) await shown.toContain(expected);
  else await shown.toBe(expected);
}

/**
 * The app for the tests of one file: started before them (one browser, the shared build) and closed after them.
 * Call it once at the top of the file; what it returns may be used inside the tests.
 */
export function useApp(): AppHarness {
  let started: AppHarness | undefined;
  beforeAll(async () => {
    started = await startHarness();
  });
  afterEach(async () => {
    await started?.releaseAll();
  });
  afterAll(async () => {
    await started?.close();
  });
  const app = () => {
    if (!started) throw new Error("the app starts before the tests: use it inside a test or a hook");
    return started;
  };
  return {
    get url() {
      return app().url;
    },
    get origin() {
      return app().origin;
    },
    get browser() {
      return app().browser;
    },
    newPage: (options) => app().newPage(options),
    releaseAll: () => app().releaseAll(),
    close: () => app().close(),
  };
}
