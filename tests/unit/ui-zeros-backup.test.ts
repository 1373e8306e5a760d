import { describe, expect, it } from "vitest";
import { backupRefusalText, serialMismatchWarning } from "../../src/i18n/outcomes/zero-words.ts";
import { FACTORY_ZEROS, STANDARD_ZEROS } from "../../src/protocol/index.ts";
import {
  createZerosBackup,
  parseZerosBackup,
  serializeZerosBackup,
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
      expect(backupRefusalText(parsed, "en")).toMatch(message);
    }
  });

  it("words a refusal from its facts, with the sentences the panel always showed", () => {
    const said = (text: string) => {
      const parsed = parseZerosBackup(text);
      if (parsed.ok) throw new Error("accepted");
      return { problem: parsed.problem, facts: parsed.facts, en: backupRefusalText(parsed, "en") };
    };
    const hint = "Choose a file saved by this panel, named like rbc-zeros-<serial>-<date>.json.";
    expect(said("{ nope")).toEqual({
      problem: "not-json",
      facts: {},
      en: `This file is not a zero backup: it is not JSON text. ${hint}`,
    });
    expect(said(backupText({ format: "rbm" }))).toEqual({
      problem: "wrong-format",
      facts: { format: "rbm" },
      en: `This file is JSON but not an RBC zero backup (its format is "rbm"). ${hint}`,
    });
    expect(said(backupText({ version: 2 }))).toEqual({
      problem: "wrong-version",
      facts: { version: "2" },
      en: "This backup is version 2; this panel reads version 1.",
    });
    expect(said(backupText({ zeros: FACTORY_ZEROS.slice(1) }))).toEqual({
      problem: "wrong-count",
      facts: { count: 15 },
      en: "This backup holds 15 values; a zero table has exactly 16, one per servo 0-15.",
    });
    const range = said(backupText({ zeros: FACTORY_ZEROS.map((v, i) => (i === 2 ? 100 : v)) }));
    expect(range.facts.problems?.map(({ id, value }) => ({ id, value }))).toEqual([{ id: 2, value: 100 }]);
    expect(range.en).toBe(
      "The robot would refuse this backup's zeros: Servo 2: 100 is outside 147-177 (standard 162 ± 15); the RBC would refuse the whole table.",
    );
    expect(said(backupText({ savedAt: "yesterday" }))).toMatchObject({
      problem: "invalid",
      facts: { path: "savedAt" },
      en: expect.stringMatching(/^This backup file is damaged \(savedAt\): .+\.$/),
    });
    expect(backupRefusalText({ problem: "not-json", facts: {} }, "ko")).toBe(
      "영점 백업 파일이 아니에요(JSON 텍스트가 아님). 이 패널이 저장한 파일을 골라 주세요. 이름은 rbc-zeros-<시리얼 번호>-<날짜>.json 같은 모양이에요.",
    );
  });

  it("warns when the backup comes from another robot", () => {
    const parsed = parseZerosBackup(backupText({ serialNumber: "1111111111111" }));
    if (!parsed.ok) throw new Error(backupRefusalText(parsed, "en"));
    expect(serialMismatchWarning(parsed.backup, "8958899989309")).toMatch(
      /saved from robot 1111111111111, not the connected robot 8958899989309/,
    );
    expect(serialMismatchWarning(parsed.backup, "1111111111111")).toBeUndefined();
    expect(serialMismatchWarning(parsed.backup, undefined)).toBeUndefined();
  });
});
