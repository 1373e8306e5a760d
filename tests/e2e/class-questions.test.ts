import type { Locator, Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { expectText, squash, useApp } from "./harness.ts";
import { exampleText, rbmFile } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

/**
 * The Class view asks what one robot is asked (issue 33 item 2): "Run on all" and "Upload to N robots" ask once
 * for the class, in the Motions view's words (the robot will move; Basic posture first; the reset forgets every
 * earlier download), naming the robots and what the reset erases, before any byte goes to any robot. Cancel and
 * Escape (inside the question) send nothing; the page's Stop closes an open question and stops a class run. The
 * Motions view's own question takes Escape the same way.
 * English and Korean on one page (the language switch).
 */

const app = useApp();

/** Each class demo robot's simulator and port, as the test sees them (as class-view.test.ts reads them). */
const robots = (page: Page) =>
  page.evaluate(() => {
    const demos =
      (
        window as unknown as {
          __rbcClassDemos?: {
            sim: { motions: unknown[]; playingMotion?: number };
            port: { stats: { bytesFromPc: number } };
          }[];
        }
      ).__rbcClassDemos ?? [];
    return demos.map((d) => ({
      sent: d.port.stats.bytesFromPc,
      playing: d.sim.playingMotion,
      motions: d.sim.motions.length,
    }));
  });

const rows = (page: Page) => page.getByTestId("class-robot");
const row = (page: Page, i: number): Locator => rows(page).nth(i);
const question = (page: Page) => page.getByTestId("class-question");
const focusedId = (page: Page) => page.evaluate(() => document.activeElement?.id ?? "");
const switchLanguage = (page: Page, to: "en" | "ko") => page.getByTestId("language-switch").selectOption(to);

/** The question's words, squashed. */
const asked = async (page: Page) => squash(await question(page).textContent());

const MOVE = "The robot will move. Hold it or give it room.";
const POSTURE = "After switching on, the robot only accepts Basic posture (7). Run it first.";
const RESET = "The motion memory is reset first: every motion uploaded before is forgotten.";
const MOVE_KO = "로봇이 움직여요. 로봇을 잡거나 주변에 공간을 비워 주세요.";
const POSTURE_KO = "로봇을 켠 뒤에는 기본 자세(7)만 받아들여요. 먼저 기본 자세를 실행해 주세요.";
const RESET_KO = "먼저 모션 메모리를 초기화해요: 전에 업로드한 모션은 모두 지워져요.";

describe("the Class view asks before the robots move or their memory is erased", () => {
  it("Run on all and Upload ask once, naming the robots; Cancel and Escape send nothing; Stop wins", async () => {
    const { page, context } = await app.newPage();
    await page.goto(`${app.url}#/class`, { waitUntil: "domcontentloaded" });
    await page.getByRole("heading", { level: 1, name: "Class: several robots at once" }).waitFor();
    for (let i = 0; i < 2; i++)
      await page.getByRole("button", { name: "Add demo robot", exact: true }).click();
    await expect.poll(() => rows(page).count()).toBe(2);
    for (let i = 0; i < 2; i++) {
      await row(page, i).getByTestId("class-phase").filter({ hasText: "Connected" }).waitFor();
      await row(page, i)
        .getByText(/bytes free/)
        .waitFor();
    }
    await page.getByTestId("class-rbm-input").setInputFiles([rbmFile("wave.rbm", exampleText("wave.rbm"))]);
    await page.getByText("Checked: the pack takes", { exact: false }).waitFor();
    const before = await robots(page);

    // Run on all (motion 1) asks first, focused, naming both robots, with the Motions view's warnings: the
    // robots have not run Basic posture on this connection.
    const run = page.getByRole("button", { name: "Run on all 2 robots" });
    await page.getByLabel("Motion", { exact: true }).selectOption("1");
    await run.click();
    await question(page).waitFor();
    await expect.poll(() => focusedId(page)).toBe("class-cancel-question");
    expect(await question(page).getAttribute("role")).toBe("alertdialog");
    const words = await asked(page);
    expect(words).toContain("on 2 robots: Demo robot 1 and Demo robot 2?");
    expect(words).toMatch(/^Run motion 1 \(.+\) on 2 robots/);
    expect(words).toContain(MOVE);
    expect(words).toContain(POSTURE);
    expect(words).toContain("2 robots have not run it on this connection: Demo robot 1 and Demo robot 2.");
    expect(words).toContain("Stop (Esc)");
    expect(await robots(page)).toEqual(before);

    // Escape inside the question cancels it: nothing is sent, and it is not the page's Stop either.
    await page.keyboard.press("Escape");
    await expect.poll(() => question(page).count()).toBe(0);
    await expect.poll(() => focusedId(page)).toBe("class-run");
    expect(await page.getByTestId("robot-stop").count()).toBe(0);
    expect(await robots(page)).toEqual(before);

    // Cancel: nothing is sent either.
    await run.click();
    await question(page).waitFor();
    await page.getByRole("button", { name: "Cancel", exact: true }).click();
    await expect.poll(() => question(page).count()).toBe(0);
    expect(await robots(page)).toEqual(before);

    // Upload asks first, naming the robots and what the reset erases; Cancel stores and sends nothing.
    await page.getByRole("button", { name: "Upload to 2 robots" }).click();
    await question(page).waitFor();
    await expect.poll(() => focusedId(page)).toBe("class-cancel-question");
    const upload = await asked(page);
    expect(upload).toContain("Upload the pack to 2 robots: Demo robot 1 and Demo robot 2?");
    expect(upload).toContain(RESET);
    expect(upload).toContain("In motion memory now: Demo robot 1, nothing; Demo robot 2, nothing.");
    await page.getByRole("button", { name: "Cancel", exact: true }).click();
    await expect.poll(() => question(page).count()).toBe(0);
    expect(await robots(page)).toEqual(before);

    // In Korean: the same questions in Korean words, no English left.
    await switchLanguage(page, "ko");
    await page.getByRole("button", { name: "로봇 2대에서 실행" }).click();
    await question(page).waitFor();
    const runKo = await asked(page);
    expect(runKo).toMatch(/^로봇 2대\(데모 로봇 1.*데모 로봇 2\)에서 모션 1번\(.+\)을 실행할까요\?/);
    expect(runKo).toContain(MOVE_KO);
    expect(runKo).toContain(POSTURE_KO);
    expect(runKo).toContain("이번 연결에서 기본 자세를 실행하지 않은 로봇 2대:");
    expect(runKo).not.toMatch(/\b(the|robots?|motion|run|will|hold|posture|demo)\b/i);
    // On a phone the question fits the screen: nothing sticks out of it or of the page.
    await page.setViewportSize({ width: 390, height: 844 });
    await question(page).scrollIntoViewIfNeeded();
    const fits = () =>
      question(page).evaluate((q) => {
        const box = q.getBoundingClientRect();
        const inside = [...q.querySelectorAll("*")].every(
          (e) => e.getBoundingClientRect().right <= box.right + 1,
        );
        return box.left >= 0 && box.right <= 390 && inside && document.documentElement.scrollWidth <= 390;
      });
    await expect.poll(fits).toBe(true);
    if (process.env.CLASS_Q_SHOTS) await page.screenshot({ path: "/tmp/class-q-phone.png", fullPage: false });
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.getByRole("button", { name: "취소", exact: true }).click();
    await expect.poll(() => question(page).count()).toBe(0);
    await page.getByRole("button", { name: "로봇 2대에 업로드" }).click();
    await question(page).waitFor();
    const uploadKo = await asked(page);
    expect(uploadKo).toMatch(/^로봇 2대\(데모 로봇 1.*데모 로봇 2\)에 묶음을 업로드할까요\?/);
    expect(uploadKo).toContain(RESET_KO);
    expect(uploadKo).toContain("지금 모션 메모리에 있는 것: 데모 로봇 1, 없음; 데모 로봇 2, 없음.");
    expect(uploadKo).not.toMatch(/\b(the|robots?|motion|upload|memory|reset|nothing|demo)\b/i);
    await page.keyboard.press("Escape");
    await expect.poll(() => question(page).count()).toBe(0);
    expect(await robots(page)).toEqual(before);
    await switchLanguage(page, "en");

    // Basic posture (7) asks too, without the Basic-posture warning; confirmed, both robots run it.
    await page.getByLabel("Motion", { exact: true }).selectOption("7");
    await run.click();
    await question(page).waitFor();
    expect(await question(page).getByTestId("class-posture-warning").count()).toBe(0);
    expect(await asked(page)).toContain(MOVE);
    await page.getByTestId("class-confirm").click();
    for (let i = 0; i < 2; i++)
      await row(page, i)
        .getByTestId("class-result")
        .filter({ hasText: "Motion 7 played" })
        .waitFor({ timeout: 20_000 });

    // Now both ran Basic posture: motion 2's question has no posture warning. The page's Stop, pressed while
    // the question is open, closes it: no Run follows.
    await page.getByLabel("Motion", { exact: true }).selectOption("2");
    await run.click();
    await question(page).waitFor();
    expect(await question(page).getByTestId("class-posture-warning").count()).toBe(0);
    const stop = page.getByRole("button", { name: "Stop", exact: true });
    await stop.click();
    await expect.poll(() => question(page).count()).toBe(0);
    await expect.poll(() => page.getByTestId("robot-stop").count()).toBe(2);
    expect((await robots(page)).map((r) => r.playing)).toEqual([undefined, undefined]);

    // Confirmed, motion 2 plays on both; the page's Stop still stops the class run.
    await run.click();
    await page.getByTestId("class-confirm").click();
    await expect.poll(async () => (await robots(page)).map((r) => r.playing)).toEqual([2, 2]);
    await stop.click();
    await expect
      .poll(async () => (await robots(page)).map((r) => r.playing), { timeout: 20_000 })
      .toEqual([undefined, undefined]);

    // Confirmed, the upload stores the pack; asked again, the question names what is now in each memory.
    await page.getByRole("button", { name: "Upload to 2 robots" }).click();
    await page.getByTestId("class-confirm").click();
    await page
      .getByTestId("class-summary")
      .filter({ hasText: "Pack upload finished" })
      .waitFor({ timeout: 30_000 });
    expect((await robots(page)).map((r) => r.motions)).toEqual([1, 1]);
    await page.getByRole("button", { name: "Upload to 2 robots" }).click();
    await expectText(
      question(page),
      "In motion memory now: Demo robot 1, 640 bytes; Demo robot 2, 640 bytes.",
      { contains: true },
    );
    const stored = await robots(page);
    await page.getByRole("button", { name: "Cancel", exact: true }).click();
    await expect.poll(() => question(page).count()).toBe(0);
    expect(await robots(page)).toEqual(stored);

    // The Motions view's own question takes Escape the same way: it cancels, nothing runs.
    await page.getByRole("link", { name: "Robot", exact: true }).click();
    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await page.getByRole("link", { name: "Motions", exact: true }).click();
    await page.getByRole("tab", { name: "Run" }).click();
    await page.locator('[data-motion="7"]').click();
    await page.getByTestId("move-confirm").waitFor();
    await expect.poll(() => focusedId(page)).toBe("confirm-move");
    await page.keyboard.press("Escape");
    await expect.poll(() => page.getByTestId("move-confirm").count()).toBe(0);
    expect(await page.getByTestId("running-motion").count()).toBe(0);
    await context.close();
  });
});
