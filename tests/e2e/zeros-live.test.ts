/**
 * Zeros on the standing robot (issue 23 items 5 and 6, issue 21 item 7's Zeros part), in the built panel:
 * - trim live takes the zero pose through tethered play's transition, then each change moves exactly that servo:
 *   the wCK move packets on the wire (the fake port's tap) are the bytes of docs/protocol.md §5, worked out by hand
 *   (example "move id 5 to 125 at torque 2" is `FF 45 7D 38`), for that servo's id only;
 * - Cancel returns to the stored zeros and leaves direct mode (§8 example 5) with every servo holding; Escape
 *   (Stop) ends it holding; Write stores the table through the existing path; a busy robot is refused with Stop
 *   beside the sentence; a pulled cable leaves a sentence that says which zeros the robot has;
 * - capture zeros on the demo robot posed by hand (its simulator, as a hand would), with the per-joint check;
 * - compare the robot's zeros with a backup kept in the browser;
 * - Korean, axe, and Write a few tab stops from a changed value.
 * Robot time is the paced virtual clock (FAST: at most 4× real time); waits are on what the page shows.
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { CABLE, loadConnected, openConnected } from "./connected-page.ts";
import { expectText, FAST, releaseRobot, useApp, watchText } from "./harness.ts";
import "./rbc-test-globals.ts";
import { axeProblems, keysShown, newLocalePage } from "./i18n-checks.ts";

const app = useApp();

/** §4: the firmware's factory zeros (the simulated robot's). */
const FACTORY = [124, 202, 162, 65, 108, 125, 46, 88, 184, 142, 90, 40, 125, 161, 210, 126];
/** §8 example 4 (direct mode on) and example 5 (leave direct mode). */
const DIRECT_ON = "FF FF AA 55 AA 55 37 BA 10 00 00 00 00 01 01 01";
const DIRECT_OFF = "FF E0 FB 01 00 1A";

const hex = (bytes: Iterable<number>) =>
  [...bytes].map((b) => b.toString(16).toUpperCase().padStart(2, "0")).join(" ");

/** Every chunk the panel wrote to the fake port from `from` on, as hex. */
async function writtenSince(page: Page, from: number): Promise<string[]> {
  const chunks = await page.evaluate(
    (n) => (window.__rbcTest?.port.written ?? []).slice(n).map((c) => [...c]),
    from,
  );
  return chunks.map(hex);
}

const writtenCount = (page: Page) => page.evaluate(() => window.__rbcTest?.port.written.length ?? 0);
const positions = (page: Page) => page.evaluate(() => window.__rbcTest?.sim.servoPositions() ?? []);
const passive = (page: Page) =>
  page.evaluate(() => (window.__rbcTest?.sim.servos ?? []).filter((s) => s.passive).map((s) => s.id));
/** wCK single-servo moves (`FF (t<<5|id) pos cs`, 4 bytes) among written chunks. */
const moves = (chunks: string[]) => chunks.filter((c) => /^FF [0-9A-F]{2} [0-9A-F]{2} [0-9A-F]{2}$/.test(c));

/**
 * The Zeros view with the robot on the cable connected (a page opened with the start option `CABLE`). With
 * `robotViewFirst`, the panel starts on the Robot view, which reads its figures when first shown (a read leaves
 * direct mode, so it would end trim live if the Robot view were first shown during it).
 */
async function openZeros(page: Page, { robotViewFirst = false } = {}): Promise<void> {
  await page.addInitScript(() => Reflect.deleteProperty(window, "showSaveFilePicker"));
  if (robotViewFirst) {
    await loadConnected(page, app.url);
    await page.getByTestId("device-card").waitFor();
    await page.getByRole("link", { name: "Zeros" }).click();
  } else {
    await loadConnected(page, app.url, "zeros");
  }
  await page.locator("#zero-0").waitFor();
}

/** Trim live…, the question, then the zero pose: returns the count of chunks written before the pose. */
async function startTrim(page: Page): Promise<number> {
  await page.getByRole("button", { name: "Trim live…" }).click();
  const question = page.getByTestId("trim-question");
  await question.waitFor();
  await expectText(question, "Keep it standing on a flat surface, or hold it.", { contains: true });
  const before = await writtenCount(page);
  await page.getByRole("button", { name: "Take the zero pose" }).click();
  await page.getByTestId("trim-on").waitFor();
  return before;
}

async function lastMove(page: Page, position: number): Promise<void> {
  await page
    .getByTestId("trim-last")
    .filter({ hasText: `at ${position}, confirmed` })
    .waitFor();
}

describe("trim live", () => {
  it("takes the zero pose gently, then moves exactly the servo changed (§5 bytes), clamped to its window", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await openZeros(page);
    const before = await startTrim(page);
    const pose = await writtenSince(page, before);
    expect(pose).toContain(DIRECT_ON);
    // Tethered play's transition from basic posture: 79 counts (servo 15, 205 → 126) / 3 = 26 frames, then the
    // pose itself: a synchronised move of ids 0-15 at torque 3 carrying the factory zeros (§5; XOR & 7F = 06).
    const syncs = pose.filter((c) => c.startsWith("FF 7F 10 "));
    expect(syncs).toHaveLength(27);
    expect(syncs.at(-1)).toBe("FF 7F 10 7C CA A2 41 6C 7D 2E 58 B8 8E 5A 28 7D A1 D2 7E 06");
    expect(await positions(page)).toEqual(FACTORY);

    const mark = await writtenCount(page);
    await page.locator("#zero-5").focus();
    await page.keyboard.press("ArrowUp");
    await lastMove(page, 126);
    await page.keyboard.press("ArrowDown");
    await lastMove(page, 125);
    // Only servo 5, at torque 2: 126 is FF 45 7E 3B, and 125 is §5's own example.
    expect(moves(await writtenSince(page, mark))).toEqual(["FF 45 7E 3B", "FF 45 7D 38"]);
    expect(await positions(page)).toEqual(FACTORY);

    // Typed outside its window (109–139): the servo goes to 139 (FF 45 8B 4E) and the field says why Write waits.
    const mark2 = await writtenCount(page);
    await page.locator("#zero-5").fill("200");
    await lastMove(page, 139);
    await expectText(
      page.getByTestId("trim-last"),
      "Right hip roll (servo 5) went to 139: the nearest value its window allows (109–139).",
      { contains: true },
    );
    expect(moves(await writtenSince(page, mark2))).toEqual(["FF 45 8B 4E"]);
    const expected = [...FACTORY];
    expected[5] = 139;
    expect(await positions(page)).toEqual(expected);
    await expect.poll(() => page.getByTestId("write-zeros").isDisabled()).toBe(true);
    expect(await page.evaluate(() => window.__rbcTest?.sim.zeros)).toEqual(FACTORY);
    await context.close();
  });

  it("Cancel returns the servos to the stored zeros and leaves direct mode with every servo holding", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await openZeros(page);
    await startTrim(page);
    await page.locator("#zero-12").fill("131");
    await lastMove(page, 131);
    const mark = await writtenCount(page);
    await page.getByRole("button", { name: "Cancel trim" }).click();
    await page.getByText("Trim cancelled: the servos are back at the stored zeros and hold them.").waitFor();
    const sent = await writtenSince(page, mark);
    expect(sent.at(-1)).toBe(DIRECT_OFF);
    expect(sent.filter((c) => c.startsWith("FF 7F 10 ")).at(-1)).toBe(
      "FF 7F 10 7C CA A2 41 6C 7D 2E 58 B8 8E 5A 28 7D A1 D2 7E 06",
    );
    expect(await positions(page)).toEqual(FACTORY);
    expect(await passive(page)).toEqual([]);
    expect(await page.evaluate(() => window.__rbcTest?.sim.directMode)).toBe(false);
    await expect.poll(() => page.locator("#zero-12").inputValue()).toBe("125");
    expect(await page.evaluate(() => window.__rbcTest?.sim.zeros)).toEqual(FACTORY);
    await context.close();
  });

  it("Escape (Stop) ends trim live with the servos holding; nothing is written", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await openZeros(page);
    await startTrim(page);
    await page.locator("#zero-0").focus();
    await page.keyboard.press("ArrowUp");
    await lastMove(page, 125);
    await page.keyboard.press("Escape");
    const ended = page.getByText(/^Trim live ended: the robot left servo control/);
    await ended.waitFor();
    await expectText(
      ended,
      "Trim live ended: the robot left servo control (Stop, or another view used the robot). The servos hold the zero pose with these servos moved: servo 0 at 125. Nothing was written: the robot keeps its zeros.",
    );
    expect(await page.evaluate(() => window.__rbcTest?.sim.directMode)).toBe(false);
    expect(await passive(page)).toEqual([]);
    const held = [...FACTORY];
    held[0] = 125;
    expect(await positions(page)).toEqual(held);
    expect(await page.evaluate(() => window.__rbcTest?.sim.zeros)).toEqual(FACTORY);
    // A change now moves nothing: trim live is over.
    const mark = await writtenCount(page);
    await page.locator("#zero-0").fill("126");
    await page.getByTestId("change-summary").filter({ hasText: "servo 0 124 → 126" }).waitFor();
    expect(moves(await writtenSince(page, mark))).toEqual([]);
    await context.close();
  });

  it("Write stores the trimmed table with the backup and read-back, and the backup compares with the robot", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await openZeros(page);
    await startTrim(page);
    await page.locator("#zero-3").fill("70");
    await lastMove(page, 70);
    // Write beside the changed value: one tab stop from the field, past its slider at most.
    await page.locator("#zero-3").focus();
    let stops = 0;
    for (; stops < 4; stops++) {
      await page.keyboard.press("Tab");
      if (await page.evaluate(() => document.activeElement?.classList.contains("write-here"))) break;
    }
    expect(stops + 1).toBeLessThanOrEqual(2);
    const download = page.waitForEvent("download");
    await page.keyboard.press("Enter");
    await page.getByRole("button", { name: "Save backup and write" }).click();
    await download;
    const result = page.getByText(/Zeros written and verified/);
    await result.waitFor();
    await expectText(result, "Trim live ended with the write: the robot holds the pose it was trimmed to.", {
      contains: true,
    });
    const written = [...FACTORY];
    written[3] = 70;
    expect(await page.evaluate(() => window.__rbcTest?.sim.zeros)).toEqual(written);
    expect(await positions(page)).toEqual(written);
    expect(await passive(page)).toEqual([]);

    // The backup the write kept (the zeros before it) against the robot's zeros now.
    await page.getByTestId("kept-backups").locator("summary").click();
    await page.getByTestId("compare-kept").first().click();
    const summary = page.getByTestId("compare-summary");
    await summary.waitFor();
    await expectText(summary, "1 of 16 zeros differs from the backup: Left ankle pitch by +5.");
    const row = page.getByTestId("compare").locator('tr[data-servo="3"]');
    await expectText(row, "3 · Left ankle pitch 70 65 differs by +5");
    await expectText(
      page.getByTestId("compare").locator('tr[data-servo="4"]'),
      "4 · Left ankle roll 108 108 same",
    );
    expect(await axeProblems(page, { within: '[data-testid="zeros-card"]' })).toEqual([]);
    await context.close();
  });

  it("is refused while the robot plays a motion started elsewhere, with Stop beside the sentence", async () => {
    const { page, context } = await app.newPage({
      start: CABLE,
      options: { timeScale: 0.25, variant: { busyMotion: 2 } },
    });
    await openZeros(page);
    await page.getByRole("button", { name: "Trim live…" }).click();
    await page.getByRole("button", { name: "Take the zero pose" }).click();
    const refused = page.getByText(/^Trim live was not started\. Not started: the robot is busy/);
    await refused.waitFor();
    expect(await page.evaluate(() => window.__rbcTest?.sim.directMode)).toBe(false);
    const written = await writtenSince(page, 0);
    expect(written).not.toContain(DIRECT_ON);
    await page.getByTestId("trim-stop").click();
    await page.getByTestId("stop-banner").filter({ hasText: /./ }).waitFor();
    await context.close();
  });

  it("a pulled cable says which zeros the robot keeps and what its servos held", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await openZeros(page);
    await startTrim(page);
    await page.locator("#zero-5").fill("127");
    await lastMove(page, 127);
    await page.evaluate(() => window.__rbcTest?.port.unplug());
    const lost = page.getByTestId("trim-lost");
    await lost.waitFor();
    await expectText(lost, /^The connection ended during trim live \(.+\)\. /);
    await expectText(
      lost,
      `No zeros were written: the robot keeps ${FACTORY.join(" ")}. While it had power its servos held the zero pose with these servos moved: servo 5 at 127;`,
      { contains: true },
    );
    // The connect card is there below it.
    await page.getByTestId("connect-card").waitFor();
    await context.close();
  });

  it("Disconnect during trim live leaves servo control first and says so on the Zeros view", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    // The Robot view is shown again below, to Disconnect: it has read its figures already.
    await openZeros(page, { robotViewFirst: true });
    await startTrim(page);
    await page.locator("#zero-5").fill("126");
    await lastMove(page, 126);
    const mark = await writtenCount(page);
    await page.getByRole("link", { name: "Robot" }).click();
    await page.getByRole("button", { name: "Disconnect" }).click();
    await page.getByRole("link", { name: "Zeros" }).click();
    const lost = page.getByTestId("trim-lost");
    await lost.waitFor();
    await expectText(
      lost,
      "Its servos hold the zero pose with these servos moved: servo 5 at 126: the panel left servo control as it disconnected.",
      { contains: true },
    );
    expect(await writtenSince(page, mark)).toEqual([DIRECT_OFF]);
    expect(await page.evaluate(() => window.__rbcTest?.sim.directMode)).toBe(false);
    expect(await passive(page)).toEqual([]);
    await context.close();
  });
});

/** The capture's countdown (its text says how long until the reading). */
const COUNTDOWN = '[data-testid="capture-countdown"]';

describe("capture zeros on the demo robot", () => {
  it("limps, counts down, reads the pose made by hand, checks each joint's window, and fills the editor", async () => {
    const { page, context } = await openConnected(app, { view: "zeros", options: FAST });
    await page.locator("#zero-0").waitFor();
    await page.getByRole("button", { name: "Capture zeros…" }).click();
    await expectText(page.getByTestId("capture-question"), "the robot falls unless you hold it", {
      contains: true,
    });
    // The robot's time stands still from the frame the countdown shows until the pose is made: the 5 s
    // (1.25 s of real time at FAST) cannot run out while a loaded machine runs the test's next step. Watched from
    // before the click: "5 s" shows for a quarter of a second of real time.
    const countdown = await watchText(page, COUNTDOWN, /Reading in 5 s\./, { hold: true });
    await page.getByRole("button", { name: "Make it limp and start the countdown" }).click();
    await countdown.moment();
    // A hand poses the limp robot in its zero pose (every joint at its stored zero), but the left knee too far
    // (window 147–177) and the left hip roll moved within its window.
    await page.evaluate((zeros) => {
      for (const [id, z] of zeros.entries()) window.__rbcDemoSim?.poseByHand(id, z);
      window.__rbcDemoSim?.poseByHand(2, 180);
      window.__rbcDemoSim?.poseByHand(0, 130);
    }, FACTORY);
    await releaseRobot(page);
    const summary = page.getByTestId("capture-summary");
    await summary.waitFor();
    await expectText(
      summary,
      "Cannot write: Left knee (servo 2) at 180, window 147–177 outside the window the robot accepts. Pose those joints again and capture again.",
    );
    expect(await page.getByTestId("capture-use").count()).toBe(0);
    const table = page.getByTestId("capture-table");
    await expectText(table.locator('tr[data-servo="0"]'), "0 · Left hip roll 124 → 130 within 110–140");
    await expectText(
      table.locator('tr[data-servo="2"]'),
      "2 · Left knee 162 → 180 outside 147–177: the robot refuses it",
    );
    expect(await axeProblems(page, { within: '[data-testid="zeros-card"]' })).toEqual([]);

    // Again, the knee within its window this time: the pose goes into the zero table, and Write is the Zeros view's.
    await page.getByRole("button", { name: "Capture again…" }).click();
    const again = await watchText(page, COUNTDOWN, /Reading in/, { hold: true });
    await page.getByRole("button", { name: "Make it limp and start the countdown" }).click();
    await again.moment();
    await page.evaluate((zeros) => {
      for (const [id, z] of zeros.entries()) window.__rbcDemoSim?.poseByHand(id, z);
      window.__rbcDemoSim?.poseByHand(2, 170);
      window.__rbcDemoSim?.poseByHand(0, 130);
    }, FACTORY);
    await releaseRobot(page);
    await summary.filter({ hasText: "All 16" }).waitFor();
    await expectText(summary, "All 16 positions are inside their windows; 2 differ from the stored zeros.");
    await page.getByTestId("capture-use").click();
    // The editor is drawn on the panel's next render: polled.
    await expect.poll(() => page.locator("#zero-0").inputValue()).toBe("130");
    await expect.poll(() => page.locator("#zero-2").inputValue()).toBe("170");
    await page.getByTestId("change-summary").filter({ hasText: "2 changes not yet written" }).waitFor();
    await expect.poll(() => page.getByTestId("write-zeros").isEnabled()).toBe(true);
    await context.close();
  });

  it("Cancel during the countdown reads nothing", async () => {
    const { page, context } = await openConnected(app, { view: "zeros", options: FAST });
    await page.getByRole("button", { name: "Capture zeros…" }).click();
    // Held from the frame the countdown shows, so the Cancel lands before the reading on a loaded machine.
    const countdown = await watchText(page, COUNTDOWN, /Reading in/, { hold: true });
    await page.getByRole("button", { name: "Make it limp and start the countdown" }).click();
    await countdown.moment();
    await page.getByTestId("capture-countdown").getByRole("button", { name: "Cancel" }).click();
    await releaseRobot(page);
    await page.getByText("Capture cancelled: nothing was read or written.").waitFor();
    expect(await page.getByTestId("capture-table").count()).toBe(0);
    await context.close();
  });
});

describe("Korean", () => {
  it("asks, trims and compares in Korean, with no catalogue key shown", async () => {
    const { page, context } = await newLocalePage(app, "ko-KR", { options: FAST });
    await page.getByTestId("connect-card").locator(".actions .btn--primary").click();
    await page.getByTestId("device-card").waitFor();
    await page.locator('nav a[href*="zeros"]').first().click();
    await page.locator("#zero-0").waitFor();
    await page.getByRole("button", { name: "실시간 영점 맞추기…" }).click();
    await expectText(page.getByTestId("trim-question"), "로봇을 영점 자세로 세울까요?", { contains: true });
    await page.getByRole("button", { name: "영점 자세 잡기" }).click();
    await page.getByTestId("trim-on").waitFor();
    await page.locator("#zero-5").fill("126");
    await page.getByTestId("trim-last").filter({ hasText: "126에 있다고 서보가 확인했어요" }).waitFor();
    await page.getByRole("button", { name: "영점 맞추기 취소" }).click();
    await page.getByText("영점 맞추기를 취소했어요.", { exact: false }).waitFor();
    await page.getByRole("button", { name: "자세로 영점 잡기…" }).click();
    await expectText(page.getByTestId("capture-question"), "로봇을 잡아 주지 않으면 넘어져요", {
      contains: true,
    });
    expect(await keysShown(page)).toEqual([]);
    expect(await axeProblems(page, { within: '[data-testid="zeros-card"]' })).toEqual([]);
    await context.close();
  });
});
