import type { Page } from "playwright-core";
import { describe, expect, it } from "vitest";
import { CABLE, loadConnected } from "./connected-page.ts";
import { expectText, FAST, holdRobot, releaseRobot, robotTime, squash, useApp } from "./harness.ts";
import { axeProblems } from "./i18n-checks.ts";
import "./rbc-test-globals.ts";

// Issue 21 item 4 and issue 20 item 2 (docs/protocol.md §3.6): a robot busy with a motion started elsewhere (the
// remote) is told apart from a silent one with the busy probe; the top bar says so with a Stop right there, and
// Stop, when the panel started nothing, asks the robot: busy, it sends 7 and says what the robot answered; idle,
// it says so and sends nothing. The robot runs on the paced virtual clock (FAST); nothing is retried.

const app = useApp();

/** The fake port's robot: what it plays, whether it has servos passive or is in direct mode. */
const robot = (page: Page) =>
  page.evaluate(() => {
    const sim = window.__rbcTest?.sim;
    return {
      playing: sim?.playingMotion,
      anyPassive: sim?.servos.slice(0, 16).some((s) => s.passive),
      direct: sim?.directMode,
    };
  });

/** Packets the robot has received (whole, handled or dropped). */
const packetsIn = (page: Page) =>
  page.evaluate(() => window.__rbcTest?.sim.stats.packetsReceived ?? Number.NaN);

const banner = (page: Page) => page.getByTestId("stop-banner");

/**
 * The Robot view has read the robot, and half a second of the robot's time has passed with the connection's own
 * requests done (the connect-time busy probe, the view's reads): packets counted after this are the test's.
 */
async function settled(page: Page): Promise<void> {
  await page.getByTestId("device-card").waitFor();
  await robotTime(page, 500);
}

describe("a robot busy with a motion started by the remote", () => {
  it("on connect the top bar says the robot is busy (not gone) with a Stop right there; that Stop sends 7 and says what the robot answered", async () => {
    const { page, context } = await app.newPage({
      start: CABLE,
      options: { ...FAST, variant: { busyMotion: 2 } },
    });
    await loadConnected(page, app.url);
    const busy = page.getByTestId("busy-banner");
    await busy.waitFor();
    // The robot's time stands still while the test looks (motion 2 plays 6.6 s of it).
    await holdRobot(page);
    await expectText(
      busy.locator("p"),
      "The robot is busy playing a motion (started with the remote or another program); it answers when the motion ends.",
    );
    expect(await robot(page)).toMatchObject({ playing: 2 });
    expect(await axeProblems(page, { within: ".top-bar" })).toEqual([]);

    await busy.getByRole("button", { name: "Stop" }).click();
    await releaseRobot(page);
    const said = banner(page).locator(".notice--ok");
    await said.filter({ hasText: "It took Stop" }).waitFor();
    await expectText(
      said.locator(".banner-text > p"),
      "The robot was busy with a motion started with the remote or another program (which one, the robot does not say). It took Stop: the motion ended at the end of the scene it was in. The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing.",
    );
    // The 7 and the 07 are the technical detail, one click away.
    const detail = said.getByTestId("notice-more");
    await expect.poll(() => detail.isVisible()).toBe(false);
    await said.locator("summary").click();
    await expectText(detail, /^Stop sent 7; the robot answered 07 after \d\.\d s\.$/);
    // The 07 came within the end of a scene (at most 1 s here), not at the end of motion 2's 6.6 s; the robot
    // stands, in packet mode.
    const elapsed = Number(/answered 07 after (\d\.\d) s/.exec(squash(await detail.textContent()))?.[1]);
    expect(elapsed).toBeLessThanOrEqual(1);
    expect(await robot(page)).toMatchObject({ playing: undefined, anyPassive: false, direct: false });
    // Its main loop answered again: the busy sentence is gone.
    await busy.waitFor({ state: "detached" });
    await context.close();
  });

  it("a motion started from the remote after connecting: the top bar's Stop asks the robot, sends 7 once and reports the 07", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await loadConnected(page, app.url);
    await settled(page);
    // The test hook: the simulated robot's remote starts Walk backward (10, 2.45 s), not the panel.
    const received = await packetsIn(page);
    // Held, so that the 2.45 s walk is still playing when Stop reaches the robot however slowly the test runs.
    await holdRobot(page);
    expect(await page.evaluate(() => window.__rbcTest?.sim.playFromRemote(10))).toBe(true);
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    await releaseRobot(page);
    await banner(page).filter({ hasText: "It took Stop" }).waitFor();
    expect(squash(await banner(page).textContent())).not.toContain("Nothing was running");
    expect(await robot(page)).toMatchObject({ playing: undefined, anyPassive: false, direct: false });
    // The probe (0x16, 0x12, 0x16, 0x12) and one 7: five packets reached the robot for this Stop.
    expect((await packetsIn(page)) - received).toBe(5);
    await context.close();
  });

  it("an idle robot: Stop says what the robot answered and sends nothing else", async () => {
    const { page, context } = await app.newPage({ start: CABLE, options: FAST });
    await loadConnected(page, app.url);
    await settled(page);
    await expect.poll(() => robot(page).then((r) => r.playing)).toBeUndefined();
    const received = await packetsIn(page);
    await page.getByRole("button", { name: "Stop", exact: true }).click();
    await banner(page).filter({ hasText: "it is idle" }).waitFor();
    await expectText(
      banner(page).locator("p").first(),
      "The robot answered at once: it is idle, nothing to stop. Nothing was sent.",
    );
    // One packet: the probe's distance read, answered at once.
    expect((await packetsIn(page)) - received).toBe(1);
    await context.close();
  });
});

describe("in Korean", () => {
  it("says the busy robot and Stop's result in Korean", async () => {
    const { page, context } = await app.newPage({
      options: { ...FAST, variant: { busyMotion: 2 } },
      locale: "ko-KR",
    });
    await page.goto(app.url, { waitUntil: "domcontentloaded" });
    await page.getByRole("button", { name: "로봇 연결" }).click();
    const busy = page.getByTestId("busy-banner");
    await busy.waitFor();
    await holdRobot(page);
    await expectText(
      busy.locator("p"),
      "로봇이 모션을 재생하느라 바빠요 (리모컨이나 다른 프로그램으로 시작한 모션). 모션이 끝나면 응답해요.",
    );
    await busy.getByRole("button", { name: "정지" }).click();
    await releaseRobot(page);
    await banner(page).filter({ hasText: "로봇이 정지를 받았어요" }).waitFor();
    await expectText(
      banner(page).locator(".banner-text > p"),
      "(어떤 모션인지는 로봇이 알려 주지 않아요). 로봇이 정지를 받았어요. 모션은 하던 장면이 끝날 때 멈췄어요. 로봇은 서보에 힘이 들어간 채로 멈춘 자세를 유지해요. 넘어지지는 않지만, 꼭 서 있는 자세는 아니에요.",
      { contains: true },
    );
    // The 7 and the 07, one click away, in Korean too.
    await expectText(
      banner(page).getByTestId("notice-more"),
      /^정지가 7을 보냈고, 로봇이 .+ 뒤에 07로 응답했어요\.$/,
    );
    await context.close();
  });
});
