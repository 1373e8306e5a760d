/**
 * The project's own test data: the example motions in examples/ (made by scripts/make-examples.ts) and their
 * golden motion images in tests/data/images/ (made by tests/data/make-golden-images.py, independently of the
 * project's encoder). See tests/data/README.md.
 */
import { readFileSync } from "node:fs";
import { fromHex } from "../../src/protocol/bytes.ts";

export const EXAMPLES_DIR = new URL("../../examples/", import.meta.url);
export const IMAGES_DIR = new URL("images/", import.meta.url);

/** The committed examples, in the order examples/README.md lists them. */
export const EXAMPLE_NAMES = ["wave.rbm", "bow.rbm", "squat.rbm", "long-walk.rbm", "arms-only.rbm"] as const;
export type ExampleName = (typeof EXAMPLE_NAMES)[number];

/** An example's `.rbm` text, exactly as committed. */
export function exampleText(name: ExampleName): string {
  return readFileSync(new URL(name, EXAMPLES_DIR), "latin1");
}

/** The golden image of an example (tests/data/images/<name>.img.hex, 16 hex bytes a line). */
export function goldenImage(name: ExampleName): Uint8Array {
  return fromHex(goldenImageText(name));
}

/** The golden image file's text. */
export function goldenImageText(name: ExampleName): string {
  return readFileSync(new URL(name.replace(/\.rbm$/, ".img.hex"), IMAGES_DIR), "ascii");
}
