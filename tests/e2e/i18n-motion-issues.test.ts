/**
 * The motion file checker's sentences in Korean (issue #14 item 1): a Korean browser opens files with errors
 * (one the RBC refuses, one that cannot be read) and warnings of every weight; each issue is a Korean sentence
 * with the file's numbers and no English left in it; the page is `lang="ko"`, shows no catalogue key, no
 * button's label overflows it and nothing scrolls sideways at 1280×800 and 390×844; axe finds no violation.
 * With RBC_SHOTS=<dir>, screenshots go there to be looked at.
 */
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { FAST } from "./harness.ts";
import {
  connectCable,
  expectPageOk,
  newLocalePage,
  SIZES,
  shot,
  sizeName as size,
  text,
  texts,
  useApp,
} from "./i18n-checks.ts";
import {
  exampleText,
  rbmFile,
  withJumps,
  withSerial,
  withShortFrames,
  withUnsafePosition,
} from "./motion-fixtures.ts";
import "./rbc-test-globals.ts";

const app = useApp();

/** The text with some `:`-separated fields replaced: [index, new text]... */
function edit(source: string, ...changes: [number, string][]): string {
  const fields = source.split(":");
  for (const [i, value] of changes) fields[i] = value;
  return fields.join(":");
}

const WAVE = exampleText("wave.rbm");
/** Field 128 of wave.rbm (16 servos): scene 0, servo record 2, its start position. */
const SCENE0_RECORD2_START = 13 + 6 * 16 + 5 + 6 * 2 + 2;

/** The files opened: warnings only; an error the RBC refuses; unreadable; warnings of every weight. */
const FILES = [
  rbmFile("Jumpy.rbm", withJumps(WAVE, 2)),
  rbmFile("Edited.rbm", withShortFrames(WAVE)),
  rbmFile("Broken.rbm", edit(WAVE, [SCENE0_RECORD2_START, "x1"])),
  rbmFile("Odd.rbm", edit(withSerial(withUnsafePosition(WAVE), "1234567890123"), [10, "5"])),
];

/** Connects the fake robot from the connect card and opens the Motions view once its memory has been read. */
async function openMotions(page: Page): Promise<void> {
  await connectCable(page);
  await page.getByRole("link", { name: "모션", exact: true }).click();
  await page.getByTestId("motion-files").waitFor();
}

describe("the motion file checker's sentences in Korean", () => {
  for (const viewport of SIZES) {
    it(`says every problem of the opened files in Korean, fitting at ${viewport.width}×${viewport.height}`, async () => {
      const { page, context } = await newLocalePage(app, "ko-KR", { size: viewport, options: FAST });
      await openMotions(page);
      await page.getByTestId("rbm-files").setInputFiles(FILES);
      await page
        .getByText(/^파일 4개를 열었어요\./)
        .first()
        .waitFor();
      const card = (name: string) => page.getByTestId("motion-file").filter({ hasText: name });

      // An error the RBC refuses: the sentence names the scene itself, so no place is said before it.
      expect(await texts(card("Edited.rbm").locator(".issue--error"))).toEqual([
        "오류 장면 0의 프레임 간격이 10ms예요 (200ms / 프레임 20개). RBC에는 20ms 이상이 필요해요. 프레임 수를 줄여 주세요.",
      ]);

      // A file that cannot be read: the field, by its number and what it holds.
      expect(await texts(card("Broken.rbm").locator(".issue--error"))).toEqual([
        '오류 128번 필드(장면 0, 서보 레코드 2번의 시작 위치)는 정수여야 해요 (지금 값: "x1").',
      ]);

      // Warnings, grouped by kind; each single warning in Korean.
      const jumps = card("Jumpy.rbm").getByTestId("warning-group");
      await jumps.getByText("16개 모두 보기").click();
      expect(await text(jumps.locator(".issues li").first())).toBe(
        "장면 0에서 서보 0번(오른쪽 엉덩이 롤)의 끝 위치는 125인데, 장면 1에서는 127에서 시작해서 서보가 튀어요.",
      );
      const odd = card("Odd.rbm");
      for (const summary of await odd.locator(".warning-details summary").all()) await summary.click();
      const said = await texts(odd.locator(".warning-details .issues li"));
      expect(said).toContainEqual(
        expect.stringMatching(
          /^장면 0에서 서보 0번\(오른쪽 엉덩이 롤\)이 안전 범위\(\d+-174\) 밖인 254 위치로 가요\.$/,
        ),
      );
      expect(said).toContainEqual(
        expect.stringMatching(
          /^이 모션은 시리얼 번호 1234567890123 로봇용으로 만들었는데, 지금 연결된 로봇은 시리얼 번호 \d{13} 로봇이에요\. Motionbuilder는 이런 파일을 거부해요\. 이 로봇에 맞는 모션인지 확인해 주세요\.$/,
        ),
      );
      expect(said).toContain("10번 필드 값이 5인데, Motionbuilder는 항상 2(으)로 써요.");
      expect(said).toContainEqual(
        expect.stringMatching(/^장면 0에서 서보 0번\(오른쪽 엉덩이 롤\)의 끝 위치는 254인데/),
      );

      // Nothing is left in English: no sentence marked as English, no English sentence unmarked.
      const lists = page.locator('[data-testid="rbm-issues"], [data-testid="rbm-warnings"]');
      expect(await lists.locator('[lang="en"]').count()).toBe(0);
      const all = await texts(page.locator(".issues li"));
      expect(all.length).toBeGreaterThan(20);
      expect(
        all.filter((s) => !/\p{Script=Hangul}/u.test(s) || /\b(Scene|servo|must|the)\b/.test(s)),
      ).toEqual([]);

      // Close-ups of each file's check, to be read (the whole page at 390 px is too tall to read).
      for (const name of ["Jumpy", "Edited", "Broken", "Odd"]) {
        await shot(card(`${name}.rbm`), `motion-issues-${name.toLowerCase()}-ko-${size(viewport)}`);
      }
      await card("Jumpy.rbm").scrollIntoViewIfNeeded();
      await expectPageOk(page, "the files", { lang: "ko", shot: `motion-issues-files-ko-${size(viewport)}` });
      await context.close();
    });
  }
});
