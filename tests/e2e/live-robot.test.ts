/**
 * The connected robot in 3D (issue #12 item 5, "while connected follows the robot's live servo positions"):
 * the Motions view's Run tab and the Servos view have a "Robot in 3D" card, collapsed until "Show the robot in
 * 3D" is pressed (nothing of the 3D view loads before). On the demo robot it follows the simulated servos
 * (watched here through `window.__rbcDemoSim`): motion 4 visibly moves it, through poses the servos really
 * took, and it ends at the basic posture; a servo moved in the Servos view moves it. On a robot on a cable (the
 * fake serial port) it shows only what the robot reported, with the time, and does not follow a motion, which
 * the RBC cannot report while it plays.
 */
import { createRequire } from "node:module";
import type { BrowserContext, Locator, Page } from "playwright-core";
import { beforeAll, describe, expect, it } from "vitest";
import { CABLE, loadMotions } from "./connected-page.ts";
import { buildOnce, cspViolations, expectText, useApp, watchPage } from "./harness.ts";
import { showTab } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

const require = createRequire(import.meta.url);
const AXE_PATH = require.resolve("axe-core/axe.min.js");

const app = useApp();
let fakeSerial: string;

beforeAll(async () => {
  ({ fakeSerial } = await buildOnce());
});

/** docs/protocol.md §5: the HUNO basic posture, where the simulated servos start and where every built-in ends. */
const POSTURE = [125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205];
const BASIC = POSTURE.join(" ");

const attr = (locator: Locator, name: string) => locator.getAttribute(name).then((v) => v ?? "");

/** Counts requests for the 3D chunk (three.js). */
function sceneRequests(page: Page): string[] {
  const seen: string[] = [];
  page.on("request", (r) => {
    if (/robot-scene-[\w-]+\.js$/.test(r.url())) seen.push(r.url());
  });
  return seen;
}

async function tryDemo(page: Page): Promise<void> {
  await page.goto(app.url, { waitUntil: "domcontentloaded" });
  await page.getByRole("button", { name: "Try the demo robot" }).click();
  await page.getByTestId("device-card").waitFor();
}

async function openRunTab(page: Page): Promise<void> {
  await page.getByRole("link", { name: "Motions" }).click();
  await showTab(page, "Run");
}

/** Shows the robot in 3D in the current view and waits for its first picture. */
async function show3d(page: Page): Promise<Locator> {
  const toggle = page.getByTestId("live-robot-toggle");
  await expect.poll(() => toggle.getAttribute("aria-expanded")).toBe("false");
  await expectText(toggle, "Show the robot in 3D");
  await toggle.click();
  const view = page.getByTestId("live-robot-view");
  await page.locator(`[data-testid="live-robot-view"][data-state="ready"]`).waitFor();
  await expect.poll(() => attr(view, "data-frames").then(Number)).toBeGreaterThan(0);
  await expect.poll(() => toggle.getAttribute("aria-expanded")).toBe("true");
  await expectText(toggle, "Hide the robot in 3D");
  return view;
}

/** Records every pose the robot's view draws (its `data-pose` as it is set) into window.__drawnPoses. */
async function recordDrawn(view: Locator): Promise<void> {
  await view.evaluate((el) => {
    const drawn: string[] = [];
    (window as unknown as { __drawnPoses: string[] }).__drawnPoses = drawn;
    new MutationObserver(() => drawn.push(el.getAttribute("data-pose") ?? "")).observe(el, {
      attributes: true,
      attributeFilter: ["data-pose"],
    });
  });
}

/** Records every change of the demo robot's servos into window.__servoPoses, as the 3D view writes them. */
async function recordServos(page: Page): Promise<void> {
  await page.evaluate(() => {
    const log: string[] = [];
    (window as unknown as { __servoPoses: string[] }).__servoPoses = log;
    window.__rbcDemoSim?.onServos((p) => log.push(p.join(" ")));
  });
}

const drawnPoses = (page: Page) =>
  page.evaluate(() => (window as unknown as { __drawnPoses: string[] }).__drawnPoses);
const servoPoses = (page: Page) =>
  page.evaluate(() => (window as unknown as { __servoPoses: string[] }).__servoPoses);

/** Runs built-in motion `n` from the Run tab (the first run asks once) and waits for the robot's reply. */
async function runMotion(page: Page, n: number, name: string, first: boolean): Promise<void> {
  await page.locator(`[data-motion="${n}"]`).click();
  if (first) await page.locator("#confirm-move").click();
  await page.getByTestId("running-motion").filter({ hasText: name }).waitFor();
  await page
    .getByText(new RegExp(`Motion ${n} \\(${name}\\) finished\\.`))
    .first()
    .waitFor({ timeout: 15_000 });
}

/** A page that lets axe in (the panel's CSP rightly refuses inline and foreign scripts), as a11y.test.ts. */
async function newAxePage(): Promise<{ context: BrowserContext; page: Page }> {
  const context = await app.browser.newContext({
    viewport: { width: 1280, height: 800 },
    serviceWorkers: "block",
    reducedMotion: "reduce",
    bypassCSP: true,
  });
  await context.addInitScript({ content: `window.__rbcTestOptions = {};\n;\n${fakeSerial}` });
  return { context, page: await context.newPage() };
}

/** axe's violations, one line each ("rule: help — elements"). */
async function axeViolations(page: Page): Promise<string[]> {
  if (!(await page.evaluate(() => "axe" in window))) await page.addScriptTag({ path: AXE_PATH });
  return page.evaluate(async () => {
    type Result = { id: string; help: string; nodes: { target: unknown[] }[] };
    const axe = (window as unknown as { axe: { run: () => Promise<{ violations: Result[] }> } }).axe;
    const { violations } = await axe.run();
    return violations.map(
      (v) => `${v.id}: ${v.help} — ${v.nodes.map((n) => JSON.stringify(n.target)).join(", ")}`,
    );
  });
}

describe("the robot in 3D, on the demo robot", () => {
  it("loads only when asked in the Run tab, moves through the servos' poses as motion 4 plays, ends at the basic posture", async () => {
    const { page, context } = await app.newPage();
    const seen = watchPage(page, app.origin);
    const requests = sceneRequests(page);
    await tryDemo(page);
    await openRunTab(page);

    // Collapsed: no canvas and no three.js until asked.
    const card = page.getByTestId("live-robot");
    await card.waitFor();
    expect(await card.locator("canvas").count()).toBe(0);
    expect(requests).toEqual([]);

    const view = await show3d(page);
    expect(requests).toHaveLength(1);
    await expectText(page.getByTestId("live-robot-caption"), "Demo robot, live");
    const canvas = view.locator("canvas.robot3d-canvas");
    await expect.poll(() => canvas.getAttribute("role")).toBe("img");
    await expect.poll(() => canvas.getAttribute("aria-label")).toContain("demo robot, live");
    await expect.poll(() => attr(view, "data-pose")).toBe(BASIC);

    // Motion 7 first (the robot accepts nothing else after switching on); the servos stay in the posture.
    await runMotion(page, 7, "Basic posture", true);
    await recordDrawn(view);
    await recordServos(page);
    await runMotion(page, 4, "Walk forward", false);
    // The last change is drawn at the next animation frame.
    await expect.poll(() => attr(view, "data-pose")).toBe(BASIC);

    const servos = await servoPoses(page);
    const drawn = (await drawnPoses(page)).filter((p, i, all) => i === 0 || p !== all[i - 1]);
    // The servos went through many poses (frames about 40 ms apart) and back to the posture.
    expect(servos.length).toBeGreaterThan(10);
    expect(servos.at(-1)).toBe(BASIC);
    // The robot was drawn in several of them while it played, and in nothing it did not take.
    const moving = drawn.filter((p) => p !== BASIC);
    expect(new Set(moving).size).toBeGreaterThanOrEqual(3);
    for (const pose of drawn) expect([BASIC, ...servos]).toContain(pose);
    expect(drawn.at(-1)).toBe(BASIC);

    // The choice is kept for the connection: another tab and back, still shown.
    await showTab(page, "Sounds");
    await expect.poll(() => page.getByTestId("live-robot").count()).toBe(0);
    await showTab(page, "Run");
    await page.locator(`[data-testid="live-robot-view"][data-state="ready"]`).waitFor();
    await expect.poll(() => page.getByTestId("live-robot-toggle").getAttribute("aria-expanded")).toBe("true");

    // Hidden again on request: the picture and its WebGL context go.
    await page.getByTestId("live-robot-toggle").click();
    await page.getByTestId("live-robot-view").waitFor({ state: "detached" });
    await expect.poll(() => card.locator("canvas").count()).toBe(0);

    expect(seen.errors).toEqual([]);
    expect(seen.foreignRequests).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("in the Servos view follows a servo moved there; axe finds nothing with the robot shown", async () => {
    const { page, context } = await newAxePage();
    const requests = sceneRequests(page);
    await tryDemo(page);
    await page.getByRole("link", { name: "Servos" }).click();
    await page.getByTestId("servo-card").waitFor();
    await page.getByTestId("live-robot").waitFor();
    expect(requests).toEqual([]);
    expect(await axeViolations(page)).toEqual([]);

    const view = await show3d(page);
    await expectText(page.getByTestId("live-robot-caption"), "Demo robot, live");
    await expect.poll(() => attr(view, "data-pose")).toBe(BASIC);
    expect(await axeViolations(page)).toEqual([]);

    await page.getByRole("button", { name: "I understand: the robot is supported" }).click();
    await page.getByTestId("enter-direct").click();
    await page.getByText("Read all 16 servos.").waitFor();
    // Servo 10 (left shoulder pitch) from 51 to 140: the arm goes forward, and the drawing follows.
    const frames = Number(await attr(view, "data-frames"));
    await page.locator("#servo-10").fill("140");
    await page.locator("#servo-10").press("Enter");
    const moved = POSTURE.map((p, id) => (id === 10 ? 140 : p)).join(" ");
    await expect.poll(() => attr(view, "data-pose")).toBe(moved);
    await expect.poll(() => attr(view, "data-frames").then(Number)).toBeGreaterThan(frames);
    expect((await page.evaluate(() => window.__rbcDemoSim?.servoPositions()))?.[10]).toBe(140);

    // The Run tab has its own card, still collapsed (each view remembers its own choice).
    await openRunTab(page);
    await expect
      .poll(() => page.getByTestId("live-robot-toggle").getAttribute("aria-expanded"))
      .toBe("false");
    await show3d(page);
    expect(await axeViolations(page)).toEqual([]);
    await context.close();
  });
});

describe("the robot in 3D, on a robot on a cable", () => {
  it("shows only the positions the robot reported, with their time, and does not follow a motion", async () => {
    const { page, context } = await app.newPage({ start: CABLE });
    await loadMotions(page, app.url);
    await showTab(page, "Run");
    const view = await show3d(page);
    const caption = page.getByTestId("live-robot-caption");
    // Nothing read yet: the basic posture, and the panel says that is not where the robot is.
    await expectText(caption, "No positions read yet: drawn in the basic posture");
    await expectText(
      page.getByTestId("live-robot-unread"),
      "every joint is drawn at the basic posture, not where the robot is",
      { contains: true },
    );
    await expect.poll(() => attr(view, "data-pose")).toBe(BASIC);
    await expectText(page.getByTestId("live-robot"), "during a motion the robot's servos cannot be read", {
      contains: true,
    });

    // The Servos view reads all 16 and moves servo 3 to 100: the robot's reply is what is drawn.
    await page.getByRole("link", { name: "Servos" }).click();
    await page.getByTestId("servo-card").waitFor();
    await page.getByRole("button", { name: "I understand: the robot is supported" }).click();
    await page.getByTestId("enter-direct").click();
    await page.getByText("Read all 16 servos.").waitFor();
    await page.locator("#servo-3").fill("100");
    await page.locator("#servo-3").press("Enter");
    await page.getByTestId("servo-pos-3").filter({ hasText: "100" }).waitFor();
    const servosView = await show3d(page);
    const read = POSTURE.map((p, id) => (id === 3 ? 100 : p)).join(" ");
    await expect.poll(() => attr(servosView, "data-pose")).toBe(read);
    await expectText(caption, /^Last read positions, \d\d:\d\d:\d\d$/);
    await expect.poll(() => page.getByTestId("live-robot-unread").count()).toBe(0);
    await expect
      .poll(() => servosView.locator("canvas").getAttribute("aria-label"))
      .toMatch(/^3D view of the robot at its last read positions, \d\d:\d\d:\d\d; the servo table/);

    // Motion 7 moves servo 3 back to 88 on the robot, which cannot say so while it plays: the picture keeps
    // the positions read, and says why.
    await openRunTab(page);
    const runView = page.getByTestId("live-robot-view");
    await page.locator(`[data-testid="live-robot-view"][data-state="ready"]`).waitFor();
    await expect.poll(() => attr(runView, "data-pose")).toBe(read);
    await page.locator('[data-motion="7"]').click();
    await page.locator("#confirm-move").click();
    const during = page.getByTestId("live-robot-motion");
    await during.waitFor();
    await expectText(during, "its servos cannot be read", { contains: true });
    await page.getByText("Motion 7 (Basic posture) finished.").first().waitFor({ timeout: 15_000 });
    expect((await page.evaluate(() => window.__rbcTest?.sim.servos.map((s) => s.position)))?.[3]).toBe(88);
    await expect.poll(() => attr(runView, "data-pose")).toBe(read);
    await during.waitFor({ state: "detached" });
    await expectText(caption, /^Last read positions, \d\d:\d\d:\d\d$/);
    await context.close();
  });
});
