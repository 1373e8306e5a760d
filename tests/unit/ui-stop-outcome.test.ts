import { describe, expect, it } from "vitest";
import { noticeMore, noticeText } from "../../src/ui/app-state.ts";
import { stopOutcome } from "../../src/ui/stop-outcome.ts";

/** The top bar's sentence after Stop says only what the robot confirmed (src/ui/stop-outcome.ts). */
describe("Stop's outcome sentence", () => {
  const base = { uploadCancelled: false, servoMovesDropped: true };

  it("names the frame tethered play stopped after, and that the servos hold it", () => {
    const notice = stopOutcome(
      { ...base, tetheredPlay: { framesSent: 14, totalFrames: 30, lastFrame: { scene: 1, frame: 4 } } },
      false,
    );
    expect(notice).toMatchObject({
      tone: "ok",
      text: "Tethered play stopped after scene 1, frame 4 (14 of 30 frames sent); the servos hold that frame.",
    });
    // Kept as a message too, so that a language switch words it again (docs/ui.md: results where the eyes are).
    expect(notice.said?.length).toBeGreaterThan(0);
  });

  it("says nothing moved when play was stopped before its first frame, and names transition frames", () => {
    expect(stopOutcome({ ...base, tetheredPlay: { framesSent: 0, totalFrames: 30 } }, false).text).toBe(
      "Tethered play stopped before its first frame; nothing moved.",
    );
    expect(
      stopOutcome(
        { ...base, tetheredPlay: { framesSent: 3, totalFrames: 40, lastFrame: { scene: -1, frame: 3 } } },
        false,
      ).text,
    ).toBe(
      "Tethered play stopped after transition frame 3 (3 of 40 frames sent); the servos hold that frame.",
    );
  });

  it("keeps the servo-control sentence when no tethered play ran", () => {
    expect(stopOutcome(base, false).text).toBe(
      "Servo moves stopped: no further move is sent, and the servos hold their last position.",
    );
  });

  it("says what the robot answered when the panel had started nothing, as a warning when unconfirmed", () => {
    const idle = stopOutcome(
      { uploadCancelled: false, servoMovesDropped: false, found: { kind: "idle" } },
      false,
    );
    expect(idle).toMatchObject({
      tone: "ok",
      text: "The robot answered at once: it is idle, nothing to stop. Nothing was sent.",
    });
    const none = stopOutcome(
      { uploadCancelled: false, servoMovesDropped: false, found: { kind: "no-answer", waitedMs: 800 } },
      false,
    );
    expect(none.tone).toBe("warning");
    expect(none.text).toContain(
      "answered neither the distance sensor nor the firmware version within 800 ms",
    );
    expect(none.text).not.toContain("Nothing was running");
  });

  it("says servo control ended when Stop left direct mode, and that limp servos stay limp", () => {
    const left = { uploadCancelled: false, servoMovesDropped: true, leftDirectMode: true };
    expect(stopOutcome(left, false).text).toBe(
      "Servo control ended (the robot is back in its normal mode); the servos hold their last position.",
    );
    expect(stopOutcome(left, true).text).toBe(
      "Servo control ended (the robot is back in its normal mode); the servos stay limp (Limp).",
    );
  });

  it("says first in plain words what Stop meant for the robot; the 7 and the 07 are the detail, which names no stopped motion", () => {
    const stopped = stopOutcome({ ...base, motion: { number: 2, outcome: "stopped" } }, false);
    expect(noticeText(stopped, "en")).toBe(
      "The robot took Stop: the motion ended at the end of the scene it was in. The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing. Basic posture (7) brings it back to standing. Servo moves stopped: no further move is sent, and the servos hold their last position.",
    );
    expect(noticeText(stopped, "ko")).toMatch(
      /^로봇이 정지를 받았어요\. 모션은 하던 장면이 끝날 때 멈췄어요\. 로봇은 서보에 힘이 들어간 채로 멈춘 자세를 유지해요\. 넘어지지는 않지만, 꼭 서 있는 자세는 아니에요\./,
    );
    for (const locale of ["en", "ko"] as const) expect(noticeText(stopped, locale)).not.toMatch(/\b07\b/);
    // docs/protocol.md §3.1: a 07 reply says that what played ended, not which motion it was.
    expect(noticeMore(stopped, "en")).toBe(
      "Stop sent 7 while motion 2, started here, was playing, and the robot answered 07. That reply says that what the robot was playing ended at the end of a scene; it does not say which motion that was.",
    );
    expect(noticeMore(stopped, "ko")).toContain("07로 응답했어요");

    const unconfirmed = stopOutcome({ ...base, motion: { number: 2, outcome: "unconfirmed" } }, false);
    expect(unconfirmed.tone).toBe("warning");
    expect(noticeText(unconfirmed, "en")).toMatch(
      /^Stop was sent, but the robot did not confirm that it took it\./,
    );
    expect(noticeMore(unconfirmed, "en")).toBe(
      "Stop's 7 to end motion 2 was not answered with 07 in time (or could not be sent).",
    );
    expect(noticeMore(stopOutcome(base, false), "en")).toBeUndefined();
  });
});
