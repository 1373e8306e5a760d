import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { HUNO_BASIC_POSTURE } from "../../src/protocol/index.ts";
import { connectRobot, cspViolations, expectText, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";
import { CABLE, loadConnected, openConnected } from "./connected-page.ts";
import { expectPageOkAtSizes, PHONE, type Size, shot, text } from "./i18n-checks.ts";
import { exampleText, rbmFile } from "./motion-fixtures.ts";

const app = useApp();

const simServos = (page: Page) => page.evaluate(() => window.__rbcTest?.sim.servos ?? []);
const simDirect = (page: Page) => page.evaluate(() => window.__rbcTest?.sim.directMode);

/** Opens the Servos view with the robot on the cable connected (a page opened with the start option `CABLE`). */
async function openServos(page: Page): Promise<void> {
  await loadConnected(page, app.url, "servos");
  await page.getByTestId("servo-card").waitFor();
}

async function startControl(page: Page): Promise<void> {
  await page.getByRole("button", { name: "I understand: the robot is supported" }).click();
  await page.getByTestId("enter-direct").click();
  await page.getByText("Read all 16 servos.").waitFor();
}

describe("servos view", () => {
  it("asks for the safety notice first, moves one servo in direct mode, Stop keeps the servos holding, Limp makes all limp", async () => {
    const { page, context } = await app.newPage({ start: CABLE });
    await openServos(page);
    const notice = page.getByTestId("servo-safety");
    await expectText(notice, "Support the robot", { contains: true });
    await expect.poll(() => page.getByTestId("enter-direct").isDisabled()).toBe(true);
    await expect.poll(() => page.locator("#servo-3").isDisabled()).toBe(true);

    await startControl(page);
    await expect.poll(() => notice.count()).toBe(0);
    expect(await simDirect(page)).toBe(true);
    await expectText(page.getByTestId("servo-pos-3"), String(HUNO_BASIC_POSTURE[3]));
    await expectText(page.getByTestId("connection-status"), "servo control", { contains: true });

    // The number input is limited to the safe range (servo 3: 40-130) and moves the servo on change.
    await expect.poll(() => page.locator("#servo-3").getAttribute("min")).toBe("40");
    await expect.poll(() => page.locator("#servo-3").getAttribute("max")).toBe("130");
    await page.locator("#servo-3").fill("100");
    await page.locator("#servo-3").press("Enter");
    await expect.poll(async () => (await simServos(page))[3]?.position).toBe(100);
    await page.getByTestId("servo-pos-3").filter({ hasText: "100" }).waitFor();
    // Out of range is refused with a sentence (as in the zeros editor), never clamped and never sent.
    const sentBeforeRefusal = await page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? 0);
    await page.locator("#servo-12").fill("300");
    await page.locator("#servo-12").press("Enter");
    const refusal = page.getByTestId("servo-refused-12");
    await refusal.waitFor();
    await expectText(
      refusal,
      "Servo 12: 300 is outside its safe range 1–198. Nothing was sent; the servo stays where it is.",
    );
    await expect.poll(() => page.locator("#servo-12").getAttribute("aria-invalid")).toBe("true");
    await page.locator("#servo-3").fill("250");
    await page.locator("#servo-3").press("Enter");
    await page
      .getByTestId("servo-refused-3")
      .filter({ hasText: "250 is outside its safe range 40–130" })
      .waitFor();
    expect(await page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? 0)).toBe(sentBeforeRefusal);
    expect((await simServos(page))[12]?.position).toBe(HUNO_BASIC_POSTURE[12]);
    expect((await simServos(page))[3]?.position).toBe(100);
    // A value within the range is taken again and clears the refusal.
    await page.locator("#servo-3").fill("110");
    await page.locator("#servo-3").press("Enter");
    await expect.poll(async () => (await simServos(page))[3]?.position).toBe(110);
    await expect.poll(() => page.getByTestId("servo-refused-3").count()).toBe(0);

    // The slider: arrow keys move it; many quick changes do not queue up.
    const slider = page.getByLabel(/Left knee \(servo 2\), target/);
    await slider.focus();
    await page.keyboard.press("ArrowRight");
    await expect.poll(async () => (await simServos(page))[2]?.position).toBe(HUNO_BASIC_POSTURE[2]! + 1);
    const before = await page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? 0);
    await page.evaluate(() => {
      const input = document.querySelector<HTMLInputElement>('tr[data-servo="5"] input[type="range"]');
      if (!input) throw new Error("no slider for servo 5");
      for (let v = 100; v < 160; v++) {
        input.value = String(v);
        input.dispatchEvent(new Event("input", { bubbles: true }));
      }
    });
    await expect.poll(async () => (await simServos(page))[5]?.position).toBe(159);
    const sent = (await page.evaluate(() => window.__rbcTest?.port.stats.bytesFromPc ?? 0)) - before;
    // 60 changes, each move 4 bytes: latest-wins sends only a few of them.
    expect(sent).toBeLessThan(20 * 4);

    // Stop: no further move is sent, the servos keep holding (torque on), and servo control ends (issue 22
    // item 6: docs/protocol.md §5's leave sequence).
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    await page.getByTestId("stop-banner").filter({ hasText: "Servo control ended" }).waitFor();
    expect((await simServos(page)).map((s) => s.passive)).toEqual(Array(16).fill(false));
    expect(await simDirect(page)).toBe(false);

    // Limp, after its question: every servo passive.
    await page.getByRole("button", { name: "Limp…" }).click();
    await page.getByRole("alertdialog").getByRole("button", { name: "Limp", exact: true }).click();
    await page.getByText(/Limp: all 16 servos confirmed passive/).waitFor();
    expect((await simServos(page)).map((s) => s.passive)).toEqual(Array(16).fill(true));
    await page.getByTestId("servo-mode").filter({ hasText: "every servo is limp" }).waitFor();
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("after Limp during a motion every servo is limp, and servo controls still wait for the safety notice", async () => {
    // Real time: basic posture (1.8 s) should still be playing when Limp is confirmed (it waits for it if not).
    const { page, context } = await app.newPage();
    await connectRobot(page, app.url);
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    // Run basic posture (always accepted) and stop it with two quick presses of Escape.
    await page.getByRole("link", { name: "Motions" }).click();
    // The Run tab, where the Motions view has tabs (it loads lazily: wait for it first).
    await page.locator('[role="tablist"][aria-label="Motions"], [data-motion="7"]').first().waitFor();
    const runTab = page.getByRole("tab", { name: "Run" });
    if (await runTab.count()) await runTab.click();
    await page.locator('[data-motion="7"]').click();
    await page.locator("#confirm-move").click();
    await page.getByTestId("running-motion").waitFor();
    await page.getByRole("button", { name: "Limp…" }).click();
    await page.getByRole("alertdialog").getByRole("button", { name: "Limp", exact: true }).click();
    await page.getByText(/Limp: all 16 servos confirmed passive/).waitFor({ timeout: 8000 });
    expect((await simServos(page)).slice(0, 16).every((s) => s.passive)).toBe(true);
    expect(await page.getByText(/Limp failed/).count()).toBe(0);

    // Limp left the link in direct mode; the servo controls still need the safety notice first.
    await page.getByRole("link", { name: "Servos" }).click();
    await page.getByTestId("servo-safety").waitFor();
    await expect.poll(() => page.getByRole("button", { name: "Read all positions" }).isDisabled()).toBe(true);
    await context.close();
  });

  it("moves all servos to the basic posture after confirming, and leaves direct mode on request and on disconnect", async () => {
    const { page, context } = await app.newPage({ start: CABLE });
    await openServos(page);
    await startControl(page);
    await page.locator("#servo-0").fill("140");
    await page.locator("#servo-0").press("Enter");
    await expect.poll(async () => (await simServos(page))[0]?.position).toBe(140);

    await page.getByRole("button", { name: "All to basic posture…" }).click();
    await page.getByText("All 16 servos move to the basic posture at speed 4. Hold the robot.").waitFor();
    await page.getByRole("button", { name: "Move all servos" }).click();
    await page.getByText(/Sent: all 16 servos move to the basic posture/).waitFor();
    // "Sent" says the bytes left the panel; the simulated robot moves when it reads them.
    await expect
      .poll(async () => (await simServos(page)).map((s) => s.position))
      .toEqual([...HUNO_BASIC_POSTURE]);

    await page.getByTestId("leave-direct").click();
    await page.getByText(/Servo control ended/).waitFor();
    expect(await simDirect(page)).toBe(false);

    // Back in, then disconnect: the client sends the exit sequence on close.
    await page.getByTestId("enter-direct").click();
    await page.getByText("Read all 16 servos.").waitFor();
    expect(await simDirect(page)).toBe(true);
    await page.getByRole("link", { name: "Robot" }).click();
    await page.getByRole("button", { name: "Disconnect" }).click();
    await page.getByTestId("connect-card").waitFor();
    await expect.poll(() => simDirect(page)).toBe(false);
    await context.close();
  });
});

/**
 * The Sensors view, the Servos view and the 3D robot in Korean (issue #14 item 1): a browser set to Korean
 * (`locale: "ko-KR"`) gets `lang="ko"`, the views' words in Korean (literal strings checked), no catalogue key
 * in place of its text, no button whose label overflows it, nothing scrolling sideways, and no axe violation, at
 * 1280×800 and 390×844. The Servos view is checked with its "Robot in 3D" card open (the demo robot, and a robot
 * on a cable), and the motion preview of the Motions view in Korean. With RBC_SHOTS=<dir>, screenshots go there.
 */
describe("in Korean (ko-KR)", () => {
  /** The panel in a browser that prefers Korean, at `size`. */
  const openKorean = (size: Size, robot: "demo" | "cable", view: string) =>
    openConnected(app, { robot, view, locale: "ko-KR", size });

  /**
   * The checks every view gets (the page's lang, keys, labels, sideways scrolling, axe), and its screenshot, at
   * both sizes on the same page (the window resized, then put back).
   */
  const checkLayout = (page: Page, name: string) =>
    expectPageOkAtSizes(page, name, { lang: "ko", shot: (size) => `sensors-servos-${name}-${size.width}` });

  // One page per test for both sizes: the flow once at 390×844 (the phone, where Korean labels are tightest),
  // each state's checks at 1280×800 and at 390×844 (`checkLayout`).
  describe("in Korean at 1280×800 and at 390×844", () => {
    it("the Sensors view: readings, events and the demo robot's world", async () => {
      const { page, context } = await openKorean(PHONE, "demo", "sensors");
      await page.getByRole("heading", { level: 1, name: "센서" }).waitFor();
      const status = page.getByTestId("poll-status");
      await status.filter({ hasText: "마지막으로" }).waitFor();
      await expectText(status, /^1초에 5번 읽고 있어요\. 마지막으로 \d\d:\d\d:\d\d에 읽었어요\.$/);
      await page.getByTestId("distance-value").filter({ hasText: "10cm" }).waitFor();
      await expectText(page.getByTestId("distance-value"), "10cm");
      await expect.poll(() => page.getByRole("heading", { level: 2, name: "거리와 가속도" }).count()).toBe(1);
      await expect.poll(() => page.getByRole("button", { name: "일시 정지" }).count()).toBe(1);
      await expect
        .poll(() => page.getByTestId("poll-rate").locator("option").allTextContents())
        .toEqual(["1초에 2번", "1초에 5번", "1초에 10번"]);
      // The charts are named in Korean, their axes too.
      const distanceChart = page.locator('[data-testid="distance-chart"][data-chart="drawn"]');
      await distanceChart.waitFor();
      await expect
        .poll(() => distanceChart.locator('[role="img"]').getAttribute("aria-label"))
        .toBe("최근 30초 동안의 거리 (cm)");
      // The legend names the line (the axes' labels are drawn on the canvas).
      await expectText(distanceChart.locator(".u-legend"), "거리 (cm)", { contains: true });
      await page.locator('[data-testid="accel-chart"][data-chart="drawn"]').waitFor();

      // The events: listening to the PF buttons, a press of the demo robot's PF2.
      await expect.poll(() => page.getByText("아직 이벤트가 없어요.").count()).toBe(1);
      await page.getByRole("radio", { name: "PF 버튼" }).check();
      await page.getByTestId("listen-status").filter({ hasText: "PF 버튼을 듣고 있어요." }).waitFor();
      await page.getByRole("button", { name: "PF2 누르기" }).click();
      await page.getByTestId("event-list").filter({ hasText: "PF2 눌림" }).waitFor();

      // The demo robot's world.
      const world = page.getByTestId("demo-world");
      await expectText(world.getByRole("heading", { level: 2 }), "데모 로봇의 주변 환경");
      await expectText(world.locator('label[for="demo-distance"]'), "앞에 있는 물체: 10cm");
      await expectText(world.locator("select option:checked"), "7 기본 자세");
      await expect.poll(() => world.getByRole("button", { name: "IR 키 보내기" }).count()).toBe(1);

      // Sound: the threshold and its level.
      await page.getByRole("radio", { name: "소리 크기" }).check();
      await page.getByTestId("listen-status").filter({ hasText: "소리 크기를 듣고 있어요." }).waitFor();
      await expectText(page.getByTestId("sound-level"), "아직 들린 소리 없음");
      // Asked for 10 a second while listening to sound, it reads at most 5, and says why.
      await page.getByTestId("poll-rate").selectOption("10");
      await status.filter({ hasText: "최대 5번" }).waitFor();
      await expectText(
        status,
        /^1초에 5번 읽고 있어요 \(소리를 듣는 동안에는 로봇이 소리를 알려 줄 수 있도록 최대 5번\)\. 마지막으로 \d\d:\d\d:\d\d에 읽었어요\.$/,
      );

      await checkLayout(page, "sensors");

      // Switched to English, the view and its charts (drawn anew with the new words) speak English.
      await page.getByLabel("언어 / Language").selectOption("en");
      await page.getByRole("heading", { level: 1, name: "Sensors" }).waitFor();
      await expect
        .poll(() => page.locator('[data-testid="distance-chart"] [role="img"]').getAttribute("aria-label"))
        .toBe("Distance in cm over the last 30 seconds");
      await page
        .getByTestId("poll-status")
        .filter({ hasText: /^Reading 5 times a second \(at most 5/ })
        .waitFor();
      await context.close();
    });

    it("the Servos view, with the demo robot in 3D", async () => {
      const { page, context } = await openKorean(PHONE, "demo", "servos");
      await page.getByRole("heading", { level: 1, name: "서보" }).waitFor();
      const safety = page.getByTestId("servo-safety");
      await expectText(safety.getByRole("heading", { level: 2 }), "서보를 움직이기 전에");
      await expectText(
        safety.locator("li").first(),
        "로봇을 받쳐 주세요: 손으로 잡거나 등을 바닥에 대고 눕혀서, 관절이 움직이거나 힘이 빠져도 넘어지지 않게 해 주세요.",
      );
      await checkLayout(page, "servos-safety");

      await page.getByRole("button", { name: "알겠어요: 로봇을 받쳐 두었어요" }).click();
      await page.getByRole("button", { name: "서보 제어 시작" }).click();
      await page.getByText("서보 16개를 모두 읽었어요.").waitFor();
      await expect
        .poll(() => page.locator(".servo-table thead th").allTextContents())
        .toEqual(["ID", "관절", "위치", "목표", "슬라이더", "토크"]);
      await expectText(page.locator('label[for="servo-12"]'), "왼쪽 팔꿈치");
      await expect.poll(() => page.getByLabel("왼쪽 팔꿈치 (서보 12번), 목표 1~198").count()).toBe(1);
      // A refused value says why, in Korean; nothing is sent.
      await page.locator("#servo-12").fill("300");
      await page.locator("#servo-12").press("Enter");
      await expectText(
        page.getByTestId("servo-refused-12"),
        "서보 12번: 300은(는) 안전 범위(1–198) 밖이에요. 아무것도 보내지 않았고, 서보는 그대로 있어요.",
      );

      // The robot in 3D: the demo robot, live.
      const toggle = page.getByTestId("live-robot-toggle");
      await expectText(toggle, "로봇을 3D로 보기");
      await toggle.click();
      await page.locator('[data-testid="live-robot-view"][data-state="ready"]').waitFor();
      await expectText(toggle, "3D 로봇 숨기기");
      await expectText(page.getByTestId("live-robot-caption"), "데모 로봇, 실시간");
      await expect
        .poll(() => page.getByTestId("live-robot-view").locator("canvas").getAttribute("aria-label"))
        .toBe(
          "데모 로봇의 실시간 3D 보기: 가상 서보가 움직이는 대로 따라가요; 서보 표에 읽은 위치가 숫자로 나와 있어요",
        );

      // The basic posture, asked in place.
      await page.getByRole("button", { name: "모두 기본 자세로…" }).click();
      await page.getByText("서보 16개가 모두 기본 자세로 움직여요 (속도 4). 로봇을 잡아 주세요.").waitFor();
      await expect.poll(() => page.getByRole("button", { name: "모든 서보 움직이기" }).count()).toBe(1);
      await checkLayout(page, "servos");
      await context.close();
    });
  });

  describe("in Korean, the 3D robot of a robot on a cable and the motion preview", () => {
    it("says what it draws of a robot on a cable, 1280×800 and 390×844", async () => {
      const { page, context } = await openKorean(PHONE, "cable", "servos");
      await page.getByTestId("live-robot-toggle").click();
      await page.locator('[data-testid="live-robot-view"][data-state="ready"]').waitFor();
      await expectText(
        page.getByTestId("live-robot-caption"),
        "아직 읽은 위치가 없어요: 기본 자세로 그렸어요",
      );
      await expectText(
        page.getByTestId("live-robot-unread"),
        "모든 관절을 로봇의 실제 자세가 아니라 기본 자세로 그렸어요",
        { contains: true },
      );
      await expectText(
        page.getByTestId("live-robot"),
        "이번 연결에서 이 로봇의 영점을 읽지 않아서, 각도는 표준 영점 표를 기준으로 재요.",
        { contains: true },
      );
      await page.getByRole("button", { name: "알겠어요: 로봇을 받쳐 두었어요" }).click();
      await page.getByRole("button", { name: "서보 제어 시작" }).click();
      await page.getByText("서보 16개를 모두 읽었어요.").waitFor();
      await expectText(page.getByTestId("live-robot-caption"), /^마지막으로 읽은 위치, \d\d:\d\d:\d\d$/);
      await expect
        .poll(() => page.getByTestId("live-robot-view").locator("canvas").getAttribute("aria-label"))
        .toMatch(/^마지막으로 읽은 위치\(\d\d:\d\d:\d\d\)에 있는 로봇의 3D 보기; 서보 표에/);
      await checkLayout(page, "servos-cable");
      await context.close();
    });

    it("plays a motion preview with Korean controls, 1280×800 and 390×844", async () => {
      const { page, context } = await openKorean(PHONE, "cable", "motions");
      await page.getByTestId("rbm-files").setInputFiles(rbmFile("wave.rbm", exampleText("wave.rbm")));
      const card = page.getByTestId("motion-file");
      await card.getByTestId("preview-toggle").click();
      const preview = card.getByTestId("motion-preview");
      await preview.locator('[data-state="ready"]').waitFor();
      // The page prefers reduced motion: the preview steps from scene to scene.
      const play = preview.getByTestId("preview-play");
      await expectText(play, "다음 장면");
      await expectText(preview.getByTestId("preview-clock"), "0.0초 / 3.2초");
      await expectText(preview.locator("label"), "시간");
      await expectText(
        preview.locator(".robot3d-hint"),
        "동작 줄이기가 켜져 있어요. '다음 장면'을 누르면 움직이는 화면 없이 각 장면의 자세를 보여 줘요. " +
          "시간: 화살표 키로 0.1초씩, Page Up과 Page Down으로 한 장면씩 움직여요. 로봇 돌리기: 로봇을 끌거나, 로봇을 선택한 뒤 화살표 키를 눌러 주세요.",
      );
      await play.click();
      await expect.poll(() => preview.getAttribute("data-time")).toBe("800");
      await expectText(preview.getByTestId("preview-clock"), "0.8초 / 3.2초");
      await expect
        .poll(() => preview.getByTestId("preview-time").getAttribute("aria-valuetext"))
        .toBe("0.8초 / 3.2초, 장면 0 끝, RaiseArm");
      // To the end: the button goes back to the start.
      await preview.getByTestId("preview-time").evaluate((input: HTMLInputElement) => {
        input.value = input.max;
        input.dispatchEvent(new Event("input", { bubbles: true }));
      });
      await expect.poll(() => text(play)).toBe("처음으로");

      // Labels and axe in the preview; the page's lang, keys and sideways scrolling.
      await expectPageOkAtSizes(page, "the motion preview", {
        lang: "ko",
        within: '[data-testid="motion-preview"]',
        ready: (size) => shot(preview, `sensors-servos-motion-preview-${size.width}`),
      });
      await context.close();
    });
  });
});
