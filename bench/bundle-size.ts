import { spawn } from "node:child_process";
import { existsSync, readFileSync } from "node:fs";
import { dirname, join, normalize, relative, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { gzipSync } from "node:zlib";
import { bytesBySource, groupShares, type SourceShare } from "./source-map.ts";

/**
 * Size of what the first page load needs, from a production build: JavaScript and CSS.
 * - JavaScript: the module and classic scripts that `dist/index.html` loads (`<script src>`), the files it
 *   preloads (`<link rel="modulepreload">`), and — in case a preload link is missing — every chunk those import
 *   statically (never other `import()`ed ones: views and the demo robot load later), plus the words of their
 *   catalogues in the page's language (`words-<locale>-…` chunks, loaded before the first render).
 * - CSS: the style sheets `index.html` links (`<link rel="stylesheet">`) and any same-origin sheet those
 *   `@import`. (CSS of lazily loaded views comes with those views, later.)
 * Each file is gzipped on its own with node:zlib level 9 and the sizes summed. 1 KB = 1,000 bytes, as Vite
 * prints sizes. The HTML page itself, icons and the web manifest are not counted.
 */

export const PROJECT_ROOT = resolve(dirname(fileURLToPath(import.meta.url)), "..");
/**
 * Budget for the first load, JavaScript + CSS, gzip, in each language. Issue #5 set 40 KB; issue #19 aims at
 * 25 KB. Loading the failure words, the bootloader's log names, the packet log and three views' styles when
 * needed brought it to 26.0 KB (English) and 26.8 KB (Korean); Stop's and Limp's sentences loading once
 * connected brought it to 24.8 / 25.5 KB, and the Servo check and Class views' menu lines to 25.0 / 25.7 KB.
 * The connect card's help loading just after the first paint, and the card of a browser without Web Serial only
 * in such a browser, brought it to 23.95 / 24.39 KB: within issue #19's 25 KB, the budget now
 * (docs/benchmarks.md).
 */
export const INITIAL_LOAD_BUDGET_KB = 25;

export type InitialVia =
  | "script"
  | "modulepreload"
  | "static import"
  | "language chunk"
  | "stylesheet"
  | "css @import";

/** The languages of the panel (src/i18n/locale.ts LOCALES; not imported, so the bench stays Node-only). */
export const BUNDLE_LOCALES = ["en", "ko"] as const;
export type BundleLocale = (typeof BUNDLE_LOCALES)[number];

export interface InitialFile {
  /** Path relative to the build folder. */
  file: string;
  kind: "js" | "css";
  bytes: number;
  gzipBytes: number;
  /** How index.html reaches it. */
  via: InitialVia;
}

export interface BundleFigures {
  outDir: string;
  files: InitialFile[];
  /** JavaScript + CSS. */
  gzipBytes: number;
  gzipKB: number;
  jsGzipBytes: number;
  jsGzipKB: number;
  cssGzipBytes: number;
  cssGzipKB: number;
  rawBytes: number;
  /** What fills the initial JavaScript, by package or src/ folder (generated characters, from source maps). */
  contributors: SourceShare[];
}

/** Runs `vite build` into `outDir` (a child process; its output goes to this process's stderr). */
export function viteBuild(outDir: string): Promise<void> {
  return runVite(["build", "--outDir", outDir, "--emptyOutDir"]);
}

/**
 * Runs `vite build --mode single` (`npm run build:single`): writes the one-file panel, rbc-panel.html, into
 * `outDir` beside whatever is there (so after viteBuild(outDir) the hosted build stays as it is).
 */
export function viteBuildSingle(outDir: string): Promise<void> {
  return runVite(["build", "--mode", "single", "--outDir", outDir]);
}

function runVite(args: string[]): Promise<void> {
  const vite = join(PROJECT_ROOT, "node_modules", "vite", "bin", "vite.js");
  return new Promise((resolveBuild, reject) => {
    const child = spawn(process.execPath, [vite, ...args], {
      cwd: PROJECT_ROOT,
      stdio: ["ignore", "pipe", "pipe"],
    });
    let output = "";
    const keep = (chunk: Buffer) => {
      output += chunk.toString();
      if (output.length > 20_000) output = output.slice(-20_000);
    };
    child.stdout.on("data", keep);
    child.stderr.on("data", keep);
    child.on("error", reject);
    child.on("close", (code) => {
      if (code === 0) resolveBuild();
      else
        reject(
          new Error(
            `vite ${args.join(" ")} failed (exit ${code}):\n${output.trim().split("\n").slice(-25).join("\n")}`,
          ),
        );
    });
  });
}

const ATTRIBUTE = (name: string) => new RegExp(`\\b${name}\\s*=\\s*(?:"([^"]*)"|'([^']*)'|([^\\s>]+))`, "i");

function attribute(tag: string, name: string): string | undefined {
  const m = ATTRIBUTE(name).exec(tag);
  return m ? (m[1] ?? m[2] ?? m[3]) : undefined;
}

type HtmlVia = "script" | "modulepreload" | "stylesheet";

/** Same-origin script, modulepreload and style sheet URLs of an HTML page, in document order. */
export function initialScripts(html: string): { url: string; via: HtmlVia }[] {
  const found: { url: string; via: HtmlVia }[] = [];
  const withoutComments = html.replace(/<!--[\s\S]*?-->/g, "");
  for (const m of withoutComments.matchAll(/<(script|link)\b[^>]*>/gi)) {
    const tag = m[0];
    if (m[1]!.toLowerCase() === "script") {
      const src = attribute(tag, "src");
      if (src) found.push({ url: src, via: "script" });
    } else {
      const rel = (attribute(tag, "rel") ?? "").toLowerCase().split(/\s+/);
      const href = attribute(tag, "href");
      if (!href) continue;
      if (rel.includes("modulepreload")) found.push({ url: href, via: "modulepreload" });
      // "alternate stylesheet" is not applied on load.
      else if (rel.includes("stylesheet") && !rel.includes("alternate"))
        found.push({ url: href, via: "stylesheet" });
    }
  }
  return found.filter(({ url }) => !/^[a-z][a-z0-9+.-]*:|^\/\//i.test(url));
}

/** Relative specifiers of the static imports in a built chunk (`import x from"./a.js"`, `import"./b.js"`). */
export function staticImports(code: string): string[] {
  const out: string[] = [];
  for (const m of code.matchAll(
    /(?:^|[;\s}])import\s*(?:[\w$*{}\s,]+?\s*from\s*)?["'](\.{1,2}\/[^"']+)["']/g,
  )) {
    out.push(m[1]!);
  }
  for (const m of code.matchAll(
    /(?:^|[;\s}])export\s*(?:\*|\{[^}]*\})\s*from\s*["'](\.{1,2}\/[^"']+)["']/g,
  )) {
    out.push(m[1]!);
  }
  return out;
}

/** Relative URLs a style sheet `@import`s (`@import "./a.css";`, `@import url(b.css) screen;`). */
export function cssImports(css: string): string[] {
  const out: string[] = [];
  const withoutComments = css.replace(/\/\*[\s\S]*?\*\//g, "");
  for (const m of withoutComments.matchAll(/@import\s+(?:url\(\s*)?["']?([^"')\s;]+)["']?/gi)) {
    const url = m[1]!;
    if (!/^[a-z][a-z0-9+.-]*:|^\/\//i.test(url)) out.push(url);
  }
  return out;
}

function toFile(outDir: string, from: string, url: string): string {
  const clean = url.split(/[?#]/)[0]!;
  const abs = clean.startsWith("/") ? join(outDir, clean) : resolve(dirname(from), clean);
  return normalize(abs);
}

/**
 * The language chunks (`words-<locale>-….js`, scripts/vite-words-per-language.ts) a built chunk imports: the
 * words of its catalogues, which the page loads before its first render.
 */
export function languageChunkImports(code: string, locale: string): string[] {
  const out: string[] = [];
  for (const m of code.matchAll(/import\(\s*[`"'](\.{1,2}\/[^`"']*?words-([a-z]+)-[^`"']+)[`"']\s*\)/g)) {
    if (m[2] === locale) out.push(m[1]!);
  }
  return out;
}

/**
 * Measures the first load (JavaScript and CSS) of a build folder for a person whose page speaks `locale`: the
 * language chunks of the catalogues in the first load count too (only that language's). Throws with a clear
 * message if it is not a build.
 */
export function measureBundle(outDir: string, locale: BundleLocale = "en"): BundleFigures {
  const indexHtml = join(outDir, "index.html");
  if (!existsSync(indexHtml))
    throw new Error(`${indexHtml} does not exist: build the app first (npm run build).`);
  const html = readFileSync(indexHtml, "utf8");
  const entries = initialScripts(html);
  if (!entries.some((e) => e.via === "script")) throw new Error(`${indexHtml} loads no script.`);
  const seen = new Map<string, InitialFile>();
  const contributors: SourceShare[] = [];
  const queue: { path: string; via: InitialVia }[] = entries.map((e) => ({
    path: toFile(outDir, indexHtml, e.url),
    via: e.via,
  }));
  while (queue.length > 0) {
    const { path, via } = queue.shift()!;
    if (seen.has(path)) continue;
    if (!existsSync(path)) {
      // An import match is a scan of minified code: skip what is not a file rather than fail on it.
      if (via === "static import" || via === "language chunk" || via === "css @import") continue;
      throw new Error(`${relative(outDir, path)} is referenced by index.html but missing.`);
    }
    const bytes = readFileSync(path);
    const kind = via === "stylesheet" || via === "css @import" ? "css" : "js";
    seen.set(path, {
      file: relative(outDir, path),
      kind,
      bytes: bytes.length,
      gzipBytes: gzipSync(bytes, { level: 9 }).length,
      via,
    });
    const code = bytes.toString("utf8");
    if (kind === "css") {
      for (const url of cssImports(code)) queue.push({ path: toFile(outDir, path, url), via: "css @import" });
      continue;
    }
    for (const spec of staticImports(code))
      queue.push({ path: toFile(outDir, path, spec), via: "static import" });
    for (const spec of languageChunkImports(code, locale))
      queue.push({ path: toFile(outDir, path, spec), via: "language chunk" });
    const mapPath = `${path}.map`;
    if (existsSync(mapPath)) {
      try {
        contributors.push(...bytesBySource(code, JSON.parse(readFileSync(mapPath, "utf8"))));
      } catch {
        // A map we cannot read only costs the breakdown.
      }
    }
  }
  const files = [...seen.values()];
  const sum = (list: InitialFile[]) => list.reduce((n, f) => n + f.gzipBytes, 0);
  const jsGzipBytes = sum(files.filter((f) => f.kind === "js"));
  const cssGzipBytes = sum(files.filter((f) => f.kind === "css"));
  const gzipBytes = jsGzipBytes + cssGzipBytes;
  return {
    outDir,
    files,
    gzipBytes,
    gzipKB: gzipBytes / 1000,
    jsGzipBytes,
    jsGzipKB: jsGzipBytes / 1000,
    cssGzipBytes,
    cssGzipKB: cssGzipBytes / 1000,
    rawBytes: files.reduce((n, f) => n + f.bytes, 0),
    contributors: groupShares(contributors),
  };
}

/** "npm:zod 56%, src/device 11%, ..." for messages. */
export function describeContributors(figures: BundleFigures, top = 6): string {
  const total = figures.contributors.reduce((n, c) => n + c.chars, 0);
  if (total === 0) return "(no source maps)";
  return figures.contributors
    .slice(0, top)
    .map((c) => `${c.source} ${Math.round((100 * c.chars) / total)}%`)
    .join(", ");
}

/** The one-file panel's name (vite.config.ts SINGLE_FILE_NAME; not imported, so the bench loads no Vite plugin). */
export const SINGLE_FILE_NAME = "rbc-panel.html";

export interface SingleFileFigures {
  path: string;
  bytes: number;
  /** Everything the panel is (every view, the demo robot, the examples, styles and icon): 1 KB = 1,000 bytes. */
  kB: number;
  gzipBytes: number;
  gzipKB: number;
}

/**
 * Size of the one-file panel in `outDir` (after viteBuildSingle): the whole file as it is downloaded from a
 * release, and gzipped at level 9 as the first-load figure is. Throws with a clear message if it is missing.
 */
export function measureSingleFile(outDir: string): SingleFileFigures {
  const path = join(outDir, SINGLE_FILE_NAME);
  if (!existsSync(path))
    throw new Error(`${path} does not exist: build the one-file panel first (npm run build:single).`);
  const bytes = readFileSync(path);
  const gzipBytes = gzipSync(bytes, { level: 9 }).length;
  return { path, bytes: bytes.length, kB: bytes.length / 1000, gzipBytes, gzipKB: gzipBytes / 1000 };
}

/** "rbc-panel.html: 485.52 KB (135.78 KB gzip)". */
export function describeSingleFile(figures: SingleFileFigures): string {
  return `${SINGLE_FILE_NAME}: ${figures.kB.toFixed(2)} KB (${figures.gzipKB.toFixed(2)} KB gzip)`;
}
