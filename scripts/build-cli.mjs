#!/usr/bin/env node
/**
 * Builds the `rbc` command line ahead of time: esbuild bundles src/cli/main.ts into dist-cli/ (ESM, Node 20,
 * code splitting), so that `rbc` starts without compiling TypeScript. `serialport` stays external and is
 * reached only through the dynamic imports of the commands that open a real port (--port, ports, sim), so
 * `--help` and `--demo` never load it.
 *
 *   node scripts/build-cli.mjs             build (run by `npm run build:cli` and by `npm install`'s prepare)
 *   node scripts/build-cli.mjs --if-stale  build only if dist-cli/ is missing or older than its sources
 *
 * Plain JavaScript, so that `prepare` runs it with plain node, and bin/rbc.mjs shares `bundleState` with it.
 * dist-cli/manifest.json lists the files the bundle was made from (and when): a bundle older than any of them
 * is stale, and bin/rbc.mjs then asks for `npm run build:cli` instead of running it.
 */
import { randomBytes } from "node:crypto";
import {
  mkdirSync,
  readdirSync,
  readFileSync,
  renameSync,
  statSync,
  unlinkSync,
  writeFileSync,
} from "node:fs";
import { join, relative, sep } from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

export const ROOT = fileURLToPath(new URL("../", import.meta.url));
export const OUT_DIR = join(ROOT, "dist-cli");
export const ENTRY = "main.js";
const MANIFEST = "manifest.json";
const SELF = relative(ROOT, fileURLToPath(import.meta.url));

/**
 * "fresh", "missing" (no bundle, or an unreadable manifest) or "stale" (a source it was made from changed or
 * went away since). Costs one small JSON read and a stat per source file (about a millisecond).
 */
export function bundleState(outDir = OUT_DIR) {
  let manifest;
  try {
    manifest = JSON.parse(readFileSync(join(outDir, MANIFEST), "utf8"));
    statSync(join(outDir, manifest.entry));
  } catch {
    return "missing";
  }
  for (const input of manifest.inputs) {
    try {
      if (statSync(join(ROOT, input)).mtimeMs > manifest.builtAt) return "stale";
    } catch {
      return "stale";
    }
  }
  return "fresh";
}

/** Writes `contents` to `path` through a temporary file and a rename: a concurrent reader sees old or new, whole. */
function writeAtomic(path, contents) {
  const tmp = `${path}.${process.pid}-${randomBytes(4).toString("hex")}.tmp`;
  writeFileSync(tmp, contents);
  renameSync(tmp, path);
}

/**
 * Bundles the CLI. Safe to run concurrently (test workers may build at the same time): every file is replaced
 * atomically, chunks before the entry, the manifest last. Returns the build's duration and output files.
 */
export async function buildCli({ outDir = OUT_DIR } = {}) {
  // The time the sources are read from, not when the build ends: an edit during the build makes it stale.
  const builtAt = Date.now();
  const started = performance.now();
  const { build } = await import("esbuild");
  const result = await build({
    absWorkingDir: ROOT,
    entryPoints: { main: "src/cli/main.ts" },
    outdir: outDir,
    bundle: true,
    splitting: true,
    format: "esm",
    platform: "node",
    target: "node20",
    // The native binding: loaded from node_modules, and only by the commands that open a real port.
    external: ["serialport"],
    chunkNames: "chunk-[hash]",
    sourcemap: "linked",
    sourcesContent: false,
    legalComments: "none",
    metafile: true,
    write: false,
    logLevel: "warning",
  });
  mkdirSync(outDir, { recursive: true });
  const entryPath = join(outDir, ENTRY);
  const files = [...result.outputFiles].sort(
    (a, b) => Number(a.path.startsWith(entryPath)) - Number(b.path.startsWith(entryPath)),
  );
  for (const file of files) writeAtomic(file.path, file.contents);
  const inputs = [
    ...Object.keys(result.metafile.inputs).filter((p) => !p.split(/[\\/]/).includes("node_modules")),
    "package.json",
    SELF,
  ].map((p) => p.split(sep).join("/"));
  writeAtomic(
    join(outDir, MANIFEST),
    `${JSON.stringify({ entry: ENTRY, builtAt, inputs: [...new Set(inputs)].sort() }, null, 2)}\n`,
  );
  // Chunks of earlier builds (their names are content hashes) are no longer referenced. Only those older than
  // a minute go: a build running at the same time from other sources may still be writing its main.js.
  const current = new Set(files.map((f) => f.path));
  for (const name of readdirSync(outDir)) {
    const path = join(outDir, name);
    if (current.has(path) || !/^chunk-.*\.js(\.map)?$/.test(name)) continue;
    try {
      if (statSync(path).mtimeMs < builtAt - 60_000) unlinkSync(path);
    } catch {
      // Removed by a concurrent build.
    }
  }
  return { ms: performance.now() - started, files: files.map((f) => relative(ROOT, f.path)) };
}

async function cli(args) {
  if (args.includes("--if-stale") && bundleState() === "fresh") return;
  try {
    await import("esbuild");
  } catch {
    // No esbuild (a dev dependency: an install without them): not a reason to fail `npm install`; bin/rbc.mjs
    // then says that the CLI needs building.
    console.warn(
      "build-cli: esbuild (a dev dependency) is not installed, so the CLI was not built; install the dev dependencies and run `npm run build:cli`.",
    );
    return;
  }
  const { ms, files } = await buildCli();
  if (!args.includes("--quiet")) {
    const dir = relative(process.cwd(), OUT_DIR) || ".";
    console.log(`build-cli: ${files.length} files in ${dir}${sep} (${Math.round(ms)} ms)`);
  }
}

if (process.argv[1] && import.meta.url === pathToFileURL(process.argv[1]).href) {
  await cli(process.argv.slice(2)).catch((e) => {
    console.error(e instanceof Error ? e.message : e);
    process.exitCode = 1;
  });
}
