import { describe, expect, it } from "vitest";
import { connectRobot, cspViolations, expectText, FAST, squash, useApp, watchPage } from "./harness.ts";
import "./rbc-test-globals.ts";
import type { Page } from "playwright-core";
import { expectPageOkAtSizes, newLocalePage, PHONE } from "./i18n-checks.ts";
import type { RbcTestOptions } from "./rbc-test-globals.ts";

const app = useApp();

describe("connecting a robot", () => {
  it("connects through the chooser and shows the simulator's identity and memory", async () => {
    const { page, context } = await app.newPage();
    const seen = watchPage(page, app.origin);
    await connectRobot(page, app.url);

    const status = page.getByTestId("connection-status");
    await expectText(status, /Connected\s*·\s*HUNO\s*·\s*fw 2\.23\s*·\s*SN 8958899989309/);
    await expectText(page.getByTestId("firmware"), "2.23");
    await expectText(page.getByTestId("serial-number"), "8958899989309");
    await expectText(page.getByTestId("memory-motion-text"), /0 of 24,576 bytes used/);
    await expectText(page.getByTestId("memory-action-text"), /0 of 8,192 bytes used/);
    await expect.poll(() => page.locator("#memory-motion").getAttribute("max")).toBe("24576");
    await expectText(page.getByTestId("error-code"), /No error/);
    await expect.poll(() => page.getByRole("button", { name: "Stop", exact: true }).isVisible()).toBe(true);
    await expect.poll(() => page.getByRole("button", { name: "Limp…" }).isVisible()).toBe(true);

    // The chooser was asked for the four USB serial vendors and paired Bluetooth modules (SPP).
    const filters = await page.evaluate(() => window.__rbcTest?.serial.requests[0]?.filters);
    expect(filters).toEqual([
      { usbVendorId: 0x0403 },
      { usbVendorId: 0x067b },
      { usbVendorId: 0x10c4 },
      { usbVendorId: 0x1a86 },
      { bluetoothServiceClassId: "00001101-0000-1000-8000-00805f9b34fb" },
    ]);
    // The port was opened with the RBC's settings.
    const opened = await page.evaluate(() => window.__rbcTest?.port.openOptions);
    expect(opened).toMatchObject({ baudRate: 115200, dataBits: 8, stopBits: 1, parity: "none" });

    expect(seen.foreignRequests).toEqual([]);
    expect(seen.errors).toEqual([]);
    expect(await cspViolations(page)).toEqual([]);
    await context.close();
  });

  it("shows help when the chooser is cancelled", async () => {
    const { page, context } = await app.newPage({ options: { userCancels: true } });
    await page.goto(app.url);
    await page.getByRole("button", { name: "Connect robot" }).click();
    await page.getByText("No port was chosen").waitFor();
    const help = page.getByTestId("connect-help");
    // The help opens on the render after the cancel, and its text is a part that loads after the first paint.
    await expect.poll(() => help.getAttribute("open")).not.toBeNull();
    for (const hint of [
      "dialout",
      "brltty",
      "snap connect chromium:raw-usb",
      "Motionbuilder",
      "CH340",
      "FTDI",
    ]) {
      await expectText(help, hint, { contains: true });
    }
    // "Show all ports" drops the filters. The first cancel's sentence is still on screen, so wait for the second
    // request itself, not for the sentence.
    const requests = () => page.evaluate(() => window.__rbcTest?.serial.requests.length ?? 0);
    const before = await requests();
    await page.getByLabel("Show all serial ports").check();
    await page.getByRole("button", { name: "Connect robot" }).click();
    await expect.poll(requests).toBe(before + 1);
    await page.getByText("No port was chosen").waitFor();
    const last = await page.evaluate(() => window.__rbcTest?.serial.requests.at(-1));
    expect(last?.filters).toBeUndefined();
    await context.close();
  });

  it("offers a port granted earlier for one-click reconnect, and forgets it", async () => {
    const { page, context } = await app.newPage({ options: { granted: true } });
    await page.goto(app.url);
    const connect = page.getByRole("button", { name: "Connect to FTDI USB serial adapter (0403:6001)" });
    await connect.click();
    await page.getByTestId("device-card").waitFor();
    expect(await page.evaluate(() => window.__rbcTest?.serial.requests.length)).toBe(0);

    await page.getByRole("button", { name: "Disconnect" }).click();
    await page.getByRole("button", { name: "Forget FTDI USB serial adapter (0403:6001)" }).click();
    await expect.poll(() => connect.count()).toBe(0);
    expect(await page.evaluate(() => window.__rbcTest?.port.forgotten)).toBe(true);
    await context.close();
  });

  it("returns to a clear disconnected state when the cable is pulled mid-operation", async () => {
    const { page, context } = await app.newPage();
    await connectRobot(page, app.url);
    await page.getByTestId("firmware").filter({ hasText: "2.23" }).waitFor();
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();

    // The robot stops answering, so the refresh stays pending; then the cable is pulled.
    await page.evaluate(() => window.__rbcTest?.port.faults.swallowReplies(20));
    await page.getByRole("button", { name: "Refresh" }).click();
    await page.getByRole("button", { name: "Reading…" }).waitFor();
    await page.evaluate(() => window.__rbcTest?.port.unplug());

    const lost = page.getByTestId("lost-notice");
    await lost.waitFor();
    await expectText(lost, "unplugged", { contains: true });
    await expectText(lost, "Did not finish: Reading device info", { contains: true });
    await expectText(page.getByTestId("connection-status"), /Disconnected/);
    // No spinner or progress left, no Stop button, and the connect buttons work again.
    await expect.poll(() => page.locator("progress").count()).toBe(0);
    await expect.poll(() => page.getByRole("button", { name: "Stop", exact: true }).count()).toBe(0);
    await expect.poll(() => page.getByRole("button", { name: "Limp…" }).count()).toBe(0);
    await expect.poll(() => page.getByRole("button", { name: "Connect robot" }).isEnabled()).toBe(true);

    // Plugged back in, it connects again.
    await page.evaluate(() => window.__rbcTest?.port.faults.clear());
    await page.evaluate(() => window.__rbcTest?.port.replug());
    await page.getByRole("button", { name: "Connect robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await context.close();
  });

  it("Escape while connected is Stop, never Limp: with nothing running no servo goes passive", async () => {
    const { page, context } = await app.newPage();
    await connectRobot(page, app.url);
    await page.getByTestId("memory-motion-text").filter({ hasText: "24,576" }).waitFor();
    await page.keyboard.press("Escape");
    await page
      .getByText("The robot answered at once: it is idle, nothing to stop. Nothing was sent.")
      .waitFor();
    const servos = await page.evaluate(() => window.__rbcTest?.sim.servos.slice(0, 16).map((s) => s.passive));
    expect(servos).toEqual(Array(16).fill(false));
    expect(await page.evaluate(() => window.__rbcTest?.sim.directMode)).toBe(false);
    expect(await page.getByTestId("connection-status").textContent().then(squash)).not.toMatch(
      /servo control|limp/,
    );
    await context.close();
  });

  it("offers Cancel while the port chooser is open; a port the chooser gives later is not opened", async () => {
    const { page, context } = await app.newPage();
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    // A chooser that never answers by itself (requestPort can hang).
    await page.evaluate(() => {
      const serial = window.__rbcTest?.serial;
      if (serial) serial.chooserHangs = true;
    });
    const connect = page.getByRole("button", { name: "Connect robot" });
    const demo = page.getByRole("button", { name: "Try the demo robot" });
    await connect.click();
    await page.getByText("Waiting for you to choose a port in the browser's list…").waitFor();
    await expect.poll(() => connect.isDisabled()).toBe(true);
    await expect.poll(() => demo.isDisabled()).toBe(true);

    await page.getByTestId("cancel-choosing").click();
    await expect.poll(() => connect.isEnabled()).toBe(true);
    await expect.poll(() => demo.isEnabled()).toBe(true);
    await expect.poll(() => page.getByTestId("connect-progress").count()).toBe(0);
    await page.getByText(/Stopped waiting for the port chooser/).waitFor();

    // The chooser answers late: the page no longer waits for it, and does not open the port.
    expect(await page.evaluate(() => window.__rbcTest?.serial.answerHeldRequests())).toBe(1);
    await page.getByRole("heading", { name: "Ports used before" }).waitFor();
    expect(await page.evaluate(() => window.__rbcTest?.port.openOptions)).toBeUndefined();
    await expectText(page.getByTestId("connection-status"), "Not connected");

    // Connect works again with a chooser that answers.
    await page.evaluate(() => {
      const serial = window.__rbcTest?.serial;
      if (serial) serial.chooserHangs = false;
    });
    await connect.click();
    await page.getByTestId("device-card").waitFor();
    await context.close();
  });

  it("names the view and the robot in the page title, and says which version the panel is", async () => {
    const { page, context } = await app.newPage();
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByRole("button", { name: "Try the demo robot" }).click();
    await page.getByTestId("device-card").waitFor();
    await expect.poll(() => page.title()).toBe("Robot · Demo robot · RBC Panel");
    await page.getByRole("link", { name: "Zeros" }).click();
    await expect.poll(() => page.title()).toBe("Zeros · Demo robot · RBC Panel");
    // The build stamps its version and commit (vite.config.ts), shown at the foot of every view.
    await expectText(
      page.getByTestId("panel-version"),
      /^RBC Panel · Version \d+\.\d+\.\d+ \([0-9a-f]{7,}\)/,
    );
    await context.close();
  });
});

/**
 * The connection in Korean (issue #14 item 1): the start card with its help open and the ports used before, the
 * top bar while connected to the demo robot, to the demo robot over Bluetooth and to a robot on a USB adapter,
 * the Limp question, Stop's and Limp's outcomes, a lost link, and a browser without Web Serial. At 1280×800
 * and 390×844: `lang="ko"`, Korean shown, no catalogue key in place of its text, no label wider than its
 * button, nothing scrolling sideways, and no axe violation. With RBC_SHOTS=<dir>, screenshots go there.
 */
describe("in Korean (ko-KR)", () => {
  /** The panel in a Korean browser, with the fake serial port (`options`) or, with `noSerial`, no Web Serial. */
  const koreanPage = (setup: { options?: RbcTestOptions; noSerial?: boolean } = {}) =>
    newLocalePage(app, "ko-KR", { size: PHONE, ...setup });

  /** The top bar's status, part by part (the dot and the separators are decoration). */
  const status = (page: Page) =>
    page.getByTestId("connection-status").locator(".status-part, .demo-tag").allTextContents();
  const banner = (page: Page) => page.getByTestId("stop-banner");

  /**
   * What every state of every view must satisfy, in Korean, at both sizes (the window resized on the same page);
   * a screenshot named `name` at each.
   */
  const checkKorean = (page: Page, name: string) =>
    expectPageOkAtSizes(page, name, { lang: "ko", shot: (size) => `connection-${name}-${size.width}` });

  // One page per state, for both sizes: the flow once at 390×844 (the phone, where Korean labels are tightest),
  // each page check at 1280×800 and at 390×844.
  describe("the connection in Korean", () => {
    const at = "1280×800 and 390×844";

    it(`the start card with its help open and the ports used before, at ${at}`, async () => {
      const { page, context } = await koreanPage({ options: { granted: true } });
      const card = page.getByTestId("connect-card");
      await card.waitFor();
      await expectText(card.getByRole("heading", { level: 1 }), "로봇 연결하기");
      await card.getByRole("button", { name: "로봇 연결", exact: true }).waitFor();
      await card.getByRole("button", { name: "데모 로봇 써 보기", exact: true }).waitFor();
      await card.getByRole("button", { name: "가상 블루투스 연결로 데모 로봇 써 보기" }).waitFor();
      await expectText(
        card.locator(".demo-bluetooth p"),
        "블루투스처럼 응답이 300 ± 150ms 늦게, 몰려서 와요.",
      );
      await expect
        .poll(() => card.getByLabel("모든 시리얼 포트 보기 (다른 어댑터, 내장 포트)").isChecked())
        .toBe(false);
      await expect.poll(() => status(page)).toEqual(["연결 안 됨"]);

      // The port granted on an earlier visit, named in Korean, with its buttons.
      await card.getByRole("heading", { name: "전에 쓴 포트" }).waitFor();
      await expect
        .poll(() => card.locator(".port-label").allTextContents())
        .toEqual(["FTDI USB 시리얼 어댑터 (0403:6001)"]);
      await card.getByRole("button", { name: "FTDI USB 시리얼 어댑터 (0403:6001)에 연결" }).waitFor();
      await card.getByRole("button", { name: "FTDI USB 시리얼 어댑터 (0403:6001) 지우기" }).waitFor();

      // The help, opened.
      await card.getByText("로봇을 찾을 수 없나요?").click();
      await expectText(
        page.getByTestId("bluetooth-help"),
        /^블루투스 모듈: 먼저 로봇을 켜고 컴퓨터의 블루투스 설정에서 모듈을 페어링해 주세요\./,
      );
      await expectText(page.getByTestId("bluetooth-help"), "PIN을 물으면 1234 또는 0000인 경우가 많아요.", {
        contains: true,
      });
      await expectText(page.getByTestId("bluetooth-help"), '"블루투스 시리얼 포트"로 나와요', {
        contains: true,
      });
      await expect
        .poll(() => page.getByTestId("connect-help").locator("code").allTextContents())
        .toEqual([
          "dialout",
          "sudo usermod -aG dialout $USER",
          "sudo apt remove brltty",
          "sudo snap connect chromium:raw-usb",
          "1234",
          "0000",
        ]);
      await checkKorean(page, "start-card");
      await context.close();
    });

    it(`the top bar with the demo robot over Bluetooth, the Limp question and Stop's outcome, at ${at}`, async () => {
      const { page, context } = await koreanPage({ options: FAST });
      await page.getByTestId("demo-bluetooth").click();
      const card = page.getByTestId("device-card");
      await card.waitFor({ timeout: 15_000 });
      await expect
        .poll(() => status(page), { timeout: 15_000 })
        .toEqual(["데모 로봇 (블루투스)", "연결됨", "HUNO", "펌웨어 2.23", "시리얼 번호 8958899989309"]);
      await expectText(card.getByRole("heading", { level: 1 }), "데모 로봇 (블루투스)");
      await expectText(
        card.locator("dd").first(),
        "가상 블루투스로 연결한 데모 로봇 (이 페이지 안의 가상 RBC이며, 실제 하드웨어가 아니에요)",
      );
      await expect.poll(() => page.title()).toBe("로봇 · 데모 로봇 (블루투스) · RBC 패널");
      await expectText(page.locator(".brand"), "RBC 패널");

      // Stop with nothing running: the robot keeps its pose.
      const stop = page.getByRole("button", { name: "정지", exact: true });
      await expect
        .poll(() => stop.getAttribute("title"))
        .toBe(
          "로봇이 하던 일을 끝내요 (Esc). 로봇은 서보에 힘이 들어간 채로 멈춘 자세를 유지해요. 넘어지지는 않지만, 꼭 서 있는 자세는 아니에요.",
        );
      await stop.click();
      await banner(page).filter({ hasText: "쉬고 있어서 멈출 것이 없어요." }).waitFor({ timeout: 15_000 });
      await expectText(
        banner(page),
        "로봇이 바로 응답했어요. 쉬고 있어서 멈출 것이 없어요. 아무것도 보내지 않았어요. 닫기",
      );

      // The Limp question, with the safe choice focused.
      await page.getByRole("button", { name: "힘 빼기…" }).click();
      const question = page.getByRole("alertdialog", {
        name: "로봇을 잡아 주세요. 모든 서보의 힘이 빠져서, 아무도 잡고 있지 않으면 로봇이 넘어져요.",
      });
      await question.waitFor();
      await expect.poll(() => page.evaluate(() => document.activeElement?.textContent?.trim())).toBe("취소");
      await question.getByRole("button", { name: "힘 빼기", exact: true }).waitFor();
      await checkKorean(page, "bluetooth-demo-limp-question");
      await context.close();
    });

    it(`the demo robot: Limp's outcome, servos limp in the top bar, then Stop, at ${at}`, async () => {
      const { page, context } = await koreanPage({ options: FAST });
      await page.getByRole("button", { name: "데모 로봇 써 보기", exact: true }).click();
      await page.getByTestId("device-card").waitFor();
      await expect
        .poll(() => status(page))
        .toEqual(["데모 로봇", "연결됨", "HUNO", "펌웨어 2.23", "시리얼 번호 8958899989309"]);
      await expect.poll(() => page.title()).toBe("로봇 · 데모 로봇 · RBC 패널");

      await page.getByRole("button", { name: "힘 빼기…" }).click();
      await page.getByRole("alertdialog").getByRole("button", { name: "힘 빼기", exact: true }).click();
      await banner(page).filter({ hasText: "서보 16개 모두" }).waitFor({ timeout: 15_000 });
      await expectText(
        banner(page).locator("p").first(),
        "힘 빼기: 서보 16개 모두 힘이 빠졌다고 확인했어요. 로봇을 잡아 주세요. 이제 혼자 서 있을 수 없어요.",
      );
      await expect.poll(() => status(page).then((parts) => parts.at(-1))).toBe("서보 힘 빠짐");

      await page.getByRole("button", { name: "정지", exact: true }).click();
      await banner(page).filter({ hasText: "서보는 힘이 빠진 채로 있어요" }).waitFor({ timeout: 15_000 });
      await expectText(
        banner(page).locator("p").first(),
        "서보 제어를 끝냈어요 (로봇이 일반 모드로 돌아왔어요). 서보는 힘이 빠진 채로 있어요 (힘 빼기).",
      );
      await checkKorean(page, "demo-limp-stop");
      await context.close();
    });

    it(`a robot on a USB adapter, then its link lost, at ${at}`, async () => {
      const { page, context } = await koreanPage();
      await page.getByRole("button", { name: "로봇 연결", exact: true }).click();
      const card = page.getByTestId("device-card");
      await card.waitFor();
      await expect
        .poll(() => status(page))
        .toEqual(["연결됨", "HUNO", "펌웨어 2.23", "시리얼 번호 8958899989309"]);
      await expectText(card.getByRole("heading", { level: 1 }), "로봇");
      await expectText(card.locator("dd").first(), "FTDI USB 시리얼 어댑터 (0403:6001)");
      await expect.poll(() => page.title()).toBe("로봇 · RBC 패널");
      await card.getByTestId("memory-action-note").filter({ hasText: "8,192" }).waitFor();
      await checkKorean(page, "usb-robot");

      // The cable is pulled: the link's reason in Korean (from its facts), its technical line the detail.
      await page.evaluate(() => window.__rbcTest?.port.unplug());
      const lost = page.getByTestId("lost-notice");
      await lost.waitFor();
      await expectText(
        lost.locator("p").first(),
        "로봇과의 연결이 끊겼어요. USB 케이블이 뽑혔거나 어댑터가 빠졌어요.",
      );
      await expectText(
        lost.locator("p").last(),
        "케이블과 로봇의 전원 스위치를 확인한 뒤 다시 연결해 주세요.",
      );
      await expectText(lost.locator("summary"), "기술 정보");
      await expect.poll(() => lost.locator("pre").getAttribute("lang")).toBe("en");
      await expectText(lost.locator("pre"), "unplugged", { contains: true });
      await expect.poll(() => status(page)).toEqual(["연결 끊김 — 통신이 끊어짐"]);
      await lost.locator("summary").click();
      await checkKorean(page, "link-lost");
      await context.close();
    });

    it(`a browser without Web Serial, then the demo robot from it, at ${at}`, async () => {
      const { page, context } = await koreanPage({ noSerial: true });
      const card = page.getByTestId("unsupported-card");
      await card.waitFor();
      await expectText(card.getByRole("heading", { level: 1 }), "이 브라우저로는 로봇에 연결할 수 없어요");
      await expectText(
        card.locator("p").first(),
        "패널은 Web Serial을 통해 로봇의 컨트롤러와 통신해요. 사용자가 고른 USB 시리얼 포트를 웹 페이지가 열 수 있게 해 주는 기능으로, 데스크톱용 Chrome, Edge, Opera (버전 89 이상)에서 쓸 수 있어요.",
      );
      await expect
        .poll(() => card.locator("strong").allTextContents())
        .toEqual(["Web Serial", "Chrome, Edge, Opera (버전 89 이상)"]);
      await checkKorean(page, "no-web-serial");

      await card.getByRole("button", { name: "데모 로봇 써 보기", exact: true }).click();
      await page.getByTestId("device-card").waitFor();
      await expect
        .poll(() => status(page).then((parts) => parts.slice(0, 2)))
        .toEqual(["데모 로봇", "연결됨"]);
      await context.close();
    });
  });
});
