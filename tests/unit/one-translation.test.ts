import { describe, expect, it } from "vitest";
import { type CatalogueEntry, catalogueEntries } from "../support/catalogue-entries.ts";

/**
 * Issue 31's rule for the words of both front ends: one fact, one entry. The command line's catalogues
 * (src/cli), the panel's (src/ui) and the shared ones (src/i18n: the outcome catalogue, the names of joints,
 * motions and sounds) are read as modules; every entry of every catalogue is compared by its English text:
 *
 * - an English text has one Korean translation, wherever it is written (two translations of one sentence is
 *   how the languages drifted apart);
 * - a text the command line and the panel both say is one entry of src/i18n that both use, never a copy in
 *   each front end (nor a front end's copy of a shared entry).
 *
 * A single word is a label whose Korean depends on what it labels ("Check" is the Editor's tab 검사 and the
 * servo doctor's column 살펴보기), and a text of placeholders only ("{path}: {why}") is framing, so only texts of
 * two words or more, with words besides their placeholders, are compared.
 */

type Entry = CatalogueEntry;

/** The front end an entry belongs to: "cli", "ui", or "i18n" (shared by both). */
const sideOf = (file: string) => file.split("/")[0] ?? file;

/** Whether a text is more than a label: two words or more, and words besides its placeholders ("{path}: {why}"). */
const compared = (en: string) =>
  en.trim().split(/\s+/).length > 1 && /[a-z]/i.test(en.replace(/\{\w+\}/g, ""));

/** The texts compared, grouped by their English. */
function byEnglish(entries: readonly Entry[]): Map<string, Entry[]> {
  const groups = new Map<string, Entry[]>();
  for (const e of entries) {
    if (!compared(e.en)) continue;
    groups.set(e.en, [...(groups.get(e.en) ?? []), e]);
  }
  return groups;
}

const where = (es: readonly Entry[]) => es.map((e) => `${e.file} ${e.key}: ${e.ko}`).join("; ");

/** English texts translated in more than one way. */
function twoTranslations(entries: readonly Entry[]): string[] {
  return [...byEnglish(entries)]
    .filter(([, es]) => new Set(es.map((e) => e.ko)).size > 1)
    .map(([en, es]) => `${en} → ${where(es)}`);
}

/** English texts written by two sides (the command line and the panel, or a front end and src/i18n). */
function wordedTwice(entries: readonly Entry[]): string[] {
  return [...byEnglish(entries)]
    .filter(([, es]) => new Set(es.map((e) => sideOf(e.file))).size > 1)
    .map(([en, es]) => `${en} → ${where(es)}`);
}

const entries = await catalogueEntries();

describe("one translation, one entry", () => {
  it("finds an English text translated twice, and one text written by both front ends", () => {
    const fake: Entry[] = [
      { file: "cli/messages.ts", key: "cli.a", en: "Hold the robot.", ko: "로봇을 잡아 주세요." },
      { file: "ui/x/messages.ts", key: "x.a", en: "Hold the robot.", ko: "로봇을 붙잡아 주세요." },
      { file: "ui/x/messages.ts", key: "x.b", en: "Check", ko: "검사" },
      { file: "ui/y/messages.ts", key: "y.b", en: "Check", ko: "살펴보기" },
      { file: "cli/messages.ts", key: "cli.e", en: "{path}: {why}", ko: "{path}: {why}" },
      { file: "ui/y/messages.ts", key: "y.e", en: "{path}: {why}", ko: "{path}에 문제가 생겼어요: {why}" },
      { file: "ui/x/messages.ts", key: "x.c", en: "Not written.", ko: "쓰지 않았어요." },
      { file: "ui/y/messages.ts", key: "y.c", en: "Not written.", ko: "쓰지 않았어요." },
      { file: "cli/messages.ts", key: "cli.d", en: "No reply.", ko: "응답이 없어요." },
      { file: "i18n/outcomes/messages.ts", key: "outcome.d", en: "No reply.", ko: "응답이 없어요." },
    ];
    expect(twoTranslations(fake)).toEqual([
      "Hold the robot. → cli/messages.ts cli.a: 로봇을 잡아 주세요.; ui/x/messages.ts x.a: 로봇을 붙잡아 주세요.",
    ]);
    expect(wordedTwice(fake)).toEqual([
      "Hold the robot. → cli/messages.ts cli.a: 로봇을 잡아 주세요.; ui/x/messages.ts x.a: 로봇을 붙잡아 주세요.",
      "No reply. → cli/messages.ts cli.d: 응답이 없어요.; i18n/outcomes/messages.ts outcome.d: 응답이 없어요.",
    ]);
  });

  it("reads the catalogues of src/i18n, src/ui and src/cli", () => {
    const sides = new Set(entries.map((e) => sideOf(e.file)));
    expect([...sides].sort()).toEqual(["cli", "i18n", "ui"]);
    expect(entries.length).toBeGreaterThan(2000);
  });

  it("translates each English text one way", () => {
    expect(twoTranslations(entries)).toEqual([]);
  });

  it("words a text both front ends say once, in src/i18n", () => {
    expect(wordedTwice(entries)).toEqual([]);
  });
});
