import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { launchChromium } from "../support/chromium.ts";
import { buildOnce, expectText } from "./harness.ts";
import {
  cspViolations,
  injectedPage,
  type SubpathServer,
  serveUnder,
  walkPanel,
  watchRequests,
} from "./single-harness.ts";
import "./rbc-test-globals.ts";

/** As GitHub Pages serves a project site: https://<owner>.github.io/<repository>/. */
const MOUNT = "/rbc-panel/";

let browser: Browser;
let server: SubpathServer;
let fakeSerial: string;

beforeAll(async () => {
  const built = await buildOnce();
  fakeSerial = built.fakeSerial;
  server = await serveUnder(built.outDir, MOUNT);
  browser = await launchChromium();
});

afterAll(async () => {
  await browser?.close();
  await server?.close();
});

/** Waits until the service worker controls the page, and returns its script and scope. */
async function controlled(page: Page): Promise<{ script: string; scope: string }> {
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null, undefined, {
    timeout: 30_000,
  });
  return page.evaluate(async () => {
    const registration = await navigator.serviceWorker.ready;
    return { script: registration.active?.scriptURL ?? "", scope: registration.scope };
  });
}

describe("the hosted panel under a sub-path", () => {
  it("passes the walk at /rbc-panel/, asks for nothing outside it, then loads offline", async () => {
    const { page, context } = await injectedPage(browser, fakeSerial, { serviceWorkers: "allow" });
    const inside = (url: string) => url.startsWith(server.url);
    const seen = watchRequests(page, inside);
    await page.goto(server.url);
    // The service worker and its scope live under the sub-path, and the manifest is found there.
    expect(await controlled(page)).toEqual({ script: `${server.url}sw.js`, scope: server.url });
    const manifest = await page.evaluate(async () => {
      const link = document.querySelector<HTMLLinkElement>('link[rel="manifest"]');
      const response = await fetch(link?.href ?? "");
      return { url: response.url, ok: response.ok, body: (await response.json()) as { start_url: string } };
    });
    expect(manifest.url).toBe(`${server.url}manifest.webmanifest`);
    expect(manifest.ok).toBe(true);
    expect(new URL(manifest.body.start_url, manifest.url).href).toBe(server.url);

    await walkPanel(page);
    expect(seen.unexpected).toEqual([]);
    expect(seen.errors).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);

    // Offline: the page, the lazily loaded views, the demo robot and the examples come from the cache.
    await page.getByRole("link", { name: "Robot", exact: true }).click();
    await context.setOffline(true);
    await page.reload();
    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await expectText(page.getByTestId("firmware"), "2.23");
    await page.getByRole("link", { name: "Sensors", exact: true }).click();
    await page.getByRole("heading", { level: 1, name: "Sensors" }).waitFor();
    await page.getByRole("link", { name: "Motions", exact: true }).click();
    await page.getByText("Open an example motion").click();
    await page.getByRole("button", { name: "Open bow.rbm" }).click();
    await page.getByText("Opened the example bow.rbm.").waitFor();
    // The version's link to what changed opens offline too: the changelog page is precached with the panel.
    const [changelog] = await Promise.all([
      page.waitForEvent("popup"),
      page.getByTestId("panel-version").getByRole("link", { name: "What changed" }).click(),
    ]);
    await changelog.getByRole("heading", { level: 1, name: "Changelog", exact: true }).waitFor();
    expect(changelog.url()).toBe(`${server.url}changelog.html`);
    await changelog.close();
    expect(seen.unexpected).toEqual([]);
    expect(seen.errors).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    // The server itself (the service worker's precache included) was never asked for anything else.
    expect(server.paths.filter((p) => !p.startsWith(MOUNT))).toEqual([]);
    await context.setOffline(false);
    await context.close();
  });

  it("offers a new version with a notice and reloads only when the owner presses Reload", async () => {
    const { page, context } = await injectedPage(browser, fakeSerial, { serviceWorkers: "allow" });
    const seen = watchRequests(page, (url) => url.startsWith(server.url));
    try {
      await page.goto(server.url);
      await controlled(page);
      // A second visit, controlled by the installed worker from the start (as an owner's usual visit).
      await page.reload();
      await controlled(page);
      await page.getByRole("button", { name: "Try the demo robot" }).click();
      await page.getByTestId("device-card").waitFor();
      await page.evaluate(() => {
        (window as unknown as { __sameDocument: boolean }).__sameDocument = true;
      });

      // A new release: the service worker's script changed on the server.
      server.swSuffix = "\n// a new release\n";
      await page.evaluate(async () => {
        const registration = await navigator.serviceWorker.ready;
        await registration.update();
      });
      const notice = page.getByTestId("update-prompt");
      await notice.waitFor({ timeout: 30_000 });
      await expectText(notice, /^A new version of the panel is ready\. Reload Later$/);
      await expect.poll(() => page.getByRole("status").filter({ has: notice }).count()).toBe(1);
      // Nothing reloaded by itself: the same document, the demo robot still connected, the new worker waiting.
      expect(
        await page.evaluate(() => (window as unknown as { __sameDocument?: boolean }).__sameDocument),
      ).toBe(true);
      await expectText(page.getByTestId("connection-status"), /Demo robot\s*·\s*Connected/);
      expect(await page.evaluate(async () => (await navigator.serviceWorker.ready).waiting !== null)).toBe(
        true,
      );

      // While something runs on the robot, Reload says what and leaves the page as it is: sound 7 plays 5.7 s.
      await page.getByRole("link", { name: "Motions", exact: true }).click();
      await page.getByRole("tab", { name: "Sounds" }).click();
      await page.locator('[data-sound="7"]').click();
      await page.getByTestId("sound-playing").waitFor();
      await notice.getByRole("button", { name: "Reload" }).click();
      await notice.getByText("Still running: Playing sound 7. Reload when it has finished.").waitFor();
      expect(
        await page.evaluate(() => (window as unknown as { __sameDocument?: boolean }).__sameDocument),
      ).toBe(true);
      // The browser's own reload or close asks first ("Leave site?") while it runs, and not after.
      const leaveAsks = () =>
        page.evaluate(() => {
          const e = new Event("beforeunload", { cancelable: true });
          window.dispatchEvent(e);
          return e.defaultPrevented;
        });
      expect(await leaveAsks()).toBe(true);
      await page.getByText("Sound 7 played (5.7 s).").waitFor({ timeout: 15_000 });
      await expect.poll(leaveAsks).toBe(false);
      await page.getByRole("link", { name: "Robot", exact: true }).click();

      // The owner chooses to reload: the new worker takes over and the page reloads once.
      await Promise.all([page.waitForEvent("load"), notice.getByRole("button", { name: "Reload" }).click()]);
      await page.getByRole("button", { name: "Try the demo robot" }).waitFor();
      expect(
        await page.evaluate(() => (window as unknown as { __sameDocument?: boolean }).__sameDocument),
      ).toBe(undefined);
      await controlled(page);
      expect(await page.evaluate(async () => (await navigator.serviceWorker.ready).waiting === null)).toBe(
        true,
      );
      expect(await page.getByTestId("update-prompt").count()).toBe(0);
      expect(seen.unexpected).toEqual([]);
      expect(seen.errors).toEqual([]);
      expect(await cspViolations(page)).toEqual([]);
    } finally {
      server.swSuffix = "";
      await context.close();
    }
  });
});
