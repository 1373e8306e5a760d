/** Motion files for the browser tests: the project's examples, and variants made with its own codec. */
import { readFileSync } from "node:fs";
import type { Page } from "playwright-core";
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

/** The same motion under another name (Motionbuilder's field 4), e.g. one too long for a button. */
export function withName(text: string, name: string): string {
  const motion = parseRbm(text);
  motion.name = name;
  return serializeRbm(motion);
}

/** Scene-jump warnings: every servo of scene 1 starts `steps` away from where scene 0 left it. */
export function withJumps(text: string, steps: number): string {
  const motion = parseRbm(text);
  const before = motion.scenes[0]!;
  const scene = motion.scenes[1]!;
  scene.servos = scene.servos.map((r, i) => ({
    ...r,
    start: Math.min(254, Math.max(0, before.servos[i]!.end + steps)),
  }));
  return serializeRbm(motion);
}

/** A serious warning: servo 0 (safe range up to 174, docs/protocol.md §5) ends scene 0 at 254. */
export function withUnsafePosition(text: string): string {
  const motion = parseRbm(text);
  motion.scenes[0]!.servos[0]!.end = 254;
  return serializeRbm(motion);
}

const TAB_IDS = { Files: "files", Memory: "uploads", Run: "run", Sounds: "sounds" } as const;

/** Chooses a tab of the Motions view and waits until its panel is shown. */
export async function showTab(page: Page, tab: keyof typeof TAB_IDS): Promise<void> {
  await page.getByRole("tab", { name: tab, exact: true }).click();
  await page.locator(`#motions-panel-${TAB_IDS[tab]}`).waitFor();
}
