/** Motion files for the browser tests: the project's examples, and variants made with its own codec. */
import { readFileSync } from "node:fs";
import { motionImage } from "../../src/protocol/motion-image.ts";
import { parseRbm, serializeRbm } from "../../src/protocol/rbm.ts";

const EXAMPLES = new URL("../../examples/", import.meta.url);

/** One of the project's example motions (examples/*.rbm), as the panel offers them. */
export function exampleText(name: string): string {
  return readFileSync(new URL(name, EXAMPLES), "latin1");
}

/** A file for the picker: name, MIME type and bytes. */
export function rbmFile(name: string, text: string) {
  return { name, mimeType: "text/plain", buffer: Buffer.from(text, "latin1") };
}

/** The hex of the motion image the panel must send for `text`. */
export function imageHex(text: string): string {
  return Buffer.from(motionImage(parseRbm(text))).toString("hex");
}

/** The same motion, marked as made for the robot with `serial` (Motionbuilder's field 2). */
export function withSerial(text: string, serial: string): string {
  const motion = parseRbm(text);
  motion.serialNumber = serial;
  return serializeRbm(motion);
}

/** A hand-edited file: scene 0's frames 10 ms apart, which the RBC refuses (error 6). */
export function withShortFrames(text: string): string {
  const motion = parseRbm(text);
  const scene = motion.scenes[0]!;
  scene.timeMs = scene.frames * 10;
  return serializeRbm(motion);
}

/** A long motion (its scenes repeated), so that an upload on a paced link takes a few seconds. */
export function longMotion(text: string, copies: number): string {
  const motion = parseRbm(text);
  const scenes = motion.scenes;
  motion.scenes = Array.from({ length: copies }, () => scenes)
    .flat()
    .map((s, index) => ({ ...s, index, servos: s.servos.map((r) => ({ ...r })) }));
  motion.sceneCount = motion.scenes.length;
  return serializeRbm(motion);
}
