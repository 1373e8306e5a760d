import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { checkPack } from "../../src/ui/features/class/pack-check.ts";
import { PackFileError, parsePack, serializePack } from "../../src/ui/features/class/pack-file.ts";
import { compareZeros } from "../../src/ui/features/class/zeros-check.ts";

const WAVE = new Uint8Array(readFileSync(new URL("../../examples/wave.rbm", import.meta.url)));

function problemOf(text: string): string {
  try {
    parsePack(text);
  } catch (e) {
    if (e instanceof PackFileError) return e.problem;
    throw e;
  }
  return "opened";
}

describe("a motion pack file", () => {
  it("reads a pack written by hand: base64 'UkJD' is the bytes R, B, C", () => {
    const text = '{"format":"rbc-motion-pack","version":1,"files":[{"name":"a.rbm","base64":"UkJD"}]}';
    const [file] = parsePack(text);
    expect(file?.name).toBe("a.rbm");
    expect([...(file?.bytes ?? [])]).toEqual([0x52, 0x42, 0x43]);
  });

  it("writes the files byte for byte, and opens them again unchanged", () => {
    const text = serializePack([{ name: "wave.rbm", bytes: WAVE }]);
    expect(JSON.parse(text)).toMatchObject({ format: "rbc-motion-pack", version: 1 });
    const [back] = parsePack(text);
    expect(back?.bytes).toEqual(WAVE);
  });

  it("refuses what is not a pack, with a typed problem", () => {
    expect(problemOf("not json")).toBe("not-json");
    expect(problemOf('{"format":"rbc-zeros","version":1}')).toBe("not-pack");
    expect(problemOf('{"format":"rbc-motion-pack","version":2,"files":[]}')).toBe("wrong-version");
    expect(problemOf('{"format":"rbc-motion-pack","version":1,"files":[]}')).toBe("damaged");
    expect(
      problemOf('{"format":"rbc-motion-pack","version":1,"files":[{"name":"a.rbm","base64":"!!"}]}'),
    ).toBe("damaged");
    expect(problemOf('{"format":"rbc-motion-pack","version":1,"files":[{"name":"","base64":"UkJD"}]}')).toBe(
      "damaged",
    );
  });

  it("checks a pack once: a broken file makes it not uploadable, and numbers follow the slots", () => {
    const good = checkPack([
      { id: 1, fileName: "wave.rbm", bytes: WAVE },
      { id: 2, fileName: "wave2.rbm", bytes: WAVE },
    ]);
    expect(good.uploadable).toBe(true);
    expect(good.files.map((f) => f.number)).toEqual([12, 13]);
    // examples/wave.rbm takes 640 bytes of memory (docs/protocol.md §6.3).
    expect(good.footprint).toBe(1280);
    const bad = checkPack([
      { id: 1, fileName: "wave.rbm", bytes: WAVE },
      { id: 2, fileName: "junk.rbm", bytes: new TextEncoder().encode("hello") },
    ]);
    expect(bad.withErrors).toBe(1);
    expect(bad.uploadable).toBe(false);
  });
});

describe("zeros against a backup", () => {
  const backup = Array.from({ length: 16 }, (_, i) => 120 + i);
  it("says same, or the joints that differ", () => {
    expect(compareZeros([...backup], backup)).toEqual({ kind: "same" });
    const robot = [...backup];
    robot[3] = 99;
    robot[15] = 1;
    expect(compareZeros(robot, backup)).toEqual({ kind: "differs", joints: [3, 15] });
    expect(compareZeros(undefined, backup)).toEqual({ kind: "unknown" });
    expect(compareZeros(robot.slice(0, 10), backup)).toEqual({ kind: "unknown" });
  });
});
