import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { type AppHarness, FAST, openMotions, robotNow, squash, startHarness } from "./harness.ts";
import "./rbc-test-globals.ts";

// The Motions view's run and sound tests, in a file of their own so that two browser files can share the
// suite's time (motions.test.ts has the file and upload tests).

let app: AppHarness;

beforeAll(async () => {
  app = await startHarness();
});

afterAll(async () => {
  await app?.close();
});

describe("motions view: running motions and sounds", () => {
  it("guides to basic posture first, asks once before moving, stops a motion with 7, and Stop makes every servo limp", async () => {
    const { page, context } = await app.newPage({ options: FAST });
    await openMotions(page, app.url);
    const guidance = page.getByTestId("posture-guidance");
    expect(await guidance.textContent().then(squash)).toContain(
      "After switching on, the robot only accepts Basic posture (7). Run it first.",
    );
    expect(await page.locator('[data-motion="7"]').getAttribute("class")).toContain("is-recommended");
    // No UI for numbers outside the allowed list.
    const offered = await page
      .locator("[data-motion]")
      .evaluateAll((els) => els.map((e) => Number(e.getAttribute("data-motion"))));
    expect(offered).toEqual([1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]);

    // Motion 4 before 7: asked once, then the robot ignores it and the panel says what to do.
    await page.locator('[data-motion="4"]').click();
    const ask = page.getByTestId("move-confirm");
    expect(await ask.textContent().then(squash)).toContain("The robot will move. Hold it or give it room.");
    await page.getByRole("button", { name: "Run motion 4 (Walk forward)" }).click();
    await page.getByTestId("running-motion").filter({ hasText: "Walk forward" }).waitFor();
    const ignored = page.getByText(/The robot ignored motion 4/);
    await ignored.waitFor({ timeout: 8000 });
    expect(await ignored.textContent().then(squash)).toContain("Run it first.");

    // 7 runs without asking again; afterwards the guidance is gone.
    await page.locator('[data-motion="7"]').click();
    expect(await page.getByTestId("move-confirm").count()).toBe(0);
    await page.getByText("Motion 7 (Basic posture) finished. The robot now accepts every motion.").waitFor({
      timeout: 6000,
    });
    expect(await guidance.count()).toBe(0);

    // Stop motion sends 7: the robot ends the scene and holds that pose (no basic posture, PROTOCOL.md §3.6).
    await page.locator('[data-motion="2"]').click();
    const motion2Started = await robotNow(page);
    await page.getByTestId("running-motion").filter({ hasText: "Get up B" }).waitFor();
    await page.getByTestId("stop-motion").click();
    await page
      .getByText(
        /Motion 2 \(Get up B \(from back\)\) stopped at the end of its scene\. The robot holds the pose/,
      )
      .waitFor();
    expect(await page.evaluate(() => window.__rbcTest?.sim.playingMotion)).toBeUndefined();
    // Stopped well before motion 2's 6.6 s: the 7 took effect at the end of a scene.
    expect((await robotNow(page)) - motion2Started).toBeLessThan(6600);
    expect(await page.locator('[data-motion="1"]').isEnabled()).toBe(true);

    // The global Stop during a motion: every servo limp.
    await page.locator('[data-motion="1"]').click();
    await page.getByTestId("running-motion").waitFor();
    await page.getByRole("button", { name: /Stop — limp/ }).click();
    await page.getByText(/Stopped: all 16 servos are limp/).waitFor({ timeout: 8000 });
    const passive = await page.evaluate(() => window.__rbcTest?.sim.servos.map((s) => s.passive));
    expect(passive).toEqual(Array(16).fill(true));
    await page.getByText(/Motion 1 \(Get up A \(from front\)\) was interrupted by Stop — limp/).waitFor();
    await context.close();
  });

  it("says at once that an empty download slot holds no motion (the robot reports error 3)", async () => {
    const { page, context } = await app.newPage({ options: FAST });
    await openMotions(page, app.url);
    await page.locator('[data-motion="7"]').click();
    await page.locator("#confirm-move").click();
    await page.getByText("Motion 7 (Basic posture) finished. The robot now accepts every motion.").waitFor({
      timeout: 6000,
    });
    await page.getByText(/Other download slots/).click();
    const started = await robotNow(page);
    await page.locator('[data-slot-motion="12"]').click();
    await page
      .getByText(/download slot 1 holds no motion \(the robot reports error 3\)/)
      .first()
      .waitFor({ timeout: 5000 });
    // Noticed within about a second of the robot's time, not after the 60 s an unknown motion may take.
    expect((await robotNow(page)) - started).toBeLessThan(5000);
    expect(await page.evaluate(() => window.__rbcTest?.sim.playingMotion)).toBeUndefined();
    await context.close();
  });

  it("plays a sound and keeps other robot actions disabled while it plays", async () => {
    const { page, context } = await app.newPage({ options: FAST });
    await openMotions(page, app.url);
    // Sound 7 (5.7 s of the robot's time) leaves time to look at the panel while it plays.
    await page.locator('[data-sound="7"]').click();
    const playing = page.getByTestId("sound-playing");
    await playing.waitFor();
    expect(await playing.textContent().then(squash)).toContain(
      "The robot does nothing else until the sound ends",
    );
    expect(await page.locator('[data-motion="7"]').isDisabled()).toBe(true);
    expect(await page.locator('[data-sound="2"]').isDisabled()).toBe(true);
    expect(await page.evaluate(() => window.__rbcTest?.sim.state.playingSound)).toBe(7);
    await page.getByText("Sound 7 played (5.7 s).").waitFor({ timeout: 6000 });
    expect(await page.locator('[data-motion="7"]').isEnabled()).toBe(true);
    await context.close();
  });
});
