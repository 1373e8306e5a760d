import { describe, expect, it } from "vitest";
import { LOCALES } from "../../src/i18n/locale.ts";
import {
  SOUND_KINDS,
  soundKindOfLength,
  soundName,
  soundNamed,
} from "../../src/i18n/sound-names/sound-name.ts";
import { runInProcess } from "../cli/in-process.ts";

/**
 * The one catalogue of sound names (issue 21 item 8): sounds 1-25 are named in both languages, by their length
 * (docs/protocol.md §3.3 gives lengths only), and `rbc sound` says the name the panel's buttons show.
 */

/** docs/protocol.md §3.3, copied from the spec (not from src/protocol/catalog.ts). */
const SPEC_LENGTHS_MS = [
  2268, 1001, 832, 365, 838, 417, 5671, 5916, 780, 2907, 552, 522, 1525, 2494, 438, 402, 433, 461, 343, 472,
  354, 461, 458, 442, 371,
];

describe("sound names", () => {
  it("name every sound 1-25 in English and Korean, and no other number", () => {
    for (const locale of LOCALES) {
      for (let n = 1; n <= 25; n++) {
        const name = soundName(n, locale);
        expect(name, `sound ${n} (${locale})`).toMatch(/\S/);
        expect(name).not.toMatch(/^sound\./);
      }
      for (const n of [0, 26, -1, 2.5, Number.NaN]) expect(soundName(n, locale)).toBeUndefined();
    }
    expect(SOUND_KINDS).toHaveLength(25);
  });

  it("name each sound by its length in the spec", () => {
    SPEC_LENGTHS_MS.forEach((ms, i) => {
      expect(SOUND_KINDS[i], `sound ${i + 1}, ${ms} ms`).toBe(soundKindOfLength(ms));
    });
    expect(soundKindOfLength(499)).toBe("blip");
    expect(soundKindOfLength(500)).toBe("short");
    expect(soundKindOfLength(2999)).toBe("medium");
    expect(soundKindOfLength(3000)).toBe("long");
  });

  it("say the names literally in both languages", () => {
    expect(soundNamed(7, "en")).toBe("Sound 7: Long");
    expect(soundNamed(7, "ko")).toBe("소리 7번: 긴 소리");
    expect(soundNamed(1, "en")).toBe("Sound 1: Medium");
    expect(soundNamed(1, "ko")).toBe("소리 1번: 중간 길이 소리");
    expect(soundNamed(3, "en")).toBe("Sound 3: Short");
    expect(soundNamed(3, "ko")).toBe("소리 3번: 짧은 소리");
    expect(soundNamed(25, "en")).toBe("Sound 25: Very short");
    expect(soundNamed(25, "ko")).toBe("소리 25번: 아주 짧은 소리");
    expect(soundNamed(26, "en")).toBeUndefined();
  });
});

describe("rbc sound", () => {
  const ENGLISH = { LANG: "en_US.UTF-8" };
  it("names the sound it plays, in English and Korean, and in --json", { timeout: 30_000 }, async () => {
    const [en, ko, json] = await Promise.all([
      runInProcess(["sound", "7", "--demo"], { env: ENGLISH }),
      runInProcess(["sound", "3", "--demo", "--lang", "ko"]),
      runInProcess(["sound", "25", "--demo", "--json"], { env: ENGLISH }),
    ]);
    expect(en.code, en.stderr).toBe(0);
    expect(en.stdout).toMatch(/^Playing sound 7 \(Long, 5671 ms\)…\nDone in 5\.\d s\.\n$/);
    expect(ko.code, ko.stderr).toBe(0);
    expect(ko.stdout).toMatch(/^소리 3번 재생 중 \(짧은 소리, 832ms\)…\n/);
    expect(json.code, json.stderr).toBe(0);
    expect(JSON.parse(json.stdout)).toMatchObject({
      ok: true,
      sound: 25,
      name: "Very short",
      lengthMs: 371,
    });
  });

  it("lists the sounds by name in its help, in both languages", async () => {
    const [en, ko] = await Promise.all([
      runInProcess(["sound", "--help"], { env: ENGLISH }),
      runInProcess(["sound", "--help", "--lang", "ko"]),
    ]);
    expect(en.stdout).toContain(
      "The sounds are named by how long they play (their real names are not known):\n" +
        "  Long: 7, 8\n" +
        "  Medium: 1, 10, 13, 14\n" +
        "  Short: 2, 3, 5, 9, 11, 12\n" +
        "  Very short: 4, 6, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25\n",
    );
    expect(ko.stdout).toContain(
      "소리 이름은 재생 길이로 붙였어요 (실제 이름은 알려져 있지 않아요):\n" +
        "  긴 소리: 7, 8\n" +
        "  중간 길이 소리: 1, 10, 13, 14\n" +
        "  짧은 소리: 2, 3, 5, 9, 11, 12\n" +
        "  아주 짧은 소리: 4, 6, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25\n",
    );
  });
});
