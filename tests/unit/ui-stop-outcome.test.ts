import { describe, expect, it } from "vitest";
import { stopOutcome } from "../../src/ui/features/connection/stop-outcome.ts";

/** The top bar's sentence after Stop says only what the robot confirmed (src/ui/features/connection/stop-outcome.ts). */
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
});
