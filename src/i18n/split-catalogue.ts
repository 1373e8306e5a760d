import type { Catalogue, MessageText } from "./catalogue.ts";
import type { Locale } from "./locale.ts";

/**
 * Catalogues whose languages load one at a time: the panel's hosted build (docs/i18n.md, "One language at a
 * time"). A catalogue is written as always, both languages side by side in one `defineMessages` call; the build
 * (scripts/vite-words-per-language.ts) turns each catalogue module into its keys plus one small chunk per
 * language, registered here as the module is evaluated:
 *
 *   const words = splitCatalogues(keys, { en: () => import(…), ko: () => import(…) });
 *
 * main.ts draws nothing before `loadLanguage(start)` has filled every catalogue of the first load, and the build
 * wraps every `import()` of the panel's code in `wordsAfter`, so a lazily loaded view arrives with its words:
 * no render shows a key or the wrong language. The language switch calls `loadLanguage` before it changes the
 * state, so the redraw finds every catalogue in the new language. Once the page is drawn, `keepLanguage("en")`
 * fetches English too, in the background (English is the language of the technical detail; code that asks for
 * it by name gets it).
 *
 * Nothing registers here in Node (the command line, the tests), on the dev server or in the one-file panel:
 * their catalogues hold both languages, and every function here then has nothing to wait for.
 */

/** One language's texts of a module's catalogues: per `defineMessages` call, its texts in key order. */
export type LanguageTexts = readonly (readonly MessageText[])[];

/** Loads one language's texts of a module (a dynamic import of the chunk the build made). */
export type LanguageLoader = () => Promise<{ readonly default: LanguageTexts }>;

/** A message whose languages arrive one by one. */
type FillingMessage = { [L in Locale]?: MessageText };

interface SplitModule {
  /** Per `defineMessages` call: its keys, in the order of the language chunks' texts. */
  readonly keys: readonly (readonly string[])[];
  readonly catalogues: readonly Record<string, FillingMessage>[];
  readonly loaders: Readonly<Record<Locale, LanguageLoader>>;
  /** Languages asked for (the promise settles when they are in the catalogues). */
  readonly loading: Map<Locale, Promise<void>>;
}

/** Thrown when a module's language chunk does not match its keys (a build fault, never a person's). */
export class CatalogueSplitError extends Error {
  override readonly name = "CatalogueSplitError";
}

function fill(module: SplitModule, locale: Locale, texts: LanguageTexts): void {
  if (texts.length !== module.keys.length)
    throw new CatalogueSplitError(
      `language chunk "${locale}" has ${texts.length} catalogues for ${module.keys.length}`,
    );
  module.keys.forEach((keys, i) => {
    const list = texts[i];
    const catalogue = module.catalogues[i];
    if (!list || !catalogue || list.length !== keys.length)
      throw new CatalogueSplitError(`language chunk "${locale}" does not match its catalogue's keys`);
    keys.forEach((key, k) => {
      const message = catalogue[key];
      const text = list[k];
      if (message && text !== undefined) message[locale] = text;
    });
  });
}

function loadInto(module: SplitModule, locale: Locale): Promise<void> {
  let promise = module.loading.get(locale);
  if (!promise) {
    promise = module.loaders[locale]().then((chunk) => fill(module, locale, chunk.default));
    // A failed load may be tried again (the switch, once the network is back).
    promise.catch(() => module.loading.delete(locale));
    module.loading.set(locale, promise);
  }
  return promise;
}

/** What a page (or a test) keeps: the catalogues registered so far and the languages they hold. */
export interface WordsRegistry {
  /**
   * Registers a module's catalogues (per `defineMessages` call, its keys) and returns them, empty at first;
   * they are filled with the active language and every kept one as those arrive. Called only by the code the
   * build writes into a catalogue module.
   */
  splitCatalogues(
    keys: readonly (readonly string[])[],
    loaders: Readonly<Record<Locale, LanguageLoader>>,
  ): Catalogue[];
  /**
   * Makes `locale` the active language: resolves once every catalogue there is (including any registered
   * meanwhile) holds it, at once where nothing was split. Rejects if a chunk cannot be loaded; the active
   * language then stays as it was.
   */
  loadLanguage(locale: Locale): Promise<void>;
  /**
   * From now on every catalogue also holds `locale`: the ones there are (loaded now) and the ones that come
   * later. Resolves when the ones there are hold it.
   */
  keepLanguage(locale: Locale): Promise<void>;
  /**
   * Resolves with what `imported` resolves with, once every catalogue registered by then holds the active
   * language and every kept one. The build wraps each `import()` of the panel's code in it, so a lazily loaded
   * view is drawn only when its words are there, like its code.
   */
  wordsAfter<T>(imported: Promise<T>): Promise<T>;
  /** Whether every catalogue there is holds `locale` (always true where nothing was split). */
  languageLoaded(locale: Locale): boolean;
}

export function wordsRegistry(): WordsRegistry {
  const modules: SplitModule[] = [];
  /** The language the page speaks, once `loadLanguage` has made one active. */
  let active: Locale | undefined;
  /** Languages every catalogue holds besides the active one (`keepLanguage`). */
  const kept = new Set<Locale>();
  const wanted = (): Locale[] => (active ? [active, ...kept] : [...kept]);
  /** Loads `locales` into every module, including modules registered while it waits. */
  const loadEverywhere = async (locales: readonly Locale[]): Promise<void> => {
    let done = -1;
    while (done !== modules.length) {
      done = modules.length;
      await Promise.all(modules.flatMap((module) => locales.map((locale) => loadInto(module, locale))));
    }
  };
  return {
    splitCatalogues(keys, loaders) {
      const catalogues = keys.map((list) =>
        Object.fromEntries(list.map((key): [string, FillingMessage] => [key, {}])),
      );
      const module: SplitModule = { keys, catalogues, loaders, loading: new Map() };
      modules.push(module);
      // Start at once; whoever waits (loadLanguage, wordsAfter) sees the failure, if any.
      for (const locale of wanted()) loadInto(module, locale).catch(() => undefined);
      // Each message holds the languages loaded so far, which are all a translator is asked for.
      return catalogues as unknown as Catalogue[];
    },
    async loadLanguage(locale) {
      await loadEverywhere([locale]);
      active = locale;
    },
    async keepLanguage(locale) {
      kept.add(locale);
      await loadEverywhere([locale]);
    },
    async wordsAfter(imported) {
      const module = await imported;
      await loadEverywhere(wanted());
      return module;
    },
    languageLoaded(locale) {
      return modules.every((module) =>
        module.catalogues.every((catalogue) =>
          Object.values(catalogue).every((m) => m[locale] !== undefined),
        ),
      );
    },
  };
}

/**
 * The page's registry (module state on purpose: catalogue modules register as they are evaluated, and the
 * language switch must reach all of them).
 */
const page = wordsRegistry();
export const splitCatalogues = page.splitCatalogues;
export const loadLanguage = page.loadLanguage;
export const keepLanguage = page.keepLanguage;
export const wordsAfter = page.wordsAfter;
export const languageLoaded = page.languageLoaded;
