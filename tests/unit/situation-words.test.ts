import { describe, expect, it } from "vitest";
import { RbcError, type RbcSituation } from "../../src/device/errors.ts";
import { errorText } from "../../src/i18n/index.ts";

/**
 * Every situation a device error can carry (src/device/situation.ts) is worded by the outcome catalogue in
 * English and in Korean (issue 31 item 1): a sentence of its own in each language, the facts in it, no
 * placeholder left, and no English inside the Korean except what the robot or a file says.
 */

const frame = { scene: 1, frame: 3 };
const SAMPLES: Readonly<Record<Exclude<RbcSituation["kind"], "code">, RbcSituation>> = {
  "cancelled-by": { kind: "cancelled-by", by: "stop" },
  "upload-cancelled-by-stop": { kind: "upload-cancelled-by-stop" },
  "upload-cancelled-early": { kind: "upload-cancelled-early" },
  "motion-not-started": { kind: "motion-not-started", motion: 12, by: "limp" },
  "stopped-waiting": { kind: "stopped-waiting", command: "Read zeros" },
  "zeros-cancelled-before-write": { kind: "zeros-cancelled-before-write", backupName: "b.json" },
  "zeros-not-read": { kind: "zeros-not-read" },
  "zeros-not-written": {
    kind: "zeros-not-written",
    problems: [{ id: 5, value: 300, message: "Servo 5: 300 is outside 0-254." }],
  },
  "direct-mode-needed": { kind: "direct-mode-needed" },
  "servo-range": { kind: "servo-range", id: 3, min: 40, max: 130, position: 200 },
  "servo-id-range": { kind: "servo-id-range", id: 40, max: 30 },
  "not-encoded": { kind: "not-encoded" },
  "file-size": { kind: "file-size", area: "action", max: 3136, total: 4000 },
  "motion-invalid": {
    kind: "motion-invalid",
    name: "Wave",
    count: 2,
    first: { code: "rbm-frames", message: "Scene 1: frames 5 ms apart." },
  },
  "motion-number-range": { kind: "motion-number-range", motion: 64 },
  "sound-number-range": { kind: "sound-number-range", sound: 26 },
  "not-enough-memory": { kind: "not-enough-memory", area: "motion", total: 30000, free: 24576 },
  "already-connected": { kind: "already-connected" },
  "connection-closed": { kind: "connection-closed" },
  "link-lost": { kind: "link-lost", reported: "The serial device was unplugged.", advice: "connect-again" },
  "needs-normal-mode": { kind: "needs-normal-mode", command: "Run motion" },
  "no-safe-range": { kind: "no-safe-range", id: 20, wiggle: true },
  "servo-move-range": { kind: "servo-move-range", id: 3, min: 40, max: 130 },
  "servo-impossible-position": { kind: "servo-impossible-position", id: 3, position: 255 },
  "doctor-needs-direct-mode": { kind: "doctor-needs-direct-mode" },
  "doctor-stopped": { kind: "doctor-stopped" },
  "set-id-range": { kind: "set-id-range", which: "new", id: 31, max: 30 },
  "set-id-same": { kind: "set-id-same", id: 4 },
  "scan-no-ids": { kind: "scan-no-ids" },
  "scan-id-twice": { kind: "scan-id-twice", id: 4 },
  "wiggle-counts": { kind: "wiggle-counts", counts: 21 },
  "limp-no-servo-control": { kind: "limp-no-servo-control" },
  "motion-stopped": { kind: "motion-stopped", motion: 12 },
  "zeros-write-unknown": { kind: "zeros-write-unknown" },
  "zeros-write-refused": { kind: "zeros-write-refused" },
  "zeros-echo-differs": { kind: "zeros-echo-differs", echo: [1, 2, 3] },
  "play-platform": { kind: "play-platform", platform: 300 },
  "play-refused": { kind: "play-refused" },
  "play-servos-silent": { kind: "play-servos-silent", silent: [0, 1, 2], maxId: 15 },
  "play-unconfirmed": { kind: "play-unconfirmed", framesSent: 30, lastFrame: frame },
  "play-link-lost": {
    kind: "play-link-lost",
    timedOut: false,
    framesSent: 2,
    totalFrames: 5,
    lastFrame: frame,
  },
};

/** English a Korean sentence may keep: the RBC's name, and what a command, a file or the link is called or said. */
const QUOTED =
  /RBC|Read zeros|Run motion|Wave|Scene 1: frames 5 ms apart\.|b\.json|Servo 5: 300 is outside 0-254\./g;

describe("a device error's situation in words", () => {
  for (const [kind, situation] of Object.entries(SAMPLES)) {
    it(`${kind}: a sentence in English and in Korean`, () => {
      const cause = new Error("Scene 1: frames 5 ms apart.");
      const e = new RbcError("invalid-argument", undefined, { situation, cause });
      const en = errorText(e, "en");
      const ko = errorText(e, "ko");
      expect(e.message).toMatch(new RegExp(`^invalid-argument: ${kind}\\b`));
      for (const text of [en, ko]) {
        expect(text).toMatch(/[.)]$/);
        expect(text).not.toMatch(/[{}]|undefined|\[object/);
      }
      expect(en).toMatch(/^[A-Z"]/);
      expect(ko.replace(QUOTED, "")).not.toMatch(/[A-Za-z]{3,}/);
    });
  }
});
