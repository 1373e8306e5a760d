import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { firmwareHexWithBadChecksum } from "../support/hex.ts";
import { CABLE, loadMotions } from "./connected-page.ts";
import { connectRobot, expectText, FAST, holdRobot, releaseRobot, squash, useApp } from "./harness.ts";
import { axeProblems } from "./i18n-checks.ts";
import { exampleText, rbmFile } from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

// Issue 21 item 6 in Motions and Firmware: a Run result, an upload result and a firmware file problem made in
// English read in Korean after the panel's own language switch, and in English again after the switch back.
// And Motions' Run buttons honour the busy probe: a motion started elsewhere disables them, with the busy
// sentence and Stop beside it; after Stop they are enabled again. The robot runs on the paced virtual clock
// (FAST); nothing is retried.

const app = useApp();

const switchLanguage = (page: Page, to: "en" | "ko") => page.getByTestId("language-switch").selectOption(to);

/** A Motions tab by its id (its name changes with the language). */
const showTab = async (page: Page, tab: "files" | "run") => {
  await page.locator(`#motions-tab-${tab}`).click();
  await page.locator(`#motions-panel-${tab}`).waitFor();
};

describe("Motions and Firmware messages made before a language switch follow it", () => {
  it("a Run result, an upload result and a firmware file problem: Korean after the switch, English after the switch back", {
    timeout: 180_000,
  }, async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    const pageErrors: string[] = [];
    page.on("pageerror", (e) => pageErrors.push(String(e)));
    await loadMotions(page, app.url);

    // A Run result: Basic posture, asked once, then run to its end.
    await showTab(page, "run");
    await page.locator('[data-motion="7"]').click();
    await page.getByRole("button", { name: "Run motion 7 (Basic posture)" }).click();
    const runResult = page.getByTestId("run-place-built-in").locator(".notice p");
    const runEn = "Motion 7 (Basic posture) finished. The robot now accepts every motion.";
    await runResult.filter({ hasText: runEn }).waitFor();

    // An upload result: wave.rbm, after the experimental notice (the fake port is a real robot to the panel).
    await showTab(page, "files");
    await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", exampleText("wave.rbm")));
    await page.getByTestId("upload-motion").click();
    await page.getByRole("button", { name: "Upload (experimental)" }).click();
    const uploadResult = page.getByTestId("motion-file").locator(".upload-in-place .live .notice p");
    await uploadResult
      .filter({ hasText: /^Uploaded wave\.rbm/ })
      // The upload's 10 chunks at the paced link's speed; a loaded machine slows the page, not the robot's clock.
      .waitFor({ timeout: 60_000 })
      .catch(async (e: unknown) => {
        throw new Error(
          `${String(e)}\nupload card: ${squash(await page.getByTestId("motion-file").textContent())}\npage errors: ${pageErrors.join("; ")}`,
        );
      });
    const uploadEn = squash(await uploadResult.textContent());
    expect(uploadEn).toContain("Stored as motion 12 (key 1): Run takes this number.");

    // A firmware file problem: a checksum broken on line 3.
    await page.getByRole("link", { name: "Firmware" }).click();
    await page.getByTestId("fw-file-input").setInputFiles({
      name: "broken.hex",
      mimeType: "text/plain",
      buffer: Buffer.from(firmwareHexWithBadChecksum(3)),
    });
    const problem = page.getByTestId("firmware-view").locator(".notice--danger p").first();
    await problem.filter({ hasText: /broken\.hex is not a firmware file/ }).waitFor();
    const problemEn = squash(await problem.textContent());
    expect(problemEn).toMatch(/Line 3: the checksum is 00/);

    // The switch: each reads in Korean, nothing of it left in English.
    await switchLanguage(page, "ko");
    await page.getByRole("heading", { level: 1, name: "펌웨어" }).waitFor();
    // The English sentence names broken.hex too: wait for the Korean one.
    await expectText(problem, /^"?broken\.hex"?.*[가-힣]/);
    expect(squash(await problem.textContent())).not.toMatch(/not a firmware file|checksum/);

    await page.locator('a[href="#/motions"]').first().click();
    await showTab(page, "run");
    await expectText(runResult, "모션 7번(기본 자세)을 마쳤어요. 이제 로봇이 모든 모션을 받아들여요.");
    await showTab(page, "files");
    await expectText(uploadResult, /^wave\.rbm을\(를\) 업로드했어요\. 624바이트를 조각 10개로 /);
    expect(squash(await uploadResult.textContent())).not.toMatch(
      /Uploaded|Stored as|Free motion memory|Error code/,
    );
    expect(await axeProblems(page)).toEqual([]);

    // And back: the English words as they were made.
    await switchLanguage(page, "en");
    await showTab(page, "run");
    await expectText(runResult, runEn);
    await showTab(page, "files");
    await expectText(uploadResult, uploadEn);
    await page.getByRole("link", { name: "Firmware" }).click();
    await problem.filter({ hasText: /not a firmware file/ }).waitFor();
    await expectText(problem, problemEn);
    expect(pageErrors).toEqual([]);
    await context.close();
  });
});

describe("Motions' Run buttons and a motion started elsewhere", () => {
  it("the busy probe's motion disables Run, with the busy sentence and Stop beside it; after Stop Run is enabled again", async () => {
    const { page, context } = await app.newPage({ options: { ...FAST, variant: { busyMotion: 2 } } });
    await connectRobot(page, app.url);
    await page.getByTestId("busy-banner").waitFor();
    // The robot's time stands still while the test looks (motion 2 plays 6.6 s of it).
    await holdRobot(page);
    await page.getByRole("link", { name: "Motions" }).click();
    await showTab(page, "run");
    const runButtons = page.getByTestId("run-card").locator("[data-motion]");
    await expect.poll(() => runButtons.count()).toBeGreaterThanOrEqual(11);
    const disabled = () => runButtons.evaluateAll((els) => els.map((e) => (e as HTMLButtonElement).disabled));
    await expect.poll(async () => new Set(await disabled())).toEqual(new Set([true]));
    const why = page.getByTestId("busy-why");
    await expectText(
      why.locator("span"),
      "A motion is playing: the robot ignores everything but Basic posture (7) until it ends.",
    );
    const stop = why.getByRole("button", { name: "Stop" });
    await expect.poll(() => stop.isEnabled()).toBe(true);
    expect(await axeProblems(page, { within: "#motions-panel-run" })).toEqual([]);

    await stop.click();
    await releaseRobot(page);
    await page.getByTestId("stop-banner").filter({ hasText: "It took Stop" }).waitFor();
    await page.getByTestId("busy-banner").waitFor({ state: "detached" });
    await why.waitFor({ state: "detached" });
    await expect.poll(async () => new Set(await disabled())).toEqual(new Set([false]));
    await context.close();
  });
});
