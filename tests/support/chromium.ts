import { existsSync } from "node:fs";
import { type Browser, chromium } from "playwright-core";

/**
 * Debian's Chromium, as the browser tests and the first-render benchmark launch it. Playwright cannot download
 * a browser on these machines; the flags keep Chromium from reaching for the network on its own.
 *
 * Debian's headless shell (package chromium-headless-shell: the same Chromium without the browser's own
 * windows, extensions and profile services) when it is installed. It is what Playwright itself runs for
 * headless tests, and a page of the panel costs it half the CPU time: 2.6 against 5.5 CPU-seconds to open a
 * page, connect the demo robot and show the Servos view (measured one after the other on a 2-core machine).
 * Otherwise the full Chromium, in its headless mode. CHROMIUM_PATH chooses another.
 */
const HEADLESS_SHELL = "/usr/bin/chromium-headless-shell";
export const CHROMIUM_PATH =
  process.env.CHROMIUM_PATH ?? (existsSync(HEADLESS_SHELL) ? HEADLESS_SHELL : "/usr/bin/chromium");

export const CHROMIUM_ARGS = [
  "--no-sandbox",
  "--disable-gpu",
  "--disable-quic",
  "--no-first-run",
  "--disable-background-networking",
  "--disable-component-update",
  "--disable-sync",
];

export function launchChromium(): Promise<Browser> {
  return chromium.launch({ executablePath: CHROMIUM_PATH, args: CHROMIUM_ARGS, headless: true });
}
