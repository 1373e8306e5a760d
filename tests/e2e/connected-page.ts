/**
 * A page that opens with a robot already connected, in the view a test looks at: the tests' start option
 * (src/ui/test-start.ts) connects the demo robot, or the fake robot on a cable, as the panel starts, so a test
 * that only needs "a robot connected, view X" does not click its way there.
 */
import type { Page } from "playwright-core";
import { afterAll, beforeAll } from "vitest";
import type { TestStart } from "../../src/ui/test-start.ts";
import type { AppHarness, TestContext } from "./harness.ts";
import { DESKTOP, type Size } from "./i18n-checks.ts";
import type { RbcTestOptions } from "./rbc-test-globals.ts";

/** The start options (`app.newPage({ start })`): the robot on the fake cable, or the demo robot, connected at start. */
export const CABLE: TestStart = { connect: "cable" };
export const DEMO: TestStart = { connect: "demo" };

export interface ConnectedSetup {
  /** The robot connected at start (default the demo robot). */
  robot?: "demo" | "cable";
  /** The view shown, by route ("servos"); the Robot view by default. */
  view?: string;
  /** The browser's language, e.g. "ko-KR" (default English). */
  locale?: string;
  size?: Size;
  options?: RbcTestOptions;
  /** The page stays open across tests (`sharedConnectedPage`). */
  kept?: boolean;
}

/** Waits until a robot is connected: the top bar's Limp button is there on every view then, and only then. */
async function connected(page: Page): Promise<void> {
  await page.locator("#limp-button").waitFor();
}

/**
 * Loads the panel in `view` (the Robot view by default) on a page opened with a start option
 * (`app.newPage({ start: { connect: "demo" } })`), and waits until its robot is connected.
 */
export async function loadConnected(page: Page, url: string, view?: string): Promise<void> {
  await page.goto(`${url}${view ? `#/${view}` : ""}`, { waitUntil: "domcontentloaded" });
  await connected(page);
}

/** Opens the panel with `setup.robot` connected at start, in `setup.view`, and waits until it is connected. */
export async function openConnected(
  app: AppHarness,
  setup: ConnectedSetup = {},
): Promise<{ context: TestContext; page: Page }> {
  const { context, page } = await app.newPage({
    start: { connect: setup.robot ?? "demo" },
    viewport: { ...(setup.size ?? DESKTOP) },
    ...(setup.locale ? { locale: setup.locale } : {}),
    ...(setup.options ? { options: setup.options } : {}),
    ...(setup.kept ? { kept: true } : {}),
  });
  await loadConnected(page, app.url, setup.view);
  return { context, page };
}

/**
 * One connected page for the tests of a describe, which look at it in order: opened before the first
 * (`openConnected`), closed after the last. Only for tests that leave nothing behind that the next one would see
 * (they read, switch the language or the window's size, and go from view to view). Call it inside the describe;
 * what it returns gives the page inside the tests.
 */
export function sharedConnectedPage(app: AppHarness, setup: ConnectedSetup = {}): () => Page {
  let opened: { context: TestContext; page: Page } | undefined;
  beforeAll(async () => {
    opened = await openConnected(app, { ...setup, kept: true });
  });
  afterAll(async () => {
    await opened?.context.close();
  });
  return () => {
    if (!opened) throw new Error("the shared page opens before the describe's first test");
    return opened.page;
  };
}

/** The Motions view once it has read the robot's memory, on a page opened with the start option `CABLE`. */
export async function loadMotions(page: Page, url: string): Promise<void> {
  await loadConnected(page, url, "motions");
  await page.getByTestId("memory-card").waitFor();
  await page.getByTestId("mem-motion-text").filter({ hasText: "24,576 of 24,576" }).waitFor();
}
