/**
 * The import rule of docs/architecture.md ("Layers, and which way they may look"), checked on every source file
 * in src/. Each import statement (static, `export … from`, dynamic `import()` and `typeof import()`) is read
 * with a regular expression, resolved to a file, and checked against three rules:
 *
 * 1. Layers: a folder of src/ imports only the folders in its row of `MAY_IMPORT` (and itself).
 * 2. Deep imports: a file of another public layer (protocol, link, device, sim, motion) may be imported
 *    directly, to keep lazily loaded chunks small, only when that layer's `index.ts` re-exports it: a deep
 *    import is a shorter path to the public API, never a way round it. The few exceptions are named, with
 *    their reason, in `DEEP_EXCEPTIONS`.
 * 3. Packages: Node built-ins and `serialport` only in the command line, the browser's packages only in the
 *    panel, and zod only through src/protocol/zod.ts (`PACKAGES`). Imports that leave src/ are the two in
 *    `OUTSIDE_SRC`.
 *
 * The checker is a pure function of a file list, so the tests at the end feed it fake files and prove that
 * each rule catches what it should.
 */
import { readdirSync, readFileSync, statSync } from "node:fs";
import { dirname, join, normalize, relative } from "node:path";
import { describe, expect, it } from "vitest";

type Layer = "protocol" | "link" | "device" | "motion" | "sim" | "shared" | "i18n" | "ui" | "cli";

const MAY_IMPORT: Record<Layer, readonly Layer[]> = {
  shared: [],
  i18n: ["protocol", "link", "device", "motion", "shared"],
  protocol: ["shared"],
  link: ["shared"],
  motion: ["protocol", "shared"],
  sim: ["protocol", "motion", "shared"],
  device: ["protocol", "link", "motion", "shared"],
  ui: ["device", "protocol", "motion", "link", "sim", "shared", "i18n"],
  cli: ["device", "protocol", "motion", "link", "sim", "shared", "i18n"],
};

/** The layers whose index.ts is the public API (docs/architecture.md); shared/ and i18n/ are leaves used file by file. */
const PUBLIC_LAYERS: ReadonlySet<Layer> = new Set(["protocol", "link", "device", "sim", "motion"]);

/** Files of a public layer that other layers may import although its index.ts does not re-export them. */
const DEEP_EXCEPTIONS: Readonly<Record<string, { readonly from: readonly Layer[]; readonly why: string }>> = {
  "src/link/node-serial-transport.ts": {
    from: ["cli"],
    why: "imports `serialport`: kept out of link/index.ts so that nothing reaching the web bundle can load it",
  },
  "src/protocol/zod.ts": {
    from: ["ui", "cli", "device", "sim", "motion"],
    why: "the one zod instance, configured for the panel's CSP (no eval) before any schema is built",
  },
};

/** Package imports (not relative paths): who may import them. A package not listed may be imported by anyone. */
const PACKAGES: readonly { readonly test: RegExp; readonly allowed: (file: string) => boolean }[] = [
  {
    test: /^(node:|serialport$)/,
    allowed: (file) => file.startsWith("src/cli/") || file === "src/link/node-serial-transport.ts",
  },
  {
    test: /^(lit-html|three|uplot|idb-keyval|vite-plugin-pwa|virtual:)(\/|$)/,
    allowed: (file) => file.startsWith("src/ui/"),
  },
  { test: /^zod$/, allowed: (file) => file === "src/protocol/zod.ts" },
];

/** Imports that leave src/: the CLI's version (package.json) and the panel's example motions (as text). */
const OUTSIDE_SRC: readonly { readonly from: string; readonly target: RegExp }[] = [
  { from: "src/cli/", target: /^package\.json$/ },
  { from: "src/ui/", target: /^examples\/[a-z0-9-]+\.rbm\?raw$/ },
];

interface SourceFile {
  /** Relative to the repository root, with forward slashes: `src/ui/app.ts`. */
  readonly path: string;
  readonly text: string;
}

const IMPORT_PATTERNS: readonly RegExp[] = [
  // import x from "…", import { a, type B } from "…", import * as n from "…", export { a } from "…", export * from "…"
  /^[ \t]*(?:import|export)\s+(?:type\s+)?(?:[\w$]+\s*,\s*)?(?:\{[^}]*\}|\*(?:\s+as\s+[\w$]+)?|[\w$]+)\s+from\s*["']([^"']+)["']/gm,
  // import "…" (for its side effects)
  /^[ \t]*import\s*["']([^"']+)["']/gm,
  // import("…") and typeof import("…")
  /\bimport\(\s*["']([^"']+)["']\s*\)/g,
];

function importsOf(text: string): string[] {
  return IMPORT_PATTERNS.flatMap((pattern) => [...text.matchAll(pattern)].map((m) => m[1] ?? ""));
}

function layerOf(path: string): Layer | undefined {
  const folder = path.split("/")[1] ?? "";
  return folder in MAY_IMPORT ? (folder as Layer) : undefined;
}

/** The files an index.ts re-exports (`export … from "./x.ts"`), as repository paths. */
function reExported(index: SourceFile): Set<string> {
  const dir = dirname(index.path);
  return new Set(
    importsOf(index.text)
      .filter((spec) => spec.startsWith("./"))
      .map((spec) => normalize(join(dir, spec))),
  );
}

/** Every import in `files` that breaks the rule, as `path: "specifier" (reason)`. Empty when all is well. */
function importViolations(files: readonly SourceFile[]): string[] {
  const publicFiles = new Map<Layer, Set<string>>();
  for (const file of files) {
    const match = /^src\/(\w+)\/index\.ts$/.exec(file.path);
    const layer = match ? layerOf(file.path) : undefined;
    if (layer && PUBLIC_LAYERS.has(layer)) publicFiles.set(layer, reExported(file));
  }
  const violations: string[] = [];
  for (const file of files) {
    const from = layerOf(file.path);
    const say = (spec: string, why: string) => violations.push(`${file.path}: "${spec}" (${why})`);
    if (!from) {
      say("", "a source file outside the layers of docs/architecture.md");
      continue;
    }
    for (const spec of importsOf(file.text)) {
      if (!spec.startsWith(".")) {
        const rule = PACKAGES.find(({ test }) => test.test(spec));
        if (rule && !rule.allowed(file.path)) say(spec, `package not allowed in ${from}/`);
        continue;
      }
      const target = normalize(join(dirname(file.path), spec));
      if (!target.startsWith("src/")) {
        const ok = OUTSIDE_SRC.some((o) => file.path.startsWith(o.from) && o.target.test(target));
        if (!ok) say(spec, "leaves src/");
        continue;
      }
      const to = layerOf(target);
      if (to === from) continue;
      if (!to || !MAY_IMPORT[from].includes(to)) {
        say(spec, `${from}/ may not import ${to ?? "that folder"}/`);
        continue;
      }
      if (!PUBLIC_LAYERS.has(to)) continue;
      const exception = DEEP_EXCEPTIONS[target];
      if (exception) {
        if (!exception.from.includes(from)) say(spec, `only ${exception.from.join(", ")} may import it`);
        continue;
      }
      const index = `src/${to}/index.ts`;
      if (target !== index && !publicFiles.get(to)?.has(target)) {
        say(spec, `not re-exported by ${index}`);
      }
    }
  }
  return violations;
}

const ROOT = new URL("../../", import.meta.url).pathname;

function sources(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return sources(path);
    return /\.ts$/.test(name) && !name.endsWith(".d.ts") ? [path] : [];
  });
}

const repository: SourceFile[] = sources(join(ROOT, "src")).map((path) => ({
  path: relative(ROOT, path).split("\\").join("/"),
  text: readFileSync(path, "utf8"),
}));

describe("the import rule (docs/architecture.md)", () => {
  it("holds for every file in src/", () => {
    expect(repository.length).toBeGreaterThan(100);
    expect(importViolations(repository)).toEqual([]);
  });

  it("keeps the layers below the front ends free of src/i18n, type imports included: they give codes and facts", () => {
    const lower = repository.filter((f) => /^src\/(protocol|link|device|motion|sim)\//.test(f.path));
    expect(lower.length).toBeGreaterThan(100);
    const fromI18n = lower.flatMap((f) =>
      importsOf(f.text)
        .filter((spec) => normalize(join(dirname(f.path), spec)).startsWith("src/i18n/"))
        .map((spec) => `${f.path}: "${spec}"`),
    );
    expect(fromI18n).toEqual([]);
    // The layer table says the same (a type import is checked against it too).
    for (const layer of ["protocol", "link", "device", "motion", "sim"] as const) {
      expect(MAY_IMPORT[layer]).not.toContain("i18n");
    }
  });

  it("has no import circle between src/i18n and another folder, type imports included", () => {
    // Only the front ends (src/ui, src/cli) import src/i18n, and src/i18n imports neither of them.
    const outside = repository.filter((f) => !/^src\/(i18n|ui|cli)\//.test(f.path));
    const intoI18n = outside.flatMap((f) =>
      importsOf(f.text)
        .filter((spec) => normalize(join(dirname(f.path), spec)).startsWith("src/i18n/"))
        .map((spec) => `${f.path}: "${spec}"`),
    );
    expect(intoI18n).toEqual([]);
    const importers = (Object.keys(MAY_IMPORT) as Layer[]).filter((l) => MAY_IMPORT[l].includes("i18n"));
    expect(importers).toEqual(["ui", "cli"]);
    for (const layer of importers) expect(MAY_IMPORT.i18n).not.toContain(layer);
  });

  it("reads every form of import, and nothing that only looks like one", () => {
    const text = [
      'import { a, type B } from "./a.ts";',
      "import {",
      "  c,",
      "  d,",
      '} from "./c.ts";',
      'import * as e from "./e.ts";',
      'import f, { g } from "./f.ts";',
      'import type { H } from "./h.ts";',
      'import "./side-effect.ts";',
      'export * from "./i.ts";',
      'export { j } from "./j.ts";',
      'const k = await import("./k.ts");',
      'type L = typeof import("./l.ts");',
      'const text = `words from "./not-an-import.ts"`;',
      '// a comment that mentions import x from "./not-either.ts" mid-line',
    ].join("\n");
    expect(importsOf(text).sort()).toEqual(
      [
        "./a.ts",
        "./c.ts",
        "./e.ts",
        "./f.ts",
        "./h.ts",
        "./side-effect.ts",
        "./i.ts",
        "./j.ts",
        "./k.ts",
        "./l.ts",
      ].sort(),
    );
  });

  const index = (layer: string, ...modules: string[]): SourceFile => ({
    path: `src/${layer}/index.ts`,
    text: modules.map((m) => `export * from "./${m}.ts";`).join("\n"),
  });
  const fake = (path: string, ...imports: string[]): SourceFile => ({
    path,
    text: imports.map((spec, i) => `import { x${i} } from "${spec}";`).join("\n"),
  });
  const base = [index("protocol", "packet"), index("device", "rbc-client"), index("link", "transport")];

  it("accepts the allowed directions and deep imports of re-exported files", () => {
    const files = [
      ...base,
      fake(
        "src/ui/features/a/view.ts",
        "../../../device/rbc-client.ts",
        "../../../protocol/index.ts",
        "../../store.ts",
      ),
      fake("src/device/upload.ts", "../protocol/packet.ts", "../link/transport.ts"),
      fake("src/cli/connect.ts", "../link/node-serial-transport.ts", "../../package.json"),
      fake("src/protocol/packet.ts", "../shared/format.ts", "./bytes.ts"),
      fake("src/motion/errors.ts", "../protocol/packet.ts"),
    ];
    expect(importViolations(files)).toEqual([]);
  });

  it("refuses a layer looking the wrong way", () => {
    const files = [
      ...base,
      fake("src/protocol/packet.ts", "../device/index.ts"),
      fake("src/device/upload.ts", "../ui/store.ts"),
      fake("src/device/stop.ts", "../i18n/translate.ts"),
      fake("src/sim/simulated-rbc.ts", "../link/index.ts"),
      fake("src/link/transport.ts", "../i18n/translate.ts"),
      fake("src/motion/errors.ts", "../i18n/outcomes/motion/motion-words.ts"),
      fake("src/protocol/rbm.ts", "../i18n/translate.ts"),
      fake("src/motion/document.ts", "../device/index.ts"),
      fake("src/ui/app.ts", "../cli/main.ts"),
      fake("src/shared/clock.ts", "../protocol/index.ts"),
    ];
    expect(importViolations(files)).toEqual([
      'src/protocol/packet.ts: "../device/index.ts" (protocol/ may not import device/)',
      'src/device/upload.ts: "../ui/store.ts" (device/ may not import ui/)',
      'src/device/stop.ts: "../i18n/translate.ts" (device/ may not import i18n/)',
      'src/sim/simulated-rbc.ts: "../link/index.ts" (sim/ may not import link/)',
      'src/link/transport.ts: "../i18n/translate.ts" (link/ may not import i18n/)',
      'src/motion/errors.ts: "../i18n/outcomes/motion/motion-words.ts" (motion/ may not import i18n/)',
      'src/protocol/rbm.ts: "../i18n/translate.ts" (protocol/ may not import i18n/)',
      'src/motion/document.ts: "../device/index.ts" (motion/ may not import device/)',
      'src/ui/app.ts: "../cli/main.ts" (ui/ may not import cli/)',
      'src/shared/clock.ts: "../protocol/index.ts" (shared/ may not import protocol/)',
    ]);
  });

  it("lets the outcome catalogue stand above the layers whose outcomes it words, and below the front ends", () => {
    const above = {
      path: "src/i18n/outcomes/words.ts",
      text:
        'import type { RbcErrorCode } from "../../device/index.ts";\n' +
        'import { RbcError } from "../../device/errors.ts";\n' +
        'import type { MotionErrorFacts } from "../../motion/errors.ts";\n',
    };
    const frontEnd = {
      path: "src/i18n/outcomes/other.ts",
      text: 'import { uiMessages } from "../../ui/messages.ts";\n',
    };
    expect(
      importViolations([...base, index("motion", "errors"), index("device", "errors"), above, frontEnd]),
    ).toEqual(['src/i18n/outcomes/other.ts: "../../ui/messages.ts" (i18n/ may not import ui/)']);
  });

  it("refuses a deep import of a file the layer's index.ts keeps private", () => {
    const files = [
      ...base,
      fake("src/ui/session.ts", "../device/rbc-connection.ts"),
      fake("src/ui/link.ts", "../link/node-serial-transport.ts"),
    ];
    expect(importViolations(files)).toEqual([
      'src/ui/session.ts: "../device/rbc-connection.ts" (not re-exported by src/device/index.ts)',
      'src/ui/link.ts: "../link/node-serial-transport.ts" (only cli may import it)',
    ]);
  });

  it("refuses packages in the wrong layer and imports that leave src/ unasked", () => {
    const files = [
      fake("src/device/rbc-client.ts", "node:fs"),
      fake("src/protocol/rbm.ts", "zod"),
      fake("src/sim/demo-world.ts", "lit-html"),
      fake("src/ui/app.ts", "../../tests/unit/helpers.ts"),
      fake("src/tools/x.ts"),
    ];
    expect(importViolations(files)).toEqual([
      'src/device/rbc-client.ts: "node:fs" (package not allowed in device/)',
      'src/protocol/rbm.ts: "zod" (package not allowed in protocol/)',
      'src/sim/demo-world.ts: "lit-html" (package not allowed in sim/)',
      'src/ui/app.ts: "../../tests/unit/helpers.ts" (leaves src/)',
      'src/tools/x.ts: "" (a source file outside the layers of docs/architecture.md)',
    ]);
  });
});

/**
 * The features of the panel (docs/architecture.md, "Features"): each folder of src/ui/features/ is one feature.
 *
 * 1. From outside feature X (another feature, the shell, the session, any file of src/ui/), an import of a file of
 *    X names X/index.ts, the feature's public face. The exceptions are named, with their reason, in
 *    `FEATURE_EXCEPTIONS`.
 * 2. No cycle between features: the graph of "a file of A imports a file of B" has none, so no two features import
 *    each other; what both need lives in a module of src/ui/ outside the features, or in the store.
 */
const FEATURE_EXCEPTIONS: readonly {
  readonly allows: (from: string, target: string, dynamic: boolean) => boolean;
  readonly why: string;
}[] = [
  {
    allows: (_from, _target, dynamic) => dynamic,
    why:
      "a lazily loaded module (a view of the registry, the packet log) is named by its own file in import(): " +
      "through an index, everything the index re-exports would load with it, or come into its importer's chunk",
  },
  {
    allows: (from, target) =>
      from === "src/ui/app-state.ts" && /^src\/ui\/features\/[^/]+\/([a-z-]+-)?state\.ts$/.test(target),
    why:
      "the store's composition: app-state.ts gathers each feature's slice (type, initial value) from its state " +
      "file (state.ts, and live-state.ts for the Editor's second slice), a leaf module, without bringing the " +
      "feature's actions and views into the first load",
  },
];

const featureOf = (path: string): string | undefined => /^src\/ui\/features\/([^/]+)\//.exec(path)?.[1];

/** Static imports (`import type` and `typeof import()` too) and dynamic `import()`s, resolved to repository paths. */
function resolvedImports(file: SourceFile): { spec: string; target: string; dynamic: boolean }[] {
  const statics = IMPORT_PATTERNS.slice(0, 2).flatMap((pattern) =>
    [...file.text.matchAll(pattern)].map((m) => ({ spec: m[1] ?? "", dynamic: false })),
  );
  const calls = [...file.text.matchAll(/(\btypeof\s+)?\bimport\(\s*["']([^"']+)["']\s*\)/g)].map((m) => ({
    spec: m[2] ?? "",
    dynamic: m[1] === undefined,
  }));
  return [...statics, ...calls]
    .filter(({ spec }) => spec.startsWith("."))
    .map((i) => ({ ...i, target: normalize(join(dirname(file.path), i.spec)) }));
}

/** Which features each feature imports (static or dynamic), by name, sorted. */
function featureGraph(files: readonly SourceFile[]): Map<string, string[]> {
  const graph = new Map<string, Set<string>>();
  for (const file of files) {
    const from = featureOf(file.path);
    if (!from) continue;
    const uses = graph.get(from) ?? new Set<string>();
    graph.set(from, uses);
    for (const { target } of resolvedImports(file)) {
      const to = featureOf(target);
      if (to && to !== from) uses.add(to);
    }
  }
  return new Map([...graph].sort(([a], [b]) => a.localeCompare(b)).map(([f, uses]) => [f, [...uses].sort()]));
}

/** Each cycle of the graph once, as "a → b → a" (starting from its first feature in alphabetical order). */
function featureCycles(graph: ReadonlyMap<string, readonly string[]>): string[] {
  const found = new Set<string>();
  const walk = (path: readonly string[]) => {
    for (const next of graph.get(path[path.length - 1] ?? "") ?? []) {
      if (next === path[0]) found.add([...path, next].join(" → "));
      else if (next > (path[0] ?? "") && !path.includes(next)) walk([...path, next]);
    }
  };
  for (const feature of graph.keys()) walk([feature]);
  return [...found];
}

/** Every import that breaks the features' rules, as `path: "specifier" (reason)`, then each cycle. */
function featureViolations(files: readonly SourceFile[]): string[] {
  const violations: string[] = [];
  for (const file of files) {
    for (const { spec, target, dynamic } of resolvedImports(file)) {
      const to = featureOf(target);
      if (!to || to === featureOf(file.path) || target === `src/ui/features/${to}/index.ts`) continue;
      if (FEATURE_EXCEPTIONS.some((e) => e.allows(file.path, target, dynamic))) continue;
      violations.push(`${file.path}: "${spec}" (outside ${to}/, import src/ui/features/${to}/index.ts)`);
    }
  }
  return [
    ...violations,
    ...featureCycles(featureGraph(files)).map((c) => `features import each other: ${c}`),
  ];
}

/** The table of docs/architecture.md ("Features"): each feature and the features it uses. */
function featureTable(graph: ReadonlyMap<string, readonly string[]>): string {
  const rows = [...graph].map(
    ([f, uses]) => `| \`${f}\` | ${uses.length === 0 ? "—" : uses.map((u) => `\`${u}\``).join(", ")} |`,
  );
  return ["| feature | uses |", "|---|---|", ...rows].join("\n");
}

describe("features", () => {
  const ui = repository.filter((f) => f.path.startsWith("src/ui/"));

  it("are used from outside only through their index.ts, and never import each other, in every file of src/ui/", () => {
    expect(featureGraph(ui).size).toBeGreaterThan(10);
    expect(featureViolations(ui)).toEqual([]);
  });

  it("are drawn in docs/architecture.md as the code has them", () => {
    const docs = readFileSync(join(ROOT, "docs/architecture.md"), "utf8");
    expect(docs).toContain(featureTable(featureGraph(ui)));
  });

  const fake = (path: string, ...imports: string[]): SourceFile => ({
    path,
    text: imports.map((spec, i) => `import { x${i} } from "${spec}";`).join("\n"),
  });

  it("accepts the index, a feature's own files, lazily loaded views and the store's composition", () => {
    const files = [
      fake("src/ui/features/a/view.ts", "./state.ts", "../b/index.ts", "../../said.ts"),
      fake("src/ui/features/b/index.ts", "./actions.ts"),
      fake("src/ui/app-state.ts", "./features/a/state.ts", "./features/b/live-state.ts"),
      { path: "src/ui/shell/registry.ts", text: 'const load = () => import("../features/a/a-view.ts");' },
    ];
    expect(featureViolations(files)).toEqual([]);
  });

  it("refuses an import of a feature's file from outside it, static or type-only", () => {
    const files = [
      fake("src/ui/features/a/view.ts", "../b/actions.ts"),
      { path: "src/ui/session.ts", text: 'import type { Log } from "./features/b/log.ts";' },
      { path: "src/ui/context.ts", text: 'type Log = typeof import("./features/b/log.ts");' },
      fake("src/ui/app-state.ts", "./features/a/actions.ts"),
      fake("src/ui/features/b/nested/deep.ts", "../../c/index.ts"),
    ];
    expect(featureViolations(files)).toEqual([
      'src/ui/features/a/view.ts: "../b/actions.ts" (outside b/, import src/ui/features/b/index.ts)',
      'src/ui/session.ts: "./features/b/log.ts" (outside b/, import src/ui/features/b/index.ts)',
      'src/ui/context.ts: "./features/b/log.ts" (outside b/, import src/ui/features/b/index.ts)',
      'src/ui/app-state.ts: "./features/a/actions.ts" (outside a/, import src/ui/features/a/index.ts)',
    ]);
  });

  it("refuses features that import each other, directly or round a longer circle, even through an index", () => {
    const files = [
      fake("src/ui/features/a/x.ts", "../b/index.ts"),
      fake("src/ui/features/b/y.ts", "../a/index.ts", "../c/index.ts"),
      fake("src/ui/features/c/z.ts", "../d/index.ts"),
      { path: "src/ui/features/d/w.ts", text: 'const later = () => import("../b/lazy-view.ts");' },
    ];
    expect(featureViolations(files)).toEqual([
      "features import each other: a → b → a",
      "features import each other: b → c → d → b",
    ]);
    expect(featureTable(featureGraph(files))).toBe(
      [
        "| feature | uses |",
        "|---|---|",
        "| `a` | `b` |",
        "| `b` | `a`, `c` |",
        "| `c` | `d` |",
        "| `d` | `b` |",
      ].join("\n"),
    );
  });
});
