/**
 * Teach-in and tethered play in the motion editor, on the demo robot (issue #12 items 3 and 4): a three-scene
 * motion made by posing limbs by hand with the demo robot's sliders, then played on the robot; its simulated
 * servos (watched through `window.__rbcDemoSim`) must go through the frames of docs/protocol.md §10, computed here
 * by hand; Stop mid-play holds the frame sent and nothing goes limp.
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { DEMO } from "./connected-page.ts";
import { openEditorOnDemo } from "./editor-fixtures.ts";
import { expectText, FAST, squash, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";

const app = useApp();

/** docs/protocol.md §4: the standard zero table (the template's) and the firmware's factory table (the demo robot's). */
const STANDARD = [125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127];
const FACTORY = [124, 202, 162, 65, 108, 125, 46, 88, 184, 142, 90, 40, 125, 161, 210, 126];
/** §10 step 4: zeroDelta = the robot's zero − the motion's zero. */
const DELTA = FACTORY.map((z, i) => z - STANDARD[i]!);
/** §5: the HUNO basic posture, the template's pose and where the simulated servos start. */
const POSTURE = [125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205];
/** §5: safe ranges. */
const LOWER = [1, 70, 124, 40, 41, 73, 22, 1, 120, 57, 1, 23, 1, 1, 25, 40];
const UPPER = [174, 228, 254, 130, 185, 254, 180, 126, 208, 208, 254, 224, 198, 254, 228, 254];

/** C's round(): halves away from zero (the firmware is C). */
const cRound = (x: number) => (x < 0 ? -Math.round(-x) : Math.round(x));
const clamp = (id: number, v: number) =>
  Math.min(UPPER[id]!, Math.max(LOWER[id]!, Math.min(254, Math.max(1, v))));

/** §10 step 3: frame k of a scene, every servo: start + round(k·(end − start)/frames) + zeroDelta, clamped. */
function sceneFrames(start: number[], end: number[], frames: number): number[][] {
  return Array.from({ length: frames }, (_, i) =>
    start.map((s, id) => clamp(id, s + cRound(((i + 1) * (end[id]! - s)) / frames) + DELTA[id]!)),
  );
}

/** §10 step 2: from the pose read to the first pose, gap/3 frames when a servo is more than 10 counts away. */
function transitionFrames(now: number[], firstPose: number[]): number[][] {
  const target = firstPose.map((p, id) => clamp(id, p + DELTA[id]!));
  const gap = Math.max(...now.map((p, id) => Math.abs(p - target[id]!)));
  if (gap <= 10) return [];
  const n = Math.floor(gap / 3);
  return Array.from({ length: n }, (_, j) =>
    now.map((p, id) => clamp(id, p + cRound(((j + 1) * (target[id]! - p)) / n))),
  );
}

/** The servos report only changes: consecutive equal frames are one. */
function changes(frames: number[][]): number[][] {
  return frames.filter((f, i) => i === 0 || f.join() !== frames[i - 1]!.join());
}

const demoServos = (page: Page) => page.evaluate(() => window.__rbcDemoSim?.servos ?? []);
const passiveIds = async (page: Page) => (await demoServos(page)).filter((s) => s.passive).map((s) => s.id);
const positions = async (page: Page) => (await demoServos(page)).map((s) => s.position);

/** Starts recording every change of the demo robot's servos (window.__rbcServoLog). */
async function recordServos(page: Page): Promise<void> {
  await page.evaluate(() => {
    const log: number[][] = [];
    (window as unknown as { __rbcServoLog: number[][] }).__rbcServoLog = log;
    const stop = window.__rbcDemoSim?.onServos((p) => log.push([...p]));
    (window as unknown as { __rbcServoStop?: () => void }).__rbcServoStop = stop;
  });
}

async function recorded(page: Page): Promise<number[][]> {
  return page.evaluate(() => {
    const w = window as unknown as { __rbcServoLog: number[][]; __rbcServoStop?: () => void };
    w.__rbcServoStop?.();
    return w.__rbcServoLog;
  });
}

async function notice(page: Page, panel: "teach-in" | "play-panel"): Promise<string> {
  return squash(await page.getByTestId(panel).locator(".live .notice p").first().textContent());
}

/** Makes `limbs` (and nothing else) limp and poses servos with the demo robot's sliders. */
async function poseByHand(page: Page, limbs: string[], poses: Record<number, number>): Promise<void> {
  for (const limb of ["right-leg", "left-leg", "right-arm", "left-arm"]) {
    await page.locator(`input[data-limb="${limb}"]`).setChecked(limbs.includes(limb));
  }
  await page.locator("#make-limp").click();
  await page.getByTestId("teach-in").getByText("limp (confirmed)").waitFor();
  for (const [id, value] of Object.entries(poses)) {
    await page.locator(`#teach-hand-${id}`).fill(String(value));
    await page
      .getByTestId(`teach-pos-${id}`)
      .filter({ hasText: String(value) })
      .waitFor();
  }
}

async function readInto(page: Page, scene: number): Promise<void> {
  await page.getByRole("button", { name: `Read pose into scene ${scene}` }).click();
  await page.getByTestId("teach-in").getByText(`into scene ${scene} (its end pose`).waitFor();
}

async function hold(page: Page): Promise<void> {
  await page.getByTestId("hold").click();
  await page.getByTestId("teach-in").getByText("where they were posed").waitFor();
  expect(await passiveIds(page)).toEqual([]);
}

type EditorTab = "pose" | "scene" | "tools" | "teach" | "play" | "check";

/** Shows a tab of the selected scene's work (the editor's tab list) and waits for its panel. */
async function showTab(page: Page, tab: EditorTab): Promise<void> {
  await page.locator(`#editor-tab-${tab}`).click();
  await page.locator(`#editor-panel-${tab}`).waitFor();
}

/** The end positions of servos `ids` in the pose table (the Pose tab), then back to the Teach-in tab. */
async function endValues(page: Page, ids: number[]): Promise<number[]> {
  await showTab(page, "pose");
  const values: number[] = [];
  for (const id of ids) values.push(Number(await page.getByTestId(`end-${id}`).inputValue()));
  await showTab(page, "teach");
  return values;
}

describe("editor: teach-in and tethered play on the demo robot", () => {
  it("makes a three-scene motion by hand, plays it through the frames of §10, and Stop holds", async () => {
    const { page, context } = await app.newPage({ start: DEMO, options: FAST });
    await openEditorOnDemo(page, app.url);
    expect(await positions(page)).toEqual(POSTURE);

    // ---- Teach-in: asks once, then servo control with every servo holding.
    await showTab(page, "teach");
    await page.locator("#start-teach-in").click();
    await expectText(page.getByTestId("teach-in-confirm"), "Hold the robot: the servos you choose go limp.", {
      contains: true,
    });
    await page.locator("#confirm-teach-in").click();
    await page.getByTestId("teach-in-status").filter({ hasText: "Every servo holds" }).waitFor();
    expect(await page.evaluate(() => window.__rbcDemoSim?.directMode)).toBe(true);
    expect(await passiveIds(page)).toEqual([]);

    // Scene 0: the left arm (10-12, the robot's own left) goes limp (only it), the hand poses the shoulder and the elbow.
    await poseByHand(page, ["left-arm"], { 10: 100, 12: 80 });
    expect(await passiveIds(page)).toEqual([10, 11, 12]);
    // The 3D view follows the live robot (the pose it last drew, by servo id).
    const drawn = () => page.getByTestId("editor-robot3d").getAttribute("data-pose");
    await expect.poll(async () => (await drawn())?.split(" ")[10]).toBe("100");
    // A holding servo has no slider: only the limp ones can be posed.
    expect(await page.locator("#teach-hand-0").count()).toBe(0);
    await readInto(page, 0);
    await expect.poll(() => notice(page, "teach-in")).toContain("Read servos 0–15 into scene 0");
    // Stored in the motion's zeros: robot 125 on a servo whose zero is 124 here and 125 in the motion is 126.
    expect(await endValues(page, [10, 12, 0])).toEqual([100, 80, 126]);
    await hold(page);

    // Scene 1: the right arm (13-15).
    await page.getByTestId("scene-add").click();
    await page.getByRole("button", { name: "Read pose into scene 1" }).waitFor();
    await poseByHand(page, ["right-arm"], { 13: 150 });
    expect(await passiveIds(page)).toEqual([13, 14, 15]);
    await readInto(page, 1);
    expect(await endValues(page, [13])).toEqual([150]);
    await hold(page);

    // Scene 2: the left knee (servo 2, the robot's own left leg 0-4); End teach-in holds it, then leaves servo control.
    await page.getByTestId("scene-add").click();
    await page.getByRole("button", { name: "Read pose into scene 2" }).waitFor();
    await poseByHand(page, ["left-leg"], { 2: 180 });
    await readInto(page, 2);
    expect(await endValues(page, [2])).toEqual([180]);
    await page.getByTestId("end-teach-in").click();
    await page.getByTestId("teach-in").getByText("Teach-in ended").waitFor();
    expect(await passiveIds(page)).toEqual([]);
    expect(await page.evaluate(() => window.__rbcDemoSim?.directMode)).toBe(false);
    const afterTeachIn = await positions(page);
    expect(afterTeachIn).toEqual(POSTURE.map((p, id) => ({ 2: 180, 10: 100, 12: 80, 13: 150 })[id] ?? p));

    // ---- Tethered play of the whole motion: one question, Cancel focused first.
    await showTab(page, "play");
    await page.getByRole("radio", { name: /Whole motion/ }).check();
    await page.locator("#play-button").click();
    await expectText(
      page.getByTestId("play-confirm").locator("#play-question"),
      "The robot will move through scenes 0–2 (1.5 s). Hold it or make sure it can stand.",
    );
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("cancel-play");
    // Escape in the question cancels it (it is not Stop there); nothing moved. Asked again, it is answered.
    await page.keyboard.press("Escape");
    await page.getByTestId("play-confirm").waitFor({ state: "detached" });
    expect(await positions(page)).toEqual(afterTeachIn);
    await page.locator("#play-button").click();
    await recordServos(page);
    await page.locator("#confirm-play").click();
    await page.getByTestId("play-panel").getByText("the servos hold the last frame").waitFor();
    await expect
      .poll(() => notice(page, "play-panel"))
      .toMatch(/^Played scenes 0–2 \(\d+ frames, \d+\.\d s\); the servos hold the last frame\.$/);

    // The poses the teach-in stored (the motion's zeros: the robot's positions − zeroDelta).
    const robot0 = POSTURE.map((p, id) => ({ 10: 100, 12: 80 })[id] ?? p);
    const robot1 = robot0.map((p, id) => (id === 13 ? 150 : p));
    const robot2 = robot1.map((p, id) => (id === 2 ? 180 : p));
    const [end0, end1, end2] = [robot0, robot1, robot2].map((r) => r.map((p, id) => p - DELTA[id]!));
    const scene0 = sceneFrames(POSTURE, end0!, 10);
    const scene1 = sceneFrames(end0!, end1!, 10);
    const scene2 = sceneFrames(end1!, end2!, 10);
    // Hand-checked anchors: servo 10 goes 51 → 100 in 10 frames (51 + round(4.9k)), servo 13 199 → 150 (halves
    // away from zero: its frame 5 is 199 + round(−24.5) = 174), servo 2 199 → 180.
    expect(scene0.map((f) => f[10])).toEqual([56, 61, 66, 71, 76, 80, 85, 90, 95, 100]);
    expect(scene1.map((f) => f[13])).toEqual([194, 189, 184, 179, 174, 170, 165, 160, 155, 150]);
    expect(scene2.map((f) => f[2])).toEqual([197, 195, 193, 191, 189, 188, 186, 184, 182, 180]);
    expect(scene0[0]?.[6]).toBe(70); // 72 + round(0.2) − 2
    const transition = transitionFrames(afterTeachIn, POSTURE);
    expect(transition).toHaveLength(16); // the largest gap is 49 (servos 10 and 13): 49 / 3 = 16 frames
    expect(await recorded(page)).toEqual(changes([...transition, ...scene0, ...scene1, ...scene2]));
    expect(await passiveIds(page)).toEqual([]);
    expect(await page.evaluate(() => window.__rbcDemoSim?.directMode)).toBe(true);

    // ---- Stop mid-play: scene 2 made long (50 frames in 5 s), Stop in the panel holds the frame sent.
    await showTab(page, "scene");
    await page.getByTestId("scene-time").fill("5000");
    await page.getByTestId("scene-time").press("Enter");
    await page.getByTestId("scene-frames").fill("50");
    await page.getByTestId("scene-frames").press("Enter");
    await showTab(page, "play");
    await page.getByRole("radio", { name: /Selected scene/ }).check();
    await page.getByTestId("play-summary").filter({ hasText: "Scene 2: 50 frames, 5.0 s." }).waitFor();
    await page.locator("#play-button").click();
    await page.locator("#confirm-play").click();
    await page
      .getByTestId("play-where")
      .filter({ hasText: /^Scene 2, frame \d+ of 50$/ })
      .waitFor();
    await page.getByTestId("play-stop").click();
    await page.getByTestId("play-panel").getByText("the servos hold that pose").waitFor();
    const stopped = /^Stopped at scene 2, frame (\d+); the servos hold that pose\.$/.exec(
      await notice(page, "play-panel"),
    );
    expect(stopped).not.toBeNull();
    const k = Number(stopped?.[1]);
    expect(k).toBeLessThan(50);
    const held = sceneFrames(end1!, end2!, 50)[k - 1];
    expect(await positions(page)).toEqual(held);
    expect(await passiveIds(page)).toEqual([]);
    // Stop leaves direct mode (issue 22 item 6); leaving changes no servo.
    expect(await page.evaluate(() => window.__rbcDemoSim?.directMode)).toBe(false);
    await context.close();
  });

  it("without a robot, both panels say what they need", async () => {
    const { page, context } = await app.newPage();
    await page.goto(`${app.url}#/editor`);
    await page.getByTestId("pose-table").waitFor();
    await showTab(page, "teach");
    await expectText(page.getByTestId("teach-in-hint"), "Connect a robot", { contains: true });
    await showTab(page, "play");
    await expectText(page.getByTestId("play-hint"), "Connect a robot", { contains: true });
    await context.close();
  });
});
