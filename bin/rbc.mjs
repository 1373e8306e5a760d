#!/usr/bin/env node
// The `rbc` command. Runs the CLI precompiled by scripts/build-cli.mjs into dist-cli/ (built by `npm install`
// through the `prepare` script, or by `npm run build:cli`): no TypeScript to compile at start-up.
//
// When that bundle is missing (e.g. installed with --ignore-scripts) or stale (a source it was made
// from changed since), rbc runs the TypeScript sources through tsx instead, slower but current, and says so in
// one line on stderr. Chosen over refusing with "run npm run build:cli": whoever edits src/ gets the code they
// just wrote, never an outdated bundle, and rbc works whatever state dist-cli/ is in. The check costs under a
// millisecond (a stat per source file).
import { join } from "node:path";
import { pathToFileURL } from "node:url";
import { bundleState, ENTRY, OUT_DIR } from "../scripts/build-cli.mjs";

const state = bundleState();
if (state === "fresh") {
  await import(pathToFileURL(join(OUT_DIR, ENTRY)).href);
} else {
  process.stderr.write(
    `rbc: the built CLI in dist-cli/ is ${state === "missing" ? "missing" : "older than its sources"}; running the sources through tsx (slower). \`npm run build:cli\` builds it.\n`,
  );
  const { register } = await import("tsx/esm/api");
  register();
  await import("../src/cli/main.ts");
}
