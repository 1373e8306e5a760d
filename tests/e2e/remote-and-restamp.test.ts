/**
 * Issue 23 items 3 and 4 in the browser. The Remote card of the Sensors view: the key map of docs/protocol.md
 * §3.1 with what each key plays on this robot (firmware 2.23 with its memory empty, and the "user" build's 9.99),
 * and a simulated IR key press lighting its key while the remote is listened to. "Make this motion usable on this
 * robot": in Motions a copy through the Save dialog and as a download, in the Editor as a download, each compared
 * byte for byte with the file as it should be (only field 2 changed). Then both in Korean at 1280×800 and
 * 390×844, with axe and the layout checks. The robot's time is the paced virtual clock of the fake port.
 */
import { readFile } from "node:fs/promises";
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { CABLE, loadMotions } from "./connected-page.ts";
import { connectRobot, expectText, FAST, useApp } from "./harness.ts";
import { axeProblems, connectCable, expectPageOkAtSizes, newLocalePage, PHONE } from "./i18n-checks.ts";
import "./rbc-test-globals.ts";

const app = useApp();

/** A one-servo motion made for robot 1111122222333, with a Latin-1 byte (0xE9) in field 4 that must survive. */
const LATIN1 =
  "1:13:1111122222333:XXXXXXXXXX:Caf\u00e9XXXXXXXXXXXXXXXX:2:Hi:0:1:1:2:1:4:00:020:030:000:0:125:000:07:Scene_0:10:500:0:00:125:125:2:0:";
const DANCE = Buffer.from(LATIN1, "latin1");
const DANCE_FOR_THIS_ROBOT = Buffer.from(LATIN1.replace("1111122222333", "8958899989309"), "latin1");
const DANCE_ZEROS = Buffer.from(LATIN1.replace("1111122222333", "0000000000000"), "latin1");

/** An ASCII 16-servo motion for the Editor (it reads files as text), made for robot 1111122222333. */
const ZEROS16 = [125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127];
const pad = (n: number, w: number) => String(n).padStart(w, "0");
const EDITOR_FILE = [
  "1:13:1111122222333:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:5:Shrug:0:1:1:2:16:4",
  ...ZEROS16.map((z, id) => `${pad(id, 2)}:020:030:000:0:${pad(z, 3)}`),
  "000:07:Scene_0:25:1000",
  ...ZEROS16.map((z, id) => `0:${pad(id, 2)}:${pad(z, 3)}:${pad(z, 3)}:2:0`),
]
  .join(":")
  .concat(":");

const rbm = (name: string, buffer: Buffer) => ({ name, mimeType: "text/plain", buffer });

/** A Save dialog where the person keeps the suggested name; the bytes written go to window.__saved. */
async function withSavePicker(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const w = window as unknown as { __saved?: number[][]; showSaveFilePicker?: unknown };
    w.__saved = [];
    w.showSaveFilePicker = async ({ suggestedName }: { suggestedName: string }) => ({
      name: suggestedName,
      createWritable: async () => ({
        // A Blob or text (UTF-8): the panel's save paths write either.
        write: async (data: Blob | string) => {
          const blob = typeof data === "string" ? new Blob([data]) : data;
          w.__saved?.push([...new Uint8Array(await blob.arrayBuffer())]);
        },
        close: async () => {},
      }),
    });
  });
}

const saved = (page: Page) =>
  page.evaluate(() => (window as unknown as { __saved?: number[][] }).__saved ?? []);

/** Presses IR key `code` on the fake robot's remote once the panel listens to the remote. */
async function pressKey(page: Page, code: number): Promise<void> {
  await expect
    .poll(() =>
      page.evaluate((c) => {
        const sim = window.__rbcTest?.sim;
        if (sim?.state.sensors.subscription !== 0x19) return false;
        sim.pressRemoteKey(c);
        return true;
      }, code),
    )
    .toBe(true);
}

const tile = (page: Page, code: number) => page.locator(`[data-testid="remote-key"][data-code="${code}"]`);

async function openSensors(page: Page, name = "Sensors"): Promise<void> {
  await page.getByRole("link", { name, exact: true }).click();
  await page.getByTestId("remote-card").waitFor();
}

describe("the Remote card", () => {
  it("shows the key map, what each key plays on this robot, and lights the key a simulated remote press sends", async () => {
    const { page, context } = await app.newPage({ options: FAST });
    await connectRobot(page, app.url);
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    await openSensors(page);
    const card = page.getByTestId("remote-card");
    await expect.poll(() => card.getByTestId("remote-key").count()).toBe(33);
    await expectText(
      card.getByTestId("remote-firmware"),
      "This robot reports firmware 2.23: its number keys play the uploaded motions. On the official “user” firmware (which reports 9.99) key 9 instead starts an endless walk that only switching the robot off ends.",
    );
    // Built-in 4, key 1 (the motion memory reads wholly free), key 9's hazard, and the # keys.
    await expectText(tile(page, 4), "code 4 Walk forward");
    await expectText(tile(page, 12), "1 key 1 · code 12 Nothing stored");
    await expectText(
      tile(page, 20),
      "9 key 9 · code 20 Nothing stored On the official “user” firmware: an endless walk that only switching the robot off ends",
    );
    await expectText(tile(page, 33), "1 * + 1 · code 33 Nothing stored");
    await expectText(
      tile(page, 0x2b),
      "A # + A · code 43 Hazard: Starts battery charging when a charger is connected",
    );
    await expectText(
      tile(page, 0x31),
      "C # + C · code 49 Hazard: Moves every servo to its stored zero (the raw zero pose) at once",
    );
    await expectText(card.getByTestId("remote-listen"), "Choose IR remote under Events", { contains: true });
    expect(await card.locator(".is-lit").count()).toBe(0);

    await page.getByRole("radio", { name: "IR remote" }).check();
    await card.getByTestId("remote-listen").filter({ hasText: "the key you press lights up" }).waitFor();
    await expectText(card.getByTestId("remote-last"), "No key pressed yet.");
    await pressKey(page, 4);
    await tile(page, 4).and(page.locator(".is-lit")).waitFor();
    await expect.poll(() => tile(page, 4).getAttribute("aria-current")).toBe("true");
    await expectText(
      card.getByTestId("remote-last"),
      /^Last key: Walk forward \(code 4\), at \d\d:\d\d:\d\d\.$/,
    );
    await pressKey(page, 13);
    await tile(page, 13).and(page.locator(".is-lit")).waitFor();
    await expect.poll(() => card.locator(".is-lit").count()).toBe(1);
    await expect.poll(() => tile(page, 4).getAttribute("aria-current")).toBeNull();
    await expectText(card.getByTestId("remote-last"), /^Last key: key 2 \(code 13\), at /);
    expect(await axeProblems(page, { within: '[data-testid="remote-card"]' })).toEqual([]);

    // Listening stops: no key is lit any more.
    await page.getByRole("radio", { name: "Nothing" }).check();
    await card.getByTestId("remote-listen").filter({ hasText: "Choose IR remote" }).waitFor();
    await expect.poll(() => card.locator(".is-lit").count()).toBe(0);
    await context.close();
  });

  it("on firmware 9.99 (the official user build): keys 1-8 play nothing, 0 the demo in flash, 9 the endless walk", async () => {
    const { page, context } = await app.newPage({
      options: { ...FAST, variant: { firmware: { major: 9, minor: 99 }, userFirmware: true } },
    });
    await connectRobot(page, app.url);
    await openSensors(page);
    await expectText(
      page.getByTestId("remote-firmware"),
      "This robot reports firmware 9.99, as the official “user” firmware (and a homebrew port of it) does",
      { contains: true },
    );
    await expectText(tile(page, 12), "1 key 1 · code 12 Nothing on this firmware (it plays no uploads)");
    await expectText(
      tile(page, 20),
      "9 key 9 · code 20 Hazard: An endless walk: only switching the robot off ends it",
    );
    await expectText(tile(page, 21), "0 key 0 · code 21 A demo motion kept in the firmware");
    await context.close();
  });
});

describe("Make this motion usable on this robot", () => {
  it("Motions: a copy with this robot's serial through the Save dialog, and with zeros as a download, byte for byte", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await withSavePicker(page);
    await loadMotions(page, app.url);
    await page.getByTestId("rbm-files").setInputFiles(rbm("dance.rbm", DANCE));
    const file = page.getByTestId("motion-file");
    const offer = file.getByTestId("restamp-offer");
    await offer.waitFor();
    await expectText(
      offer.locator("p"),
      "This motion was made for the robot with serial number 1111122222333; this robot is 8958899989309. Motionbuilder refuses such a file. The copy differs from the file only in its serial number (field 2); the motion is the same.",
    );
    await file.getByRole("button", { name: "Make this motion usable on this robot" }).click();
    await file
      .locator(".notice--ok")
      .filter({
        hasText:
          "Saved dance-8958899989309.rbm. Only the serial number (field 2) changed, from 1111122222333 to 8958899989309; every other byte of the file is as it was.",
      })
      .waitFor();
    expect(await saved(page)).toEqual([[...DANCE_FOR_THIS_ROBOT]]);

    // Without a Save dialog the copy is offered as a download, and said so.
    await page.evaluate(() => Reflect.deleteProperty(window, "showSaveFilePicker"));
    const downloading = page.waitForEvent("download");
    await file.getByRole("button", { name: "Save a copy with zeros" }).click();
    const download = await downloading;
    expect(download.suggestedFilename()).toBe("dance-zeros.rbm");
    expect([...(await readFile(await download.path()))]).toEqual([...DANCE_ZEROS]);
    await file
      .locator(".notice--ok")
      .filter({ hasText: "dance-zeros.rbm offered as a download: the browser decides where it goes" })
      .waitFor();
    expect(await axeProblems(page, { within: '[data-testid="motion-file"]' })).toEqual([]);
    await context.close();
  });

  it("Motions: a file with zeros or this robot's serial gets no offer", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await loadMotions(page, app.url);
    await page
      .getByTestId("rbm-files")
      .setInputFiles([rbm("zeros.rbm", DANCE_ZEROS), rbm("mine.rbm", DANCE_FOR_THIS_ROBOT)]);
    await expect.poll(() => page.getByTestId("motion-file").count()).toBe(2);
    expect(await page.getByTestId("restamp-offer").count()).toBe(0);
    await context.close();
  });

  it("Editor: the opened motion saved with zeros in field 2, nothing else changed", async () => {
    const { page, context } = await app.newPage({ options: FAST });
    await withSavePicker(page);
    await connectRobot(page, app.url);
    await page.getByRole("link", { name: "Editor", exact: true }).click();
    await page.getByTestId("editor").waitFor();
    await page.getByTestId("editor-file").setInputFiles(rbm("shrug.rbm", Buffer.from(EDITOR_FILE, "ascii")));
    const toolbar = page.getByTestId("editor-toolbar");
    await toolbar.getByTestId("restamp-offer").waitFor();
    await toolbar.getByRole("button", { name: "Save a copy with zeros" }).click();
    await toolbar
      .locator(".notice--ok")
      .filter({ hasText: "Saved Shrug-zeros.rbm. Only the serial number (field 2) changed" })
      .waitFor();
    expect(await saved(page)).toEqual([
      [...Buffer.from(EDITOR_FILE.replace("1111122222333", "0000000000000"), "ascii")],
    ]);
    expect(await axeProblems(page, { within: '[data-testid="editor-toolbar"]' })).toEqual([]);
    await context.close();
  });
});

describe("in Korean (ko-KR)", () => {
  // One page for both sizes: the flow once at 390×844, each page check at 1280×800 and at 390×844 (`expectPageOkAtSizes`).
  it("the Remote card with a lit key, and the restamp offer, at 1280×800 and at 390×844", async () => {
    const { page, context } = await newLocalePage(app, "ko-KR", { size: PHONE, options: FAST });
    await withSavePicker(page);
    await page.reload({ waitUntil: "domcontentloaded" });
    await connectCable(page);
    await openSensors(page, "센서");
    const card = page.getByTestId("remote-card");
    await expectText(card.locator("h2"), "리모컨");
    await expectText(tile(page, 12), "1 1 키 · 코드 12 저장된 모션 없음");
    await page.getByRole("radio", { name: "IR 리모컨" }).check();
    await pressKey(page, 34);
    await tile(page, 34).and(page.locator(".is-lit")).waitFor();
    await expectText(card.getByTestId("remote-last"), /^마지막 키: \* \+ 2 \(코드 34\), /);
    await expectPageOkAtSizes(page, "the Sensors view in Korean", {
      lang: "ko",
      shot: (size) => `remote-card-ko-${size.width}`,
      ready: () => card.scrollIntoViewIfNeeded(),
    });

    await page.getByRole("link", { name: "모션", exact: true }).click();
    await page.getByTestId("rbm-files").setInputFiles(rbm("dance.rbm", DANCE));
    const file = page.getByTestId("motion-file");
    await file.getByTestId("restamp-offer").waitFor();
    await file.getByRole("button", { name: "이 로봇에서 쓸 수 있게 만들기" }).click();
    await file
      .locator(".notice--ok")
      .filter({
        hasText:
          "dance-8958899989309.rbm(으)로 저장했어요. 시리얼 번호(2번 필드)만 1111122222333에서 8958899989309(으)로 바뀌었어요.",
      })
      .waitFor();
    expect(await saved(page)).toEqual([[...DANCE_FOR_THIS_ROBOT]]);
    await expectPageOkAtSizes(page, "the Motions view's restamp offer in Korean", {
      lang: "ko",
      shot: (size) => `restamp-ko-${size.width}`,
    });
    await context.close();
  });
});
