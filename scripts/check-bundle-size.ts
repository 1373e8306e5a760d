/**
 * Budget check for CI: what the first page load needs — JavaScript and CSS — must stay within 40 KB gzip
 * (issue #5). Beside it, the size of the one-file panel (rbc-panel.html, `npm run build:single`), which has no
 * budget but must build: a build that fails here fails the check.
 *
 *   tsx scripts/check-bundle-size.ts              runs `vite build` and the one-file build (into dist/), checks
 *   tsx scripts/check-bundle-size.ts --no-build   checks the existing dist/ (fails if there is none)
 *   tsx scripts/check-bundle-size.ts --dist <dir> checks another build folder
 *
 * What counts and how it is measured: bench/bundle-size.ts (scripts and modulepreloads of index.html plus their
 * static imports, and the style sheets it links plus their @imports; each file gzipped at level 9, 1 KB =
 * 1,000 bytes). Exit 0 within budget, 1 over it or on error.
 */
import { existsSync } from "node:fs";
import { join } from "node:path";
import {
  describeContributors,
  describeSingleFile,
  INITIAL_LOAD_BUDGET_KB,
  measureBundle,
  measureSingleFile,
  PROJECT_ROOT,
  SINGLE_FILE_NAME,
  viteBuild,
  viteBuildSingle,
} from "../bench/bundle-size.ts";

const args = process.argv.slice(2);
const distIndex = args.indexOf("--dist");
const outDir = distIndex >= 0 && args[distIndex + 1] ? args[distIndex + 1]! : join(PROJECT_ROOT, "dist");

try {
  if (distIndex < 0 && !args.includes("--no-build")) {
    process.stderr.write(`check-bundle-size: building into ${outDir}\n`);
    await viteBuild(outDir);
    process.stderr.write(`check-bundle-size: building the one-file panel into ${outDir}\n`);
    await viteBuildSingle(outDir);
  }
  const figures = measureBundle(outDir);
  const single = existsSync(join(outDir, SINGLE_FILE_NAME))
    ? `One-file panel: ${describeSingleFile(measureSingleFile(outDir))}`
    : `One-file panel: not built in ${outDir} (npm run build:single)`;
  const files = figures.files
    .map((f) => `  ${f.file}: ${(f.gzipBytes / 1000).toFixed(2)} KB gzip (${f.via})`)
    .join("\n");
  const summary =
    `First load: ${figures.gzipKB.toFixed(2)} KB gzip (JavaScript ${figures.jsGzipKB.toFixed(2)} KB + ` +
    `CSS ${figures.cssGzipKB.toFixed(2)} KB; budget ${INITIAL_LOAD_BUDGET_KB} KB)`;
  if (figures.gzipKB > INITIAL_LOAD_BUDGET_KB) {
    process.stderr.write(
      `check-bundle-size: FAILED. ${summary}, ${(figures.gzipKB - INITIAL_LOAD_BUDGET_KB).toFixed(2)} KB over.\n${files}\n` +
        `Largest contributors to the JavaScript: ${describeContributors(figures)}.\n` +
        `${single}\n` +
        "Load what the first screen does not need with import() (views, zod, the simulator, a view's own CSS), or raise the budget in bench/bundle-size.ts with a reason.\n",
    );
    process.exit(1);
  }
  process.stdout.write(`check-bundle-size: OK. ${summary}.\n${files}\n${single}\n`);
} catch (e) {
  process.stderr.write(`check-bundle-size: FAILED. ${e instanceof Error ? e.message : String(e)}\n`);
  process.exit(1);
}
