import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { sharedConnectedPage } from "./connected-page.ts";
import { expectText, squash, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";

/**
 * Words a new owner tripped over (issue 33, item 10, in part), in English and in Korean, on one connected page
 * per language:
 * - the Zeros view names its own table "the zero table" ("영점 표"), never "the editor" (the Editor is a view);
 * - a file that is not Intel HEX at all, opened as firmware, is said to be that first (the parser's complaint
 *   second), and the Update button's hint no longer says to open a file first when one was just opened;
 * - in Korean the Log names the packets in Korean, and the Editor shows a new scene's default name in Korean
 *   ("장면_0"; the motion file keeps "Scene_0": a scene name in a .rbm file is ASCII only, said beside the field).
 */

const app = useApp();

/** Bytes that are no text file at all (a picture, a program), the first one not ':'. */
const RANDOM_BINARY = Buffer.from(
  Array.from({ length: 600 }, (_, i) => (i * 73 + 11) % 256).map((b, i) => (i === 0 ? 0x89 : b)),
);

const WORDS = {
  en: {
    locale: "en-US",
    zerosSource: "The values in the zero table come from the robot.",
    zerosStale: /\bthe editor\b/i,
    notHex:
      "random.bin is not an Intel HEX firmware file: the RBC's firmware is a text file (.hex) of lines that start with ':'.",
    technical: "Line 1: a record starts with ':'.",
    openFirst: "Open a firmware file first.",
    openHex: "Open an Intel HEX firmware file (.hex) to update the robot.",
    packet: "Read firmware version",
    englishPacket: undefined,
    sceneName: "Scene_0",
    storedAs: undefined,
  },
  ko: {
    locale: "ko-KR",
    zerosSource: "영점 표의 값은 로봇에서 가져왔어요.",
    zerosStale: /편집 표|편집기/,
    notHex:
      "random.bin은(는) Intel HEX 펌웨어 파일이 아니에요. RBC 펌웨어는 ':'로 시작하는 줄로 된 텍스트 파일(.hex)이에요.",
    technical: "1번째 줄: 레코드는 ':'로 시작해야 해요.",
    openFirst: "먼저 펌웨어 파일을 열어 주세요.",
    openHex: "로봇을 업데이트하려면 Intel HEX 펌웨어 파일(.hex)을 열어 주세요.",
    packet: "펌웨어 버전 읽기",
    englishPacket: "Read firmware version",
    sceneName: "장면_0",
    storedAs:
      "모션 파일에는 Scene_0(으)로 저장돼요. 모션 파일의 장면 이름에는 영문, 숫자, 기호만 쓸 수 있어요.",
  },
} as const;

const show = async (page: Page, route: string, ready: string) => {
  await page.goto(`${app.url}#/${route}`);
  await page.getByTestId(ready).waitFor();
};

for (const [language, w] of Object.entries(WORDS)) {
  describe(`item 10's words, ${language}`, () => {
    const page = sharedConnectedPage(app, { locale: w.locale });

    it("the Zeros view calls its table the zero table", async () => {
      await show(page(), "zeros", "zeros-card");
      const intro = page().getByTestId("zeros-card").locator("p.muted").first();
      await expect.poll(async () => squash(await intro.textContent())).toContain(w.zerosSource);
      expect(squash(await page().locator("main").textContent())).not.toMatch(w.zerosStale);
    });

    it("a random binary opened as firmware is not an Intel HEX firmware file, and no 'open a file first'", async () => {
      await show(page(), "firmware", "firmware-view");
      await expectText(page().locator("main"), w.openFirst, { contains: true });
      await page().getByTestId("fw-file-input").setInputFiles({
        name: "random.bin",
        mimeType: "application/octet-stream",
        buffer: RANDOM_BINARY,
      });
      const problem = page().getByText(w.notHex, { exact: false });
      await problem.waitFor();
      // Plain words first, the parser's technical line second.
      const text = squash(await page().locator("main").textContent());
      expect(text.indexOf(w.notHex)).toBeGreaterThanOrEqual(0);
      expect(text.indexOf(w.technical)).toBeGreaterThan(text.indexOf(w.notHex));
      expect(text).not.toContain(w.openFirst);
      expect(text).toContain(w.openHex);
    });

    it("the Log names the packets in the page's language", async () => {
      await show(page(), "log", "log-card");
      const names = page().getByTestId("log-card").locator("td.log-name");
      await names.filter({ hasText: w.packet }).first().waitFor();
      if (w.englishPacket) expect(await names.filter({ hasText: w.englishPacket }).count()).toBe(0);
    });

    it("the Editor shows a new scene's default name in the page's language; the file keeps Scene_0", async () => {
      await show(page(), "editor", "pose-table");
      const option = page().locator('[data-testid="scene-list"] .scene-option .scene-name').first();
      await expectText(option, w.sceneName);
      await page().locator("#editor-tab-scene").click();
      await expect.poll(() => page().getByTestId("scene-name").inputValue()).toBe("Scene_0");
      await expectText(page().locator("#scene-title"), new RegExp(`${w.sceneName}$`));
      const stored = page().getByTestId("scene-name-stored");
      if (w.storedAs) await expectText(stored, w.storedAs);
      else expect(await stored.count()).toBe(0);
    });
  });
}
