/**
 * Accessibility: axe-core on every view of the panel, on the demo robot, in light and in dark mode (issue #11,
 * item 11; issue #33, item 12). Each state of the page is checked in both colour schemes on the same page: the
 * scheme is switched with page.emulateMedia, nothing else changes between the two runs. The Class view is checked
 * with a class robot connected, so the top bar's Stop for every robot of the page is on screen. The target is zero
 * violations; a failure lists each one (rule, impact, elements, scheme) so it can be fixed without running axe by
 * hand.
 */
import { createRequire } from "node:module";
import type { BrowserContext, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { buildOnce, useApp } from "./harness.ts";
import { exampleText, rbmFile, showTab } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

const require = createRequire(import.meta.url);
const AXE_PATH = require.resolve("axe-core/axe.min.js");

interface AxeNode {
  target: unknown[];
  failureSummary?: string;
}
interface AxeViolation {
  id: string;
  impact: string | null;
  help: string;
  nodes: AxeNode[];
}

const app = useApp();
let fakeSerial: string;

beforeAll(async () => {
  ({ fakeSerial } = await buildOnce());
});

/**
 * A page like the harness's, but with the page's Content Security Policy bypassed so that axe can be added as a
 * script tag (the panel's CSP rightly refuses inline and foreign scripts).
 */
async function newAxePage(): Promise<{ context: BrowserContext; page: Page }> {
  const context = await app.browser.newContext({
    viewport: { width: 1280, height: 800 },
    serviceWorkers: "block",
    reducedMotion: "reduce",
    colorScheme: "light",
    bypassCSP: true,
  });
  await context.addInitScript({ content: `window.__rbcTestOptions = {};\n;\n${fakeSerial}` });
  const page = await context.newPage();
  return { context, page };
}

/**
 * axe's "needs review" results that are accepted, each with the reason. Every other one fails the test like a
 * violation: axe reports `aria-label` on a plain span (issue #11) as needing review, not as a violation.
 */
const REVIEWED: Record<string, string> = {
  "color-contrast":
    "axe cannot measure text it cannot see the background of (aria-hidden icons, text over other elements); " +
    "the colour tokens are chosen for 4.5:1, and the chart lines are measured in sensors.test.ts",
};

/** One line per violation or unreviewed "needs review": "rule (impact): help — element, element". */
async function violations(page: Page): Promise<string[]> {
  if (!(await page.evaluate(() => "axe" in window))) await page.addScriptTag({ path: AXE_PATH });
  const found = await page.evaluate(async () => {
    type Run = (o: unknown) => Promise<{ violations: unknown[]; incomplete: unknown[] }>;
    const axe = (window as unknown as { axe: { run: Run } }).axe;
    const result = await axe.run({ resultTypes: ["violations", "incomplete"] });
    return { violations: result.violations, incomplete: result.incomplete };
  });
  const line = (v: AxeViolation, kind: string) =>
    `${v.id} (${v.impact ?? "?"}${kind}): ${v.help} — ${v.nodes.map((n) => `${JSON.stringify(n.target)} ${(n.failureSummary ?? "").replace(/\s+/g, " ")}`).join(", ")}`;
  return [
    ...(found.violations as AxeViolation[]).map((v) => line(v, "")),
    ...(found.incomplete as AxeViolation[])
      .filter((v) => !(v.id in REVIEWED))
      .map((v) => line(v, ", needs review")),
  ];
}

const SCHEMES = ["light", "dark"] as const;

/**
 * Zero violations in the light and in the dark colour scheme, or a failure that lists them all. The page is left
 * in the light scheme. The charts and the 3D robot follow the scheme by a media-query listener: the check waits a
 * frame after each switch for them (and the CSS) to have redrawn.
 */
async function expectNoViolations(page: Page, where: string): Promise<void> {
  const found: string[] = [];
  for (const scheme of SCHEMES) {
    await page.emulateMedia({ colorScheme: scheme });
    await page.waitForFunction(
      (dark) => matchMedia("(prefers-color-scheme: dark)").matches === dark,
      scheme === "dark",
    );
    await page.evaluate(
      () => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))),
    );
    found.push(...(await violations(page)).map((v) => `[${scheme}] ${v}`));
  }
  await page.emulateMedia({ colorScheme: "light" });
  expect(found, `axe found ${found.length} violation(s) on ${where}:\n${found.join("\n")}\n`).toEqual([]);
}

const heading = (page: Page, name: string | RegExp) =>
  page.getByRole("heading", { level: 1, name }).waitFor();

/** The views, each with what shows it is ready (its heading, and its figures read from the robot). */
const VIEWS: readonly [string, (page: Page) => Promise<void>][] = [
  [
    "Robot",
    async (page) => {
      await heading(page, "Demo robot");
      await page.getByTestId("memory-action-text").filter({ hasText: "8,192" }).waitFor();
    },
  ],
  [
    "Zeros",
    async (page) => {
      await heading(page, "Zero positions");
      await page.locator("#zero-15").waitFor();
      // Idle: the table was read. While it is read, buttons are disabled and faded, and axe measures a button
      // that is disabled in the middle of its run as if it were active.
      await page.waitForFunction(() => {
        const field = document.querySelector<HTMLInputElement>("#zero-15");
        const read = document.querySelector("button:not([disabled])");
        return (
          field !== null &&
          field.value !== "" &&
          read !== null &&
          !document.body.textContent?.includes("Reading…")
        );
      });
      await page.locator("button:not([disabled])", { hasText: "Load factory zeros" }).waitFor();
    },
  ],
  ["Motions", (page) => heading(page, /^Motions/)],
  [
    "Editor",
    async (page) => {
      await heading(page, "Motion editor");
      // With a robot connected, teach-in and tethered play are offered too (in their tabs); the 3D robot is drawn.
      await page.locator("#editor-tab-teach").click();
      await page
        .getByRole("button", { name: /teach-in/i })
        .first()
        .waitFor();
    },
  ],
  [
    "Sensors",
    async (page) => {
      await heading(page, "Sensors");
      await page.locator('[data-testid="accel-chart"][data-chart="drawn"]').waitFor();
    },
  ],
  ["Servos", (page) => heading(page, /^Servos/)],
  [
    "Servo check",
    async (page) => {
      await heading(page, "Servo check");
      await page.getByTestId("doctor-scan-card").waitFor();
    },
  ],
  [
    "Firmware",
    async (page) => {
      await heading(page, /^Firmware/);
      await page.getByRole("button", { name: "Use the demo firmware file (2.50)" }).click();
      await page
        .getByText(/16,384 bytes|16 KiB/)
        .first()
        .waitFor();
      await page.locator('[data-testid="flash-start"]:not([disabled])').waitFor();
      await page.locator('[data-testid="fw-demo-file"]:not([disabled])').waitFor();
    },
  ],
  ["Log", (page) => heading(page, "Packet log")],
];

/**
 * Connects the demo robot unless it already is, so each test stands on its own (`-t` runs one alone): it waits
 * for the page to show either the start card or the connected robot before it looks, never a first render's
 * "not there yet".
 */
async function connectDemo(page: Page): Promise<void> {
  const demo = page.getByRole("button", { name: "Try the demo robot" });
  // The top bar's Limp button is there on every view while a robot is connected, and only then.
  const connected = page.locator("#limp-button");
  await demo.or(connected).first().waitFor();
  if (await connected.isVisible()) return;
  await demo.click();
  await connected.waitFor();
}

describe("axe on every view, light and dark colour scheme", () => {
  let context: BrowserContext;
  let page: Page;

  beforeAll(async () => {
    ({ context, page } = await newAxePage());
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
  });

  afterAll(async () => {
    await context?.close();
  });

  it("the start card (disconnected)", async () => {
    await page.getByRole("button", { name: "Try the demo robot" }).waitFor();
    await expectNoViolations(page, "the start card");
  });

  for (const [name, ready] of VIEWS) {
    it(`the ${name} view`, async () => {
      await connectDemo(page);
      await page.getByRole("link", { name, exact: true }).click();
      await ready(page);
      await expectNoViolations(page, `the ${name} view`);
    });
  }

  it("every Motions tab, with a motion file open and its scenes shown", async () => {
    await connectDemo(page);
    await page.getByRole("link", { name: "Motions", exact: true }).click();
    await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", exampleText("wave.rbm")));
    await page.getByTestId("scene-section").waitFor();
    await expectNoViolations(page, "the Motions Files tab with wave.rbm open");
    for (const tab of ["Memory", "Run", "Sounds"] as const) {
      await showTab(page, tab);
      await expectNoViolations(page, `the Motions ${tab} tab`);
    }
  });

  it("the Limp question", async () => {
    await connectDemo(page);
    await page.getByRole("button", { name: "Limp…" }).click();
    await page.getByRole("alertdialog").waitFor();
    await expectNoViolations(page, "the Limp question");
    await page.getByRole("alertdialog").getByRole("button", { name: "Cancel" }).click();
  });

  // Last: the class robot stays connected, so the top bar offers Stop from here on.
  it("the Class view with a class robot connected, the top bar's Stop on screen, and what Stop said", async () => {
    await connectDemo(page);
    await page.getByRole("link", { name: "Class", exact: true }).click();
    await heading(page, "Class: several robots at once");
    await page.getByRole("button", { name: "Add demo robot", exact: true }).click();
    await page
      .getByTestId("class-robot")
      .getByTestId("class-phase")
      .filter({ hasText: "Connected" })
      .waitFor();
    const stop = page.locator(".top-bar").getByRole("button", { name: "Stop", exact: true });
    await stop.waitFor();
    await expectNoViolations(page, "the Class view with a class robot");
    // What Stop said, per robot, in the top bar; the pointer still over Stop (its hover colour is measured) and
    // the keyboard focus on it.
    await stop.click();
    await page.getByTestId("robot-stop").first().waitFor();
    await stop.hover();
    await expectNoViolations(page, "the Class view after Stop, the pointer over Stop");
    // The Class view's own "Stop all", hovered and focused as well.
    const stopAll = page.locator("main").getByRole("button", { name: /^Stop all/ });
    await stopAll.hover();
    await stopAll.focus();
    await expectNoViolations(page, "the Class view, the pointer over Stop all");
  });
});
