import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { openConnected } from "./connected-page.ts";
import { connectRobot, expectText, squash, type TestContext, useApp } from "./harness.ts";
import "./rbc-test-globals.ts";
import {
  axeProblems,
  connectDemo,
  keysShown,
  newLocalePage,
  PHONE,
  pageProblems,
  type Size,
  text,
} from "./i18n-checks.ts";

/**
 * The Servo check (issue 22) on the demo robot, on the paced virtual clock of the tests (tests/support/paced-clock.ts):
 * a replacement servo still at the factory id 0 is found, fixed with the guided id fix and scanned clean; the
 * fault survives a reconnect; Cancel and the top bar's Stop end a scan and it says which ids were read.
 */

const app = useApp();

/**
 * The robot's clock at a quarter of real speed. A scan reads each id within a 48 ms window of robot time; the
 * paced clock lets robot time follow real time up to the next timer while a request is on its way through the
 * page, so a page starved for a whole window (a loaded machine) would close it before the simulated servo's
 * reply is due, and read the servo as silent. At a quarter speed that takes 192 ms of starvation.
 */
const QUARTER = { timeScale: 0.25 };

/** Opens the Servo check with the demo robot connected (on the QUARTER clock), in a browser in `locale`. */
async function openDoctor(locale: string, size?: Size): Promise<{ page: Page; context: TestContext }> {
  const opened = await openConnected(app, { view: "doctor", locale, size, options: QUARTER });
  await opened.page.getByTestId("doctor-scan-card").waitFor();
  return opened;
}

/**
 * Restarts the demo robot with a fault of its servo bus, from the view's demo control, and waits until the
 * restarted robot is connected and the view names the fault (`now`, in the page's language).
 */
async function simulateFault(page: Page, kind: string, servo: number, now: string): Promise<void> {
  await page.getByTestId("doctor-demo-kind").selectOption(kind);
  await page.getByTestId("doctor-demo-servo").selectOption(String(servo));
  await page.getByTestId("doctor-demo-apply").click();
  await page.getByTestId("doctor-demo-now").filter({ hasText: now }).waitFor();
  await page.getByTestId("doctor-scan").and(page.locator(":enabled")).waitFor();
}

/**
 * Scans and waits for this scan's result (its summary line). The last scan's summary stays on screen until the
 * click is drawn, and may read the same words, so the robot's clock is held until the view shows this scan under
 * way (its Cancel): the summary waited for is then the new one.
 */
async function scanNow(page: Page, done: RegExp): Promise<string> {
  await page.evaluate(() => window.__rbcTest?.clock.hold());
  await page.getByTestId("doctor-scan").click();
  await page.getByTestId("doctor-cancel").waitFor();
  await page.evaluate(() => window.__rbcTest?.clock.release());
  const status = page.getByTestId("doctor-scan-status").filter({ hasText: done });
  await status.waitFor();
  return text(status);
}

const status = (page: Page, id: number) => text(page.getByTestId(`doctor-status-${id}`));
const findings = (page: Page) =>
  page
    .locator("[data-testid=doctor-findings] li")
    .allTextContents()
    .then((l) => l.map(squash));

/** The ids the table shows as read (a status other than "not read"), in order. */
function readIds(page: Page): Promise<number[]> {
  return page.evaluate(() =>
    [...document.querySelectorAll("[data-testid^=doctor-status-]")]
      .filter((cell) => !cell.querySelector(".muted"))
      .map((cell) => Number(cell.getAttribute("data-testid")?.replace("doctor-status-", ""))),
  );
}

/**
 * Holds the robot's clock from inside the page the moment the table shows at least `count` ids read, so the scan
 * is caught in the middle however slowly the test's own steps run; returns the ids read then.
 */
async function holdAfterReads(page: Page, count: number): Promise<number[]> {
  const handle = await page.waitForFunction((n) => {
    const read = [...document.querySelectorAll("[data-testid^=doctor-status-]")].filter(
      (cell) => !cell.querySelector(".muted"),
    );
    if (read.length < n) return false;
    window.__rbcTest?.clock.hold();
    return read.map((cell) => Number(cell.getAttribute("data-testid")?.replace("doctor-status-", "")));
  }, count);
  return (await handle.jsonValue()) as number[];
}

describe("Servo check on the demo robot", () => {
  it("finds a replacement servo at id 0, fixes its id with the guided fix, and scans clean; axe clean before and after", async () => {
    const { page, context } = await openDoctor("en-US");
    await expectText(
      page.locator(".doctor-view .view-head p").first(),
      "Find servos that do not answer or carry the wrong id",
      { contains: true },
    );
    expect(await axeProblems(page, { within: ".doctor-view" })).toEqual([]);

    // A replacement servo for the right knee (7), still at the factory id 0; it survives a reconnect.
    await simulateFault(page, "replacement", 7, "replacement servo (still id 0), servo 7");
    await page.getByRole("link", { name: "Robot", exact: true }).click();
    await page.getByRole("button", { name: "Disconnect" }).click();
    await connectDemo(page);
    await page.getByRole("link", { name: "Servo check", exact: true }).click();
    await page
      .getByTestId("doctor-demo-now")
      .filter({ hasText: "replacement servo (still id 0), servo 7" })
      .waitFor();

    await scanNow(page, /Scanned 16 ids/);
    await expectText(
      page.getByTestId("doctor-scan-status"),
      "Scanned 16 ids: 14 answered, 1 silent, 1 garbled.",
    );
    await expect.poll(() => status(page, 0)).toMatch(/^garbled/);
    await expect.poll(() => status(page, 7)).toBe("silent");
    await expect.poll(() => status(page, 8)).toBe("answered");
    await expect
      .poll(() => findings(page))
      .toEqual([
        "Id 0 is answered by two servos and id 7 by none: a replacement servo still has the factory id 0. Unplug servo 0, then give the new servo id 7 with the guided id fix.",
      ]);
    // The figure shows the same: id 0 a garbled mark, id 7 a silent one (the robot's left leg on the viewer's right).
    const mark = (id: number) => page.locator(`[data-testid=servo-figure] g[data-servo="${id}"]`);
    await expect.poll(() => mark(0).getAttribute("class")).toContain("mark--garbled");
    await expect.poll(() => mark(7).getAttribute("class")).toContain("mark--silent");
    const x = async (id: number) => Number(await mark(id).locator("text").getAttribute("x"));
    await expect.poll(() => x(0)).toBeGreaterThan(await x(5));
    expect(await axeProblems(page, { within: ".doctor-view" })).toEqual([]);

    // The guided fix, filled in from the scan: id 0 is garbled, so it is refused and asks to unplug the other one.
    await page.getByTestId("doctor-fix-suggested").filter({ hasText: "id 0 → id 7" }).waitFor();
    await expect.poll(() => page.locator("#doctor-fix-from").inputValue()).toBe("0");
    await expect.poll(() => page.locator("#doctor-fix-to").inputValue()).toBe("7");
    await page.getByTestId("doctor-fix").click();
    const result = page.getByTestId("doctor-fix-result");
    await result.filter({ hasText: "Not changed" }).waitFor();
    await expectText(
      result,
      "Not changed: more than one servo answers at id 0, and all of them would take the new id. Unplug the other servos of that chain, then try again.",
    );

    // Unplug servo 0 (as a person would), scan again: id 0 is one servo now, id 7 still silent.
    await page.getByTestId("doctor-demo-unplug").click();
    await scanNow(page, /Scanned 16 ids/);
    await expect.poll(() => status(page, 0)).toBe("answered");
    await expect.poll(() => status(page, 7)).toBe("silent");
    await expect
      .poll(() => findings(page))
      .toEqual(["Servo 7 (Right knee) does not answer: check its cable and the one before it in the chain."]);

    // The fix asks once, then says what it read after.
    await page.getByTestId("doctor-fix").click();
    const question = page.getByRole("alertdialog");
    await question.waitFor();
    await expectText(
      question,
      /^One servo answers at id 0 \(position \d+\) and none at id 7\. Give it id 7\?/,
    );
    await page.getByTestId("doctor-fix-confirm").click();
    await result.filter({ hasText: "Done" }).waitFor();
    await expectText(
      result,
      /^Done: the servo that was id 0 is now id 7\. A read at id 7 answered \(position \d+\) and id 0 is silent\.$/,
    );

    // Servo 0 plugged back in: a clean scan.
    await page.getByTestId("doctor-demo-plug-back").click();
    await scanNow(page, /Scanned 16 ids/);
    await expectText(
      page.getByTestId("doctor-scan-status"),
      "Scanned 16 ids: 16 answered, 0 silent, 0 garbled. Every servo 0-15 answered, with no high load at rest.",
    );
    await expect.poll(() => page.getByTestId("doctor-findings").count()).toBe(0);
    await expect.poll(() => status(page, 7)).toBe("answered");
    expect(await axeProblems(page, { within: ".doctor-view" })).toEqual([]);
    await context.close();
  });

  it("speaks Korean through the same walk", async () => {
    const { page, context } = await openDoctor("ko-KR");
    await simulateFault(page, "replacement", 3, "교체한 서보 (아직 ID 0), 서보 3번");
    await scanNow(page, /ID 16개를 검사했어요/);
    await expect.poll(() => status(page, 0)).toMatch(/^깨진 응답/);
    await expect.poll(() => status(page, 3)).toBe("응답 없음");
    await expect
      .poll(() => findings(page))
      .toEqual([
        "ID 0에는 서보 두 개가 응답하고 ID 3에는 아무것도 응답하지 않아요. 새로 바꾼 서보가 아직 공장 ID 0을 갖고 있어요. 서보 0번을 뺀 다음, ID 고치기로 새 서보에 ID 3을 주세요.",
      ]);
    await expectText(
      page.locator(".doctor-view .sides-note"),
      "왼쪽과 오른쪽은 로봇 기준이에요. 로봇이 나를 마주 보고 있으면 로봇의 왼팔은 내 오른쪽에 있어요.",
    );
    await page.getByTestId("doctor-fix").click();
    const result = page.getByTestId("doctor-fix-result");
    await result.filter({ hasText: "바꾸지 않았어요" }).waitFor();
    await page.getByTestId("doctor-demo-unplug").click();
    await scanNow(page, /ID 16개를 검사했어요/);
    await page.getByTestId("doctor-fix").click();
    await page.getByRole("alertdialog").filter({ hasText: "ID 3을 줄까요?" }).waitFor();
    await page.getByTestId("doctor-fix-confirm").click();
    await result.filter({ hasText: "다 됐어요" }).waitFor();
    await expectText(result, /^다 됐어요\. ID 0이던 서보가 이제 ID 3이에요\./);
    await page.getByTestId("doctor-demo-plug-back").click();
    await scanNow(page, /ID 16개를 검사했어요/);
    await expectText(
      page.getByTestId("doctor-scan-status"),
      "ID 16개를 검사했어요. 응답함 16, 응답 없음 0, 깨진 응답 0. 서보 0-15가 모두 응답했고, 쉬는 동안 부하가 높은 서보도 없어요.",
    );
    expect(await keysShown(page)).toEqual([]);
    expect(await axeProblems(page, { within: ".doctor-view" })).toEqual([]);
    await context.close();
  });

  it("Cancel mid-scan says which ids were read and which were not", async () => {
    const { page, context } = await openDoctor("en-US");
    await page.getByText("All 31 ids (0-30)").click();
    await page.getByTestId("doctor-scan").click();
    const read = await holdAfterReads(page, 4);
    // The progress bar counts the ids read, out of 31.
    const bar = page.getByRole("progressbar");
    await expect.poll(() => bar.getAttribute("max")).toBe("31");
    await expect.poll(() => bar.evaluate((p) => (p as HTMLProgressElement).value)).toBe(read.length);
    await page.getByTestId("doctor-cancel").click();
    await page.evaluate(() => window.__rbcTest?.clock.release());
    const stopped = await text(
      page.getByTestId("doctor-scan-status").filter({ hasText: "The scan stopped (cancelled)" }),
    );
    // The ids read: those shown when Cancel was pressed, and at most the one whose read was on the wire then.
    const after = await readIds(page);
    expect(after.slice(0, read.length)).toEqual(read);
    expect(after.length - read.length).toBeLessThanOrEqual(1);
    const unread = Array.from({ length: 31 - after.length }, (_, i) => after.length + i);
    expect(stopped).toBe(
      `The scan stopped (cancelled). Read: ${after.join(", ")}. Not read: ${unread.join(", ")}. Scanned ${after.length} ids: ${after.length} answered, 0 silent, 0 garbled.`,
    );
    await expect.poll(() => status(page, after.length)).toBe("not read");
    // Direct mode was left at the end: the top bar no longer says servo control.
    await expect.poll(() => text(page.getByTestId("connection-status"))).not.toContain("servo control");
    await context.close();
  });

  it("the top bar's Stop during a scan ends it, and the view says so", async () => {
    const { page, context } = await openDoctor("en-US");
    await page.getByText("All 31 ids (0-30)").click();
    await page.getByTestId("doctor-scan").click();
    const read = await holdAfterReads(page, 3);
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    await page.evaluate(() => window.__rbcTest?.clock.release());
    const stopped = await text(
      page.getByTestId("doctor-scan-status").filter({ hasText: "The scan stopped (Stop was pressed)" }),
    );
    // The ids read: those shown when Stop was pressed, and those read before the Stop reached the servo bus.
    const after = await readIds(page);
    expect(after.slice(0, read.length)).toEqual(read);
    expect(after.length).toBeLessThan(31);
    expect(stopped).toContain(`Read: ${after.join(", ")}. Not read: ${after.length}, `);
    // Stop leaves the servos holding: no servo was made passive.
    const passive = await page.evaluate(() => window.__rbcDemoSim?.servos.map((s) => s.passive));
    expect(passive).toEqual(Array(16).fill(false));

    // Stop while the next scan is still entering direct mode (docs/protocol.md §3.6): the robot's clock is held
    // the moment the robot answers the 0x10, before that answer reaches the page. Stop wins: the top bar says
    // what it did (servo control ended), not "Stop failed", and the scan says Stop stopped it, no id read.
    await page.evaluate(() => {
      const sim = window.__rbcDemoSim;
      const unwatch = sim?.onTransmit((bytes) => {
        if (bytes[8] !== 0x10) return;
        window.__rbcTest?.clock.hold();
        unwatch?.();
      });
    });
    await page.getByTestId("doctor-scan").click();
    await page.waitForFunction(() => window.__rbcDemoSim?.directMode === true);
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    await page.evaluate(() => window.__rbcTest?.clock.release());
    const banner = page.getByTestId("stop-banner");
    await banner.filter({ hasText: "Servo control ended" }).waitFor();
    expect(await text(banner)).not.toContain("Stop failed");
    const entryStopped = await text(
      page.getByTestId("doctor-scan-status").filter({ hasText: "The scan stopped (Stop was pressed)" }),
    );
    expect(entryStopped).toContain("Not read: 0, 1, 2,");
    expect(await readIds(page)).toEqual([]);
    await expect.poll(() => page.evaluate(() => window.__rbcDemoSim?.directMode)).toBe(false);
    const stillHolding = await page.evaluate(() => window.__rbcDemoSim?.servos.map((s) => s.passive));
    expect(stillHolding).toEqual(Array(16).fill(false));
    await context.close();
  });

  it("picks a servo on the figure, reads its settings, and wiggles it after one question: a loaded servo does not follow", async () => {
    const { page, context } = await openDoctor("en-US");
    await simulateFault(page, "loaded", 4, "loaded servo, servo 4");
    await scanNow(page, /Scanned 16 ids/);
    await expect
      .poll(async () => (await findings(page))[0])
      .toMatch(/^Servo 4 \(Left ankle roll\) carries a high load at rest \(\d+\)/);
    const mark = page.locator('[data-testid=servo-figure] g[data-servo="4"]');
    await expect.poll(() => mark.getAttribute("class")).toContain("mark--high-load");
    await mark.click();
    // The pick is drawn on the panel's next render: polled.
    await expect.poll(() => page.getByTestId("doctor-pick").inputValue()).toBe("4");
    await page.getByTestId("doctor-read").click();
    const info = page.getByTestId("doctor-info");
    await info.waitFor();
    await expectText(
      info,
      /^Status: answered, position \d+, load 180\. Settings read from servo 4 P and D gains P \d+, D \d+ /,
    );
    await expectText(info, "bounds (lower, upper) 1, 254", { contains: true });

    // Nothing moves before the question is answered.
    await page.getByTestId("doctor-wiggle-ask").click();
    const question = page.getByRole("alertdialog");
    await expectText(question, "Hold the robot or lay it down: servo 4 will move a few counts each way.", {
      contains: true,
    });
    const before = await page.evaluate(() => window.__rbcDemoSim?.servos[4]?.position);
    await page.getByTestId("doctor-wiggle-go").click();
    const result = page.getByTestId("doctor-wiggle-result");
    await result.waitFor();
    await expectText(
      result,
      new RegExp(
        `^Servo 4 \\(Left ankle roll\\) did not follow the wiggle \\(±5 from ${before}, at the lowest torque\\): it made \\d+% of the swing; highest load \\d+\\.$`,
      ),
    );
    expect(await axeProblems(page, { within: ".doctor-view" })).toEqual([]);
    await context.close();
  });

  it("is refused while the robot plays a motion started elsewhere, says so, and offers Stop", async () => {
    const { page, context } = await newLocalePage(app, "en-US", {
      options: { ...QUARTER, variant: { busyMotion: 2 } },
    });
    await connectRobot(page, app.url);
    await page.getByRole("link", { name: "Servo check", exact: true }).click();
    await page.getByTestId("doctor-scan").click();
    const problem = page.getByTestId("doctor-problem");
    await problem.filter({ hasText: "Not started" }).waitFor();
    await expectText(
      problem,
      "The servo check could not run. Not started: the robot is busy, probably playing a motion started elsewhere",
      { contains: true },
    );
    expect(await page.evaluate(() => window.__rbcTest?.sim.directMode)).toBe(false);
    await problem.getByRole("button", { name: "Stop" }).click();
    await page.getByTestId("stop-banner").waitFor();
    // The motion ends at the end of its scene (robot time at a quarter of real speed).
    await expect
      .poll(() => page.evaluate(() => window.__rbcTest?.sim.playingMotion ?? null), { timeout: 30_000 })
      .toBe(null);
    await scanNow(page, /Scanned 16 ids/);
    await expectText(problem, "");
    await context.close();
  });

  it("the top bar's Stop during a wiggle ends it, and the servo keeps holding", async () => {
    const { page, context } = await openDoctor("en-US");
    await page.getByTestId("doctor-pick").selectOption("2");
    await page.getByTestId("doctor-wiggle-ask").click();
    // Caught in the middle: the robot's clock is held the moment servo 2 first moves (an event in the
    // simulator, not a poll of the page that a short wiggle could slip past).
    await page.evaluate(() => {
      const sim = window.__rbcDemoSim;
      const start = sim?.servoPositions()[2];
      const unwatch = sim?.onServos((positions) => {
        if (positions[2] === start) return;
        window.__rbcTest?.clock.hold();
        unwatch?.();
      });
    });
    await page.getByTestId("doctor-wiggle-go").click();
    await page.waitForFunction(() =>
      document.querySelector("[data-testid=doctor-servo-card]")?.textContent?.includes("Wiggling"),
    );
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    await page.evaluate(() => window.__rbcTest?.clock.release());
    const result = page.getByTestId("doctor-wiggle-result");
    await result.waitFor();
    await expectText(
      result,
      "The wiggle stopped (Stop was pressed); nothing more was sent. The servo holds where it got to.",
    );
    expect(await page.evaluate(() => window.__rbcDemoSim?.servos[2]?.passive)).toBe(false);
    await context.close();
  });

  it("a scan ended by a pulled cable says, on the next connection, which ids were read", async () => {
    const { page, context } = await newLocalePage(app, "en-US", { options: QUARTER });
    await connectRobot(page, app.url);
    await page.getByRole("link", { name: "Servo check", exact: true }).click();
    await page.getByText("All 31 ids (0-30)").click();
    await page.getByTestId("doctor-scan").click();
    const read = await holdAfterReads(page, 3);
    await page.evaluate(() => window.__rbcTest?.port.unplug());
    await page.evaluate(() => window.__rbcTest?.clock.release());
    await page.getByTestId("lost-notice").filter({ hasText: "Did not finish: Servo check" }).waitFor();

    await page.evaluate(() => window.__rbcTest?.port.replug());
    await page.getByRole("button", { name: "Connect robot" }).click();
    const said = page.getByTestId("doctor-scan-status").filter({ hasText: "link was lost" });
    await said.waitFor();
    const sentence = await text(said);
    const shown = /Read: ([\d, ]+)\. Not read: ([\d, ]+)\.$/.exec(sentence);
    expect(sentence).toMatch(
      /^The last scan, on the connection before this one: The scan stopped \(the robot's link was lost\)\. Read: /,
    );
    const readIds = (shown?.[1] ?? "").split(", ").map(Number);
    const notRead = (shown?.[2] ?? "").split(", ").map(Number);
    expect(readIds.slice(0, read.length)).toEqual(read);
    expect([...readIds, ...notRead]).toEqual([...Array(31).keys()]);
    await context.close();
  });

  for (const [locale, lang, now] of [
    ["en-US", "en", "replacement servo (still id 0), servo 12"],
    ["ko-KR", "ko", "교체한 서보 (아직 ID 0), 서보 12번"],
  ] as const) {
    it(`fits a phone in ${locale} after a scan and a refused fix: no key, no label overflow, no sideways scroll, axe clean`, async () => {
      const { page, context } = await openDoctor(locale, PHONE);
      await simulateFault(page, "replacement", 12, now);
      await page.getByTestId("doctor-scan").click();
      await page.getByTestId("doctor-findings").waitFor();
      await page.getByTestId("doctor-fix").click();
      await page.getByTestId("doctor-demo-unplug").waitFor();
      await page.getByTestId("doctor-pick").selectOption("12");
      expect(await pageProblems(page, { lang })).toEqual([]);
      await context.close();
    });
  }
});
