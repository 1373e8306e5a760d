/**
 * The binary motion image uploaded by Write Motion (docs/protocol.md §6.3, a project decision): the layout of the
 * firmware's motion and scene structures, multi-byte fields little-endian, listing only the file's W servos.
 *
 * | offset               | bytes | field                                     |
 * |----------------------|-------|-------------------------------------------|
 * | 0                    | 1     | platform                                  |
 * | 1                    | 1     | motion index                              |
 * | 2                    | 4     | absolute index, 0                         |
 * | 6                    | 2     | scenes S                                  |
 * | 8                    | 2     | servos W                                  |
 * | 10 + 6i              | 6     | servo i: id, P, D, I, portEnable, zero    |
 * | 10 + 6W              | 2     | image size                                |
 * | B_k = 12+6W+k(6+5W)  | 6     | scene k: index, frames, time (ms), u16 LE |
 * | B_k + 6 + 5i         | 5     | id, start, end, torque, port              |
 */
import { RbmError, type RbmIssueValues, type RbmMotion } from "./rbm.ts";
import { rbmIssue } from "./rbm-issue.ts";

/** Image size for W servos and S scenes: 12 + 6W + S(6 + 5W). */
export function motionImageSize(servoCount: number, sceneCount: number): number {
  return 12 + 6 * servoCount + sceneCount * (6 + 5 * servoCount);
}

/**
 * Encodes a motion as its §6.3 image. Throws `RbmError("rbm-image-range")` if a value does not fit its byte
 * field and `RbmError("rbm-servo-count")` if a scene does not list every servo. It does not apply the other
 * rules of §7: call `validateRbm` first.
 */
export function motionImage(motion: RbmMotion): Uint8Array {
  const W = motion.servos.length;
  const S = motion.scenes.length;
  const size = motionImageSize(W, S);
  check(size, 0xffff, { field: "imageSize" });
  const out = new Uint8Array(size);
  let o = 0;
  /** `subject` names the field for the error's values: `{ field: "start", scene: 2, servo: 5 }`. */
  const u8 = (value: number, subject: RbmIssueValues): void => {
    check(value, 0xff, subject);
    out[o++] = value;
  };
  const u16le = (value: number, subject: RbmIssueValues): void => {
    check(value, 0xffff, subject);
    out[o++] = value & 0xff;
    out[o++] = value >>> 8;
  };

  u8(motion.platform, { field: "platform" });
  u8(motion.motionIndex, { field: "motionIndex" });
  o += 4; // absolute index, always 0
  u16le(S, { field: "sceneCount" });
  u16le(W, { field: "servoCount" });
  for (const servo of motion.servos) {
    const at = { servo: servo.id };
    u8(servo.id, { field: "id", ...at });
    u8(servo.p, { field: "p", ...at });
    u8(servo.d, { field: "d", ...at });
    u8(servo.i, { field: "i", ...at });
    u8(servo.portEnable, { field: "portEnable", ...at });
    u8(servo.zero, { field: "zero", ...at });
  }
  u16le(size, { field: "imageSize" });
  motion.scenes.forEach((scene, k) => {
    if (scene.servos.length !== W) {
      const values = { kind: "scene", scene: k, records: scene.servos.length, servos: W };
      const issue = rbmIssue("rbm-servo-count", values, { scene: k });
      throw new RbmError(issue.code, issue.message, [issue]);
    }
    u16le(scene.index, { field: "index", scene: k });
    u16le(scene.frames, { field: "frames", scene: k });
    u16le(scene.timeMs, { field: "timeMs", scene: k });
    for (const rec of scene.servos) {
      const at = { scene: k, servo: rec.id };
      u8(rec.id, { field: "id", ...at });
      u8(rec.start, { field: "start", ...at });
      u8(rec.end, { field: "end", ...at });
      u8(rec.torque, { field: "torque", ...at });
      u8(rec.port, { field: "port", ...at });
    }
  });
  return out;
}

function check(value: number, max: number, subject: RbmIssueValues): void {
  if (!Number.isInteger(value) || value < 0 || value > max) {
    const issue = rbmIssue("rbm-image-range", {
      ...subject,
      value: Number.isSafeInteger(value) ? value : String(value),
      max,
    });
    throw new RbmError(issue.code, issue.message, [issue]);
  }
}
