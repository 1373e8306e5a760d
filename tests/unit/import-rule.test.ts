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
  device: ["protocol", "link", "motion", "shared", "i18n"],
  ui: ["device", "protocol", "motion", "link", "sim", "shared", "i18n"],
  cli: ["device", "protocol", "motion", "link", "sim", "shared", "i18n"],
};

/**
 * Type-only imports (`import type`) allowed beyond MAY_IMPORT: the outcome catalogue (src/i18n/outcomes) words
 * the codes and facts that protocol/, link/, device/ and motion/ define, so it names their types; it never runs
 * their code.
 */
const MAY_IMPORT_TYPES: Partial<Record<Layer, readonly Layer[]>> = {
  i18n: ["protocol", "link", "device", "motion"],
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
  return importsWithKind(text).map((i) => i.spec);
}

/** Each import's specifier, and whether it is type-only (`import type … from`, erased at build time). */
function importsWithKind(text: string): { spec: string; typeOnly: boolean }[] {
  return IMPORT_PATTERNS.flatMap((pattern) =>
    [...text.matchAll(pattern)].map((m) => ({
      spec: m[1] ?? "",
      typeOnly: /^\s*(?:import|export)\s+type\s/.test(m[0]),
    })),
  );
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
    for (const { spec, typeOnly } of importsWithKind(file.text)) {
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
      const typesAllowed = typeOnly && to !== undefined && (MAY_IMPORT_TYPES[from] ?? []).includes(to);
      if (!to || !(MAY_IMPORT[from].includes(to) || typesAllowed)) {
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

  it("keeps the layers below the device free of src/i18n, type imports included: they give codes and facts", () => {
    const lower = repository.filter((f) => /^src\/(protocol|link|motion|sim)\//.test(f.path));
    expect(lower.length).toBeGreaterThan(50);
    const fromI18n = lower.flatMap((f) =>
      importsOf(f.text)
        .filter((spec) => normalize(join(dirname(f.path), spec)).startsWith("src/i18n/"))
        .map((spec) => `${f.path}: "${spec}"`),
    );
    expect(fromI18n).toEqual([]);
    // The layer table says the same (a type import is checked against it too).
    for (const layer of ["protocol", "link", "motion", "sim"] as const) {
      expect(MAY_IMPORT[layer]).not.toContain("i18n");
      expect(MAY_IMPORT_TYPES[layer] ?? []).not.toContain("i18n");
    }
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
      fake("src/device/upload.ts", "../protocol/packet.ts", "../link/transport.ts", "../i18n/translate.ts"),
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
