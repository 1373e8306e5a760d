/**
 * The robot over Bluetooth in the panel (issue #14, item 2): the demo robot behind a simulated Bluetooth link
 * (replies 300 ± 150 ms late, seeded, in 20 ms bursts) through the whole flow — zeros read, wave.rbm uploaded,
 * run, the Sensors view reading — with no timeout anywhere; "Connect robot" offering a paired module beside the
 * USB adapters (and an older browser still getting the USB chooser); the help for pairing.
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { FACTORY_ZEROS } from "../../src/protocol/zeros.ts";
import { cspViolations, expectText, FAST, squash, useApp, watchPage } from "./harness.ts";
import { exampleText, imageHex, rbmFile, showTab } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

const SPP = "00001101-0000-1000-8000-00805f9b34fb";
/** What a timeout says anywhere in the panel (RbcTimeoutError and the motion/upload sentences built on it). */
const TIMEOUT_WORDS = /did not answer|did not report|stopped acknowledging|did not acknowledge|timed? ?out/i;

const app = useApp();

/** The demo robot's stored motions, as hex. */
const demoMotionsHex = (page: Page) =>
  page.evaluate(() =>
    (window.__rbcDemoSim?.motions ?? []).map((m) =>
      Array.from(m.bytes, (b) => b.toString(16).padStart(2, "0")).join(""),
    ),
  );

describe("the robot over Bluetooth", () => {
  it("runs the demo robot over a simulated Bluetooth link: zeros, upload, run, sensors, and never a timeout", async () => {
    const { page, context } = await app.newPage({ options: FAST });
    const seen = watchPage(page, app.origin);
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByTestId("demo-bluetooth").click();
    await page.getByTestId("device-card").waitFor({ timeout: 15_000 });
    await expectText(
      page.getByTestId("connection-status"),
      /^Demo robot \(Bluetooth\)\s*·\s*Connected\s*·\s*HUNO\s*·\s*fw 2\.23\s*·\s*SN 8958899989309/,
    );

    // Zeros: read from the robot over the slow link.
    await page.getByRole("link", { name: "Zeros" }).click();
    await page.getByTestId("zeros-card").waitFor();
    await page.locator("#zero-0").waitFor({ timeout: 15_000 });
    const shown = () =>
      page
        .locator("[id^=zero-]")
        .evaluateAll((els) =>
          els.filter((e) => /^zero-\d+$/.test(e.id)).map((e) => Number((e as HTMLInputElement).value)),
        );
    await expect.poll(shown).toEqual([...FACTORY_ZEROS]);
    expect(await page.evaluate(() => window.__rbcDemoSim?.zeros)).toEqual([...FACTORY_ZEROS]);

    // Upload wave.rbm (the demo robot uploads at once) and check the robot holds its exact image.
    await page.getByRole("link", { name: "Motions" }).click();
    const wave = exampleText("wave.rbm");
    await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", wave));
    const card = page.getByTestId("motion-file");
    await card.waitFor();
    await page.getByTestId("upload-motion").click();
    const uploaded = card.getByText(/^Uploaded wave\.rbm/);
    await uploaded.waitFor({ timeout: 30_000 });
    await expectText(uploaded, /624 bytes in 10 chunks/);
    expect(await demoMotionsHex(page)).toEqual([imageHex(wave)]);

    // Run basic posture, then the uploaded wave (motion 12), each confirmed by the robot.
    await showTab(page, "Run");
    // The first movement asks once ("The robot will move"); the next one does not.
    await page.locator('[data-motion="7"]').click();
    await page.locator("#confirm-move").click();
    await page.getByText(/Motion 7 \(Basic posture\) finished/).waitFor({ timeout: 20_000 });
    await page.locator('[data-testid="downloaded-motions"] [data-motion="12"]').click();
    await page.getByText(/Motion 12 .*finished/).waitFor({ timeout: 20_000 });

    // The Sensors view reads the distance and the accelerometer over the link.
    await page.getByRole("link", { name: "Sensors" }).click();
    await page.getByTestId("poll-card").waitFor();
    await page.evaluate(() => window.__rbcDemoSim?.setDistance(30));
    await page.getByTestId("distance-value").filter({ hasText: "30 cm" }).waitFor({ timeout: 20_000 });
    await page
      .getByTestId("accel-value")
      .filter({ hasText: /X -?\d+ · Y -?\d+ · Z \d+/ })
      .waitFor();
    const chart = page.getByTestId("distance-chart");
    await expect.poll(async () => Number(await chart.getAttribute("data-samples"))).toBeGreaterThan(2);

    // Not one timeout notice anywhere, and the top bar still names the link.
    expect(await page.locator("body").textContent().then(squash)).not.toMatch(TIMEOUT_WORDS);
    await page.getByRole("link", { name: "Robot" }).click();
    await page.getByTestId("device-card").waitFor();
    expect(await page.locator("body").textContent().then(squash)).not.toMatch(TIMEOUT_WORDS);
    await expectText(page.getByTestId("connection-status"), /^Demo robot \(Bluetooth\)/);
    expect(seen.errors).toEqual([]);
    expect(seen.foreignRequests).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("lists a paired Bluetooth module in the chooser beside USB adapters, and says the link is Bluetooth", async () => {
    const { page, context } = await app.newPage({ options: { ...FAST, bluetooth: true } });
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByRole("button", { name: "Connect robot" }).click();
    await page.getByTestId("device-card").waitFor({ timeout: 15_000 });
    await expectText(
      page.getByTestId("connection-status"),
      /^Connected\s*·\s*Bluetooth\s*·\s*HUNO\s*·\s*fw 2\.23/,
    );
    const request = await page.evaluate(() => window.__rbcTest?.serial.requests[0]);
    expect(request?.filters?.at(-1)).toEqual({ bluetoothServiceClassId: SPP });
    expect(request?.filters?.slice(0, -1).map((f) => f.usbVendorId)).toEqual([
      0x0403, 0x067b, 0x10c4, 0x1a86,
    ]);
    expect(request?.allowedBluetoothServiceClassIds).toEqual([SPP]);

    // Known afterwards as a Bluetooth serial port, for one-click reconnect.
    await page.getByRole("button", { name: "Disconnect" }).click();
    await page.getByRole("button", { name: "Connect to Bluetooth serial port" }).click();
    await page.getByTestId("device-card").waitFor({ timeout: 15_000 });
    await expectText(page.getByTestId("connection-status"), /^Connected\s*·\s*Bluetooth/);
    await context.close();
  });

  it("still offers the USB chooser on a browser that does not know the Bluetooth filter", async () => {
    const { page, context } = await app.newPage({ options: { noBluetoothChooser: true } });
    const seen = watchPage(page, app.origin);
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByRole("button", { name: "Connect robot" }).click();
    await page.getByTestId("device-card").waitFor();
    const requests = await page.evaluate(() => window.__rbcTest?.serial.requests);
    expect(requests).toHaveLength(2);
    expect(requests?.[1]?.filters).toEqual([
      { usbVendorId: 0x0403 },
      { usbVendorId: 0x067b },
      { usbVendorId: 0x10c4 },
      { usbVendorId: 0x1a86 },
    ]);
    await expectText(page.getByTestId("connection-status"), /^Connected/);
    expect(seen.errors).toEqual([]);
    await context.close();
  });

  it("says how to pair the module first, that the robot must be on, and that replies are slower", async () => {
    const { page, context } = await app.newPage();
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByText("Can't find your robot?").click();
    const help = page.getByTestId("bluetooth-help");
    for (const words of [
      "switch the robot on",
      "pair the module in the computer's Bluetooth settings first",
      "it is often 1234 or 0000",
      "Bluetooth serial port",
      "Replies are slower over Bluetooth",
    ]) {
      await expectText(help, words, { contains: true });
    }
    await context.close();
  });
});
