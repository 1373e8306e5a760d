import { readdirSync, readFileSync, statSync } from "node:fs";
import { dirname, join, relative } from "node:path";
import { describe, expect, it } from "vitest";
import { RbcTimeoutError, RbcUploadError } from "../../src/device/errors.ts";
import {
  type Catalogue,
  defineMessages,
  formatBytes,
  formatDate,
  formatDateTime,
  formatDecimal,
  formatKilobytes,
  formatMilliseconds,
  formatNumber,
  formatSeconds,
  formatTime,
  LOCALE_NAMES,
  LOCALES,
  type Message,
  type MessageText,
  pickLocale,
  placeholdersOf,
  translator,
} from "../../src/i18n/index.ts";
import { LinkError } from "../../src/link/transport.ts";
import { initialState } from "../../src/ui/app-state.ts";
import { busySentence } from "../../src/ui/busy.ts";
import { errorMessage, errorNotice } from "../../src/ui/error-text.ts";
import { robotMessages } from "../../src/ui/features/robot/messages.ts";
import { formatCount, formatDelta } from "../../src/ui/format.ts";
import { pageTitle } from "../../src/ui/shell/app-view.ts";
import { LOCALE_STORAGE_KEY, saveLocale, startLocale } from "../../src/ui/shell/locale-choice.ts";
import { versionText } from "../../src/ui/version.ts";
import { isCatalogue } from "../support/catalogue-shape.ts";

/**
 * The panel's two languages (issue #14 item 1, docs/i18n.md): every catalogue (a `messages.ts` under src/) is
 * complete and consistent in both languages and has no unused key; the language of a browser; the translator;
 * numbers, units, dates and times in both languages; the device's errors in Korean.
 */

const SRC = new URL("../../src/", import.meta.url).pathname;

function sourceFiles(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return sourceFiles(path);
    return name.endsWith(".ts") && !name.endsWith(".d.ts") ? [path] : [];
  });
}

const SOURCES = sourceFiles(SRC);
const CATALOGUE_FILES = SOURCES.filter((path) => path.endsWith("/messages.ts"));

/** Every catalogue exported by every messages.ts, with the file it is in. */
const catalogues: { file: string; name: string; messages: Catalogue }[] = [];
for (const file of CATALOGUE_FILES) {
  const module = (await import(file)) as Record<string, unknown>;
  for (const [name, value] of Object.entries(module)) {
    if (isCatalogue(value)) catalogues.push({ file: relative(SRC, file), name, messages: value });
  }
}

/** Each text of a message: "en", or "en.one" and "en.other" for plural forms. */
function textsOf(message: Message): [string, string][] {
  return LOCALES.flatMap((locale): [string, string][] => {
    const text: MessageText = message[locale];
    if (typeof text === "string") return [[locale, text]];
    return Object.entries(text).map(([form, value]): [string, string] => [`${locale}.${form}`, value]);
  });
}

const sorted = (names: string[]) => [...names].sort().join(", ");

describe("the catalogues", () => {
  it("are found: one per messages.ts, at least the shell's, the Robot view's, the panel's and the units'", () => {
    expect(catalogues.map((c) => c.file).sort()).toEqual(CATALOGUE_FILES.map((f) => relative(SRC, f)).sort());
    expect(catalogues.map((c) => c.file)).toEqual(
      expect.arrayContaining([
        "i18n/messages.ts",
        "ui/messages.ts",
        "ui/shell/messages.ts",
        "ui/features/robot/messages.ts",
      ]),
    );
  });

  it("name their keys area.name, each key once across all catalogues", () => {
    const keys = catalogues.flatMap((c) => Object.keys(c.messages));
    expect(keys.filter((k) => !/^[a-z][a-zA-Z0-9]*(\.[a-z][a-zA-Z0-9]*)+$/.test(k))).toEqual([]);
    expect(keys.filter((k, i) => keys.indexOf(k) !== i)).toEqual([]);
  });

  it("have a text in every language, without white space at either end", () => {
    const problems = catalogues.flatMap(({ file, messages }) =>
      Object.entries(messages).flatMap(([key, message]) =>
        textsOf(message)
          .filter(([, text]) => text.trim() === "" || text !== text.trim())
          .map(([where]) => `${file} ${key} ${where}`),
      ),
    );
    expect(problems).toEqual([]);
  });

  it("have the same placeholders in every language and plural form, and no stray brace", () => {
    const problems = catalogues.flatMap(({ file, messages }) =>
      Object.entries(messages).flatMap(([key, message]) => {
        const texts = textsOf(message);
        const [, first] = texts[0]!;
        const expected = sorted(placeholdersOf(first));
        const out: string[] = [];
        for (const [where, text] of texts) {
          if (sorted(placeholdersOf(text)) !== expected)
            out.push(`${file} ${key}: ${where} has {${sorted(placeholdersOf(text))}}, not {${expected}}`);
          if (/[{}]/.test(text.replace(/\{[A-Za-z][A-Za-z0-9]*\}/g, "")))
            out.push(`${file} ${key}: ${where} has a brace that is not a placeholder`);
        }
        return out;
      }),
    );
    expect(problems).toEqual([]);
  });

  it("give plural forms as exactly { one, other }, chosen by a {count} every form shows", () => {
    const problems = catalogues.flatMap(({ file, messages }) =>
      Object.entries(messages).flatMap(([key, message]) =>
        LOCALES.flatMap((locale) => {
          const text = message[locale];
          if (typeof text === "string") return [];
          const forms = Object.keys(text).sort().join(",");
          const out = forms === "one,other" ? [] : [`${file} ${key} ${locale}: forms ${forms}`];
          if (!placeholdersOf(text.one).includes("count"))
            out.push(`${file} ${key} ${locale}: no {count} in its forms`);
          return out;
        }),
      ),
    );
    expect(problems).toEqual([]);
  });

  it("have no unused key: each is written literally in a source file beside its catalogue (or below it)", () => {
    const unused = catalogues.flatMap(({ file, messages }) => {
      const dir = join(SRC, dirname(file));
      const beside = SOURCES.filter((path) => path.startsWith(`${dir}/`) && !path.endsWith("/messages.ts"))
        .map((path) => readFileSync(path, "utf8"))
        .join("\n");
      return Object.keys(messages)
        .filter((key) => !beside.includes(`"${key}"`))
        .map((key) => `${file}: ${key}`);
    });
    expect(unused).toEqual([]);
  });

  it("are Korean in the Korean texts: none is an English word or sentence left untranslated", () => {
    // Without Hangul, a Korean text may only be names, units and numbers ("{size}KB", "HUNO"), never a word.
    const untranslated = catalogues.flatMap(({ file, messages }) =>
      Object.entries(messages).flatMap(([key, message]) =>
        textsOf(message)
          .filter(([where]) => where.startsWith("ko"))
          .filter(([, text]) => {
            const words = text.replace(/\{\w+\}/g, "");
            return !/\p{Script=Hangul}/u.test(words) && /\b[A-Za-z][a-z]{2,}\b/.test(words);
          })
          .map(([, text]) => `${file} ${key}: ${text}`),
      ),
    );
    expect(untranslated).toEqual([]);
  });
});

describe("the language of a browser", () => {
  it("is the first of its languages the panel speaks, by the primary subtag; English otherwise", () => {
    expect(pickLocale(["ko"])).toBe("ko");
    expect(pickLocale(["ko-KR"])).toBe("ko");
    expect(pickLocale(["KO-kr", "en"])).toBe("ko");
    expect(pickLocale(["en-US", "ko-KR"])).toBe("en");
    expect(pickLocale(["fr-FR", "ko"])).toBe("ko");
    expect(pickLocale(["fr-FR", "de"])).toBe("en");
    expect(pickLocale(["kok-IN"])).toBe("en");
    expect(pickLocale([])).toBe("en");
  });

  it("names each language in itself", () => {
    expect(LOCALES).toEqual(["en", "ko"]);
    expect(LOCALE_NAMES).toEqual({ en: "English", ko: "한국어" });
  });

  it("is the saved choice when there is one, the browser's otherwise, and survives a storage that throws", () => {
    const store = new Map<string, string>();
    const storage = {
      getItem: (key: string) => store.get(key) ?? null,
      setItem: (key: string, value: string) => void store.set(key, value),
    };
    expect(startLocale(storage, ["ko-KR"])).toBe("ko");
    expect(saveLocale(storage, "en")).toBe(true);
    expect(store.get(LOCALE_STORAGE_KEY)).toBe("en");
    expect(LOCALE_STORAGE_KEY).toBe("rbc-panel-locale");
    expect(startLocale(storage, ["ko-KR"])).toBe("en");
    store.set(LOCALE_STORAGE_KEY, "fr");
    expect(startLocale(storage, ["ko-KR"])).toBe("ko");
    const refusing = {
      getItem: (): string | null => {
        throw new Error("SecurityError");
      },
      setItem: () => {
        throw new Error("SecurityError");
      },
    };
    expect(startLocale(refusing, ["ko"])).toBe("ko");
    expect(saveLocale(refusing, "ko")).toBe(false);
    expect(startLocale(undefined, ["en-GB"])).toBe("en");
  });
});

describe("the translator", () => {
  const messages = defineMessages({
    "test.plain": { en: "Refresh", ko: "다시 읽기" },
    "test.two": { en: "{used} of {size} bytes used", ko: "{size}바이트 중 {used}바이트 사용" },
    "test.count": { en: { one: "{count} servo", other: "{count} servos" }, ko: "서보 {count}개" },
    "test.link": { en: "Saved as {file}.", ko: "{file}(으)로 저장했어요." },
  });

  it("gives each language its text, with numbers formatted for it", () => {
    const en = translator(messages, "en");
    const ko = translator(messages, "ko");
    expect(en("test.plain")).toBe("Refresh");
    expect(ko("test.plain")).toBe("다시 읽기");
    expect(en("test.two", { used: 640, size: 24576 })).toBe("640 of 24,576 bytes used");
    expect(ko("test.two", { used: 640, size: 24576 })).toBe("24,576바이트 중 640바이트 사용");
    expect(en("test.link", { file: "rbc-zeros-1.json" })).toBe("Saved as rbc-zeros-1.json.");
    expect(en.locale).toBe("en");
    expect(ko.locale).toBe("ko");
  });

  it("chooses English plural forms by count; Korean has one form", () => {
    const en = translator(messages, "en");
    const ko = translator(messages, "ko");
    expect(en("test.count", { count: 1 })).toBe("1 servo");
    expect(en("test.count", { count: 0 })).toBe("0 servos");
    expect(en("test.count", { count: 16 })).toBe("16 servos");
    expect(en("test.count", { count: 1200 })).toBe("1,200 servos");
    expect(ko("test.count", { count: 1 })).toBe("서보 1개");
    expect(ko("test.count", { count: 16 })).toBe("서보 16개");
  });

  it("cuts a message at its placeholders for markup, in each language's word order", () => {
    const link = { tag: "a" };
    expect(translator(messages, "en").parts("test.link", { file: link })).toEqual(["Saved as ", link, "."]);
    expect(translator(messages, "ko").parts("test.link", { file: link })).toEqual([
      link,
      "(으)로 저장했어요.",
    ]);
  });

  it("refuses, at compile time, a key that does not exist and parameters that do not fit", () => {
    const t = translator(robotMessages, "en");
    expect(t("robot.refresh")).toBe("Refresh");
    // @ts-expect-error: no such key
    expect(t("robot.nope")).toBe("robot.nope");
    // @ts-expect-error: the message needs its {time}
    t("robot.readAt");
    // @ts-expect-error: {time}, not {when}
    t("robot.readAt", { when: "14:02:11" });
    // @ts-expect-error: a plural's count is a number
    t("robot.bytesFree", { count: "5" });
    // @ts-expect-error: this message takes no parameters
    t("robot.refresh", { count: 1 });
  });
});

describe("numbers, units, dates and times", () => {
  const date = new Date(2026, 10, 21, 9, 2, 11);

  it("write numbers with grouped thousands in both languages", () => {
    expect(formatNumber(24576, "en")).toBe("24,576");
    expect(formatNumber(24576, "ko")).toBe("24,576");
    expect(formatNumber(-1234.5, "ko")).toBe("-1,234.5");
    expect(formatDecimal(1.25, "en", 1)).toBe("1.3");
    expect(formatDecimal(1234.5, "ko", 2)).toBe("1,234.50");
    expect(formatCount(24576)).toBe("24,576");
    expect(formatCount(8192, "ko")).toBe("8,192");
    expect(formatDelta(-1200, "ko")).toBe("\u22121,200");
  });

  it("write bytes, kilobytes, seconds and milliseconds", () => {
    expect(formatBytes(24576, "en")).toBe("24,576 bytes");
    expect(formatBytes(1, "en")).toBe("1 byte");
    expect(formatBytes(0, "en")).toBe("0 bytes");
    expect(formatBytes(24576, "ko")).toBe("24,576바이트");
    expect(formatKilobytes(24576, "en")).toBe("24 KB");
    expect(formatKilobytes(1536, "ko")).toBe("1.5KB");
    expect(formatKilobytes(8192, "en")).toBe("8 KB");
    expect(formatKilobytes(409600, "en")).toBe("400 KB");
    expect(formatSeconds(1.5, "en")).toBe("1.5 s");
    expect(formatSeconds(12, "ko")).toBe("12.0초");
    expect(formatSeconds(2.345, "en", 2)).toBe("2.35 s");
    expect(formatMilliseconds(250, "en")).toBe("250 ms");
    expect(formatMilliseconds(1250.4, "ko")).toBe("1,250ms");
  });

  it("write dates in each language's order, times on the 24-hour clock", () => {
    expect(formatDate(date, "en")).toBe("Nov 21, 2026");
    expect(formatDate(date, "ko")).toBe("2026년 11월 21일");
    expect(formatTime(date, "en")).toBe("09:02:11");
    expect(formatTime(date.getTime(), "ko")).toBe("09:02:11");
    expect(formatTime(new Date(2026, 10, 21, 14, 2, 11), "ko")).toBe("14:02:11");
    expect(formatDateTime(date, "en")).toBe("Nov 21, 2026, 09:02");
    expect(formatDateTime(date, "ko")).toBe("2026년 11월 21일 09:02");
  });
});

describe("the panel's words in Korean", () => {
  it("title the page with the view, the demo robot and the panel", () => {
    const state = initialState({ serialSupported: true, secureContext: true, route: "zeros", locale: "ko" });
    expect(pageTitle({ state })).toBe("영점 · RBC 패널");
    const demo = {
      ...state,
      route: "robot",
      connection: {
        ...state.connection,
        phase: "connected" as const,
        robot: { kind: "demo" as const, name: "Demo" },
      },
    };
    expect(pageTitle({ state: demo })).toBe("로봇 · 데모 로봇 · RBC 패널");
    expect(pageTitle({ state: { ...demo, locale: "en" } })).toBe("Robot · Demo robot · RBC Panel");
  });

  it("say what runs, and the version", () => {
    expect(busySentence(["모션 업로드"], "ko")).toBe("아직 실행 중이에요: 모션 업로드.");
    expect(busySentence(["Writing zeros", "Playing sound 7"])).toBe(
      "Still running: Writing zeros, Playing sound 7.",
    );
    expect(busySentence([], "ko")).toBeUndefined();
    const info = { version: "0.1.0", commit: "67f4344", changelogUrl: "" };
    expect(versionText(info, "ko")).toBe("버전 0.1.0 (67f4344)");
    expect(versionText(info)).toBe("Version 0.1.0 (67f4344)");
    expect(versionText({ ...info, commit: "unknown" }, "ko")).toBe("버전 0.1.0");
  });
});

describe("the device's errors", () => {
  const timeout = new RbcTimeoutError("read error code", 400);

  it("are the device's own sentence in English, and a Korean sentence from the code in Korean", () => {
    expect(errorMessage(timeout)).toBe(
      'The robot did not answer "read error code" within 400 ms. Check that it is switched on and the cable is plugged in; the RBC also stays silent when it refuses a request.',
    );
    expect(errorMessage(timeout, "ko")).toBe(
      '로봇이 400ms 안에 "read error code"에 응답하지 않았어요. 로봇이 켜져 있는지, 케이블이 꽂혀 있는지 확인해 주세요. RBC는 요청을 거부할 때도 응답하지 않아요.',
    );
    expect(errorMessage(new LinkError("port-busy", "The port is in use by another program."), "ko")).toBe(
      "다른 프로그램(또는 다른 탭)이 이 포트를 쓰고 있어요. 그 프로그램을 닫고 다시 연결해 주세요.",
    );
    expect(errorMessage(new Error("boom"), "ko")).toBe(
      "예상하지 못한 문제가 생겼어요. 자세한 내용은 기술 정보에 있어요.",
    );
  });

  it("keep the device's English sentence as the technical detail of a Korean notice", () => {
    const n = errorNotice("로봇 정보를 읽지 못했어요.", timeout, "ko");
    expect(n.text.startsWith("로봇 정보를 읽지 못했어요. 로봇이 400ms 안에")).toBe(true);
    expect(n.detail).toBe(`RbcTimeoutError (timeout): ${timeout.message}`);
  });

  it("say in Korean what an interrupted upload left on the robot", () => {
    const interrupted = new RbcUploadError(
      "disconnected",
      "The connection was lost…",
      128,
      640,
      "interrupted",
    );
    expect(errorMessage(interrupted, "ko")).toBe(
      "로봇과의 연결이 끊겼어요. 케이블을 확인한 뒤 다시 연결해 주세요. 로봇이 640바이트 중 128바이트를 받았다고 확인했어요. " +
        "로봇이 아직 파일의 나머지를 기다리고 있고, 아무것도 기록하지 않았을 거예요. 다음 업로드 전에 로봇을 껐다가 다시 켜 주세요.",
    );
    const nothing = new RbcUploadError("upload-failed", "…", 640, 640, "nothing-recorded");
    expect(errorMessage(nothing, "ko")).toBe(
      "업로드를 마치지 못했어요. 로봇이 640바이트 중 640바이트를 받았다고 확인했어요. 로봇은 아무것도 기록하지 않았어요. 파일을 다시 업로드해 주세요.",
    );
  });
});
