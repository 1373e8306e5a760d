import { readdirSync, statSync } from "node:fs";
import { join, relative } from "node:path";
import { fileURLToPath } from "node:url";
import { parseAst, transformWithOxc } from "vite";
import { describe, expect, it } from "vitest";
import {
  splitModule,
  UnsplittableCatalogue,
  waitForWords,
  wordsChunkName,
} from "../../scripts/vite-words-per-language.ts";
import { defineMessages } from "../../src/i18n/catalogue.ts";
import type { Locale } from "../../src/i18n/locale.ts";
import { type LanguageLoader, type LanguageTexts, wordsRegistry } from "../../src/i18n/split-catalogue.ts";
import { translator } from "../../src/i18n/translate.ts";
import { initialState } from "../../src/ui/app-state.ts";
import { chooseLocale } from "../../src/ui/shell/actions.ts";
import { LOCALE_STORAGE_KEY } from "../../src/ui/shell/locale-choice.ts";
import { createStore } from "../../src/ui/store.ts";

/**
 * One language at a time (issue 19 item 6, docs/i18n.md): the build's split of a catalogue module into keys and
 * a chunk per language (scripts/vite-words-per-language.ts), checked on literal text and on every catalogue in
 * src/; and the page's registry (src/i18n/split-catalogue.ts): only the languages asked for are loaded, an
 * import waits for its words, a failed load changes nothing.
 */

const ROOT = fileURLToPath(new URL("../..", import.meta.url));
const OPTIONS = { locales: ["en", "ko"], runtime: "/r/split-catalogue.ts" };
const chunkId = (locale: string) => `rbc-words:${locale}:/p/messages.ts`;

type Program = Parameters<typeof splitModule>[1];
const parse = (code: string) => parseAst(code) as unknown as Program;

const SAMPLE = `import { defineMessages } from "../../i18n/catalogue.ts";
export const aMessages = defineMessages({
  "a.refresh": { en: "Refresh", ko: "다시 읽기" },
  "a.bytes": { ko: \`{count}바이트\`, en: { one: "{count} byte", other: "{count} bytes" } },
});
export const bMessages = defineMessages({ "b.title": { en: "Log", ko: "로그" } });
`;

describe("the build's split of a catalogue module", () => {
  it("writes each language's texts, in key order, into a chunk of its own", () => {
    const split = splitModule(SAMPLE, parse(SAMPLE), OPTIONS, chunkId);
    expect(split?.chunks.get("en")).toBe(
      'export default [[\n"Refresh",\n{ one: "{count} byte", other: "{count} bytes" }\n], [\n"Log"\n]];\n',
    );
    expect(split?.chunks.get("ko")).toBe(
      'export default [[\n"다시 읽기",\n`{count}바이트`\n], [\n"로그"\n]];\n',
    );
  });

  it("leaves the keys in the module and no text of either language", () => {
    const code = splitModule(SAMPLE, parse(SAMPLE), OPTIONS, chunkId)?.code ?? "";
    expect(code).toContain('__rbcSplit([["a.refresh","a.bytes"],["b.title"]], ');
    expect(code).toContain('"en": () => import("rbc-words:en:/p/messages.ts")');
    expect(code).toContain('"ko": () => import("rbc-words:ko:/p/messages.ts")');
    expect(code).toContain("export const aMessages = defineMessages(__rbcWords[0]);");
    expect(code).toContain("export const bMessages = defineMessages(__rbcWords[1]);");
    for (const text of ["Refresh", "다시 읽기", "{count} byte", "바이트", '"Log"', "로그"])
      expect(code).not.toContain(text);
  });

  it("leaves a module without defineMessages alone", () => {
    const code = 'import { translator } from "../i18n/translate.ts";\nexport const x = 1;\n';
    expect(splitModule(code, parse(code), OPTIONS, chunkId)).toBeUndefined();
  });

  it.each([
    ["a spread", 'defineMessages({ ...other, "a.b": { en: "A", ko: "가" } })'],
    ["a computed key", 'defineMessages({ [key]: { en: "A", ko: "가" } })'],
    ["a constant for a text", 'defineMessages({ "a.b": { en: TEXT, ko: "가" } })'],
    ["a template with a placeholder", `defineMessages({ "a.b": { en: \`A \${x}\`, ko: "가" } })`],
    ["a missing language", 'defineMessages({ "a.b": { en: "A" } })'],
    ["a language it does not know", 'defineMessages({ "a.b": { en: "A", ko: "가", fr: "A" } })'],
    [
      "plural forms besides one and other",
      'defineMessages({ "a.b": { en: { one: "A", few: "B" }, ko: "가" } })',
    ],
    ["an argument that is not an object literal", "defineMessages(table)"],
  ])("refuses %s (the module then ships both languages)", (_, call) => {
    const code = `import { defineMessages } from "./catalogue.ts";\nexport const m = ${call};\n`;
    expect(() => splitModule(code, parse(code), OPTIONS, chunkId)).toThrow(UnsplittableCatalogue);
  });

  it("wraps each import() in wordsAfter, so lazily loaded code waits for its words", () => {
    const code = 'const views = [() => import("./a.ts"), () => import("./b.ts")];\n';
    expect(waitForWords(code, parse(code), "/r/split-catalogue.ts")).toBe(
      'import { wordsAfter as __rbcAfter } from "/r/split-catalogue.ts";\n' +
        'const views = [() => __rbcAfter(import("./a.ts")), () => __rbcAfter(import("./b.ts"))];\n',
    );
    expect(waitForWords("export const x = 1;\n", parse("export const x = 1;\n"), "/r")).toBeUndefined();
  });

  it("names the chunks by language and catalogue folder", () => {
    expect(wordsChunkName("/p", "/p/src/ui/features/connection/messages.ts", "ko")).toBe(
      "words-ko-ui-features-connection",
    );
    expect(wordsChunkName("/p", "/p/src/i18n/messages.ts", "en")).toBe("words-en-i18n");
  });
});

function sources(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? sources(path) : path.endsWith(".ts") ? [path] : [];
  });
}

const CATALOGUE_MODULES = sources(join(ROOT, "src")).filter((p) => p.endsWith("/messages.ts"));

/** Evaluates a chunk's code (`export default [...]`). */
async function chunkTexts(code: string): Promise<LanguageTexts> {
  const module = (await import(`data:text/javascript,${encodeURIComponent(code)}`)) as {
    default: LanguageTexts;
  };
  return module.default;
}

describe("every catalogue in src/ splits without losing a text", () => {
  it("finds the catalogues", () => {
    expect(CATALOGUE_MODULES.length).toBeGreaterThan(15);
  });

  it.each(CATALOGUE_MODULES.map((p) => [relative(ROOT, p), p]))("%s", async (_, path) => {
    const { readFile } = await import("node:fs/promises");
    const { code } = await transformWithOxc(await readFile(path, "utf8"), path, { lang: "ts" });
    const split = splitModule(code, parse(code), OPTIONS, chunkId);
    expect(split).toBeDefined();
    const keys = JSON.parse(/__rbcSplit\((\[.*?\]\]), \{/.exec(split?.code ?? "")?.[1] ?? "[]") as string[][];
    // The module as written: its catalogues, in the order of their defineMessages calls.
    const original = Object.values((await import(path)) as Record<string, unknown>).filter(
      (v): v is Record<string, Record<Locale, unknown>> => typeof v === "object" && v !== null,
    );
    for (const locale of ["en", "ko"] as const) {
      const texts = await chunkTexts(split?.chunks.get(locale) ?? "");
      const rebuilt = keys.map((list, i) => Object.fromEntries(list.map((k, j) => [k, texts[i]?.[j]])));
      expect(rebuilt).toEqual(
        original.map((catalogue) =>
          Object.fromEntries(Object.entries(catalogue).map(([k, m]) => [k, m[locale]])),
        ),
      );
    }
  });
});

/** A loader that resolves when the test says so, and counts its calls. */
function deferredLoader(texts: LanguageTexts) {
  const state = { calls: 0, release: (): void => undefined, fail: (_e: Error): void => undefined };
  const load: LanguageLoader = () => {
    state.calls++;
    return new Promise((resolve, reject) => {
      state.release = () => resolve({ default: texts });
      state.fail = reject;
    });
  };
  return Object.assign(state, { load });
}

const shapeOnly = defineMessages({
  "t.hello": { en: "Hello", ko: "안녕하세요" },
  "t.items": { en: { one: "{count} item", other: "{count} items" }, ko: "{count}개" },
});

function registered() {
  const registry = wordsRegistry();
  const en = deferredLoader([["Hello", { one: "{count} item", other: "{count} items" }]]);
  const ko = deferredLoader([["안녕하세요", "{count}개"]]);
  const [catalogue] = registry.splitCatalogues([["t.hello", "t.items"]], { en: en.load, ko: ko.load });
  return { registry, en, ko, catalogue: catalogue as unknown as typeof shapeOnly };
}

const settled = () => new Promise((resolve) => setTimeout(resolve, 0));

describe("the page's registry of split catalogues", () => {
  it("loads only the language asked for, and fills the catalogue when it arrives", async () => {
    const { registry, en, ko, catalogue } = registered();
    expect(catalogue["t.hello"]).toEqual({});
    const loading = registry.loadLanguage("ko");
    ko.release();
    await loading;
    expect([en.calls, ko.calls]).toEqual([0, 1]);
    expect(registry.languageLoaded("ko")).toBe(true);
    expect(registry.languageLoaded("en")).toBe(false);
    const t = translator(catalogue, "ko");
    expect(t("t.hello")).toBe("안녕하세요");
    expect(t("t.items", { count: 3 })).toBe("3개");
  });

  it("loads the other language when it is switched to, once", async () => {
    const { registry, en, ko, catalogue } = registered();
    const first = registry.loadLanguage("en");
    en.release();
    await first;
    const switching = registry.loadLanguage("ko");
    ko.release();
    await switching;
    await registry.loadLanguage("en");
    expect([en.calls, ko.calls]).toEqual([1, 1]);
    expect(translator(catalogue, "en")("t.items", { count: 1 })).toBe("1 item");
    expect(translator(catalogue, "ko")("t.hello")).toBe("안녕하세요");
  });

  it("lets an import() resolve only once the catalogues it brought hold the active language", async () => {
    const { registry, ko } = registered();
    const first = registry.loadLanguage("ko");
    ko.release();
    await first;
    // A view's chunk arrives and registers its catalogue while it is evaluated.
    const view = deferredLoader([["보기"]]);
    let arrived = false;
    const imported = registry.wordsAfter(
      Promise.resolve().then(() => {
        registry.splitCatalogues([["v.title"]], { en: deferredLoader([["View"]]).load, ko: view.load });
        return { default: "view" };
      }),
    );
    void imported.then(() => {
      arrived = true;
    });
    await settled();
    expect(view.calls).toBe(1);
    expect(arrived).toBe(false);
    view.release();
    expect((await imported).default).toBe("view");
  });

  it("keeps the active language when a load fails, and tries again on the next switch", async () => {
    const { registry, en, ko, catalogue } = registered();
    const first = registry.loadLanguage("en");
    en.release();
    await first;
    const failing = registry.loadLanguage("ko");
    ko.fail(new Error("offline"));
    await expect(failing).rejects.toThrow("offline");
    expect(registry.languageLoaded("ko")).toBe(false);
    expect(translator(catalogue, "en")("t.hello")).toBe("Hello");
    const again = registry.loadLanguage("ko");
    ko.release();
    await again;
    expect(ko.calls).toBe(2);
    expect(translator(catalogue, "ko")("t.hello")).toBe("안녕하세요");
  });

  it("keeps English for the catalogues there are and those that come later", async () => {
    const { registry, en, ko } = registered();
    const first = registry.loadLanguage("ko");
    ko.release();
    await first;
    const keeping = registry.keepLanguage("en");
    en.release();
    await keeping;
    const laterEn = deferredLoader([["Later"]]);
    const laterKo = deferredLoader([["나중"]]);
    const [later] = registry.splitCatalogues([["l.x"]], { en: laterEn.load, ko: laterKo.load });
    expect([laterEn.calls, laterKo.calls]).toEqual([1, 1]);
    laterEn.release();
    laterKo.release();
    await registry.wordsAfter(Promise.resolve());
    expect(later?.["l.x"]).toEqual({ en: "Later", ko: "나중" });
  });

  it("stands in with the language there is for one asked for by name before it arrives", async () => {
    const { registry, ko, catalogue } = registered();
    const first = registry.loadLanguage("ko");
    ko.release();
    await first;
    expect(translator(catalogue, "en")("t.hello")).toBe("안녕하세요");
  });

  it("has nothing to wait for where nothing was split (Node, the dev server, the one-file panel)", async () => {
    const registry = wordsRegistry();
    await registry.loadLanguage("ko");
    expect(await registry.wordsAfter(Promise.resolve(7))).toBe(7);
    expect(registry.languageLoaded("en")).toBe(true);
  });
});

describe("the language switch", () => {
  const memoryStorage = () => {
    const items = new Map<string, string>();
    return {
      items,
      getItem: (k: string) => items.get(k) ?? null,
      setItem: (k: string, v: string) => void items.set(k, v),
    };
  };

  it("changes the language only after its words are loaded, and remembers it", async () => {
    const store = createStore(
      initialState({ serialSupported: true, secureContext: true, route: "robot", locale: "en" }),
    );
    const storage = memoryStorage();
    let release: () => void = () => undefined;
    const choosing = chooseLocale(store, "ko", storage, () => new Promise<void>((r) => (release = r)));
    await settled();
    expect(store.get().locale).toBe("en");
    release();
    expect(await choosing).toBe(true);
    expect(store.get().locale).toBe("ko");
    expect(storage.items.get(LOCALE_STORAGE_KEY)).toBe("ko");
  });

  it("changes nothing when the words cannot be loaded", async () => {
    const store = createStore(
      initialState({ serialSupported: true, secureContext: true, route: "robot", locale: "en" }),
    );
    const storage = memoryStorage();
    const chosen = await chooseLocale(store, "ko", storage, () => Promise.reject(new Error("offline")));
    expect(chosen).toBe(false);
    expect(store.get().locale).toBe("en");
    expect(storage.items.size).toBe(0);
  });
});
