/**
 * The hosted panel loads one language's words at a time (docs/i18n.md, "One language at a time"). Catalogues
 * are written with both languages side by side (`defineMessages({ key: { en, ko } })`); this Vite plugin
 * rewrites each catalogue module of the hosted build into its keys plus one small chunk per language:
 *
 *   // src/ui/shell/messages.ts, as built
 *   import { splitCatalogues } from "/src/i18n/split-catalogue.ts";
 *   const words = splitCatalogues([["nav.robot", …]],
 *     { en: () => import("rbc-words:en:…"), ko: () => import("rbc-words:ko:…") });
 *   export const shellMessages = defineMessages(words[0]);
 *
 *   // its English chunk, words-en-ui-shell-<hash>.js
 *   export default [["Robot", …]];
 *
 * A module is split only if every `defineMessages` argument is an object literal of literal keys, each holding
 * exactly one literal text (a string, a template without `${}`, or `{ one, other }` of those) per language;
 * anything else (a spread, a computed key, a constant) leaves the module whole, with a warning: it then ships
 * both languages, which the first-load budget (npm run check:bundle) notices.
 *
 * And every `import(x)` of the panel's code becomes `wordsAfter(import(x))`: what a lazily loaded chunk brings
 * is used only once its catalogues hold the page's language (src/i18n/split-catalogue.ts).
 *
 * Pure string surgery on the module's ESTree (`this.parse`, after TypeScript is stripped): no evaluation.
 */
import { relative } from "node:path";
import type { Plugin } from "vite";

export interface WordsPerLanguageOptions {
  /** The project's root (paths in chunk names are relative to it). */
  root: string;
  /** The languages, as every catalogue has them ("en", "ko"). */
  locales: readonly string[];
  /** The module that holds the registry (src/i18n/split-catalogue.ts), as an absolute path. */
  runtime: string;
  /** The panel's code (absolute folder): its `import()`s wait for the words they bring (`wordsAfter`). */
  source: string;
}

/** The prefix of a language chunk's module id: `rbc-words:<locale>:<catalogue module's id>`. */
const PREFIX = "rbc-words:";

/** The ESTree nodes this plugin reads (a structural subset; `this.parse` gives more). */
interface Node {
  type: string;
  start: number;
  end: number;
  [field: string]: unknown;
}

const isNode = (value: unknown): value is Node =>
  typeof value === "object" && value !== null && typeof (value as Node).type === "string";

function children(node: Node): Node[] {
  const out: Node[] = [];
  for (const [field, value] of Object.entries(node)) {
    if (field === "type" || field === "start" || field === "end") continue;
    if (Array.isArray(value)) for (const v of value) if (isNode(v)) out.push(v);
    if (isNode(value)) out.push(value);
  }
  return out;
}

function walk(node: Node, visit: (n: Node) => void): void {
  visit(node);
  for (const child of children(node)) walk(child, visit);
}

/** A property's literal key ("robot.refresh" or `en`), or undefined if it is computed or not a property. */
function keyOf(property: Node): string | undefined {
  if (property.type !== "Property" || property.computed || property.kind !== "init") return undefined;
  const key = property.key as Node;
  if (key.type === "Identifier") return key.name as string;
  if (key.type === "Literal" && typeof key.value === "string") return key.value;
  return undefined;
}

/** Whether `node` is a text the plugin can copy as it is: a string or a template without `${}`. */
function isLiteralText(node: Node): boolean {
  if (node.type === "Literal") return typeof node.value === "string";
  return node.type === "TemplateLiteral" && (node.expressions as Node[]).length === 0;
}

/** Whether `node` is a message's text in one language: literal text, or `{ one, other }` of literal texts. */
function isMessageText(node: Node): boolean {
  if (isLiteralText(node)) return true;
  if (node.type !== "ObjectExpression") return false;
  const properties = node.properties as Node[];
  const keys = properties.map(keyOf);
  return (
    properties.length === 2 &&
    keys.includes("one") &&
    keys.includes("other") &&
    properties.every((p) => isLiteralText(p.value as Node))
  );
}

export interface SplitModule {
  /** The module's code with its catalogues' texts replaced by the registry's (undefined: nothing to split). */
  code: string;
  /** Per language, the code of its chunk. */
  chunks: Map<string, string>;
}

/** Why a module stays whole. */
export class UnsplittableCatalogue extends Error {
  override readonly name = "UnsplittableCatalogue";
}

/**
 * Splits a catalogue module (JavaScript, as `program` parses it). Returns undefined when it has no
 * `defineMessages` call; throws UnsplittableCatalogue when a call is not plain data.
 */
export function splitModule(
  code: string,
  program: Node,
  options: Pick<WordsPerLanguageOptions, "locales" | "runtime">,
  chunkId: (locale: string) => string,
): SplitModule | undefined {
  // The local name of defineMessages, from its import (src/i18n/catalogue.ts or the i18n index).
  let local: string | undefined;
  for (const statement of program.body as Node[]) {
    if (statement.type !== "ImportDeclaration") continue;
    const from = (statement.source as Node).value;
    if (typeof from !== "string" || !/(^|\/)(catalogue|i18n\/index)(\.ts)?$/.test(from)) continue;
    for (const s of statement.specifiers as Node[]) {
      const imported = s.imported as Node | undefined;
      if (s.type === "ImportSpecifier" && imported?.name === "defineMessages")
        local = (s.local as Node).name as string;
    }
  }
  if (!local) return undefined;
  const calls: Node[] = [];
  walk(program, (n) => {
    const callee = n.callee as Node | undefined;
    if (n.type === "CallExpression" && callee?.type === "Identifier" && callee.name === local) calls.push(n);
  });
  if (calls.length === 0) return undefined;

  const keys: string[][] = [];
  const texts = new Map<string, string[][]>(options.locales.map((l) => [l, []]));
  for (const call of calls) {
    const args = call.arguments as Node[];
    const arg = args[0];
    if (args.length !== 1 || !arg || arg.type !== "ObjectExpression")
      throw new UnsplittableCatalogue("a defineMessages call whose argument is not an object literal");
    const callKeys: string[] = [];
    const callTexts = new Map<string, string[]>(options.locales.map((l) => [l, []]));
    for (const property of arg.properties as Node[]) {
      const key = keyOf(property);
      const message = property.value as Node | undefined;
      if (key === undefined || message?.type !== "ObjectExpression")
        throw new UnsplittableCatalogue(
          `a message that is not a literal key with an object literal (${key ?? "?"})`,
        );
      const byLocale = new Map<string, Node>();
      for (const p of message.properties as Node[]) {
        const locale = keyOf(p);
        if (locale === undefined || !options.locales.includes(locale) || byLocale.has(locale))
          throw new UnsplittableCatalogue(
            `"${key}" has a field that is not one of ${options.locales.join(", ")}`,
          );
        byLocale.set(locale, p.value as Node);
      }
      callKeys.push(key);
      for (const locale of options.locales) {
        const text = byLocale.get(locale);
        if (!text || !isMessageText(text))
          throw new UnsplittableCatalogue(`"${key}" has no literal text in "${locale}"`);
        callTexts.get(locale)?.push(code.slice(text.start, text.end));
      }
    }
    keys.push(callKeys);
    for (const locale of options.locales) texts.get(locale)?.push(callTexts.get(locale) ?? []);
  }

  // Replace each call's argument, last first so earlier offsets stay valid.
  let out = code;
  [...calls].reverse().forEach((call, reversed) => {
    const index = calls.length - 1 - reversed;
    const arg = (call.arguments as Node[])[0] as Node;
    out = `${out.slice(0, arg.start)}__rbcWords[${index}]${out.slice(arg.end)}`;
  });
  const loaders = options.locales
    .map((l) => `${JSON.stringify(l)}: () => import(${JSON.stringify(chunkId(l))})`)
    .join(", ");
  const head =
    `import { splitCatalogues as __rbcSplit } from ${JSON.stringify(options.runtime)};\n` +
    `const __rbcWords = __rbcSplit(${JSON.stringify(keys)}, { ${loaders} });\n`;
  const chunks = new Map<string, string>();
  for (const locale of options.locales) {
    const lists = (texts.get(locale) ?? []).map((list) => `[\n${list.join(",\n")}\n]`);
    chunks.set(locale, `export default [${lists.join(", ")}];\n`);
  }
  return { code: head + out, chunks };
}

/**
 * Wraps each `import(…)` of a module in the registry's `wordsAfter(…)`, so what it loads is used only once its
 * catalogues hold the page's language. Undefined when the module has no `import()`.
 */
export function waitForWords(code: string, program: Node, runtime: string): string | undefined {
  const imports: Node[] = [];
  walk(program, (n) => {
    if (n.type === "ImportExpression") imports.push(n);
  });
  if (imports.length === 0) return undefined;
  let out = code;
  for (const node of [...imports].sort((a, b) => b.start - a.start))
    out = `${out.slice(0, node.start)}__rbcAfter(${out.slice(node.start, node.end)})${out.slice(node.end)}`;
  return `import { wordsAfter as __rbcAfter } from ${JSON.stringify(runtime)};\n${out}`;
}

/** The chunk name of a module's language: "words-ko-ui-features-connection" for …/connection/messages.ts. */
export function wordsChunkName(root: string, id: string, locale: string): string {
  const path = relative(root, id)
    .replace(/\\/g, "/")
    .replace(/^src\//, "")
    .replace(/\/messages\.ts$|\.ts$/, "")
    .replace(/[^a-zA-Z0-9]+/g, "-");
  return `words-${locale}-${path}`;
}

export function wordsPerLanguage(options: WordsPerLanguageOptions): Plugin {
  /** Language chunk id → its code, filled as catalogue modules are transformed. */
  const chunks = new Map<string, string>();
  return {
    name: "rbc-words-per-language",
    apply: "build",
    transform(code, id) {
      if (!id.startsWith(`${options.source}/`) || !/\.ts$/.test(id) || id === options.runtime) return null;
      const hasImport = /\bimport\s*\(/.test(code);
      const hasCatalogue = code.includes("defineMessages");
      if (!hasImport && !hasCatalogue) return null;
      const program = this.parse(code) as unknown as Node;
      // First the module's own import()s, then (on the new text) its catalogues; never the language chunks.
      const waiting = hasImport ? waitForWords(code, program, options.runtime) : undefined;
      if (!hasCatalogue) return waiting === undefined ? null : { code: waiting, map: null };
      const text = waiting ?? code;
      const chunkId = (locale: string) => `${PREFIX}${locale}:${id}`;
      let split: SplitModule | undefined;
      try {
        split = splitModule(
          text,
          waiting ? (this.parse(text) as unknown as Node) : program,
          options,
          chunkId,
        );
      } catch (e) {
        if (!(e instanceof UnsplittableCatalogue)) throw e;
        this.warn(`${relative(options.root, id)} ships every language: ${e.message}`);
        return waiting === undefined ? null : { code: waiting, map: null };
      }
      if (!split) return waiting === undefined ? null : { code: waiting, map: null };
      for (const [locale, chunk] of split.chunks) chunks.set(chunkId(locale), chunk);
      return { code: split.code, map: null };
    },
    resolveId(source) {
      return source.startsWith(PREFIX) ? `\0${source}` : null;
    },
    load(id) {
      if (!id.startsWith(`\0${PREFIX}`)) return null;
      const code = chunks.get(id.slice(1));
      if (code === undefined) throw new Error(`no language chunk for ${id.slice(1)}`);
      return code;
    },
    outputOptions(output) {
      const previous = output.chunkFileNames;
      return {
        ...output,
        chunkFileNames: (chunk) => {
          const facade = chunk.facadeModuleId ?? "";
          const m = facade.startsWith(`\0${PREFIX}`) ? /^\0rbc-words:([^:]+):(.*)$/.exec(facade) : null;
          if (m) return `assets/${wordsChunkName(options.root, m[2] ?? "", m[1] ?? "")}-[hash].js`;
          if (typeof previous === "function") return previous(chunk);
          return previous ?? "assets/[name]-[hash].js";
        },
      };
    },
  };
}
