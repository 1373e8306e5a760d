#!/usr/bin/env node
// The `rbc` command. Runs the CLI precompiled by scripts/build-cli.mjs into dist-cli/ (built by `npm install`
// through the `prepare` script, or by `npm run build:cli`): no TypeScript to compile at start-up, and nothing
// but the runtime dependencies needed to run it.
//
// When that bundle is missing (e.g. installed with --ignore-scripts) or stale (a source it was made from changed
// since), rbc runs nothing: it says in one line on stderr to run `npm run build:cli` and exits with 1. It never
// runs an outdated bundle, and it does not compile the sources itself (that needs the dev dependencies). The
// check costs about a millisecond (a stat per source file).
import { join } from "node:path";
import { pathToFileURL } from "node:url";
import { bundleState, ENTRY, OUT_DIR } from "../scripts/build-cli.mjs";

const state = bundleState();
if (state === "fresh") {
  await import(pathToFileURL(join(OUT_DIR, ENTRY)).href);
} else {
  process.stderr.write(
    `rbc: the built CLI in dist-cli/ is ${state === "missing" ? "missing" : "older than its sources"}: run \`npm run build:cli\`, then try again.\n`,
  );
  process.exitCode = 1;
}
