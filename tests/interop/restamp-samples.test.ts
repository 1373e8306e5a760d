/**
 * Interop: restamping the third-party Motionbuilder samples in `../shared/fixtures/rbm` (not part of this
 * repository, see tests/interop/motionbuilder-samples.test.ts): each file, its bytes as they are, restamped with
 * a robot's serial number and with zeros changes only the 13 bytes of field 2, and restamped back is the very
 * same file. Without that folder this prints one line and its tests are reported as skipped;
 * tests/unit/restamp.test.ts covers the same code on the project's own examples and generated motions.
 */
import { existsSync, readdirSync, readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { RBM_ZERO_SERIAL, rbmSerial, restampRbmBytes } from "../../src/motion/index.ts";

const FIXTURES = new URL("../../../shared/fixtures/rbm/", import.meta.url);
const PRESENT = existsSync(FIXTURES);
if (!PRESENT) {
  console.log(
    "restamp interop skipped: ../shared/fixtures not found (third-party Motionbuilder files are not part of this repository)",
  );
}

const NAMES = PRESENT ? readdirSync(FIXTURES).filter((n) => n.endsWith(".rbm")) : ["(none)"];

describe.runIf(PRESENT)("interop: restamping Motionbuilder's files", () => {
  it.each(NAMES)("%s: only field 2's 13 bytes change, and back is byte-identical", (name) => {
    const bytes = new Uint8Array(readFileSync(new URL(name, FIXTURES)));
    const original = rbmSerial(Buffer.from(bytes).toString("latin1"));
    for (const serial of ["8958899989309", RBM_ZERO_SERIAL]) {
      const r = restampRbmBytes(bytes, serial);
      const changed = [...r.output.keys()].filter((i) => r.output[i] !== bytes[i]);
      expect(changed.every((i) => i >= r.offset && i < r.offset + 13)).toBe(true);
      expect(Buffer.from(r.output.subarray(r.offset, r.offset + 13)).toString("latin1")).toBe(serial);
      expect(r.output.length).toBe(bytes.length);
      expect([...restampRbmBytes(r.output, original).output]).toEqual([...bytes]);
    }
  });
});
