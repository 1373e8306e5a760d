import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { type AppHarness, connectRobot, cspViolations, squash, startHarness, watchPage } from "./harness.ts";
import "./rbc-test-globals.ts";

let app: AppHarness;

beforeAll(async () => {
  app = await startHarness();
});

afterAll(async () => {
  await app?.close();
});

describe("connecting a robot", () => {
  it("connects through the chooser and shows the simulator's identity and memory", async () => {
    const { page, context } = await app.newPage();
    const seen = watchPage(page, app.origin);
    await connectRobot(page, app.url);

    const status = page.getByTestId("connection-status");
    await expect
      .poll(() => status.textContent().then(squash))
      .toMatch(/Connected\s*·\s*HUNO\s*·\s*fw 2\.23\s*·\s*SN 8958899989309/);
    await expect.poll(() => page.getByTestId("firmware").textContent().then(squash)).toBe("2.23");
    expect(await page.getByTestId("serial-number").textContent().then(squash)).toBe("8958899989309");
    await expect
      .poll(() => page.getByTestId("memory-motion-text").textContent().then(squash))
      .toMatch(/0 of 24,576 bytes used/);
    expect(await page.getByTestId("memory-action-text").textContent().then(squash)).toMatch(
      /0 of 8,192 bytes used/,
    );
    expect(await page.locator("#memory-motion").getAttribute("max")).toBe("24576");
    expect(await page.getByTestId("error-code").textContent().then(squash)).toMatch(/No error/);
    await expect.poll(() => page.getByRole("button", { name: "Stop", exact: true }).isVisible()).toBe(true);
    expect(await page.getByRole("button", { name: "Limp…" }).isVisible()).toBe(true);

    // The chooser was asked for the four USB serial vendors and paired Bluetooth modules (SPP).
    const filters = await page.evaluate(() => window.__rbcTest?.serial.requests[0]?.filters);
    expect(filters).toEqual([
      { usbVendorId: 0x0403 },
      { usbVendorId: 0x067b },
      { usbVendorId: 0x10c4 },
      { usbVendorId: 0x1a86 },
      { bluetoothServiceClassId: "00001101-0000-1000-8000-00805f9b34fb" },
    ]);
    // The port was opened with the RBC's settings.
    const opened = await page.evaluate(() => window.__rbcTest?.port.openOptions);
    expect(opened).toMatchObject({ baudRate: 115200, dataBits: 8, stopBits: 1, parity: "none" });

    expect(seen.foreignRequests).toEqual([]);
    expect(seen.errors).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("shows help when the chooser is cancelled", async () => {
    const { page, context } = await app.newPage({ options: { userCancels: true } });
    await page.goto(app.url);
    await page.getByRole("button", { name: "Connect robot" }).click();
    await page.getByText("No port was chosen").waitFor();
    const help = page.getByTestId("connect-help");
    expect(await help.getAttribute("open")).not.toBeNull();
    const text = await help.textContent().then(squash);
    for (const hint of [
      "dialout",
      "brltty",
      "snap connect chromium:raw-usb",
      "Motionbuilder",
      "CH340",
      "FTDI",
    ]) {
      expect(text).toContain(hint);
    }
    // "Show all ports" drops the filters.
    await page.getByLabel("Show all serial ports").check();
    await page.getByRole("button", { name: "Connect robot" }).click();
    await page.getByText("No port was chosen").waitFor();
    const last = await page.evaluate(() => window.__rbcTest?.serial.requests.at(-1));
    expect(last?.filters).toBeUndefined();
    await context.close();
  });

  it("offers a port granted earlier for one-click reconnect, and forgets it", async () => {
    const { page, context } = await app.newPage({ options: { granted: true } });
    await page.goto(app.url);
    const connect = page.getByRole("button", { name: "Connect to FTDI USB serial adapter (0403:6001)" });
    await connect.click();
    await page.getByTestId("device-card").waitFor();
    expect(await page.evaluate(() => window.__rbcTest?.serial.requests.length)).toBe(0);

    await page.getByRole("button", { name: "Disconnect" }).click();
    await page.getByRole("button", { name: "Forget FTDI USB serial adapter (0403:6001)" }).click();
    await expect.poll(() => connect.count()).toBe(0);
    expect(await page.evaluate(() => window.__rbcTest?.port.forgotten)).toBe(true);
    await context.close();
  });

  it("returns to a clear disconnected state when the cable is pulled mid-operation", async () => {
    const { page, context } = await app.newPage();
    await connectRobot(page, app.url);
    await page.getByTestId("firmware").filter({ hasText: "2.23" }).waitFor();
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();

    // The robot stops answering, so the refresh stays pending; then the cable is pulled.
    await page.evaluate(() => window.__rbcTest?.port.faults.swallowReplies(20));
    await page.getByRole("button", { name: "Refresh" }).click();
    await page.getByRole("button", { name: "Reading…" }).waitFor();
    await page.evaluate(() => window.__rbcTest?.port.unplug());

    const lost = page.getByTestId("lost-notice");
    await lost.waitFor();
    const text = await lost.textContent().then(squash);
    expect(text).toContain("unplugged");
    expect(text).toContain("Did not finish: Reading device info");
    expect(await page.getByTestId("connection-status").textContent().then(squash)).toMatch(/Disconnected/);
    // No spinner or progress left, no Stop button, and the connect buttons work again.
    expect(await page.locator("progress").count()).toBe(0);
    expect(await page.getByRole("button", { name: "Stop", exact: true }).count()).toBe(0);
    expect(await page.getByRole("button", { name: "Limp…" }).count()).toBe(0);
    expect(await page.getByRole("button", { name: "Connect robot" }).isEnabled()).toBe(true);

    // Plugged back in, it connects again.
    await page.evaluate(() => window.__rbcTest?.port.faults.clear());
    await page.evaluate(() => window.__rbcTest?.port.replug());
    await page.getByRole("button", { name: "Connect robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await context.close();
  });

  it("Escape while connected is Stop, never Limp: with nothing running no servo goes passive", async () => {
    const { page, context } = await app.newPage();
    await connectRobot(page, app.url);
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    await page.keyboard.press("Escape");
    await page.getByText("Nothing was running; the robot keeps its pose.").waitFor();
    const servos = await page.evaluate(() => window.__rbcTest?.sim.servos.slice(0, 16).map((s) => s.passive));
    expect(servos).toEqual(Array(16).fill(false));
    expect(await page.evaluate(() => window.__rbcTest?.sim.directMode)).toBe(false);
    expect(await page.getByTestId("connection-status").textContent().then(squash)).not.toMatch(
      /servo control|limp/,
    );
    await context.close();
  });

  it("offers Cancel while the port chooser is open; a port the chooser gives later is not opened", async () => {
    const { page, context } = await app.newPage();
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    // A chooser that never answers by itself (requestPort can hang).
    await page.evaluate(() => {
      const serial = window.__rbcTest?.serial;
      if (serial) serial.chooserHangs = true;
    });
    const connect = page.getByRole("button", { name: "Connect robot" });
    const demo = page.getByRole("button", { name: "Try the demo robot" });
    await connect.click();
    await page.getByText("Waiting for you to choose a port in the browser's list…").waitFor();
    expect(await connect.isDisabled()).toBe(true);
    expect(await demo.isDisabled()).toBe(true);

    await page.getByTestId("cancel-choosing").click();
    await expect.poll(() => connect.isEnabled()).toBe(true);
    expect(await demo.isEnabled()).toBe(true);
    expect(await page.getByTestId("connect-progress").count()).toBe(0);
    await page.getByText(/Stopped waiting for the port chooser/).waitFor();

    // The chooser answers late: the page no longer waits for it, and does not open the port.
    expect(await page.evaluate(() => window.__rbcTest?.serial.answerHeldRequests())).toBe(1);
    await page.getByRole("heading", { name: "Ports used before" }).waitFor();
    expect(await page.evaluate(() => window.__rbcTest?.port.openOptions)).toBeUndefined();
    expect(await page.getByTestId("connection-status").textContent().then(squash)).toBe("Not connected");

    // Connect works again with a chooser that answers.
    await page.evaluate(() => {
      const serial = window.__rbcTest?.serial;
      if (serial) serial.chooserHangs = false;
    });
    await connect.click();
    await page.getByTestId("device-card").waitFor();
    await context.close();
  });

  it("names the view and the robot in the page title, and says which version the panel is", async () => {
    const { page, context } = await app.newPage();
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await expect.poll(() => page.title()).toBe("Robot · Demo robot · RBC Panel");
    await page.getByRole("link", { name: "Zeros" }).click();
    await expect.poll(() => page.title()).toBe("Zeros · Demo robot · RBC Panel");
    // The build stamps its version and commit (vite.config.ts), shown at the foot of every view.
    expect(await page.getByTestId("panel-version").textContent().then(squash)).toMatch(
      /^RBC Panel · Version \d+\.\d+\.\d+ \([0-9a-f]{7,}\)/,
    );
    await context.close();
  });
});
