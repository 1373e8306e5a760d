/**
 * The Zeros and Log views in Korean (issue #14 item 1): a Korean browser gets both views in Korean with
 * `lang="ko"`, their sentences from the actions too (write, backup files, copy); no catalogue key shows; no
 * button's label overflows it and nothing scrolls sideways at 1280×800 and 390×844; axe finds no violation.
 * With RBC_SHOTS=<dir>, screenshots of both views at both sizes go there to be looked at.
 */
import { readFile } from "node:fs/promises";
import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { FACTORY_ZEROS } from "../../src/protocol/index.ts";
import { parseZerosBackup } from "../../src/protocol/zeros-backup.ts";
import { FAST, squash } from "./harness.ts";
import {
  connectCable,
  expectPageOk,
  keysShown,
  pageLang as lang,
  newLocalePage,
  SIZES,
  shot,
  sizeName as size,
  useApp,
} from "./i18n-checks.ts";
import "./rbc-test-globals.ts";

const app = useApp();

const simZeros = (page: Page) => page.evaluate(() => window.__rbcTest?.sim.zeros);

/** The paragraph under the Zeros view's heading: what zeros are, what a backup is, where the values came from. */
const intro = async (page: Page) =>
  squash(await page.getByTestId("zeros-card").locator("p.muted").first().textContent());

/** Opens the Zeros view once its table has been read and the view is idle. */
async function openZeros(page: Page): Promise<void> {
  await connectCable(page);
  await page.getByRole("link", { name: "영점", exact: true }).click();
  await page.getByTestId("zeros-card").waitFor();
  await page.locator("#zero-15").waitFor();
  await page.locator("button:not([disabled])", { hasText: "공장 영점 불러오기" }).waitFor();
}

describe("the Zeros view in Korean", () => {
  for (const viewport of SIZES) {
    it(`is in Korean, fits and passes axe at ${viewport.width}×${viewport.height}`, async () => {
      const { page, context } = await newLocalePage(app, "ko-KR", { size: viewport });
      await openZeros(page);
      expect(await lang(page)).toBe("ko");
      const card = page.getByTestId("zeros-card");
      expect(await card.getByRole("heading", { level: 1 }).textContent()).toBe("영점 위치");
      await card.getByRole("button", { name: "로봇에서 읽기" }).waitFor();
      await card.getByRole("button", { name: "영점 백업" }).waitFor();
      await card.getByRole("button", { name: "공장 영점 불러오기" }).waitFor();
      expect(squash(await card.locator("label.file-button").textContent())).toBe("백업에서 복원…");
      expect(await card.locator("thead th").allTextContents()).toEqual([
        "ID",
        "관절",
        "영점",
        "슬라이더",
        "저장된 값",
        "변경",
      ]);
      expect(await page.getByLabel("오른쪽 발목 피치", { exact: true }).inputValue()).toBe("65");
      const slider = page.getByLabel("오른쪽 발목 피치 (서보 3) 슬라이더, 51–81");
      expect(await slider.getAttribute("type")).toBe("range");
      expect(await intro(page)).toBe(
        "로봇은 모션을 재생할 때마다 각 서보의 영점을 더해요. '영점 백업'은 로봇의 지금 영점을 파일로 저장해요. 나중에 그 파일로 복원할 수 있어요. 편집 표의 값은 로봇에서 가져왔어요.",
      );
      expect(squash(await page.getByTestId("zero-tables").textContent())).toContain(
        `공장 영점 새 로봇의 펌웨어에 들어 있는 값이에요: ${FACTORY_ZEROS.join(" ")}.`,
      );
      expect(await page.locator('tr[data-servo="1"] .zero-diff .sr-only').textContent()).toBe("변경 없음");
      expect(squash(await page.getByTestId("change-summary").textContent())).toBe(
        "편집 표가 로봇에 저장된 영점과 같아요.",
      );
      expect(squash(await page.getByTestId("write-why").textContent())).toBe(
        "아직 쓸 것이 없어요. 먼저 값을 바꿔 주세요.",
      );
      await expectPageOk(page, "the Zeros view", { shot: `zeros-ko-${size(viewport)}` });

      // An edit, and the question before the write.
      await page.locator("#zero-3").fill("70");
      await page
        .getByTestId("change-summary")
        .filter({ hasText: "아직 쓰지 않은 변경 1개: 서보 3 65 → 70." })
        .waitFor();
      expect(squash(await page.getByTestId("write-why").textContent())).toBe(
        "쓰기 전에 로봇의 지금 영점을 백업 파일로 저장해요.",
      );
      await page.getByTestId("write-zeros").click();
      const confirm = page.getByRole("group", { name: /바뀐 영점 1개를 로봇에 쓸까요\?/ });
      await confirm.waitFor();
      await confirm.getByRole("button", { name: "백업 저장 후 쓰기" }).waitFor();
      await confirm.getByRole("button", { name: "취소" }).waitFor();
      await confirm.scrollIntoViewIfNeeded();
      await shot(page, `zeros-confirm-ko-${size(viewport)}`, { fullPage: false });
      await expectPageOk(page, "the question before the write");
      await confirm.getByRole("button", { name: "취소" }).click();

      // A value the robot would refuse.
      await page.locator("#zero-3").fill("200");
      await page.getByTestId("write-why").filter({ hasText: "쓸 수 없어요" }).waitFor();
      expect(squash(await page.getByTestId("write-why").textContent())).toBe(
        "쓸 수 없어요: 허용 범위를 벗어난 값이 1개 있어요.",
      );
      expect(squash(await page.locator("#zero-3-hint").textContent())).toBe("51–81만 가능");
      await expectPageOk(page, "a refused value", { axe: false });
      await context.close();
    });
  }

  it("says in Korean what a write, a backup and a backup file did", async () => {
    const { page, context } = await newLocalePage(app, "ko-KR");
    await openZeros(page);

    // The write: a backup first, then the verified table.
    await page.locator("#zero-3").fill("70");
    await page.getByTestId("write-zeros").click();
    const downloadPromise = page.waitForEvent("download");
    await page.getByRole("button", { name: "백업 저장 후 쓰기" }).click();
    const name = (await downloadPromise).suggestedFilename();
    expect(name).toMatch(/^rbc-zeros-8958899989309-\d{4}-\d{2}-\d{2}\.json$/);
    const written = page.getByText(/^영점을 쓰고 다시 읽어 확인했어요/);
    await written.waitFor();
    expect(squash(await written.textContent())).toBe(
      `영점을 쓰고 다시 읽어 확인했어요(16/16). 백업을 ${name}(으)로 저장했어요.`,
    );
    expect((await simZeros(page))?.[3]).toBe(70);

    // A backup on its own.
    const backupPromise = page.waitForEvent("download");
    await page.getByRole("button", { name: "영점 백업" }).click();
    const backup = await backupPromise;
    const saved = page.getByText(/^백업을 .*\.json\(으\)로 저장했어요\. 로봇에서/);
    await saved.waitFor();
    expect(squash(await saved.textContent())).toBe(
      `백업을 ${backup.suggestedFilename()}(으)로 저장했어요. 로봇에서 영점 16개를 읽었어요. 나중에 되돌리려면 '백업에서 복원'을 눌러 주세요.`,
    );
    const parsed = parseZerosBackup(await readFile(await backup.path(), "utf8"));
    expect(parsed.ok && parsed.backup.zeros[3]).toBe(70);

    // Files that are refused: a Korean sentence from the parser's code, its English sentence as the detail.
    const file = page.getByTestId("zeros-file");
    await file.setInputFiles({
      name: "broken.json",
      mimeType: "application/json",
      buffer: Buffer.from("{ no"),
    });
    const broken = page.getByText('"broken.json" 파일을 불러오지 않았어요.', { exact: false });
    await broken.waitFor();
    expect(squash(await broken.textContent())).toBe(
      '"broken.json" 파일을 불러오지 않았어요. 영점 백업 파일이 아니에요(JSON 텍스트가 아님). 이 패널이 저장한 파일을 골라 주세요. 이름은 rbc-zeros-<시리얼 번호>-<날짜>.json 같은 모양이에요.',
    );
    const notice = page.locator(".notice", { has: broken });
    expect(await notice.locator("summary").textContent()).toBe("기술 정보");
    expect(await notice.locator("pre").getAttribute("lang")).toBe("en");
    expect(await notice.locator("pre").textContent()).toMatch(/^not-json: This file is not a zero backup/);

    const backupOf = (serialNumber: string, zeros: readonly number[]) =>
      Buffer.from(
        JSON.stringify({
          format: "rbc-zeros",
          version: 1,
          serialNumber,
          firmware: "2.23",
          savedAt: "2026-11-21T10:00:00.000Z",
          zeros,
        }),
      );
    await file.setInputFiles({
      name: "range.json",
      mimeType: "application/json",
      buffer: backupOf(
        "8958899989309",
        FACTORY_ZEROS.map((v, i) => (i === 5 ? 250 : v)),
      ),
    });
    await page
      .getByText(
        '"range.json" 파일을 불러오지 않았어요. 로봇이 이 백업의 영점을 거부할 거예요. 서보 5의 값이',
      )
      .waitFor();

    // A backup from another robot: loaded, with the warning and its date in Korean.
    const zeros = FACTORY_ZEROS.map((v, i) => (i === 0 ? v + 3 : v));
    await file.setInputFiles({
      name: "other.json",
      mimeType: "application/json",
      buffer: backupOf("1111111111111", zeros),
    });
    const other = page.getByText(
      /^"other\.json" 파일\(2026년 11월 21일 \d\d:\d\d에 저장\)을 편집 표에 불러왔어요\./,
    );
    await other.waitFor();
    expect(squash(await other.textContent())).toContain(
      "이 백업은 연결된 로봇(8958899989309)이 아니라 다른 로봇(1111111111111)에서 저장했어요.",
    );
    expect(await page.locator("#zero-0").inputValue()).toBe(String(zeros[0]));
    expect(await intro(page)).toContain("편집 표의 값은 백업 파일 other.json에서 가져왔어요.");

    await page.getByRole("button", { name: "공장 영점 불러오기" }).click();
    await page
      .getByText("공장 영점을 편집 표에 넣었어요. '로봇에 쓰기'를 누르기 전에는 아무것도 쓰지 않아요.")
      .waitFor();
    expect(await keysShown(page)).toEqual([]);
    await context.close();
  });
});

/** Adds packets to the log: every "다시 읽기" on the Robot view reads the robot's details again. */
async function refreshTimes(page: Page, times: number): Promise<void> {
  const refresh = page.getByTestId("device-card").getByRole("button", { name: "다시 읽기" });
  for (let i = 0; i < times; i++) {
    await refresh.click();
    await refresh.waitFor();
  }
}

const entries = async (page: Page) =>
  Number(
    squash(await page.getByTestId("log-count").textContent())
      .match(/^항목 ([\d,]+)개/)?.[1]
      ?.replace(/,/g, ""),
  );

describe("the Log view in Korean", () => {
  it("says in Korean that there is nothing yet, before a robot is connected", async () => {
    const { page, context } = await newLocalePage(app, "ko-KR");
    await page.getByRole("link", { name: "로그", exact: true }).click();
    const card = page.getByTestId("log-card");
    await card.waitFor();
    expect(await card.getByRole("heading", { level: 1 }).textContent()).toBe("패킷 로그");
    expect(squash(await card.locator(".empty").textContent())).toBe(
      "아직 패킷이 없어요. 로봇(또는 데모 로봇)을 연결하면 주고받는 모든 패킷이 여기에 나와요.",
    );
    expect(squash(await page.getByTestId("log-count").textContent())).toBe(
      "항목 0개 (최근 항목 5,000개까지, 바이트는 최대 1,024KB까지 보관해요). 연달아 버린 바이트는 한 항목으로 묶어요.",
    );
    expect(await card.getByRole("button", { name: "지우기" }).isDisabled()).toBe(true);
    await context.close();
  });

  for (const viewport of SIZES) {
    it(`is in Korean, fits and passes axe at ${viewport.width}×${viewport.height}`, async () => {
      const { page, context } = await newLocalePage(app, "ko-KR", { size: viewport, options: FAST });
      await connectCable(page);
      // Stray bytes and a frame too long for its type before the next reply: one row of discarded bytes.
      await page.evaluate(() => {
        const stray = Array.from({ length: 3000 }, (_, i) => (i * 13 + 1) & 0x7f);
        const oversize = [0xff, 0xff, 0xaa, 0x55, 0xaa, 0x55, 0x37, 0xba, 0x11, 0x01, 0x00, 0x00, 0x0f, 0x00];
        window.__rbcTest?.port.faults.garbageBeforeReply([...stray, ...oversize, 0, 0]);
      });
      await refreshTimes(page, 20);
      await page.getByRole("link", { name: "로그", exact: true }).click();
      const card = page.getByTestId("log-card");
      await card.locator("tbody tr").first().waitFor();
      expect(await lang(page)).toBe("ko");

      expect(await card.getByRole("heading", { level: 1 }).textContent()).toBe("패킷 로그");
      for (const name of ["일시 정지", "지우기", "복사", "다운로드 (.txt)"]) {
        await card.getByRole("button", { name, exact: true }).waitFor();
      }
      expect(await card.locator("thead th").allTextContents()).toEqual([
        "시간",
        "방향",
        "종류",
        "바이트 (16진수)",
      ]);
      const total = await entries(page);
      expect(total).toBeGreaterThan(100);
      expect(squash(await page.getByTestId("log-count").textContent())).toBe(
        `항목 ${total.toLocaleString("ko")}개 (최근 항목 5,000개까지, 바이트는 최대 1,024KB까지 보관해요). 연달아 버린 바이트는 한 항목으로 묶어요. 한 쪽에 100개씩 보여요. '복사'와 '다운로드'는 전체를 가져가요.`,
      );
      expect(squash(await page.getByTestId("log-page").textContent())).toBe(
        `${total.toLocaleString("ko")}개 중 1–100번째 (최신순)`,
      );
      const pages = page.getByRole("navigation", { name: "로그 쪽" });
      await pages.getByRole("button", { name: "더 최근" }).waitFor();
      await pages.getByRole("button", { name: "더 이전" }).waitFor();
      await page.getByRole("region", { name: "패킷 (최신순)" }).waitFor();

      // The view's words are Korean; the packets' names come from the device, in English, marked so.
      const directions = await card.locator("tbody .log-dir").allTextContents();
      expect(new Set(directions.map(squash))).toEqual(new Set(["→ 보냄", "← 받음"]));
      const named = card.locator("tbody tr.log-packet .log-name span[lang='en']").first();
      expect(await named.textContent()).toMatch(/^[A-Z][A-Za-z ()0-9-]+$/);
      await expectPageOk(page, "the Log view", { shot: `log-ko-${size(viewport)}` });

      // The run of discarded bytes is on an older page.
      await pages.getByRole("button", { name: "더 이전" }).click();
      const discard = card.locator("tr.log-discard");
      await discard.first().waitFor();
      const row = squash(await discard.first().textContent());
      expect(row).toContain("버린 바이트 종류에 비해 너무 긴 프레임 1개, 프레임이 아닌 바이트");
      expect(row).toContain("(3,016바이트)");
      expect(row).toContain("01 0E 1B 28");

      // Paused: the button says what it will do, and the line says what happens meanwhile.
      await card.getByRole("button", { name: "일시 정지", exact: true }).click();
      const resume = card.getByRole("button", { name: "계속", exact: true });
      await resume.waitFor();
      expect(await resume.getAttribute("aria-pressed")).toBe("true");
      expect(squash(await page.getByTestId("log-count").textContent())).toMatch(
        /일시 정지됨: 새 패킷은 계속 기록하지만 화면에는 보여 주지 않아요\.$/,
      );
      await expectPageOk(page, "the Log view, paused", { axe: false });
      await context.close();
    });
  }

  it("says in Korean what Copy did; the copied log stays a packet trace in English", async () => {
    const { page, context } = await newLocalePage(app, "ko-KR", { options: FAST });
    await connectCable(page);
    await page.getByRole("link", { name: "로그", exact: true }).click();
    const card = page.getByTestId("log-card");
    await card.locator("tbody tr").first().waitFor();
    const total = await entries(page);
    await context.grantPermissions(["clipboard-read", "clipboard-write"], { origin: app.origin });
    await card.getByRole("button", { name: "복사", exact: true }).click();
    await page.getByText(`${total}줄을 클립보드에 복사했어요.`).waitFor();
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    expect(copied).toMatch(/^RBC Panel packet log, /);
    expect(copied).toContain(
      "PC → RBC  Read firmware version (16 bytes)  FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01",
    );
    expect(await keysShown(page)).toEqual([]);
    await context.close();
  });
});
