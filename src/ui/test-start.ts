import type { AppContext } from "./context.ts";

/**
 * The browser tests' start option: the page opens with a robot already connected, as if its button had been
 * pressed (the demo robot, or the fake robot on a cable through its fake chooser), so that a test that only
 * needs "a robot connected, view X" skips the clicks (tests/e2e/connected-page.ts). The tests' init script sets
 * `window.__RBC_TEST_START__` before the panel loads.
 *
 * Only the tests' build has this module: main.ts imports it only when the build's mode is the tests' ("e2e",
 * tests/e2e/harness.ts), so `npm run build` leaves it out, and `npm run check:bundle` fails if the option's name
 * is in the production bundle.
 */
/** The global the tests' init script sets, and the name `npm run check:bundle` looks for in the production bundle. */
export const TEST_START_NAME = "__RBC_TEST_START__";

export interface TestStart {
  /** The robot connected at start: the demo robot, or the robot on the (fake) cable. */
  connect: "demo" | "cable";
}

function isTestStart(value: unknown): value is TestStart {
  if (typeof value !== "object" || value === null || !("connect" in value)) return false;
  return value.connect === "demo" || value.connect === "cable";
}

/** Connects the robot the tests' start option names, if the page has one. */
export function applyTestStart(app: AppContext): void {
  const start = (globalThis as Record<string, unknown>)[TEST_START_NAME];
  if (!isTestStart(start)) return;
  if (start.connect === "demo") void app.session.connectDemo();
  else app.session.chooseAndConnect();
}
