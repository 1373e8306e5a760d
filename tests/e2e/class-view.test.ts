import { createRequire } from "node:module";
import type { BrowserContext, Locator, Page } from "playwright-core";
import { beforeAll, describe, expect, it } from "vitest";
import { buildOnce, expectText, squash, useApp } from "./harness.ts";
import { exampleText, rbmFile } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

/**
 * The Class view (issue 24): four demo robots, each its own simulator with its own serial number, on the fake
 * port's paced virtual clock (the class demo robots run on `__rbcTest.clock` as the page's demo robot does).
 * Names, one pack uploaded to all with one cable pulled mid-upload, Run on all with the skew shown, Stop all,
 * Limp all asking once; the Korean words; axe on the view.
 */

const require = createRequire(import.meta.url);
const AXE_PATH = require.resolve("axe-core/axe.min.js");

const app = useApp();
let fakeSerial: string;

beforeAll(async () => {
  ({ fakeSerial } = await buildOnce());
});

/** A page with the fake serial port at 4× robot time, its CSP bypassed so that axe can be added. */
async function classPage(locale: string): Promise<{ context: BrowserContext; page: Page }> {
  const context = await app.browser.newContext({
    viewport: { width: 1280, height: 800 },
    serviceWorkers: "block",
    reducedMotion: "reduce",
    locale,
    bypassCSP: true,
  });
  await context.addInitScript({ content: `window.__rbcTestOptions = { timeScale: 4 };\n;\n${fakeSerial}` });
  const page = await context.newPage();
  await page.goto(`${app.url}#/class`, { waitUntil: "domcontentloaded" });
  return { context, page };
}

async function axeViolations(page: Page): Promise<string[]> {
  await page.addScriptTag({ path: AXE_PATH });
  return page.evaluate(async () => {
    type Result = { violations: { id: string; help: string; nodes: { target: unknown[] }[] }[] };
    const axe = (window as unknown as { axe: { run: () => Promise<Result> } }).axe;
    const result = await axe.run();
    return result.violations.map(
      (v) => `${v.id}: ${v.help} — ${JSON.stringify(v.nodes.map((n) => n.target))}`,
    );
  });
}

/** The class demo robots' simulators, as the test sees them. */
const sims = (page: Page) =>
  page.evaluate(() => {
    const demos =
      (
        window as unknown as {
          __rbcClassDemos?: {
            sim: { motions: unknown[]; playingMotion?: number; servos: { passive: boolean }[] };
          }[];
        }
      ).__rbcClassDemos ?? [];
    return demos.map((d) => ({
      motions: d.sim.motions.length,
      playing: d.sim.playingMotion,
      passive: d.sim.servos.slice(0, 16).filter((s) => s.passive).length,
    }));
  });

const rows = (page: Page) => page.getByTestId("class-robot");
const row = (page: Page, i: number): Locator => rows(page).nth(i);

/** Run on all and Upload ask once for the class first (issue 33 item 2): the answer that goes ahead. */
const confirm = (page: Page) => page.getByTestId("class-confirm").click();

async function addDemos(page: Page, count: number, label = "Add demo robot", connected = "Connected") {
  for (let i = 0; i < count; i++) await page.getByRole("button", { name: label, exact: true }).click();
  await expect.poll(() => rows(page).count()).toBe(count);
  for (let i = 0; i < count; i++)
    await row(page, i).getByTestId("class-phase").filter({ hasText: connected }).waitFor();
}

describe("the Class view with four demo robots", () => {
  it("names robots, uploads a pack to all (one cable pulled mid-upload), runs on all, stops all", async () => {
    const { page, context } = await classPage("en-US");
    await page.getByRole("heading", { level: 1, name: "Class: several robots at once" }).waitFor();
    await addDemos(page, 4);
    await expect
      .poll(async () => (await rows(page).locator("dd.mono").allTextContents()).map(squash))
      .toEqual(["DEMO-00000001", "DEMO-00000002", "DEMO-00000003", "DEMO-00000004"]);
    // The session's robot is untouched: the top bar still says no robot is connected.
    await expectText(page.getByTestId("connection-status"), "Not connected");

    // A name, kept by serial number.
    await row(page, 0).getByRole("button", { name: /^Name/ }).click();
    const field = page.getByLabel("Name of the robot with serial number DEMO-00000001");
    await field.fill("Mina's robot");
    await field.press("Enter");
    await row(page, 0).getByTestId("class-robot-name").filter({ hasText: "Mina's robot" }).waitFor();

    // The pack: two example motions, checked once.
    await page
      .getByTestId("class-rbm-input")
      .setInputFiles([
        rbmFile("wave.rbm", exampleText("wave.rbm")),
        rbmFile("bow.rbm", exampleText("bow.rbm")),
      ]);
    await page.getByText("Checked: the pack takes", { exact: false }).waitFor();

    // Robot 3's cable comes out 400 bytes into the upload (inside wave.rbm's 624-byte image).
    await page.evaluate(() => {
      const demos = (
        window as unknown as {
          __rbcClassDemos: {
            port: { faults: { disconnectAtPcBytes?: number }; stats: { bytesFromPc: number } };
          }[];
        }
      ).__rbcClassDemos;
      const port = demos[2]!.port;
      port.faults.disconnectAtPcBytes = port.stats.bytesFromPc + 400;
    });
    // While the robots upload, closing or reloading the page asks first ("Leave site?"); afterwards it does not.
    const leaveAsks = () =>
      page.evaluate(() => {
        const e = new Event("beforeunload", { cancelable: true });
        window.dispatchEvent(e);
        return e.defaultPrevented;
      });
    expect(await leaveAsks()).toBe(false);
    await page.getByRole("button", { name: "Upload to 4 robots" }).click();
    await confirm(page);
    await expect.poll(leaveAsks, { interval: 5 }).toBe(true);
    const summary = page.getByTestId("class-summary");
    await summary.filter({ hasText: "Pack upload finished" }).waitFor({ timeout: 30_000 });
    await expect.poll(leaveAsks).toBe(false);
    await expectText(summary, "Pack upload finished on 4 robots: 3 stored, 0 partly stored, 1 not stored.");
    for (const i of [0, 1, 3]) {
      await expectText(
        row(page, i).getByTestId("class-result"),
        /^Stored and verified: all 2 motions are on the robot: 12 \(wave\.rbm\), 13 \(bow\.rbm\)\. The robot reports [\d,]+ of 24,576 bytes of motion memory free\.$/,
      );
    }
    await expectText(row(page, 2).getByTestId("class-phase"), "Connection lost", { contains: true });
    await expectText(
      row(page, 2).getByTestId("class-result"),
      /^Not stored\. .*wave\.rbm: The connection was lost during the upload/,
    );
    expect((await sims(page)).map((s) => s.motions)).toEqual([2, 2, 0, 2]);

    // Run on all: Basic posture first (the RBC ignores other motions until 7 has run), then the pack's motion 12.
    await page.getByLabel("Motion", { exact: true }).selectOption("7");
    await page.getByRole("button", { name: "Run on all 3 robots" }).click();
    await confirm(page);
    const skew = page.getByTestId("class-skew");
    await skew.filter({ hasText: "Motion 7 was sent to 3 robots" }).waitFor({ timeout: 20_000 });
    for (const i of [0, 1, 3]) {
      await row(page, i).getByTestId("class-result").filter({ hasText: "Motion 7 played" }).waitFor();
    }
    await expectText(skew, /within [\d.]+ ms/);
    const shown = /within ([\d.]+) ms/.exec(squash(await skew.textContent()));
    expect(Number(shown?.[1])).toBeGreaterThanOrEqual(0);

    await page.getByLabel("Motion", { exact: true }).selectOption("12");
    await page.getByRole("button", { name: "Run on all 3 robots" }).click();
    await confirm(page);
    await expect.poll(async () => (await sims(page)).map((s) => s.playing)).toEqual([12, 12, undefined, 12]);
    await page.getByRole("button", { name: "Stop all" }).click();
    for (const i of [0, 1, 3]) {
      await row(page, i)
        .getByTestId("class-result")
        .filter({ hasText: "Stopped by Stop" })
        .waitFor({ timeout: 20_000 });
    }
    const after = await sims(page);
    expect(after.map((s) => s.playing)).toEqual([undefined, undefined, undefined, undefined]);
    // Stop leaves the servos holding: no servo was made passive.
    expect(after.map((s) => s.passive)).toEqual([0, 0, 0, 0]);

    // Limp all asks once, naming how many robots will fall; Cancel changes nothing.
    await page.getByRole("button", { name: "Limp all…" }).click();
    const question = page.getByRole("alertdialog");
    await expectText(question, "3 robots will fall unless someone holds each one.", { contains: true });
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe("class-cancel-question");
    await page.getByRole("button", { name: "Cancel", exact: true }).click();
    expect((await sims(page)).map((s) => s.passive)).toEqual([0, 0, 0, 0]);

    // With a robot connected in the top bar too, the top bar's Stop also stops every class robot (and the
    // session's robot stays the session's: the class robots are not it).
    await page.getByRole("link", { name: "Robot", exact: true }).click();
    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await page.getByRole("link", { name: "Class", exact: true }).click();
    await page.getByRole("button", { name: "Run on all 3 robots" }).click();
    await confirm(page);
    await expect.poll(async () => (await sims(page)).map((s) => s.playing)).toEqual([12, 12, undefined, 12]);
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    for (const i of [0, 1, 3]) {
      await row(page, i)
        .getByTestId("class-result")
        .filter({ hasText: "Stopped by Stop" })
        .waitFor({ timeout: 20_000 });
    }
    expect((await sims(page)).map((s) => s.playing)).toEqual([undefined, undefined, undefined, undefined]);

    expect(await axeViolations(page)).toEqual([]);

    // The name comes back with the robot (by its serial number) on the next visit.
    await page.reload({ waitUntil: "domcontentloaded" });
    await addDemos(page, 1);
    await row(page, 0).getByTestId("class-robot-name").filter({ hasText: "Mina's robot" }).waitFor();
    await context.close();
  });
});

describe("the Class view in Korean", () => {
  it("says everything in Korean, with the device's outcomes from the one catalogue", async () => {
    const { page, context } = await classPage("ko-KR");
    await page.getByRole("heading", { level: 1, name: "교실: 여러 로봇 한꺼번에" }).waitFor();
    await addDemos(page, 2, "데모 로봇 추가", "연결됨");
    await page.getByTestId("class-rbm-input").setInputFiles([rbmFile("wave.rbm", exampleText("wave.rbm"))]);
    await page.getByText("검사했어요", { exact: false }).waitFor();
    await page.getByRole("button", { name: "로봇 2대에 업로드" }).click();
    await confirm(page);
    await page.getByTestId("class-summary").filter({ hasText: "저장 2대" }).waitFor({ timeout: 30_000 });
    for (const i of [0, 1]) {
      await expectText(
        row(page, i).getByTestId("class-result"),
        /^저장하고 확인했어요\. 모션 1개가 모두 로봇에 있어요: 12 \(wave\.rbm\)\. 로봇이 알려 준 모션 메모리: 24,576바이트 중 [\d,]+바이트 남음\.$/,
      );
    }
    // Run on all in Korean, then Escape (nothing focused, no robot in the top bar) stops every class robot.
    await page.getByRole("button", { name: "로봇 2대에서 실행" }).click();
    await confirm(page);
    for (const i of [0, 1]) {
      await row(page, i)
        .getByTestId("class-result")
        .filter({ hasText: "모션 7번을 재생했어요" })
        .waitFor({ timeout: 20_000 });
    }
    await page.getByLabel("모션", { exact: true }).selectOption("12");
    await page.getByRole("button", { name: "로봇 2대에서 실행" }).click();
    await confirm(page);
    await expect.poll(async () => (await sims(page)).map((s) => s.playing)).toEqual([12, 12]);
    await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
    await page.keyboard.press("Escape");
    for (const i of [0, 1]) {
      await row(page, i)
        .getByTestId("class-result")
        // The catalogue says the Stop in Korean as in English ("Stopped by Stop: motion 12 ended …").
        .filter({ hasText: "정지로 멈췄어요. 모션 12번은 장면이 끝나는 곳에서 끝났고" })
        .waitFor({ timeout: 20_000 });
    }
    const after = await sims(page);
    expect(after.map((s) => [s.playing, s.passive])).toEqual([
      [undefined, 0],
      [undefined, 0],
    ]);
    expect(await axeViolations(page)).toEqual([]);
    await context.close();
  });
});

describe("the Class view's demo robots keep their memory", () => {
  it("a pack stored on demo robot 1 is still on it after a page reload, as a real robot's EEPROM keeps it", async () => {
    const { page, context } = await classPage("en-US");
    await addDemos(page, 1);
    const free = () =>
      row(page, 0)
        .getByText(/bytes free/)
        .textContent();
    await expect.poll(async () => squash(await free())).toBe("24,576 of 24,576 bytes free");
    await page.getByTestId("class-rbm-input").setInputFiles([rbmFile("wave.rbm", exampleText("wave.rbm"))]);
    await page.getByText("Checked: the pack takes", { exact: false }).waitFor();
    await page.getByRole("button", { name: "Upload to 1 robot" }).click();
    await confirm(page);
    await page.getByTestId("class-summary").filter({ hasText: "Pack upload finished" }).waitFor();
    await expect.poll(async () => squash(await free())).toBe("23,936 of 24,576 bytes free");

    // The robot saves its memory a moment after it changed (the page counts the saves for tests); then the page
    // reloads and demo robot 1 comes back as the same robot.
    await expect
      .poll(() => page.evaluate(() => (window as { __rbcDemoSaves?: number }).__rbcDemoSaves ?? 0))
      .toBeGreaterThan(0);
    await page.reload({ waitUntil: "domcontentloaded" });
    await addDemos(page, 1);
    await expectText(row(page, 0).locator("dd.mono").first(), "DEMO-00000001");
    await expect.poll(async () => squash(await free())).toBe("23,936 of 24,576 bytes free");
    expect((await sims(page))[0]?.motions).toBe(1);
    await context.close();
  });
});
