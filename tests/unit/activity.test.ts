import { describe, expect, it } from "vitest";
import {
  Activity,
  ActivityRefusedError,
  type ActivitySnapshot,
  type Doing,
} from "../../src/device/activity.ts";
import type { LimpResult } from "../../src/device/limp.ts";
import type { StopActivityResult } from "../../src/device/stop.ts";
import { errorText } from "../../src/i18n/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";

const STOP_RESULT: StopActivityResult = { uploadCancelled: false, servoMovesDropped: false };
const LIMP_RESULT: LimpResult = { confirmed: [0], silent: [] };

function machine() {
  const clock = new VirtualClock();
  const seen: ActivitySnapshot[] = [];
  const activity = new Activity(clock, (s) => seen.push(s));
  return { clock, activity, seen };
}

type Machine = ReturnType<typeof machine>;

/** Puts a fresh machine in each state of the `doing` region. */
const ARRANGE: Record<Doing["kind"], (m: Machine) => void> = {
  idle: () => {},
  motion: ({ activity }) => {
    activity.startMotion(2, 1800);
  },
  busy: ({ activity }) => activity.noticeBusy("probe"),
  sound: ({ activity }) => {
    activity.startSound(8, 5916);
  },
  upload: ({ activity }) => activity.startUpload(new AbortController()),
  firmware: ({ activity }) => activity.startFirmware(),
  direct: ({ activity }) => activity.enterDirect("servo-control"),
};

/** Each transition of the `doing` region, and the states it is allowed from. */
const TRANSITIONS: Array<{
  name: string;
  label?: string;
  from: Doing["kind"][];
  apply: (m: Machine) => unknown;
}> = [
  { name: "startMotion", from: ["idle", "busy"], apply: ({ activity }) => activity.startMotion(4, 3100) },
  { name: "sendStop7", from: ["motion"], apply: ({ activity }) => activity.sendStop7("stop") },
  { name: "motionReplied", from: ["motion"], apply: ({ activity }) => activity.motionReplied(2) },
  { name: "motionFailed", from: ["motion"], apply: ({ activity }) => activity.motionFailed() },
  { name: "noticeBusy", from: ["idle"], apply: ({ activity }) => activity.noticeBusy("probe") },
  { name: "busyEnded", from: ["busy"], apply: ({ activity }) => activity.busyEnded() },
  { name: "startSound", from: ["idle"], apply: ({ activity }) => activity.startSound(3, 1000) },
  { name: "soundEnded", from: ["sound"], apply: ({ activity }) => activity.soundEnded(8) },
  {
    name: "startUpload",
    from: ["idle"],
    apply: ({ activity }) => activity.startUpload(new AbortController()),
  },
  { name: "startFirmware", from: ["idle", "busy"], apply: ({ activity }) => activity.startFirmware() },
  { name: "enterDirect", from: ["idle"], apply: ({ activity }) => activity.enterDirect("teach-in") },
  { name: "handDirect", from: ["direct"], apply: ({ activity }) => activity.handDirect("tethered-play") },
  { name: "exitDirect", from: ["direct"], apply: ({ activity }) => activity.exitDirect() },
  {
    name: "enterDirect",
    label: "requireIdle (asked before entering direct mode)",
    from: ["idle"],
    apply: ({ activity }) => activity.requireIdle("enterDirect"),
  },
];

const KINDS = Object.keys(ARRANGE) as Doing["kind"][];

describe("the activity machine: every transition of what the robot is doing, allowed and refused", () => {
  for (const t of TRANSITIONS) {
    for (const kind of KINDS) {
      const allowed = t.from.includes(kind);
      it(`${t.label ?? t.name} from ${kind}: ${allowed ? "allowed" : "refused, nothing changes"}`, () => {
        const m = machine();
        ARRANGE[kind](m);
        const before = m.activity.snapshot;
        const changes = m.seen.length;
        if (allowed) {
          expect(() => t.apply(m)).not.toThrow();
          return;
        }
        let error: unknown;
        try {
          t.apply(m);
        } catch (e) {
          error = e;
        }
        expect(error).toBeInstanceOf(ActivityRefusedError);
        expect(error).toMatchObject({ code: "wrong-mode", transition: t.name, from: kind });
        expect(errorText(error, "en")).toMatch(/^Not started: the robot is .+\. Nothing was sent\.$/);
        expect(errorText(error, "ko")).toMatch(
          /^시작하지 않았어요\. 로봇이 지금 .+\. 아무것도 보내지 않았어요\.$/,
        );
        expect(m.activity.snapshot).toEqual(before);
        expect(m.activity.doing).toBe(before.doing);
        expect(m.seen.length).toBe(changes);
      });
    }
  }
});

describe("the activity machine: what each transition leads to", () => {
  it("starts at idle, stamped with the clock", async () => {
    const clock = new VirtualClock();
    await clock.advance(250);
    expect(new Activity(clock).doing).toEqual({ kind: "idle", since: 250 });
  });

  it("a motion: started (number, sent at, expected length), replied, then idle; its end settles with the echo", async () => {
    const { clock, activity, seen } = machine();
    await clock.advance(100);
    const started = activity.startMotion(2, 1800);
    expect(activity.doing).toMatchObject({
      kind: "motion",
      motion: 2,
      startedAt: 100,
      expectedMs: 1800,
      after: "idle",
    });
    expect(activity.motion).toBe(started);
    expect(activity.isCurrent(started)).toBe(true);
    await clock.advance(1800);
    const { ended, postureFollows } = activity.motionReplied(2);
    expect(ended.motion).toBe(2);
    expect(postureFollows).toBe(false);
    expect(activity.doing).toEqual({ kind: "idle", since: 1900 });
    expect(activity.isCurrent(started)).toBe(false);
    expect(await started.ended).toBe(2);
    expect(seen.map((s) => s.doing.kind)).toEqual(["motion", "idle"]);
  });

  it("a motion over one started elsewhere is recorded as such (after: busy)", () => {
    const { activity } = machine();
    activity.noticeBusy("probe");
    expect(activity.doing).toMatchObject({ kind: "busy", evidence: "probe" });
    expect(activity.startMotion(4, 3100).after).toBe("busy");
  });

  it("a motion started elsewhere ends: busy → idle", async () => {
    const { clock, activity } = machine();
    activity.noticeBusy();
    await clock.advance(2800);
    activity.busyEnded();
    expect(activity.doing).toEqual({ kind: "idle", since: 2800 });
  });

  it("7 is sent once whoever asks: the first asker sends it, later ones only wait", async () => {
    const { clock, activity } = machine();
    const started = activity.startMotion(2, 1800);
    await clock.advance(300);
    expect(activity.sendStop7("stop")).toBe(true);
    expect(activity.motion?.stop7).toEqual({ by: "stop", sentAt: 300 });
    expect(activity.sendStop7("limp")).toBe(false);
    expect(activity.sendStop7("caller")).toBe(false);
    expect(activity.motion?.stop7?.by).toBe("stop");
    // The record changed, the motion is still the same one.
    expect(activity.isCurrent(started)).toBe(true);
    const { ended, postureFollows } = activity.motionReplied(7);
    expect(ended.stop7?.by).toBe("stop");
    expect(postureFollows).toBe(false);
    expect(activity.doing.kind).toBe("idle");
    expect(await started.ended).toBe(7);
  });

  it("Basic posture cannot be stopped: no 7 is sent for it", () => {
    const { activity } = machine();
    activity.startMotion(7, 1800);
    expect(activity.sendStop7("stop")).toBe(false);
    expect(activity.motion?.stop7).toBeUndefined();
  });

  it("it ended just before the 7: the robot took the 7 as Basic posture, which then plays and answers 07", async () => {
    const { clock, activity } = machine();
    const started = activity.startMotion(2, 1800);
    await clock.advance(1790);
    activity.sendStop7("caller");
    await clock.advance(20);
    const { ended, postureFollows } = activity.motionReplied(2);
    expect(ended.motion).toBe(2);
    expect(postureFollows).toBe(true);
    expect(await started.ended).toBe(2);
    const posture = activity.motion;
    expect(posture).toMatchObject({ kind: "motion", motion: 7, endedMotion: 2, startedAt: 1810 });
    expect(posture?.expectedMs).toBeGreaterThan(0);
    // A 7 is not sent again for the posture it started.
    expect(activity.sendStop7("stop")).toBe(false);
    activity.motionReplied(7);
    expect(activity.doing.kind).toBe("idle");
    expect(await posture?.ended).toBe(7);
  });

  it("a motion whose end is not known (timeout, cancel): idle, and its end settles with undefined", async () => {
    const { activity } = machine();
    const started = activity.startMotion(2, 1800);
    expect(activity.motionFailed()).toBe(started);
    expect(activity.doing.kind).toBe("idle");
    expect(await started.ended).toBeUndefined();
  });

  it("a sound: started, ended with the robot's echo (confirmed) or without (not confirmed)", async () => {
    const { clock, activity } = machine();
    await clock.advance(40);
    const first = activity.startSound(8, 5916);
    expect(activity.sound).toMatchObject({ kind: "sound", sound: 8, startedAt: 40, expectedMs: 5916 });
    activity.soundEnded(8);
    expect(await first.ended).toBe(true);
    const second = activity.startSound(3, 1000);
    activity.soundEnded(undefined);
    expect(await second.ended).toBe(false);
    expect(activity.doing.kind).toBe("idle");
  });

  it("an upload: its later turns pass, another upload is refused, only its own end ends it", () => {
    const { activity } = machine();
    const mine = new AbortController();
    const other = new AbortController();
    activity.startUpload(mine);
    activity.startUpload(mine);
    expect(activity.upload?.abort).toBe(mine);
    expect(() => activity.startUpload(other)).toThrow(ActivityRefusedError);
    activity.uploadEnded(other);
    expect(activity.doing.kind).toBe("upload");
    activity.uploadEnded(mine);
    expect(activity.doing.kind).toBe("idle");
    // Ended twice (cancelled by Stop, then its own clean-up): the second is harmless.
    activity.uploadEnded(mine);
    expect(activity.doing.kind).toBe("idle");
  });

  it("an upload's Cancel: cancelling from that moment (once, stamped), kept by its later turns, gone with its end", async () => {
    const { clock, activity, seen } = machine();
    const mine = new AbortController();
    activity.cancelUpload(mine); // not begun yet: nothing to mark
    expect(activity.doing).toEqual({ kind: "idle", since: 0 });
    await clock.advance(10);
    activity.startUpload(mine);
    await clock.advance(30);
    activity.cancelUpload(new AbortController()); // another upload's Cancel
    expect(activity.upload?.cancelling).toBeUndefined();
    activity.cancelUpload(mine);
    expect(activity.doing).toEqual({ kind: "upload", since: 10, abort: mine, cancelling: { since: 40 } });
    const changes = seen.length;
    await clock.advance(5);
    activity.cancelUpload(mine); // pressed again: the first press stands
    activity.startUpload(mine); // its next turn
    expect(activity.doing).toEqual({ kind: "upload", since: 10, abort: mine, cancelling: { since: 40 } });
    expect(seen.length).toBe(changes);
    activity.uploadEnded(mine);
    expect(activity.doing).toEqual({ kind: "idle", since: 45 });
    activity.cancelUpload(mine); // after its end: nothing
    expect(activity.doing).toEqual({ kind: "idle", since: 45 });
  });

  it("a firmware update: started from idle or over a motion started elsewhere, cancelled once, ended to idle", async () => {
    const { clock, activity, seen } = machine();
    await clock.advance(20);
    activity.noticeBusy("probe");
    activity.startFirmware();
    expect(activity.doing).toEqual({ kind: "firmware", since: 20 });
    expect(activity.firmware).toEqual({ kind: "firmware", since: 20 });
    await clock.advance(1500);
    activity.cancelFirmware();
    expect(activity.doing).toEqual({ kind: "firmware", since: 20, cancelling: { since: 1520 } });
    const changes = seen.length;
    await clock.advance(100);
    activity.cancelFirmware();
    expect(activity.doing).toEqual({ kind: "firmware", since: 20, cancelling: { since: 1520 } });
    expect(seen.length).toBe(changes);
    activity.firmwareEnded();
    expect(activity.doing).toEqual({ kind: "idle", since: 1620 });
    // After its end (or with nothing under way) neither changes anything.
    activity.cancelFirmware();
    activity.firmwareEnded();
    expect(activity.doing).toEqual({ kind: "idle", since: 1620 });
    expect(seen.length).toBe(changes + 1);
  });

  it("a firmware update makes the robot restart: the servos are no longer known to be limp", async () => {
    const { activity } = machine();
    await activity.beginLimp(async () => LIMP_RESULT);
    expect(activity.limp).toBe(true);
    activity.startFirmware();
    expect(activity.snapshot).toMatchObject({ doing: { kind: "firmware" }, limp: false });
  });

  it("direct mode: entered from idle for a use, handed over, left", () => {
    const { activity, seen } = machine();
    activity.enterDirect("teach-in");
    expect(activity.direct).toMatchObject({ kind: "direct", use: "teach-in" });
    activity.handDirect("tethered-play");
    expect(activity.direct?.use).toBe("tethered-play");
    const changes = seen.length;
    activity.handDirect("tethered-play");
    expect(seen.length).toBe(changes);
    activity.handDirect("limp");
    expect(activity.direct?.use).toBe("limp");
    activity.exitDirect();
    expect(activity.doing.kind).toBe("idle");
  });

  it("a lost link ends whatever was under way; a motion's end is then unknown", async () => {
    const { activity } = machine();
    const started = activity.startMotion(2, 1800);
    activity.disconnected();
    expect(activity.doing.kind).toBe("idle");
    expect(await started.ended).toBeUndefined();
    activity.enterDirect("servo-control");
    activity.disconnected();
    expect(activity.doing.kind).toBe("idle");
  });
});

describe("the activity machine: Stop and Limp under way", () => {
  it("Stop runs once; a second Stop joins it; when it is done nothing is under way", async () => {
    const { clock, activity } = machine();
    let runs = 0;
    const stop = () => {
      runs++;
      return new Promise<StopActivityResult>((resolve) => clock.setTimeout(() => resolve(STOP_RESULT), 500));
    };
    await clock.advance(10);
    const first = activity.beginStop(stop);
    expect(activity.halt).toMatchObject({ kind: "stop", since: 10 });
    const second = activity.beginStop(stop);
    expect(second).toBe(first);
    expect(runs).toBe(1);
    await clock.run(first);
    expect(activity.halt).toBeUndefined();
    expect(await first).toBe(STOP_RESULT);
  });

  it("a Stop that fails ends too", async () => {
    const { activity } = machine();
    const failed = activity.beginStop(() => Promise.reject(new Error("lost")));
    await expect(failed).rejects.toThrow("lost");
    expect(activity.halt).toBeUndefined();
  });

  it("Limp runs once, a second Limp joins it; Stop during Limp is refused and changes nothing", async () => {
    const { clock, activity } = machine();
    let runs = 0;
    const limp = () => {
      runs++;
      return new Promise<LimpResult>((resolve) => clock.setTimeout(() => resolve(LIMP_RESULT), 500));
    };
    const first = activity.beginLimp(limp);
    expect(activity.beginLimp(limp)).toBe(first);
    expect(runs).toBe(1);
    let stopRan = false;
    expect(() =>
      activity.beginStop(async () => {
        stopRan = true;
        return STOP_RESULT;
      }),
    ).toThrow(expect.objectContaining({ code: "wrong-mode", transition: "beginStop", from: "limp" }));
    expect(stopRan).toBe(false);
    expect(activity.halt?.kind).toBe("limp");
    expect(await clock.run(first)).toBe(LIMP_RESULT);
    expect(activity.halt).toBeUndefined();
  });

  it("Limp during Stop takes over, and stays under way when the Stop it took over from ends", async () => {
    const { clock, activity } = machine();
    const stop = activity.beginStop(
      () => new Promise<StopActivityResult>((resolve) => clock.setTimeout(() => resolve(STOP_RESULT), 100)),
    );
    const limp = activity.beginLimp(
      () => new Promise<LimpResult>((resolve) => clock.setTimeout(() => resolve(LIMP_RESULT), 300)),
    );
    expect(activity.halt?.kind).toBe("limp");
    await clock.run(stop);
    expect(activity.halt?.kind).toBe("limp");
    await clock.run(limp);
    expect(activity.halt).toBeUndefined();
  });

  it("Stop and Limp run beside what they end: the doing region keeps its state", () => {
    const { activity } = machine();
    activity.startMotion(2, 1800);
    activity.beginStop(() => new Promise<StopActivityResult>(() => {}));
    expect(activity.snapshot.doing.kind).toBe("motion");
    expect(activity.snapshot.halt?.kind).toBe("stop");
  });
});

describe("the activity machine: every servo limp, until one is driven", () => {
  /** A machine whose Limp has resolved: every servo passive. */
  async function limped(): Promise<Machine> {
    const m = machine();
    m.activity.enterDirect("limp");
    await m.activity.beginLimp(async () => LIMP_RESULT);
    return m;
  }

  it("starts not limp; a Limp that resolves makes it limp, told with the snapshot that ends the Limp", async () => {
    const { activity, seen } = machine();
    expect(activity.snapshot).toEqual({ doing: { kind: "idle", since: 0 }, halt: undefined, limp: false });
    activity.enterDirect("limp");
    const done = activity.beginLimp(async () => LIMP_RESULT);
    expect(activity.limp).toBe(false);
    expect(await done).toBe(LIMP_RESULT);
    expect(activity.limp).toBe(true);
    expect(seen.at(-1)).toEqual({
      doing: { kind: "direct", use: "limp", since: 0 },
      halt: undefined,
      limp: true,
    });
  });

  it("a Limp that fails leaves the servos as they were: not limp", async () => {
    const { activity } = machine();
    await expect(activity.beginLimp(() => Promise.reject(new Error("lost")))).rejects.toThrow("lost");
    expect(activity.limp).toBe(false);
  });

  it("leaving direct mode, servo control and Stop move no servo: still limp", async () => {
    const { activity } = await limped();
    activity.exitDirect();
    expect(activity.limp).toBe(true);
    activity.enterDirect("servo-control");
    activity.handDirect("teach-in");
    expect(activity.limp).toBe(true);
    await activity.beginStop(async () => STOP_RESULT);
    expect(activity.snapshot.limp).toBe(true);
  });

  const DRIVES: Array<{ name: string; drive: (m: Machine) => unknown }> = [
    { name: "a servo driven (servosDriven)", drive: ({ activity }) => activity.servosDriven() },
    {
      name: "tethered play taking direct mode (handDirect)",
      drive: ({ activity }) => activity.handDirect("tethered-play"),
    },
    {
      name: "tethered play entering direct mode (enterDirect)",
      drive: ({ activity }) => {
        activity.exitDirect();
        activity.enterDirect("tethered-play");
      },
    },
    {
      name: "a motion of this client (startMotion)",
      drive: ({ activity }) => {
        activity.exitDirect();
        activity.startMotion(7, 1800);
      },
    },
    {
      name: "a motion noticed playing elsewhere (noticeBusy)",
      drive: ({ activity }) => {
        activity.exitDirect();
        activity.noticeBusy("probe");
      },
    },
    { name: "a lost link (disconnected)", drive: ({ activity }) => activity.disconnected() },
  ];

  for (const { name, drive } of DRIVES) {
    it(`${name} ends it, told with the snapshot`, async () => {
      const m = await limped();
      drive(m);
      expect(m.activity.limp).toBe(false);
      expect(m.seen.at(-1)?.limp).toBe(false);
    });
  }

  it("servosDriven when not limp changes nothing and tells nothing", () => {
    const { activity, seen } = machine();
    activity.servosDriven();
    expect(seen).toEqual([]);
  });
});
