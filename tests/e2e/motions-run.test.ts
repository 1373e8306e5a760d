import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { CABLE, loadMotions } from "./connected-page.ts";
import {
  expectText,
  FAST,
  holdRobot,
  holdRobotWhenShown,
  releaseRobot,
  robotNow,
  squash,
  useApp,
  watchText,
} from "./harness.ts";
import { showTab } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

// The Motions view's run and sound tests, in a file of their own so that two browser files can share the
// suite's time (motions.test.ts has the file and upload tests).

const app = useApp();

/** The Motions view's Run or Sounds tab, with the fake robot connected. */
async function openTab(page: Page, tab: "Run" | "Sounds"): Promise<void> {
  await loadMotions(page, app.url);
  await showTab(page, tab);
}

/** The element's box lies wholly inside the viewport (seen without scrolling). */
async function inViewport(page: Page, testId: string, within?: string): Promise<boolean> {
  const scope = within ? page.getByTestId(within) : page;
  const box = await scope.getByTestId(testId).first().boundingBox();
  const size = page.viewportSize();
  if (!box || !size) return false;
  return box.y >= 0 && box.x >= 0 && box.y + box.height <= size.height && box.x + box.width <= size.width;
}

/** The panel that shows the motion playing now. */
const RUNNING = '[data-testid="running-motion"]';
/** The same once the robot was seen busy with it ("Running", docs/protocol.md §3.1): the Run has gone out. */
const RUNNING_CONFIRMED = '[data-testid="running-motion"][data-confirmed="yes"]';

describe("motions view: running motions and sounds", () => {
  it("guides to basic posture first, asks once before moving, and both Stop motion and Stop end a motion with 7, the robot holding its pose", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await openTab(page, "Run");
    const guidance = page.getByTestId("posture-guidance");
    await expectText(
      guidance,
      "After switching on, the robot only accepts Basic posture (7). Run it first.",
      { contains: true },
    );
    await expect
      .poll(() => page.locator('[data-motion="7"]').getAttribute("class"))
      .toContain("is-recommended");
    // No UI for numbers outside the allowed list.
    const offered = () =>
      page
        .locator("[data-motion]")
        .evaluateAll((els) => els.map((e) => Number(e.getAttribute("data-motion"))));
    await expect.poll(offered).toEqual([1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]);

    // Motion 4 before 7: asked once, then the robot ignores it and the panel says what to do.
    await page.locator('[data-motion="4"]').click();
    const ask = page.getByTestId("move-confirm");
    await expectText(ask, "The robot will move. Hold it or give it room.", { contains: true });
    await page.getByRole("button", { name: "Run motion 4 (Walk forward)" }).click();
    await page.getByTestId("running-motion").filter({ hasText: "Walk forward" }).waitFor();
    const ignored = page.getByText(/The robot ignored motion 4/);
    await ignored.waitFor({ timeout: 8000 });
    await expectText(ignored, "Run it first.", { contains: true });

    // 7 runs without asking again; afterwards the guidance is gone.
    await page.locator('[data-motion="7"]').click();
    await page.getByText("Motion 7 (Basic posture) finished. The robot now accepts every motion.").waitFor({
      timeout: 6000,
    });
    // Read after the motion's own result, not before the click was drawn (when no question could show yet).
    expect(await page.getByTestId("move-confirm").count()).toBe(0);
    await expect.poll(() => guidance.count()).toBe(0);

    // Stop motion sends 7: the robot ends the scene and holds that pose (no basic posture, docs/protocol.md §3.6).
    await page.locator('[data-motion="2"]').click();
    const motion2Started = await robotNow(page);
    // Held from the frame the motion shows as running (the robot seen busy with it) until Stop motion is pressed:
    // motion 2's 6.6 s are
    // 1.65 s of real time at FAST, which a loaded machine can spend before the click lands.
    await holdRobotWhenShown(page, RUNNING_CONFIRMED, /Get up B/);
    await page.getByTestId("stop-motion").click();
    await releaseRobot(page);
    await page
      .getByText(
        /Motion 2 \(Get up B \(from back\)\) stopped at the end of its scene\. The robot holds the pose/,
      )
      .waitFor();
    expect(await page.evaluate(() => window.__rbcTest?.sim.playingMotion)).toBeUndefined();
    // Stopped well before motion 2's 6.6 s: the 7 took effect at the end of a scene.
    expect((await robotNow(page)) - motion2Started).toBeLessThan(6600);
    await expect.poll(() => page.locator('[data-motion="1"]').isEnabled()).toBe(true);

    // The top bar's Stop during a motion ends it with 7 as well: no servo goes limp. The running panel says so.
    await page.locator('[data-motion="1"]').click();
    const running = page.getByTestId("running-motion");
    // Held likewise while the test reads the running panel and presses Stop.
    await holdRobotWhenShown(page, RUNNING, /./);
    await expectText(
      running,
      "The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing.",
      { contains: true },
    );
    expect(await running.textContent().then(squash)).not.toContain("Stop — limp");
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    await releaseRobot(page);
    await running.waitFor({ state: "detached", timeout: 8000 });
    expect(await page.evaluate(() => window.__rbcTest?.sim.playingMotion)).toBeUndefined();
    const passive = await page.evaluate(() => window.__rbcTest?.sim.servos.map((s) => s.passive));
    expect(passive).toEqual(Array(16).fill(false));
    await context.close();
  });

  it("says at once, beside the slot button pressed, that the robot holds no motion under that number (error 3)", async () => {
    // A phone: the slot buttons are far below the top of the Run card there.
    const { page, context } = await app.newPage({
      start: CABLE,
      options: FAST,
      viewport: { width: 390, height: 844 },
    });
    await openTab(page, "Run");
    await page.locator('[data-motion="7"]').click();
    await page.locator("#confirm-move").click();
    await page.getByText("Motion 7 (Basic posture) finished. The robot now accepts every motion.").waitFor({
      timeout: 6000,
    });
    await page.getByText(/Other upload slots/).click();
    // The click happens while the robot's time stands still, so `started` is the robot's time of the click
    // however long the click takes on a busy machine.
    await holdRobot(page);
    const started = await robotNow(page);
    // The robot's time when the notice appears, noted in the page (not after the test's next steps).
    const notice = await watchText(
      page,
      '[data-testid="run-place-slots"]',
      /Motion 42 did not run: the robot holds no motion under that number \(it reports error 3\)/,
    );
    await page.locator('[data-slot-motion="42"]').click();
    await releaseRobot(page);
    const shownAt = await notice.moment();
    // Shown under the slot buttons, in view, and not at the top of the card.
    await expectText(page.getByTestId("run-place-built-in"), "");
    await expect
      .poll(() =>
        page.evaluate(() => {
          const n = document.querySelector('[data-testid="run-place-slots"] .notice');
          const r = n?.getBoundingClientRect();
          return r ? r.top >= 0 && r.bottom <= window.innerHeight : false;
        }),
      )
      .toBe(true);
    // Noticed within about a second of the robot's time, not after the 60 s an unknown motion may take.
    expect(shownAt - started).toBeLessThan(5000);
    expect(await page.evaluate(() => window.__rbcTest?.sim.playingMotion)).toBeUndefined();
    await context.close();
  });

  it("says a Run was sent and is being checked (no 'Running', no bar) until the robot is seen busy, and an ignored Run as soon as its reply comes", async () => {
    // Issue 33 item 5: the base showed "Running motion 12 … 3.2 s of 3.2 s" for a Run the robot had ignored.
    // The official "user" firmware: 12 holds nothing and its reply comes at once (docs/protocol.md §3.1).
    const { page, context } = await app.newPage({
      start: CABLE,
      options: { ...FAST, variant: { userFirmware: true } },
    });
    await openTab(page, "Run");
    const running = page.getByTestId("running-motion");
    // Held at the first frame the run shows: the busy check (asked 250 ms into the Run) has not answered yet.
    const checking = await watchText(page, RUNNING, /sent: checking that the robot plays it/, { hold: true });
    await page.locator('[data-motion="7"]').click();
    await page.locator("#confirm-move").click();
    await checking.moment();
    await expectText(running, "Motion 7 — Basic posture sent: checking that the robot plays it", {
      contains: true,
    });
    expect(await running.locator("progress").count()).toBe(0);
    expect(squash(await running.textContent())).not.toContain("Running");
    // Seen busy (0x12 answered at once, 0x16 not): now "Running", with its time and bar.
    const busy = await watchText(page, RUNNING, /Running motion 7/, { hold: true });
    await releaseRobot(page);
    await busy.moment();
    expect(await running.locator("progress").count()).toBe(1);
    await releaseRobot(page);
    await page.getByText("Motion 7 (Basic posture) finished. The robot now accepts every motion.").waitFor({
      timeout: 6000,
    });

    // Motion 12 on this firmware: ignored, said when its reply comes, and never shown as running.
    await page.evaluate(() => {
      const w = window as unknown as { __sawRunning12?: boolean };
      w.__sawRunning12 = false;
      new MutationObserver(() => {
        const el = document.querySelector('[data-testid="running-motion"]');
        if (el && (/Running motion 12/.test(el.textContent ?? "") || el.querySelector("progress"))) {
          w.__sawRunning12 = true;
        }
      }).observe(document.body, { subtree: true, childList: true, characterData: true });
    });
    await page.getByText(/Other upload slots/).click();
    await holdRobot(page);
    const started = await robotNow(page);
    const ignored = await watchText(
      page,
      '[data-testid="run-place-slots"]',
      /The robot ignored motion 12: its reply came at once \(after 0\.0 s\) and it was never busy\./,
    );
    await page.locator('[data-slot-motion="12"]').click();
    await releaseRobot(page);
    // Said as soon as the reply came (within a few tens of ms of the robot's time), not after a wait.
    expect((await ignored.moment()) - started).toBeLessThan(250);
    expect(
      await page.evaluate(() => (window as unknown as { __sawRunning12?: boolean }).__sawRunning12),
    ).toBe(false);

    // Stop motion while the Run has not gone out yet (its busy probe waits on the held robot): the Run is
    // cancelled and never sent, instead of playing whole with Basic posture after it.
    await holdRobot(page);
    await page.locator('[data-motion="2"]').click();
    await running.filter({ hasText: /sent: checking/ }).waitFor();
    await page.getByTestId("stop-motion").click();
    await releaseRobot(page);
    await page
      .getByText(/Motion 2 was not started: Stop came first/)
      .first()
      .waitFor({ timeout: 10_000 });
    expect(await page.evaluate(() => window.__rbcTest?.sim.playingMotion)).toBeUndefined();
    await context.close();
  });

  it("plays a sound, shows its own length while it plays, and keeps other robot actions disabled", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await openTab(page, "Sounds");
    // Sound 7 (5.7 s of the robot's time) leaves time to look at the panel while it plays.
    await page.locator('[data-sound="7"]').click();
    const playing = page.getByTestId("sound-playing");
    await playing.waitFor();
    // The robot's time stands still while the test looks at the panel in the middle of the sound.
    await holdRobot(page);
    await expectText(playing, "The robot does nothing else until the sound ends", { contains: true });
    // The same length as on its button (5.7 s), not the robot's reply time (5.9 s with its 200 ms delay).
    await expectText(page.locator('[data-sound="7"]'), "Sound 7 Long 5.7 s");
    await expectText(page.getByTestId("sound-time"), / of 5\.7 s$/);
    await expect.poll(() => inViewport(page, "sound-playing")).toBe(true);
    await expect.poll(() => page.locator('[data-sound="2"]').isDisabled()).toBe(true);
    await showTab(page, "Run");
    await expect.poll(() => page.locator('[data-motion="7"]').isDisabled()).toBe(true);
    expect(await page.evaluate(() => window.__rbcTest?.sim.state.playingSound)).toBe(7);
    await releaseRobot(page);
    await showTab(page, "Sounds");
    await page.getByText("Sound 7 played (5.7 s).").waitFor({ timeout: 6000 });
    await showTab(page, "Run");
    await expect.poll(() => page.locator('[data-motion="7"]').isEnabled()).toBe(true);
    await context.close();
  });

  it("a firmware that answers a sound at once: says the answer proves only that the request arrived", async () => {
    const { page, context } = await app.newPage({
      start: CABLE,
      options: { ...FAST, variant: { soundReplyAtOnce: true } },
    });
    await openTab(page, "Sounds");
    await page.locator('[data-sound="4"]').click();
    const said = page.getByText("The robot answered at once", { exact: false });
    await said.waitFor({ timeout: 6000 });
    // Sound 4 lasts 365 ms: busy for 0.6 s with the 200 ms before it (docs/protocol.md §3.3).
    await expectText(
      said,
      /^The robot answered at once \(after \d+ ms\): this firmware answers before it plays a sound, so the answer shows only that the request arrived, not that the sound played\. The sound keeps the robot busy for 0\.6 s/,
    );
    expect(await page.getByText("Sound 4 played", { exact: false }).count()).toBe(0);
    await context.close();
  });
});
