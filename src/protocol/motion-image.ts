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
import { rbmIssueMessages } from "../i18n/outcomes/rbm/messages.ts";
import { translator } from "../i18n/translate.ts";
import { RbmError, type RbmIssueValues, type RbmMotion } from "./rbm.ts";

/** A file problem's English sentence, from the outcome catalogue (src/i18n/outcomes/rbm/), as Korean is. */
const en = translator(rbmIssueMessages, "en");

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
  check(size, 0xffff, "The image size", { field: "imageSize" });
  const out = new Uint8Array(size);
  let o = 0;
  /** `subject` names the field for the error's values: `{ field: "start", scene: 2, servo: 5 }`. */
  const u8 = (value: number, what: string, subject: RbmIssueValues): void => {
    check(value, 0xff, what, subject);
    out[o++] = value;
  };
  const u16le = (value: number, what: string, subject: RbmIssueValues): void => {
    check(value, 0xffff, what, subject);
    out[o++] = value & 0xff;
    out[o++] = value >>> 8;
  };

  u8(motion.platform, "The platform", { field: "platform" });
  u8(motion.motionIndex, "The motion index", { field: "motionIndex" });
  o += 4; // absolute index, always 0
  u16le(S, "The number of scenes", { field: "sceneCount" });
  u16le(W, "The number of servos", { field: "servoCount" });
  for (const servo of motion.servos) {
    const what = `Servo ${servo.id}:`;
    const at = { servo: servo.id };
    u8(servo.id, `${what} id`, { field: "id", ...at });
    u8(servo.p, `${what} P gain`, { field: "p", ...at });
    u8(servo.d, `${what} D gain`, { field: "d", ...at });
    u8(servo.i, `${what} I gain`, { field: "i", ...at });
    u8(servo.portEnable, `${what} port enable`, { field: "portEnable", ...at });
    u8(servo.zero, `${what} zero position`, { field: "zero", ...at });
  }
  u16le(size, "The image size", { field: "imageSize" });
  motion.scenes.forEach((scene, k) => {
    if (scene.servos.length !== W) {
      const message = en("outcome.rbm.servoCount.scene", {
        scene: String(k),
        records: String(scene.servos.length),
        servos: String(W),
      });
      const values = { kind: "scene", scene: k, records: scene.servos.length, servos: W };
      throw new RbmError("rbm-servo-count", message, [
        { code: "rbm-servo-count", message, scene: k, values },
      ]);
    }
    const what = `Scene ${k}:`;
    u16le(scene.index, `${what} index`, { field: "index", scene: k });
    u16le(scene.frames, `${what} frames`, { field: "frames", scene: k });
    u16le(scene.timeMs, `${what} time`, { field: "timeMs", scene: k });
    for (const rec of scene.servos) {
      const rw = `${what} servo ${rec.id}`;
      const at = { scene: k, servo: rec.id };
      u8(rec.id, `${rw} id`, { field: "id", ...at });
      u8(rec.start, `${rw} start position`, { field: "start", ...at });
      u8(rec.end, `${rw} end position`, { field: "end", ...at });
      u8(rec.torque, `${rw} torque`, { field: "torque", ...at });
      u8(rec.port, `${rw} port`, { field: "port", ...at });
    }
  });
  return out;
}

function check(value: number, max: number, what: string, subject: RbmIssueValues): void {
  if (!Number.isInteger(value) || value < 0 || value > max) {
    const message = en("outcome.rbm.imageRange", { what, value: String(value), max: String(max) });
    const values = { ...subject, value: Number.isSafeInteger(value) ? value : String(value), max };
    throw new RbmError("rbm-image-range", message, [{ code: "rbm-image-range", message, values }]);
  }
}
