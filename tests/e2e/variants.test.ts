import { describe, expect, it } from "vitest";
import { connectRobot, expectText, squash, useApp, watchPage } from "./harness.ts";
import "./rbc-test-globals.ts";

/**
 * The panel against firmware builds that differ from the standard one (docs/protocol.md §3.5): the fake port's
 * simulated robot with a `variant` (tests/e2e/fake-serial-entry.ts). Each connects, shows what the robot
 * said as it said it, and stays usable.
 */

/** An empty memory area, read from the robot (the bar shows what is used; it used to show what is free). */
const EMPTY_MOTION = /^0 of 24,576 bytes used|24,576 of 24,576 bytes free/;
const EMPTY_ACTION = /^0 of 8,192 bytes used|8,192 of 8,192 bytes free/;

const app = useApp();

describe("firmware variants", () => {
  it("a robot that answers neither 0x0C nor 0x1E connects; its serial number is 'not reported'", async () => {
    const { page, context } = await app.newPage({
      options: { variant: { answersSerialNumber: false, answersExecutionStatus: false } },
    });
    const seen = watchPage(page, app.origin);
    await connectRobot(page, app.url);

    await expectText(page.getByTestId("serial-number"), "not reported");
    await expectText(page.getByTestId("connection-status"), /Connected\s*·\s*HUNO\s*·\s*fw 2\.23/);
    const status = await page.getByTestId("connection-status").textContent().then(squash);
    expect(status).not.toContain("SN");
    // The panel is usable: the Robot view's reads after the identity went through.
    await expect
      .poll(() => page.getByTestId("memory-motion-text").textContent().then(squash))
      .toMatch(EMPTY_MOTION);
    await expectText(page.getByTestId("error-code"), /No error/);
    // The robot really was asked for its serial number and stayed silent.
    const drops = await page.evaluate(() => window.__rbcTest?.sim.stats.drops["unknown-type"]);
    expect(drops).toBeGreaterThanOrEqual(1);
    expect(seen.errors).toEqual([]);
    await context.close();
  });

  it("firmware 9.99 and platform 4 are shown as the robot reports them", async () => {
    const { page, context } = await app.newPage({
      options: { variant: { firmware: { major: 9, minor: 99 }, platform: 4 } },
    });
    await connectRobot(page, app.url);
    await expectText(page.getByTestId("firmware"), "9.99");
    await expectText(
      page.getByTestId("connection-status"),
      /Connected\s*·\s*PF2\s*·\s*fw 9\.99\s*·\s*SN 8958899989309/,
    );
    await expectText(page.getByTestId("device-card"), "Platform PF2 (user mode)", { contains: true });
    await expect
      .poll(() => page.getByTestId("memory-action-text").textContent().then(squash))
      .toMatch(EMPTY_ACTION);
    await context.close();
  });

  it("a platform outside 1-4 is shown as reported, with a warning on the device card", async () => {
    const { page, context } = await app.newPage({ options: { variant: { platform: 9 } } });
    await connectRobot(page, app.url);
    const warning = page.getByTestId("identity-warnings");
    await warning.waitFor();
    await expectText(
      warning.locator("p"),
      "The robot reports platform 9; known platforms are 1-4 (HUNO, DINO, DOGY, PF2).",
    );
    // The device's technical line, one click away.
    await expectText(warning.locator("pre"), "platform 9 is not one of 1-4");
    await context.close();
  });

  it("a robot that repeats a reply endlessly: the panel still connects and reads", async () => {
    // The homebrew port's bug with the reply the panel reads first (0x12, the version), about every 1 ms: every
    // later request meets a flood of unasked replies.
    const { page, context } = await app.newPage({
      options: { variant: { repeatReplies: { type: 0x12, intervalMs: 1 } } },
    });
    const seen = watchPage(page, app.origin);
    await connectRobot(page, app.url);
    await expectText(page.getByTestId("firmware"), "2.23");
    await expectText(page.getByTestId("serial-number"), "8958899989309");
    await expect
      .poll(() => page.getByTestId("memory-motion-text").textContent().then(squash))
      .toMatch(EMPTY_MOTION);
    await expectText(page.getByTestId("error-code"), /No error/);
    // The flood is real: the robot goes on sending the version reply, hundreds of times unasked.
    await expect
      .poll(() => page.evaluate(() => window.__rbcTest?.sim.stats.bytesSent ?? 0))
      .toBeGreaterThan(200 * 17);
    // Reading again (Refresh) in the middle of it still works: the requests go out and their replies count.
    const before = await page.evaluate(() => window.__rbcTest?.sim.stats.packetsReceived ?? 0);
    await page.getByRole("button", { name: "Refresh" }).click();
    // The error code and the two memory areas are asked for again, and the reading ends.
    await expect
      .poll(() => page.evaluate(() => window.__rbcTest?.sim.stats.packetsReceived ?? 0))
      .toBeGreaterThanOrEqual(before + 3);
    await expect.poll(() => page.getByRole("button", { name: "Refresh" }).isEnabled()).toBe(true);
    await expectText(page.getByTestId("memory-motion-text"), EMPTY_MOTION);
    await expectText(page.getByTestId("error-code"), /No error/);
    await expectText(page.getByTestId("connection-status"), /Connected/);
    expect(seen.errors).toEqual([]);
    await context.close();
  });
});
