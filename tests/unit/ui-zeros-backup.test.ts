import { describe, expect, it } from "vitest";
import { FACTORY_ZEROS, STANDARD_ZEROS } from "../../src/protocol/index.ts";
import {
  createZerosBackup,
  parseZerosBackup,
  serializeZerosBackup,
  serialMismatchWarning,
  zerosBackupFileName,
} from "../../src/protocol/zeros-backup.ts";

const SAVED = new Date(2026, 10, 21, 9, 30, 0);

function backupText(overrides: Record<string, unknown> = {}): string {
  return JSON.stringify({
    format: "rbc-zeros",
    version: 1,
    serialNumber: "8958899989309",
    firmware: "2.23",
    savedAt: "2026-11-21T09:30:00.000Z",
    zeros: [...FACTORY_ZEROS],
    ...overrides,
  });
}

describe("zero backups", () => {
  it("round-trips through serialise and parse", () => {
    const backup = createZerosBackup({
      serialNumber: "8958899989309",
      firmware: "2.23",
      zeros: STANDARD_ZEROS,
      savedAt: SAVED,
    });
    expect(backup).toEqual({
      format: "rbc-zeros",
      version: 1,
      serialNumber: "8958899989309",
      firmware: "2.23",
      savedAt: SAVED.toISOString(),
      zeros: [...STANDARD_ZEROS],
    });
    const parsed = parseZerosBackup(serializeZerosBackup(backup));
    expect(parsed).toEqual({ ok: true, backup });
  });

  it("names the file after the serial number and the local date", () => {
    expect(zerosBackupFileName("8958899989309", SAVED)).toBe("rbc-zeros-8958899989309-2026-11-21.json");
    expect(zerosBackupFileName("AB/12 ?", SAVED)).toBe("rbc-zeros-AB_12__-2026-11-21.json");
    expect(zerosBackupFileName("  ", SAVED)).toBe("rbc-zeros-unknown-2026-11-21.json");
  });

  it.each([
    ["not JSON", "{ nope", "not-json", /not JSON text/],
    ["JSON of another kind", JSON.stringify([1, 2, 3]), "wrong-format", /not an RBC zero backup/],
    ["another format", backupText({ format: "rbm" }), "wrong-format", /its format is "rbm"/],
    ["a newer version", backupText({ version: 2 }), "wrong-version", /version 2; this panel reads version 1/],
    [
      "15 values",
      backupText({ zeros: FACTORY_ZEROS.slice(1) }),
      "wrong-count",
      /holds 15 values; .* exactly 16/,
    ],
    ["no values", backupText({ zeros: "124" }), "wrong-count", /holds no list of values/],
    [
      "a value out of range",
      backupText({ zeros: FACTORY_ZEROS.map((v, i) => (i === 2 ? 100 : v)) }),
      "out-of-range",
      /Servo 2: 100 is outside 147-177/,
    ],
    [
      "a fraction",
      backupText({ zeros: FACTORY_ZEROS.map((v, i) => (i === 2 ? 162.5 : v)) }),
      "out-of-range",
      /Servo 2: "162.5" is not a whole number/,
    ],
    ["a bad date", backupText({ savedAt: "yesterday" }), "invalid", /damaged \(savedAt\)/],
    [
      "a missing serial number",
      backupText({ serialNumber: undefined }),
      "invalid",
      /damaged \(serialNumber\)/,
    ],
  ])("refuses %s", (_what, text, problem, message) => {
    const parsed = parseZerosBackup(text);
    expect(parsed.ok).toBe(false);
    if (!parsed.ok) {
      expect(parsed.problem).toBe(problem);
      expect(parsed.message).toMatch(message);
    }
  });

  it("warns when the backup comes from another robot", () => {
    const parsed = parseZerosBackup(backupText({ serialNumber: "1111111111111" }));
    if (!parsed.ok) throw new Error(parsed.message);
    expect(serialMismatchWarning(parsed.backup, "8958899989309")).toMatch(
      /saved from robot 1111111111111, not the connected robot 8958899989309/,
    );
    expect(serialMismatchWarning(parsed.backup, "1111111111111")).toBeUndefined();
    expect(serialMismatchWarning(parsed.backup, undefined)).toBeUndefined();
  });
});
