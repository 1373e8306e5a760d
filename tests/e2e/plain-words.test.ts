/**
 * Issue 21, item 8 ("Words a hobbyist knows") and the rest of item 5, as a new owner meets them in the built
 * panel, in English and Korean:
 * - the Firmware view says what a file is in plain words (its size, the version it states or "Not stated", that
 *   it was checked), with the address range, flash pages, lines and record types one click away; a file that
 *   carries the mark of this project's demo files (`RBCFW M.mm`) is flagged, and on a robot that is not the demo
 *   robot the update waits for an extra tick;
 * - the Servos view leads with what it does for the robot, "direct mode" and "synchronised move" one click away;
 * - the sound buttons name each sound (one catalogue with `rbc sound`);
 * - Zeros: beside a value that cannot be written, the comparison speaks only of the values that can be;
 * - teach-in's question says which servos hold and which stay limp (a servo that did not answer Hold).
 * With RBC_SHOTS=<dir>, screenshots of what changed.
 */
import { readFile } from "node:fs/promises";
import { join } from "node:path";
import type { Page } from "playwright-core";
import { describe, expect, it, vi } from "vitest";
import { hexLines } from "../support/hex.ts";
import { openConnected } from "./connected-page.ts";
import { expectText, FAST, ROOT, useApp } from "./harness.ts";
import { axeProblems, DESKTOP, PHONE, type Size, shot, text, texts } from "./i18n-checks.ts";
import "./rbc-test-globals.ts";

const app = useApp();

vi.setConfig({ testTimeout: 120_000 });

/** The project's demo firmware file, as it is opened from disk. */
async function demoFile(): Promise<{ name: string; mimeType: string; buffer: Buffer }> {
  const buffer = await readFile(join(ROOT, "examples/firmware/demo-2.50.hex"));
  return { name: "demo-2.50.hex", mimeType: "text/plain", buffer };
}

/** A firmware file that states no version (no demo mark), as real firmware files are. */
function plainFile(): { name: string; mimeType: string; buffer: Buffer } {
  const bytes = new Uint8Array(2048);
  for (let i = 0; i < bytes.length; i++) bytes[i] = (i * 13 + 5) & 0xff;
  return {
    name: "huno-2.30.hex",
    mimeType: "text/plain",
    buffer: Buffer.from(`${hexLines(bytes).join("\r\n")}\r\n`),
  };
}

/** Opens the panel on the Firmware view with `robot` connected. */
async function openFirmware(robot: "demo" | "cable", locale = "en-US", size: Size = DESKTOP) {
  const opened = await openConnected(app, { robot, view: "firmware", locale, size, options: FAST });
  await opened.page.getByTestId("firmware-view").waitFor();
  return opened;
}

async function openFile(page: Page, file: { name: string; mimeType: string; buffer: Buffer }): Promise<void> {
  await page.getByTestId("fw-file-input").setInputFiles(file);
  await page.getByTestId("fw-summary").filter({ hasText: file.name }).waitFor();
}

const detailOpen = (page: Page) =>
  page.getByTestId("fw-detail").evaluate((d) => (d as HTMLDetailsElement).open);

describe("Firmware: plain words first, and the demo file flagged before a real robot gets it", () => {
  it("English: a robot on a cable; the demo file states 2.50, is flagged, and Update waits for the tick", async () => {
    const { page, context } = await openFirmware("cable");
    await openFile(page, await demoFile());

    await expectText(page.getByTestId("fw-declared"), "2.50");
    await expectText(
      page.getByTestId("fw-demo-mark"),
      "A demo file: not firmware a real robot can run. It carries the mark of this project's demo and test files " +
        "(RBCFW 2.50), which only the demo robot understands. Written to a real robot, it would leave that robot " +
        "without working firmware until real firmware is written again.",
    );
    await expect
      .poll(() => page.getByTestId("fw-demo-mark").getAttribute("class"))
      .toContain("notice--warning");
    // Plain words in sight; the technical words only inside the closed "Technical detail".
    await expectText(
      page.getByTestId("fw-checked"),
      "Checked: the file is complete and undamaged, fits the robot's controller, and leaves its bootloader alone, " +
        "so a failed update can always be run again.",
    );
    await expect.poll(() => detailOpen(page)).toBe(false);
    await expect.poll(() => page.getByTestId("fw-pages").isVisible()).toBe(false);
    await expect.poll(() => page.getByText(/record types 00, 01, 02 and 04/).isVisible()).toBe(false);
    await page.getByTestId("fw-detail").locator("summary").click();
    await expectText(page.getByTestId("fw-pages"), "64 of 256 bytes");
    await expect
      .poll(() => page.getByText(/record types 00, 01, 02 and 04 only.*\(0x1E000\)/).isVisible())
      .toBe(true);

    // The question: a warning, and Update stays disabled until the tick; nothing reaches the robot meanwhile.
    await page.getByTestId("flash-start").click();
    const confirm = page.getByTestId("fw-demo-confirm");
    await confirm.waitFor();
    await expectText(
      confirm,
      "demo-2.50.hex is a demo file, and this is a real robot. The robot cannot run it: after the update it will " +
        "not move or answer until you write real firmware to it (the bootloader stays, so that remains possible). " +
        "I understand: the robot will not work until I write real firmware",
    );
    const update = page.getByRole("button", { name: "Update firmware", exact: true });
    await expect.poll(() => update.isDisabled()).toBe(true);
    await shot(page, "plain-words-firmware-demo-file-real-robot");
    await page.locator("#accept-demo-file").check();
    await expect.poll(() => update.isEnabled()).toBe(true);
    await page.locator("#accept-demo-file").uncheck();
    await expect.poll(() => update.isDisabled()).toBe(true);
    expect(await axeProblems(page, { within: "[data-testid=firmware-view]" })).toEqual([]);
    await page.getByRole("button", { name: "Cancel", exact: true }).click();

    // A file without the mark states no version and asks nothing more.
    await openFile(page, plainFile());
    await expectText(page.getByTestId("fw-declared"), "Not stated");
    await expect.poll(() => page.getByTestId("fw-demo-mark").count()).toBe(0);
    await page.getByTestId("flash-start").click();
    await page.getByTestId("flash-confirm").waitFor();
    expect(await page.getByTestId("fw-demo-confirm").count()).toBe(0);
    await expect.poll(() => update.isEnabled()).toBe(true);
    await context.close();
  });

  it("English: on the demo robot the same file from disk is fine to try, without the extra tick", async () => {
    const { page, context } = await openFirmware("demo");
    await openFile(page, await demoFile());
    await expectText(page.getByTestId("fw-demo-mark"), "On the demo robot it is fine to try.", {
      contains: true,
    });
    await page.getByTestId("flash-start").click();
    await page.getByTestId("flash-confirm").waitFor();
    expect(await page.getByTestId("fw-demo-confirm").count()).toBe(0);
    await expect
      .poll(() => page.getByRole("button", { name: "Update firmware", exact: true }).isEnabled())
      .toBe(true);
    await context.close();
  });

  it("Korean: the version stated or not, the flag, the tick, and the technical detail's label", async () => {
    const { page, context } = await openFirmware("cable", "ko-KR", PHONE);
    await openFile(page, await demoFile());
    await expectText(page.getByTestId("fw-declared"), "2.50");
    await expectText(
      page.getByTestId("fw-demo-mark"),
      "데모 파일이에요. 실제 로봇이 실행할 수 있는 펌웨어가 아니에요. 이 프로젝트의 데모·테스트 파일 표시(RBCFW 2.50)가 " +
        "들어 있어요. 이 표시는 데모 로봇만 알아들어요. 실제 로봇에 쓰면, 진짜 펌웨어를 다시 쓸 때까지 그 로봇에는 " +
        "작동하는 펌웨어가 없어요.",
    );
    await expectText(page.getByTestId("fw-detail").locator("summary"), "기술 정보");
    await page.getByTestId("flash-start").click();
    const confirm = page.getByTestId("fw-demo-confirm");
    await confirm.waitFor();
    await expectText(confirm, "demo-2.50.hex은(는) 데모 파일인데, 이 로봇은 실제 로봇이에요.", {
      contains: true,
    });
    const update = page.getByRole("button", { name: "펌웨어 업데이트", exact: true });
    await expect.poll(() => update.isDisabled()).toBe(true);
    await page.getByText("알겠어요: 진짜 펌웨어를 쓸 때까지 로봇이 작동하지 않아요").click();
    await expect.poll(() => update.isEnabled()).toBe(true);
    await shot(page, "plain-words-firmware-ko-phone");
    await page.getByRole("button", { name: "취소", exact: true }).click();
    await openFile(page, plainFile());
    await expectText(page.getByTestId("fw-declared"), "적혀 있지 않음");
    await context.close();
  });
});

describe("Servos: what it does for the robot first, the protocol's words one click away", () => {
  for (const [locale, lead, posture, jargon] of [
    [
      "en-US",
      "Move the robot's joints one at a time, each only within its safe range, and see where each one is.",
      "Moves all 16 joints at once into the HUNO's basic posture, standing straight.",
      ["direct mode", "synchronised move"],
    ],
    [
      "ko-KR",
      "로봇의 관절을 하나씩, 각 관절의 안전 범위 안에서만 움직이고 지금 어디에 있는지 봐요.",
      "관절 16개를 한꺼번에 움직여 HUNO의 기본 자세(똑바로 선 자세)로 만들어요.",
      ["직접 모드", "동시 이동"],
    ],
  ] as const) {
    it(`${locale}: no "direct mode" or "synchronised move" in sight until Technical detail is opened`, async () => {
      const { page, context } = await openConnected(app, { view: "servos", locale, options: FAST });
      await page.getByTestId("servo-mode").waitFor();
      await expectText(page.locator(".servos-view .view-head p"), lead);
      await expect.poll(() => page.getByText(posture, { exact: true }).isVisible()).toBe(true);
      const detail = page.getByTestId("servo-detail");
      for (const word of jargon) {
        const shown = page.getByText(word, { exact: false });
        // Every place the word appears is inside the closed detail, so none is visible.
        for (const element of await shown.all())
          await expect.poll(() => element.isVisible(), { message: word }).toBe(false);
        await expectText(detail, word, { contains: true });
      }
      await detail.locator("summary").click();
      for (const word of jargon)
        await expect.poll(() => detail.getByText(word, { exact: false }).isVisible()).toBe(true);
      await context.close();
    });
  }
});

describe("Sounds have names as well as numbers", () => {
  it("names each sound button in English and Korean, and says the name while it plays", async () => {
    for (const [locale, seven, label, playing] of [
      ["en-US", "7 Long 5.7 s", "Sound 7 Long 5.7 s", "Sound 7 (Long) is playing"],
      ["ko-KR", "7 긴 소리 5.7초", "소리 7 긴 소리 5.7초", "소리 7번(긴 소리) 재생 중"],
    ] as const) {
      const { page, context } = await openConnected(app, { view: "motions", locale, options: FAST });
      await page.locator("#motions-tab-sounds").click();
      const button = page.locator('[data-sound="7"]');
      // What is seen, and what a screen reader says (the seen text with "Sound" before it).
      await expect
        .poll(async () => (await texts(button.locator(":scope > :not(.sr-only)"))).join(" "))
        .toBe(seven);
      await expect
        .poll(() => page.getByRole("button", { name: label, exact: true }).getAttribute("data-sound"))
        .toBe("7");
      expect(await axeProblems(page, { within: "[data-testid=sound-card]" })).toEqual([]);
      await expect.poll(() => page.locator("[data-sound]").count()).toBe(25);
      for (let n = 1; n <= 25; n++) await expectText(page.locator(`[data-sound="${n}"] .motion-name`), /\S/);
      await button.click();
      await page.getByTestId("sound-playing").filter({ hasText: playing }).waitFor();
      await context.close();
    }
  });
});

describe("Zeros: the comparison agrees with 'Cannot write'", () => {
  for (const [locale, none, some] of [
    [
      "en-US",
      "The 15 values that can be written match the robot's zeros.",
      /^Of the values that can be written, 1 differs from the robot's zeros: servo 5 \d+ → \d+\.$/,
    ],
    [
      "ko-KR",
      "쓸 수 있는 값 15개는 로봇의 영점과 같아요.",
      /^쓸 수 있는 값 중 1개가 로봇의 영점과 달라요: 서보 5 \d+ → \d+\.$/,
    ],
  ] as const) {
    it(`${locale}: speaks only of the values that can be written`, async () => {
      const { page, context } = await openConnected(app, { view: "zeros", locale, options: FAST });
      await page.locator("#zero-3").waitFor();
      await page.getByTestId("change-summary").waitFor();
      await page.locator("#zero-3").fill("200");
      await page.locator("#zero-3").press("Tab");
      await page
        .getByTestId("write-why")
        .filter({ hasText: locale === "en-US" ? "Cannot write" : "쓸 수 없어요" })
        .waitFor();
      await expectText(page.getByTestId("change-summary"), none);
      const five = Number(await page.locator("#zero-5").inputValue());
      await page.locator("#zero-5").fill(String(five + 1));
      await page.locator("#zero-5").press("Tab");
      // The summary is drawn on the panel's next render, not at once: polled.
      await expect.poll(() => text(page.getByTestId("change-summary"))).toMatch(some);
      await context.close();
    });
  }
});

describe("Teach-in's question says which servos hold and which stay limp", () => {
  async function openTeachIn(page: Page): Promise<void> {
    await page.getByTestId("pose-table").waitFor();
    await page.locator("#editor-tab-teach").click();
    await page.locator("#editor-panel-teach").waitFor();
  }

  for (const [locale, plain, some] of [
    [
      "en-US",
      "as far as the panel knows, all 16 hold their position until you make some limp. A servo made limp outside this panel (for example with rbc limp) stays limp",
      "The servos keep doing what they do now: servo 12 was made limp earlier and has not confirmed holding since, so it stays limp; servos 0–11, 13–15 hold their position until you make some limp.",
    ],
    [
      "ko-KR",
      "패널이 아는 한 서보 16개 모두 힘을 빼기 전까지 제자리를 유지해요. 이 패널 밖에서 힘을 뺀 서보(예: rbc limp)는 계속 힘이 빠져 있고",
      "서보는 지금 하던 대로 있어요. 서보 12은(는) 전에 힘을 뺀 뒤 다시 힘을 준다고 확인하지 않아서 계속 힘이 빠져 있어요. 서보 0–11, 13–15은(는) 힘을 빼기 전까지 제자리를 유지해요.",
    ],
  ] as const) {
    it(`${locale}: a servo that did not answer Hold is named as staying limp the next time`, async () => {
      const { page, context } = await openConnected(app, { view: "editor", locale, options: FAST });
      await openTeachIn(page);
      await page.locator("#start-teach-in").click();
      await expectText(page.getByTestId("teach-in-detail"), plain, { contains: true });
      await page.locator("#confirm-teach-in").click();
      await page.locator('input[data-limb="left-arm"]').waitFor();
      await page.locator('input[data-limb="left-arm"]').setChecked(true);
      await page.locator("#make-limp").click();
      await page.getByTestId("teach-in-status").filter({ hasText: /10–12/ }).waitFor();
      // The left elbow's cable comes loose: End teach-in cannot make servo 12 hold again.
      await page.evaluate(() => window.__rbcDemoSim?.connectServo(12, false));
      await page.getByTestId("end-teach-in").click();
      await page.locator("#start-teach-in:not([disabled])").waitFor({ timeout: 30_000 });
      await page.locator("#start-teach-in").click();
      await expectText(page.getByTestId("teach-in-detail"), some);
      await shot(page, `plain-words-teach-in-${locale}`);
      await context.close();
    });
  }
});
