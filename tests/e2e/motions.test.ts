import type { Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { memoryFootprint } from "../../src/protocol/catalog.ts";
import { motionImage } from "../../src/protocol/motion-image.ts";
import { motionDurationMs, parseRbm } from "../../src/protocol/rbm.ts";
import { formatSeconds } from "../../src/ui/features/motions/plot-data.ts";
import {
  type AppHarness,
  cspViolations,
  FAST,
  openMotions,
  robotTime,
  squash,
  startHarness,
  watchPage,
} from "./harness.ts";
import {
  exampleText,
  imageHex,
  longMotion,
  rbmFile,
  showTab,
  withSerial,
  withShortFrames,
} from "./motion-fixtures.ts";
import type { RbcTestOptions } from "./rbc-test-globals.ts";
import "./rbc-test-globals.ts";

let app: AppHarness;

beforeAll(async () => {
  app = await startHarness();
});

afterAll(async () => {
  await app?.close();
});

/** A paced link (115200 baud, 16 ms FTDI latency), so uploads take as long as on the wire. */
const PACED: RbcTestOptions = { baudPacing: true, latencyMs: 16 };
/** The simulated robot's time (ms of its clock). */
const _robotNow = (page: Page) => page.evaluate(() => window.__rbcTest?.clock.now() ?? Number.NaN);

const bytesFromPc = (page: Page) => page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? -1);
const simMotionsHex = (page: Page) =>
  page.evaluate(() =>
    (window.__rbcTest?.sim.motions ?? []).map((m) =>
      Array.from(m.bytes, (b) => b.toString(16).padStart(2, "0")).join(""),
    ),
  );

/** Records every text the upload figures show, so a test can see the progress that flashed by. */
async function recordFigures(page: Page): Promise<void> {
  await page.evaluate(() => {
    const seen: string[] = [];
    (window as unknown as { __figures: string[] }).__figures = seen;
    new MutationObserver(() => {
      const el = document.querySelector('[data-testid="upload-figures"]');
      const text = el?.textContent?.replace(/\s+/g, " ").trim();
      if (text && seen.at(-1) !== text) seen.push(text);
    }).observe(document.body, { subtree: true, childList: true, characterData: true });
  });
}

describe("motions view", () => {
  it("checks wave.rbm, uploads it after the experimental notice, and the robot holds the exact image", async () => {
    // The paced link 3 times faster: the progress of its 10 chunks still shows (figures, rate, time left).
    const { page, context } = await app.newPage({ options: { ...PACED, timeScale: 3 } });
    const seen = watchPage(page, app.origin);
    await openMotions(page, app.url);
    const wave = exampleText("wave.rbm");
    await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", wave));
    const card = page.getByTestId("motion-file");
    await card.waitFor();
    const facts = await card.textContent().then(squash);
    expect(facts).toContain("RbcPanel_Wave");
    expect(facts).toMatch(/Scenes\s*6 Servos\s*16/);
    expect(facts).toMatch(/Plays for\s*3\.2 s/);
    expect(facts).toMatch(/Image\s*624 bytes/);
    expect(facts).toMatch(/On the robot\s*640 bytes/);
    // The scene table and the chart (uPlot, loaded on demand).
    await page.getByTestId("scene-section").waitFor();
    expect(await page.locator(".scene-table tbody tr").count()).toBe(6);
    await page.locator('[data-testid="motion-chart"][data-chart="drawn"]').waitFor();
    expect(await page.locator('[data-testid="motion-chart"] canvas').count()).toBeGreaterThan(0);
    expect(await page.locator('[data-testid="motion-chart"] .u-legend').textContent()).toContain("Left knee");

    // A real robot (the fake port is hardware): the panel says it is experimental and asks first.
    const before = await bytesFromPc(page);
    await page.getByTestId("upload-motion").click();
    const confirm = page.getByTestId("upload-confirm");
    await confirm.waitFor();
    const words = await confirm.textContent().then(squash);
    expect(words).toContain("experimental");
    expect(words).toContain("not been verified on real RBC firmware");
    expect(words).toContain("held or lying down");
    expect(await bytesFromPc(page)).toBe(before);

    await recordFigures(page);
    await page.getByRole("button", { name: "Upload (experimental)" }).click();
    // The result shows in the file's card, where the upload was started.
    const result = card.getByText(/^Uploaded wave\.rbm/);
    await result.waitFor({ timeout: 15_000 });
    const text = await result.textContent().then(squash);
    expect(text).toMatch(/624 bytes in 10 chunks/);
    expect(text).toMatch(/bytes\/s/);
    expect(text).toContain("It is downloaded motion 1: run it as motion number 12");
    expect(text).toContain("Free motion memory: 23,936 of 24,576 bytes (was 24,576");
    expect(text).toContain("Error code after the upload: no error");
    expect(text).toContain("held or lying down");
    const figures = await page.evaluate(() => (window as unknown as { __figures: string[] }).__figures);
    expect(figures.some((f) => f.includes("624 of 624 bytes (100%)"))).toBe(true);
    expect(figures.some((f) => /bytes\/s/.test(f) && /left/.test(f))).toBe(true);

    expect(await simMotionsHex(page)).toEqual([imageHex(wave)]);
    // Memory figures refreshed: used and free on the Files tab, the counts on the Memory tab, and the device card.
    expect(await page.getByTestId("mem-motion-used").textContent().then(squash)).toBe("640 bytes used");
    expect(await page.getByTestId("mem-motion-text").textContent().then(squash)).toBe(
      "23,936 of 24,576 bytes free",
    );
    await showTab(page, "Memory");
    expect(await page.getByTestId("mem-motion-used").textContent().then(squash)).toBe(
      "640 of 24,576 bytes used",
    );
    expect(await page.getByTestId("mem-motion-count").textContent().then(squash)).toMatch(/^1 of 20 motions/);
    expect(await page.getByTestId("uploaded-list").textContent().then(squash)).toContain(
      "slot 1 → motion number 12",
    );
    // Run offers it by name and length.
    await showTab(page, "Run");
    const download = page.locator('[data-testid="downloaded-motions"] [data-motion="12"]');
    expect(await download.textContent().then(squash)).toBe("12 RbcPanel_Wave 3.2 s");
    await page.getByRole("link", { name: "Robot" }).click();
    expect(await page.getByTestId("memory-motion-text").textContent().then(squash)).toMatch(
      /640 of 24,576 bytes used|23,936 of 24,576 bytes free/,
    );

    expect(seen.errors).toEqual([]);
    expect(seen.foreignRequests).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("cancels an upload: sending stops, the robot records nothing, and the panel says how much was acknowledged", async () => {
    // The paced link in real time: the 20 KB upload takes seconds, and every acknowledgement keeps its full
    // timeout (500 ms) on a busy machine (at 4 times the speed, a CI machine once missed one by a few ms).
    const { page, context } = await app.newPage({ options: PACED });
    await openMotions(page, app.url);
    const long = longMotion(exampleText("wave.rbm"), 40);
    await page.getByTestId("rbm-files").setInputFiles(rbmFile("Long.rbm", long));
    await page.getByTestId("upload-motion").click();
    await page.getByRole("button", { name: "Upload (experimental)" }).click();
    const midway = page.getByTestId("upload-figures").filter({ hasText: /\((?:[5-9]|[1-9]\d)%\)/ });
    const ended = page.getByRole("status", { name: "Upload result" }).locator(".notice");
    await midway.or(ended).first().waitFor({ timeout: 15_000 });
    // An upload that ended before it could be cancelled says why here, not as a time-out.
    expect(await ended.count().then((n) => (n ? ended.first().textContent() : ""))).toBe("");
    await page.getByRole("button", { name: "Cancel upload" }).click();

    const result = page.getByText(/^Upload cancelled/);
    await result.waitFor({ timeout: 10_000 });
    const text = await result.textContent().then(squash);
    expect(text).toMatch(/Upload cancelled \([\d,]+ of 20,?748 bytes were acknowledged\)/);
    expect(text).toContain("recorded nothing");
    expect(await page.getByTestId("upload-progress").count()).toBe(0);
    // Nothing more goes out, and the robot holds no motion.
    const after = await bytesFromPc(page);
    await robotTime(page, 400);
    expect(await bytesFromPc(page)).toBe(after);
    expect(await simMotionsHex(page)).toEqual([]);
    await context.close();
  });

  it("never sends a byte of a file with errors and says why in words", async () => {
    const { page, context } = await app.newPage({ options: FAST });
    await openMotions(page, app.url);
    const before = await bytesFromPc(page);
    await page
      .getByTestId("rbm-files")
      .setInputFiles(rbmFile("Edited.rbm", withShortFrames(exampleText("wave.rbm"))));
    const card = page.getByTestId("motion-file");
    await card.waitFor();
    const issues = await page.getByTestId("rbm-issues").textContent().then(squash);
    expect(issues).toMatch(
      /Error Scene 0 has frames 10 ms apart \(200 ms \/ 20 frames\); the RBC needs at least 20 ms/,
    );
    // The file is still shown, so the person can see which scene is wrong.
    expect(await page.getByTestId("scene-section").isVisible()).toBe(true);
    const upload = page.getByTestId("upload-motion");
    expect(await upload.isDisabled()).toBe(true);
    expect(await page.getByTestId("upload-why").textContent().then(squash)).toBe(
      "Cannot upload: the file has 1 error (listed above). Nothing is sent.",
    );
    await upload.click({ force: true }).catch(() => {});
    await robotTime(page, 200);
    expect(await bytesFromPc(page)).toBe(before);
    expect(await simMotionsHex(page)).toEqual([]);
    await context.close();
  });

  it("opens files by drop and by keyboard, and warns about a motion made for another robot", async () => {
    const { page, context } = await app.newPage();
    await openMotions(page, app.url);
    const text = withSerial(exampleText("bow.rbm"), "1234567890123");
    const transfer = await page.evaluateHandle((t) => {
      const dt = new DataTransfer();
      dt.items.add(new File([t], "Other.rbm", { type: "text/plain" }));
      return dt;
    }, text);
    await page.dispatchEvent('[data-testid="rbm-drop"]', "drop", { dataTransfer: transfer });
    const card = page.getByTestId("motion-file");
    await card.waitFor();
    expect(await card.textContent().then(squash)).toContain(
      "made for the robot with serial number 1234567890123, but the connected robot is 8958899989309",
    );
    // Warnings do not block an upload.
    expect(await page.getByTestId("upload-motion").isEnabled()).toBe(true);

    // The drop zone is a button for the keyboard too: Enter and Space open the (multiple) file picker.
    expect(await page.getByTestId("rbm-files").getAttribute("multiple")).not.toBeNull();
    await page.evaluate(() => {
      const w = window as unknown as { __picks: number };
      w.__picks = 0;
      document.getElementById("rbm-input")?.addEventListener("click", (e) => {
        w.__picks++;
        e.preventDefault();
      });
    });
    await page.getByTestId("rbm-drop").focus();
    await page.keyboard.press("Enter");
    await page.keyboard.press("Space");
    await expect.poll(() => page.evaluate(() => (window as unknown as { __picks: number }).__picks)).toBe(2);
    await context.close();
  });

  it("opens one of the project's example motions from the keyboard, exactly like a picked file", async () => {
    const { page, context } = await app.newPage({ options: FAST });
    const seen = watchPage(page, app.origin);
    const scripts: string[] = [];
    page.on("request", (r) => {
      if (r.resourceType() === "script") scripts.push(new URL(r.url()).pathname);
    });
    await openMotions(page, app.url);
    const text = exampleText("squat.rbm");
    const motion = parseRbm(text);
    const image = motionImage(motion);
    // The examples are not loaded until one is opened.
    expect(scripts.some((s) => s.includes("squat"))).toBe(false);

    // A disclosure, then one button per example that says what the motion does.
    const examples = page.getByTestId("examples");
    await examples.locator("summary").focus();
    await page.keyboard.press("Enter");
    const open = page.getByRole("button", { name: "Open squat.rbm" });
    await open.waitFor();
    const description = await open.getAttribute("aria-describedby");
    expect(await page.locator(`#${description}`).textContent().then(squash)).toContain("squats twice");
    await open.focus();
    await page.keyboard.press("Enter");

    const card = page.getByTestId("motion-file");
    await card.waitFor();
    expect(scripts.some((s) => s.includes("squat"))).toBe(true);
    await page.getByText("Opened the example squat.rbm.").waitFor();
    const facts = await card.textContent().then(squash);
    const fact = (label: string, value: string | number) =>
      expect(facts).toContain(`${label}${String(value)}`.replace(/\s+/g, " "));
    expect(facts).toContain(`${motion.name} squat.rbm`);
    fact("Scenes", motion.scenes.length);
    fact("Servos", motion.servos.length);
    fact("Plays for", formatSeconds(motionDurationMs(motion)));
    fact("Image", `${image.length.toLocaleString("en-US")} bytes`);
    fact("On the robot", `${memoryFootprint(image.length).toLocaleString("en-US")} bytes`);
    expect(facts).toContain("Checked: no errors, no warnings.");
    expect(await page.locator(".scene-table tbody tr").count()).toBe(motion.scenes.length);

    // Uploaded like any other file: the robot holds exactly its image.
    await card.getByTestId("upload-motion").click();
    await page.getByRole("button", { name: "Upload (experimental)" }).click();
    await page.getByText(/^Uploaded squat\.rbm/).waitFor();
    expect(await simMotionsHex(page)).toEqual([imageHex(text)]);

    expect(seen.errors).toEqual([]);
    expect(seen.foreignRequests).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("on the demo robot uploads without asking, and a reset first puts the upload into slot 1", async () => {
    // The in-app demo robot on the faster clock too (its simulator and the panel's client share it).
    const { page, context } = await app.newPage({ options: FAST });
    await page.goto(app.url);
    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await page.getByRole("link", { name: "Motions" }).click();
    await page.getByTestId("mem-motion-text").filter({ hasText: "24,576 of 24,576" }).waitFor();
    await page
      .getByTestId("rbm-files")
      .setInputFiles([
        rbmFile("wave.rbm", exampleText("wave.rbm")),
        rbmFile("bow.rbm", exampleText("bow.rbm")),
      ]);
    const cards = page.getByTestId("motion-file");
    await cards.nth(1).waitFor();
    await cards.nth(0).getByTestId("upload-motion").click();
    expect(await page.getByTestId("upload-confirm").count()).toBe(0);
    await page.getByText(/^Uploaded wave\.rbm/).waitFor();
    await cards.nth(1).getByTestId("upload-motion").click();
    await page.getByText(/^Uploaded bow\.rbm/).waitFor();
    await showTab(page, "Memory");
    expect(await page.getByTestId("uploaded-list").textContent().then(squash)).toMatch(
      /RbcPanel_Wave wave\.rbm — slot 1 → motion number 12.*RbcPanel_Bow bow\.rbm — slot 2 → motion number 13/,
    );
    await showTab(page, "Files");
    await page.getByTestId("reset-first").check();
    await cards.nth(1).getByTestId("upload-motion").click();
    const result = page.getByText(/^Uploaded bow\.rbm/);
    await result.filter({ hasText: "Free motion memory: 24,064 of" }).waitFor();
    expect(await page.getByTestId("mem-motion-text").textContent().then(squash)).toBe(
      "24,064 of 24,576 bytes free",
    );
    await showTab(page, "Memory");
    const list = await page.getByTestId("uploaded-list").textContent().then(squash);
    expect(list).toContain("RbcPanel_Bow bow.rbm — slot 1 → motion number 12");
    expect(list).not.toContain("RbcPanel_Wave");

    // An action file goes up byte for byte, with the format called unverified; its result shows beside it.
    expect(await page.getByTestId("action-card").textContent().then(squash)).toContain(
      "No action file format is known: the file's bytes are sent as they are",
    );
    await page.getByTestId("action-file").setInputFiles({
      name: "wave.act",
      mimeType: "application/octet-stream",
      buffer: Buffer.from(Array.from({ length: 100 }, (_, i) => i)),
    });
    await page.getByTestId("upload-action").click();
    await page
      .getByTestId("action-card")
      .getByText(/^Uploaded wave\.act: 100 bytes in 2 chunks/)
      .waitFor();
    expect(await page.getByTestId("mem-action-text").textContent().then(squash)).toBe(
      "8,064 of 8,192 bytes free",
    );
    await context.close();
  });
});
