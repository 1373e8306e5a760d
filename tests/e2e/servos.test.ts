import type { Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { HUNO_BASIC_POSTURE } from "../../src/protocol/index.ts";
import { type AppHarness, connectRobot, cspViolations, squash, startHarness } from "./harness.ts";
import "./rbc-test-globals.ts";

let app: AppHarness;

beforeAll(async () => {
  app = await startHarness();
});

afterAll(async () => {
  await app?.close();
});

const simServos = (page: Page) => page.evaluate(() => window.__rbcTest?.sim.servos ?? []);
const simDirect = (page: Page) => page.evaluate(() => window.__rbcTest?.sim.directMode);

async function openServos(page: Page): Promise<void> {
  await connectRobot(page, app.url);
  await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
  await page.getByRole("link", { name: "Servos" }).click();
  await page.getByTestId("servo-card").waitFor();
}

async function startControl(page: Page): Promise<void> {
  await page.getByRole("button", { name: "I understand: the robot is supported" }).click();
  await page.getByTestId("enter-direct").click();
  await page.getByText("Read all 16 servos.").waitFor();
}

describe("servos view", () => {
  it("asks for the safety notice first, moves one servo in direct mode, Stop keeps the servos holding, Limp makes all limp", async () => {
    const { page, context } = await app.newPage();
    await openServos(page);
    const notice = page.getByTestId("servo-safety");
    expect(await notice.textContent().then(squash)).toContain("Support the robot");
    expect(await page.getByTestId("enter-direct").isDisabled()).toBe(true);
    expect(await page.locator("#servo-3").isDisabled()).toBe(true);

    await startControl(page);
    expect(await notice.count()).toBe(0);
    expect(await simDirect(page)).toBe(true);
    expect(await page.getByTestId("servo-pos-3").textContent().then(squash)).toBe(
      String(HUNO_BASIC_POSTURE[3]),
    );
    expect(await page.getByTestId("connection-status").textContent().then(squash)).toContain("servo control");

    // The number input is limited to the safe range (servo 3: 40-130) and moves the servo on change.
    expect(await page.locator("#servo-3").getAttribute("min")).toBe("40");
    expect(await page.locator("#servo-3").getAttribute("max")).toBe("130");
    await page.locator("#servo-3").fill("100");
    await page.locator("#servo-3").press("Enter");
    await expect.poll(async () => (await simServos(page))[3]?.position).toBe(100);
    await page.getByTestId("servo-pos-3").filter({ hasText: "100" }).waitFor();
    // Out of range is refused with a sentence (as in the zeros editor), never clamped and never sent.
    const sentBeforeRefusal = await page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? 0);
    await page.locator("#servo-12").fill("300");
    await page.locator("#servo-12").press("Enter");
    const refusal = page.getByTestId("servo-refused-12");
    await refusal.waitFor();
    expect(await refusal.textContent().then(squash)).toBe(
      "Servo 12: 300 is outside its safe range 1–198. Nothing was sent; the servo stays where it is.",
    );
    expect(await page.locator("#servo-12").getAttribute("aria-invalid")).toBe("true");
    await page.locator("#servo-3").fill("250");
    await page.locator("#servo-3").press("Enter");
    await page
      .getByTestId("servo-refused-3")
      .filter({ hasText: "250 is outside its safe range 40–130" })
      .waitFor();
    expect(await page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? 0)).toBe(sentBeforeRefusal);
    expect((await simServos(page))[12]?.position).toBe(HUNO_BASIC_POSTURE[12]);
    expect((await simServos(page))[3]?.position).toBe(100);
    // A value within the range is taken again and clears the refusal.
    await page.locator("#servo-3").fill("110");
    await page.locator("#servo-3").press("Enter");
    await expect.poll(async () => (await simServos(page))[3]?.position).toBe(110);
    expect(await page.getByTestId("servo-refused-3").count()).toBe(0);

    // The slider: arrow keys move it; many quick changes do not queue up.
    const slider = page.getByLabel(/Left knee \(servo 2\), target/);
    await slider.focus();
    await page.keyboard.press("ArrowRight");
    await expect.poll(async () => (await simServos(page))[2]?.position).toBe(HUNO_BASIC_POSTURE[2]! + 1);
    const before = await page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? 0);
    await page.evaluate(() => {
      const input = document.querySelector<HTMLInputElement>('tr[data-servo="5"] input[type="range"]');
      if (!input) throw new Error("no slider for servo 5");
      for (let v = 100; v < 160; v++) {
        input.value = String(v);
        input.dispatchEvent(new Event("input", { bubbles: true }));
      }
    });
    await expect.poll(async () => (await simServos(page))[5]?.position).toBe(159);
    const sent = (await page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? 0)) - before;
    // 60 changes, each move 4 bytes: latest-wins sends only a few of them.
    expect(sent).toBeLessThan(20 * 4);

    // Stop: no further move is sent, the servos keep holding (torque on), servo control stays on.
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    await page.getByTestId("stop-banner").filter({ hasText: "Servo moves stopped" }).waitFor();
    expect((await simServos(page)).map((s) => s.passive)).toEqual(Array(16).fill(false));
    expect(await simDirect(page)).toBe(true);

    // Limp, after its question: every servo passive.
    await page.getByRole("button", { name: "Limp…" }).click();
    await page.getByRole("alertdialog").getByRole("button", { name: "Limp", exact: true }).click();
    await page.getByText(/Limp: all 16 servos confirmed passive/).waitFor();
    expect((await simServos(page)).map((s) => s.passive)).toEqual(Array(16).fill(true));
    await page.getByTestId("servo-mode").filter({ hasText: "every servo is limp" }).waitFor();
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("after Limp during a motion every servo is limp, and servo controls still wait for the safety notice", async () => {
    // Real time: basic posture (1.8 s) should still be playing when Limp is confirmed (it waits for it if not).
    const { page, context } = await app.newPage();
    await connectRobot(page, app.url);
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    // Run basic posture (always accepted) and stop it with two quick presses of Escape.
    await page.getByRole("link", { name: "Motions" }).click();
    // The Run tab, where the Motions view has tabs (it loads lazily: wait for it first).
    await page.locator('[role="tablist"][aria-label="Motions"], [data-motion="7"]').first().waitFor();
    const runTab = page.getByRole("tab", { name: "Run" });
    if (await runTab.count()) await runTab.click();
    await page.locator('[data-motion="7"]').click();
    await page.locator("#confirm-move").click();
    await page.getByTestId("running-motion").waitFor();
    await page.getByRole("button", { name: "Limp…" }).click();
    await page.getByRole("alertdialog").getByRole("button", { name: "Limp", exact: true }).click();
    await page.getByText(/Limp: all 16 servos confirmed passive/).waitFor({ timeout: 8000 });
    expect((await simServos(page)).slice(0, 16).every((s) => s.passive)).toBe(true);
    expect(await page.getByText(/Limp failed/).count()).toBe(0);

    // Limp left the link in direct mode; the servo controls still need the safety notice first.
    await page.getByRole("link", { name: "Servos" }).click();
    await page.getByTestId("servo-safety").waitFor();
    expect(await page.getByRole("button", { name: "Read all positions" }).isDisabled()).toBe(true);
    await context.close();
  });

  it("moves all servos to the basic posture after confirming, and leaves direct mode on request and on disconnect", async () => {
    const { page, context } = await app.newPage();
    await openServos(page);
    await startControl(page);
    await page.locator("#servo-0").fill("140");
    await page.locator("#servo-0").press("Enter");
    await expect.poll(async () => (await simServos(page))[0]?.position).toBe(140);

    await page.getByRole("button", { name: "All to basic posture…" }).click();
    await page.getByText("All 16 servos move to the basic posture at speed 4. Hold the robot.").waitFor();
    await page.getByRole("button", { name: "Move all servos" }).click();
    await page.getByText(/Sent: all 16 servos move to the basic posture/).waitFor();
    expect((await simServos(page)).map((s) => s.position)).toEqual([...HUNO_BASIC_POSTURE]);

    await page.getByTestId("leave-direct").click();
    await page.getByText(/Servo control ended/).waitFor();
    expect(await simDirect(page)).toBe(false);

    // Back in, then disconnect: the client sends the exit sequence on close.
    await page.getByTestId("enter-direct").click();
    await page.getByText("Read all 16 servos.").waitFor();
    expect(await simDirect(page)).toBe(true);
    await page.getByRole("link", { name: "Robot" }).click();
    await page.getByRole("button", { name: "Disconnect" }).click();
    await page.getByTestId("connect-card").waitFor();
    await expect.poll(() => simDirect(page)).toBe(false);
    await context.close();
  });
});
