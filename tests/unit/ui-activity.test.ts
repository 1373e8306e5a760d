import { describe, expect, it } from "vitest";
import type { ActivitySnapshot, MotionActivity } from "../../src/device/index.ts";
import { initialState } from "../../src/ui/app-state.ts";
import { initialClass } from "../../src/ui/features/class/state.ts";
import {
  busyElsewhere,
  cancellingNow,
  isCancelling,
  isLimp,
  isPlaying,
  isStopping,
  isUploading,
  playingMotion,
  playingSound,
} from "../../src/ui/features/connection/activity.ts";
import type { ConnectionState } from "../../src/ui/features/connection/state.ts";
import { noticeText } from "../../src/ui/notices.ts";
import { anyRobotConnected } from "../../src/ui/stop-all.ts";
import { stoppingNotice } from "../../src/ui/stop-outcome.ts";

/** The panel reads what the robot does from the device's activity snapshot, through small selectors. */

const base = initialState({ serialSupported: true, secureContext: true, route: "robot" });
const idle: ActivitySnapshot = { doing: { kind: "idle", since: 0 }, halt: undefined, limp: false };
const playing: MotionActivity = {
  kind: "motion",
  motion: 2,
  startedAt: 100,
  expectedMs: 6600,
  after: "idle",
  ended: new Promise(() => {}),
};
const motion: ActivitySnapshot = { doing: playing, halt: undefined, limp: false };
const connected = (activity: ActivitySnapshot): ConnectionState => ({
  ...base.connection,
  phase: "connected",
  activity,
});

describe("the selectors of the device's activity", () => {
  it("idle, or no robot: nothing plays, nothing stops, not limp", () => {
    for (const c of [base.connection, connected(idle)]) {
      expect([playingMotion(c), playingSound(c), busyElsewhere(c)]).toEqual([
        undefined,
        undefined,
        undefined,
      ]);
      expect([isPlaying(c), isStopping(c), isLimp(c)]).toEqual([false, false, false]);
    }
  });

  it("a motion of the panel: playing; stopping once its 7 was sent or Stop is under way", () => {
    const c = connected(motion);
    expect(playingMotion(c)).toMatchObject({ motion: 2, startedAt: 100, expectedMs: 6600 });
    expect([isPlaying(c), isStopping(c)]).toEqual([true, false]);
    const sent = connected({ ...motion, doing: { ...playing, stop7: { by: "caller", sentAt: 900 } } });
    expect(isStopping(sent)).toBe(true);
    const halting = connected({ ...motion, halt: { kind: "stop", since: 900, done: new Promise(() => {}) } });
    expect(isStopping(halting)).toBe(true);
  });

  it("a sound, a motion started elsewhere, every servo limp", () => {
    const sound = connected({
      ...idle,
      doing: { kind: "sound", sound: 8, startedAt: 40, expectedMs: 5916, ended: new Promise(() => {}) },
    });
    expect(playingSound(sound)).toMatchObject({ sound: 8, startedAt: 40, expectedMs: 5916 });
    expect(isPlaying(sound)).toBe(false);
    const busy = connected({ ...idle, doing: { kind: "busy", since: 7, evidence: "probe" } });
    expect(busyElsewhere(busy)).toEqual({ kind: "busy", since: 7, evidence: "probe" });
    expect(isPlaying(busy)).toBe(true);
    expect(isLimp(connected({ ...idle, limp: true }))).toBe(true);
  });

  it("an upload or a firmware update is cancelling only once the machine says so; nothing else is", () => {
    const abort = new AbortController();
    const upload: ActivitySnapshot = { ...idle, doing: { kind: "upload", since: 5, abort } };
    expect([isUploading(connected(upload)), isCancelling(connected(upload))]).toEqual([true, false]);
    expect(isUploading(connected(idle))).toBe(false);
    // Stop pressed during any step of it, the free-memory read or the reset too, says it cancels the upload.
    const notice = stoppingNotice({ ...base, connection: connected(upload) }, 50);
    expect(noticeText(notice, "en")).toBe("Stopping: cancelling the upload…");
    const cancelled = {
      ...upload,
      doing: { kind: "upload", since: 5, abort, cancelling: { since: 60 } },
    } as const;
    expect(isCancelling(connected(cancelled))).toBe(true);
    expect(cancellingNow(cancelled)).toBe(true);
    const firmware: ActivitySnapshot = { ...idle, doing: { kind: "firmware", since: 5 } };
    expect(cancellingNow(firmware)).toBe(false);
    expect(
      cancellingNow({ ...firmware, doing: { kind: "firmware", since: 5, cancelling: { since: 9 } } }),
    ).toBe(true);
    expect([cancellingNow(undefined), cancellingNow(idle), cancellingNow(motion)]).toEqual([
      false,
      false,
      false,
    ]);
    expect(isCancelling(base.connection)).toBe(false);
  });
});

describe("the page's Stop is there whenever a robot of the page is connected", () => {
  const classRobot = (phase: "connecting" | "connected" | "lost") => ({
    ...initialClass(),
    robots: [{ id: 1, demo: true, portLabel: "demo", demoNumber: 1, phase, selected: true }],
  });

  it("no robot: no Stop; the top-bar robot or a connected Class view robot: Stop", () => {
    expect(anyRobotConnected(base)).toBe(false);
    expect(anyRobotConnected({ ...base, connection: connected(idle) })).toBe(true);
    expect(anyRobotConnected({ ...base, classRoom: classRobot("connected") })).toBe(true);
    expect(anyRobotConnected({ ...base, classRoom: classRobot("connecting") })).toBe(false);
    expect(anyRobotConnected({ ...base, classRoom: classRobot("lost") })).toBe(false);
  });
});
