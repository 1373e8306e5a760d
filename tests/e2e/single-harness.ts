/**
 * Set-up shared by the delivery tests: the one-file panel built into a temporary folder, pages with the fake
 * `navigator.serial` injected exactly as tests/e2e/harness.ts does it, a tiny static server that mounts a build
 * under a sub-path (as GitHub Pages serves a project site at /<repository>/), and the walk every delivery of
 * the panel must pass.
 */
import { mkdtemp, readFile } from "node:fs/promises";
import { createServer, type Server } from "node:http";
import { tmpdir } from "node:os";
import { extname, join, normalize, sep } from "node:path";
import type { Browser, BrowserContext, Page } from "playwright-core";
import { build } from "vite";
import { expect } from "vitest";
import { SINGLE_FILE_MODE, SINGLE_FILE_NAME } from "../../vite.config.ts";
import { expectText, FAST, ROOT, squash } from "./harness.ts";
import type { RbcTestOptions } from "./rbc-test-globals.ts";

/** Builds the one-file panel (`npm run build:single`'s configuration) into a new temporary folder. */
export async function buildSingleFile(): Promise<{ dir: string; file: string }> {
  const dir = await mkdtemp(join(tmpdir(), "rbc-panel-single-"));
  await build({
    root: ROOT,
    configFile: join(ROOT, "vite.config.ts"),
    mode: SINGLE_FILE_MODE,
    logLevel: "warn",
    build: { outDir: dir, emptyOutDir: true },
  });
  return { dir, file: join(dir, SINGLE_FILE_NAME) };
}

/** Records CSP violations into window.__cspViolations, from the very start of every page (as harness.ts). */
const CSP_WATCH = `window.__cspViolations = [];
document.addEventListener("securitypolicyviolation", (e) => {
  window.__cspViolations.push(e.violatedDirective + " " + (e.blockedURI || "inline") + " " + e.sourceFile + ":" + e.lineNumber);
});`;

/** A page with the fake navigator.serial (the IIFE from harness.ts's buildOnce()) and the CSP watch. */
export async function injectedPage(
  browser: Browser,
  fakeSerial: string,
  options: { serviceWorkers?: "allow" | "block"; rbc?: RbcTestOptions } = {},
): Promise<{ context: BrowserContext; page: Page }> {
  const context = await browser.newContext({
    viewport: { width: 1280, height: 800 },
    serviceWorkers: options.serviceWorkers ?? "block",
    reducedMotion: "reduce",
  });
  await context.addInitScript({
    content: [
      CSP_WATCH,
      `window.__rbcTestOptions = ${JSON.stringify(options.rbc ?? FAST)};`,
      fakeSerial,
    ].join("\n;\n"),
  });
  return { context, page: await context.newPage() };
}

/**
 * Collects every request the page makes that `allowed` does not accept (data: and blob: URLs are always
 * fine: they never leave the page), and page errors and console errors.
 */
export function watchRequests(
  page: Page,
  allowed: (url: string) => boolean,
): { requests: string[]; unexpected: string[]; errors: string[] } {
  const seen = { requests: [] as string[], unexpected: [] as string[], errors: [] as string[] };
  page.on("request", (request) => {
    const url = request.url();
    seen.requests.push(url);
    if (url.startsWith("data:") || url.startsWith("blob:")) return;
    if (!allowed(url)) seen.unexpected.push(url);
  });
  page.on("pageerror", (error) => seen.errors.push(`pageerror: ${error.message}`));
  page.on("console", (message) => {
    if (message.type() === "error") seen.errors.push(`console: ${message.text()}`);
  });
  return seen;
}

/** Each view's link in the navigation and the heading it shows (the Robot view's says which robot). */
const VIEW_HEADINGS: readonly (readonly [string, string | RegExp])[] = [
  ["Robot", /^(Demo robot|Robot)$/],
  ["Zeros", "Zero positions"],
  ["Motions", "Motions"],
  ["Sensors", "Sensors"],
  ["Servos", "Servos"],
  ["Log", "Packet log"],
];

async function openEachView(page: Page): Promise<void> {
  for (const [link, heading] of VIEW_HEADINGS) {
    await page.getByRole("link", { name: link, exact: true }).click();
    await page.getByRole("heading", { level: 1, name: heading }).waitFor();
  }
}

async function openExampleAndUpload(page: Page, confirm: boolean): Promise<string> {
  await page.getByRole("link", { name: "Motions", exact: true }).click();
  await page
    .getByText(/24,576 of 24,576/)
    .first()
    .waitFor();
  const picker = page.getByText("Open an example motion");
  const open = page.getByRole("button", { name: "Open wave.rbm" });
  if (!(await open.isVisible())) await picker.click();
  await open.click();
  await page.getByText("Opened the example wave.rbm.").waitFor();
  await page.getByRole("button", { name: "Upload to robot" }).first().click();
  if (confirm) await page.getByRole("button", { name: "Upload (experimental)" }).click();
  const result = page.getByText(/^Uploaded wave\.rbm/).first();
  await result.waitFor({ timeout: 20_000 }).catch(async (e) => {
    throw new Error(`${e}\nThe Motions view said: ${squash(await page.locator("main").textContent())}`);
  });
  return squash(await result.textContent());
}

/**
 * The walk every delivery of the panel passes: the demo robot ("Try the demo robot"), each view, an example
 * motion uploaded; then Disconnect and the robot on the (fake) serial port, each view again and the same
 * upload, confirmed as on real hardware.
 */
export async function walkPanel(page: Page): Promise<void> {
  await page.getByRole("button", { name: "Try the demo robot" }).click();
  await page.getByTestId("device-card").waitFor();
  await expectText(page.getByTestId("firmware"), "2.23");
  await openEachView(page);
  expect(await openExampleAndUpload(page, false)).toMatch(/624 bytes/);
  // The page's fake port was never touched: that was the built-in demo robot.
  expect(await page.evaluate(() => window.__rbcTest?.port.stats.opens)).toBe(0);

  await page.getByRole("link", { name: "Robot", exact: true }).click();
  await page.getByRole("button", { name: "Disconnect" }).click();
  await page.getByRole("button", { name: "Connect robot" }).click();
  await page.getByTestId("device-card").waitFor();
  await expectText(page.getByTestId("connection-status"), /^(?!Demo robot).*Connected/);
  expect(await page.evaluate(() => window.__rbcTest?.port.stats.opens)).toBe(1);
  await openEachView(page);
  expect(await openExampleAndUpload(page, true)).toMatch(/624 bytes/);
  // The simulated robot behind the serial port holds one downloaded motion now.
  expect(await page.evaluate(() => window.__rbcTest?.sim.motions.length)).toBe(1);
}

export async function cspViolations(page: Page): Promise<string[]> {
  return page.evaluate(() => window.__cspViolations ?? []);
}

const TYPES: Record<string, string> = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript; charset=utf-8",
  ".css": "text/css; charset=utf-8",
  ".svg": "image/svg+xml",
  ".webmanifest": "application/manifest+json",
  ".map": "application/json",
  ".json": "application/json",
};

export interface SubpathServer {
  /** The panel's address: http://127.0.0.1:<port><mount> */
  url: string;
  origin: string;
  /** Every path the server was asked for, in order. */
  paths: string[];
  /** Text appended to sw.js from now on (a changed service worker, as a new release would bring). */
  swSuffix: string;
  close(): Promise<void>;
}

/** Serves the files of `dir` at `mount` (e.g. "/rbc-panel/"), and nothing anywhere else. */
export async function serveUnder(dir: string, mount: string): Promise<SubpathServer> {
  const root = normalize(dir + sep);
  const state = { paths: [] as string[], swSuffix: "" };
  const server: Server = createServer((req, res) => {
    const path = decodeURIComponent(new URL(req.url ?? "/", "http://x").pathname);
    state.paths.push(path);
    if (!path.startsWith(mount)) {
      res.writeHead(404, { "content-type": "text/plain" }).end("not found");
      return;
    }
    const rel = path.slice(mount.length) || "index.html";
    const file = normalize(join(root, rel));
    if (!file.startsWith(root)) {
      res.writeHead(403).end();
      return;
    }
    readFile(file)
      .then((body) => {
        const extra = rel === "sw.js" ? Buffer.from(state.swSuffix) : Buffer.alloc(0);
        res.writeHead(200, {
          "content-type": TYPES[extname(file)] ?? "application/octet-stream",
          "cache-control": "no-cache",
        });
        res.end(Buffer.concat([body, extra]));
      })
      .catch(() => res.writeHead(404, { "content-type": "text/plain" }).end("not found"));
  });
  await new Promise<void>((resolve) => server.listen(0, "127.0.0.1", resolve));
  const address = server.address();
  const port = typeof address === "object" && address ? address.port : 0;
  const origin = `http://127.0.0.1:${port}`;
  return {
    url: `${origin}${mount}`,
    origin,
    paths: state.paths,
    get swSuffix() {
      return state.swSuffix;
    },
    set swSuffix(text: string) {
      state.swSuffix = text;
    },
    close: () =>
      new Promise<void>((resolve) => {
        server.closeAllConnections();
        server.close(() => resolve());
      }),
  };
}
