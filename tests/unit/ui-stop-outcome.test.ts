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
});
