import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { CABLE, DEMO, loadConnected } from "./connected-page.ts";
import { cspViolations, expectText, FAST, robotTime, useApp, watchPage } from "./harness.ts";
import "./rbc-test-globals.ts";

const app = useApp();

/** Opens the Sensors view with the robot on the cable connected (a page opened with the start option `CABLE`). */
async function openSensors(page: Page): Promise<void> {
  await loadConnected(page, app.url, "sensors");
  await page.getByTestId("poll-card").waitFor();
}

const simSubscription = (page: Page) => page.evaluate(() => window.__rbcTest?.sim.state.sensors.subscription);

/** Presses IR key `code` if the simulated RBC is listening to the remote at this moment. */
const pressWhileListening = (page: Page, code: number) =>
  page.evaluate((c) => {
    const sim = window.__rbcTest?.sim;
    if (sim?.state.sensors.subscription !== 0x19) return false;
    sim.pressRemoteKey(c);
    return true;
  }, code);

const bytesFromPc = (page: Page) => page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? -1);

/** Nothing goes out any more (polling and listening have stopped). Waits are in the robot's time. */
async function expectQuiet(page: Page): Promise<void> {
  // A request in flight when polling stopped may still finish: first a poll period without a byte…
  await expect
    .poll(async () => {
      const before = await bytesFromPc(page);
      await robotTime(page, 300);
      return (await bytesFromPc(page)) === before;
    })
    .toBe(true);
  // …then nothing for a whole second (five poll periods).
  const before = await bytesFromPc(page);
  await robotTime(page, 1000);
  expect(await bytesFromPc(page)).toBe(before);
}

describe("sensors view", () => {
  it("polls distance and accelerometer into live charts, lists button and remote events, and stops when left", async () => {
    const { page, context } = await app.newPage({ options: FAST, start: CABLE });
    const seen = watchPage(page, app.origin);
    await openSensors(page);
    const distance = page.getByTestId("distance-value");
    await distance.filter({ hasText: "10 cm" }).waitFor();
    const chart = page.getByTestId("distance-chart");
    await page.locator('[data-testid="distance-chart"][data-chart="drawn"]').waitFor();

    await page.evaluate(() => window.__rbcTest?.sim.setDistance(30));
    await distance.filter({ hasText: "30 cm" }).waitFor();
    await expect.poll(() => chart.getAttribute("data-last")).toBe("30");
    const samples = Number(await chart.getAttribute("data-samples"));
    await expect.poll(async () => Number(await chart.getAttribute("data-samples"))).toBeGreaterThan(samples);

    await page.evaluate(() => window.__rbcTest?.sim.setAccelerometer(4, 3, -6));
    await page.getByTestId("accel-value").filter({ hasText: "X 4 · Y 3 · Z -6" }).waitFor();
    await expect.poll(() => page.getByTestId("accel-chart").getAttribute("data-last")).toBe("4,3,-6");

    // The rate select changes how often it reads.
    await page.getByTestId("poll-rate").selectOption("10");
    await page.getByTestId("poll-status").filter({ hasText: "Reading 10 times a second" }).waitFor();

    // PF buttons: one subscription at a time.
    await expect.poll(() => page.getByText("The robot reports only one of these at a time").count()).toBe(1);
    await page.getByRole("radio", { name: "PF buttons" }).check();
    await page.getByTestId("listen-status").filter({ hasText: "Listening to PF buttons" }).waitFor();
    await expect.poll(() => simSubscription(page)).toBe(0x18);
    await page.evaluate(() => window.__rbcTest?.sim.pressButton(2, 300));
    await page.getByTestId("event-list").filter({ hasText: "PF2 pressed" }).waitFor();

    await page.getByRole("radio", { name: "IR remote" }).check();
    await page.getByTestId("listen-status").filter({ hasText: "Listening to IR remote" }).waitFor();
    // Each reading ends the RBC's subscription for a moment (the client re-arms it): press while it listens.
    await expect.poll(() => pressWhileListening(page, 7), { timeout: 5000 }).toBe(true);
    await page.getByTestId("event-list").filter({ hasText: "IR key 7 (Basic posture)" }).waitFor();

    await page.getByRole("radio", { name: "Sound level" }).check();
    await page.locator("#sound-threshold").fill("40");
    await page.locator("#sound-threshold").press("Tab");
    await expect.poll(() => page.evaluate(() => window.__rbcTest?.sim.state.sensors.soundThreshold)).toBe(40);
    await page.evaluate(() => window.__rbcTest?.sim.setSoundLevel(55));
    await page
      .getByTestId("sound-level")
      .filter({ hasText: /^55 at/ })
      .waitFor();

    // Leaving the view stops polling and the subscription.
    await page.getByRole("link", { name: "Robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await expectQuiet(page);
    expect(await page.evaluate(() => window.__rbcTest?.sim.state.sensors.subscription)).toBeUndefined();

    expect(seen.errors).toEqual([]);
    expect(seen.foreignRequests).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("draws the distance axis from 0 to 60 cm, lines with 3:1 contrast in dark and light mode, times to the second", async () => {
    const { page, context } = await app.newPage({ options: FAST, start: CABLE });
    await page.emulateMedia({ colorScheme: "dark" });
    await openSensors(page);
    await page.getByTestId("distance-value").filter({ hasText: "10 cm" }).waitFor();
    const distance = page.getByTestId("distance-chart");
    const accel = page.getByTestId("accel-chart");
    // The reading of 10 cm lies inside the axis (it began at 20 before), with room above the sensor's 50 cm.
    await expect.poll(() => distance.getAttribute("data-y-axis")).toBe("0 to 60");

    /** The contrast of each line of a chart against the background of the card it is drawn on. */
    const contrasts = (testId: string) =>
      page.evaluate((id) => {
        const host = document.querySelector<HTMLElement>(`[data-testid="${id}"]`);
        const card = host?.closest(".card");
        if (!host || !card) return [];
        const ctx = document.createElement("canvas").getContext("2d");
        const rgb = (css: string) => {
          if (!ctx) return [0, 0, 0];
          ctx.fillStyle = "#000";
          ctx.fillStyle = css;
          ctx.fillRect(0, 0, 1, 1);
          return [...ctx.getImageData(0, 0, 1, 1).data.slice(0, 3)];
        };
        const lum = (c: number[]) => {
          const [r, g, b] = c.map((v) => {
            const s = v / 255;
            return s <= 0.03928 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
          });
          return 0.2126 * (r ?? 0) + 0.7152 * (g ?? 0) + 0.0722 * (b ?? 0);
        };
        const bg = lum(rgb(getComputedStyle(card).backgroundColor));
        return (host.dataset.lineColours ?? "").split(" ").map((c) => {
          const l = lum(rgb(c));
          return Math.round(((Math.max(l, bg) + 0.05) / (Math.min(l, bg) + 0.05)) * 100) / 100;
        });
      }, testId);
    await accel.locator("canvas").first().waitFor();
    // The three lines' colours are set when the chart draws: polled until they are.
    await expect.poll(() => contrasts("accel-chart")).toHaveLength(3);
    for (const c of await contrasts("accel-chart")) expect(c).toBeGreaterThanOrEqual(3);
    await expect.poll(async () => Math.min(...(await contrasts("distance-chart")))).toBeGreaterThanOrEqual(3);
    // The colours follow a change of scheme without leaving the view.
    const darkColours = await accel.getAttribute("data-line-colours");
    await page.emulateMedia({ colorScheme: "light" });
    await expect.poll(() => accel.getAttribute("data-line-colours")).not.toBe(darkColours);
    // The new colours and the card's background settle on the chart's next draw: read them once both have.
    await expect.poll(async () => Math.min(...(await contrasts("accel-chart")))).toBeGreaterThanOrEqual(3);

    // "last reading at 14:02:11", not "14:02:11.045".
    const status = page.getByTestId("poll-status");
    await expectText(status, /last reading at \d{1,2}:\d{2}:\d{2}( [AP]M)?\./);
    expect(await status.textContent()).not.toMatch(/\d{2}:\d{2}:\d{2}\.\d/);
    await context.close();
  });

  it("stops polling while the tab is hidden and after Limp (not after Stop), and resumes", async () => {
    const { page, context } = await app.newPage({ options: FAST, start: CABLE });
    await openSensors(page);
    await page.getByTestId("distance-value").filter({ hasText: "10 cm" }).waitFor();
    await page.evaluate(() => {
      Object.defineProperty(document, "hidden", { configurable: true, get: () => true });
      document.dispatchEvent(new Event("visibilitychange"));
    });
    await page.getByText("Paused while this tab is hidden.").waitFor();
    await expectQuiet(page);
    await page.evaluate(() => {
      Object.defineProperty(document, "hidden", { configurable: true, get: () => false });
      document.dispatchEvent(new Event("visibilitychange"));
    });
    const before = await bytesFromPc(page);
    await expect.poll(() => bytesFromPc(page)).toBeGreaterThan(before);

    // Stop (Escape) keeps the robot as it is: nothing was running, and polling goes on in normal mode.
    await page.keyboard.press("Escape");
    await page
      .getByText("The robot answered at once: it is idle, nothing to stop. Nothing was sent.")
      .waitFor();
    const afterStop = await bytesFromPc(page);
    await expect.poll(() => bytesFromPc(page)).toBeGreaterThan(afterStop);
    expect(await page.evaluate(() => window.__rbcTest?.sim.directMode)).toBe(false);
    // Limp: the robot goes to servo control, polling pauses and says why; Resume returns to normal.
    await page.getByRole("button", { name: "Limp…" }).click();
    await page.getByRole("alertdialog").getByRole("button", { name: "Limp", exact: true }).click();
    await page.getByText(/Limp: all 16 servos confirmed passive/).waitFor();
    await page.getByText(/Paused: the robot is in servo control/).waitFor();
    await page.getByRole("button", { name: "Resume reading" }).click();
    await page.getByTestId("poll-status").filter({ hasText: "Reading 5 times a second" }).waitFor();
    await expect.poll(() => page.evaluate(() => window.__rbcTest?.sim.directMode)).toBe(false);
    await context.close();
  });

  it("on the demo robot, its buttons and remote can be pressed from the panel", async () => {
    const { page, context } = await app.newPage({ start: DEMO });
    await loadConnected(page, app.url, "sensors");
    await page.getByTestId("demo-world").waitFor();
    // The demo accelerometer is alive (noise around an upright robot).
    await page
      .getByTestId("accel-value")
      .filter({ hasText: /X -?\d+ · Y -?\d+ · Z \d+/ })
      .waitFor();
    await page.getByRole("radio", { name: "PF buttons" }).check();
    await page.getByTestId("listen-status").filter({ hasText: "Listening to PF buttons" }).waitFor();
    await page.getByRole("button", { name: "Press PF2" }).click();
    await page.getByTestId("event-list").filter({ hasText: "PF2 pressed" }).waitFor();
    await page.locator("#demo-distance").fill("42");
    await page.getByTestId("distance-value").filter({ hasText: "42 cm" }).waitFor();
    await context.close();
  });
});
