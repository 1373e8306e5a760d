/**
 * Budget check for CI: what the first page load needs — JavaScript and CSS — must stay within the budget of
 * bench/bundle-size.ts (INITIAL_LOAD_BUDGET_KB, gzip) in every language: the page loads only its own language's
 * words (docs/i18n.md, "One language at a time"), so the first load is measured once per language. Beside it,
 * the size of the one-file panel (rbc-panel.html, `npm run build:single`), which has no budget but must build: a
 * build that fails here fails the check.
 *
 *   tsx scripts/check-bundle-size.ts              runs `vite build` and the one-file build (into dist/), checks
 *   tsx scripts/check-bundle-size.ts --no-build   checks the existing dist/ (fails if there is none)
 *   tsx scripts/check-bundle-size.ts --dist <dir> checks another build folder
 *
 * What counts and how it is measured: bench/bundle-size.ts (scripts and modulepreloads of index.html plus their
 * static imports and the language's word chunks they load, and the style sheets it links plus their @imports;
 * each file gzipped at level 9, 1 KB = 1,000 bytes). Exit 0 within budget, 1 over it or on error.
 *
 * It also fails if a file of the build (its scripts and pages, source maps aside) holds the browser tests' start
 * option (src/ui/test-start.ts, a robot connected at start): only the tests' build may contain it.
 */
import { existsSync, readdirSync, readFileSync } from "node:fs";
import { join, relative } from "node:path";
import {
  BUNDLE_LOCALES,
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
import { TEST_START_NAME } from "../src/ui/test-start.ts";

/** The files under `dir` (source maps aside: they quote the source, comments and all) that name the start option. */
function withTestStart(dir: string): string[] {
  return readdirSync(dir, { recursive: true, withFileTypes: true })
    .filter((entry) => entry.isFile() && !entry.name.endsWith(".map"))
    .map((entry) => join(entry.parentPath, entry.name))
    .filter((file) => readFileSync(file, "latin1").includes(TEST_START_NAME))
    .map((file) => relative(dir, file));
}

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
  const testOnly = withTestStart(outDir);
  if (testOnly.length > 0) {
    process.stderr.write(
      `check-bundle-size: FAILED. The browser tests' start option (${TEST_START_NAME}) is in the production ` +
        `build: ${testOnly.join(", ")}. Only the tests' build (mode "e2e") may contain src/ui/test-start.ts.\n`,
    );
    process.exit(1);
  }
  const single = existsSync(join(outDir, SINGLE_FILE_NAME))
    ? `One-file panel: ${describeSingleFile(measureSingleFile(outDir))}`
    : `One-file panel: not built in ${outDir} (npm run build:single)`;
  // The first load in each language: the same code and CSS, and that language's words.
  const byLocale = BUNDLE_LOCALES.map((locale) => ({ locale, figures: measureBundle(outDir, locale) }));
  const report = byLocale.map(({ locale, figures }) => {
    const files = figures.files
      .map((f) => `  ${f.file}: ${(f.gzipBytes / 1000).toFixed(2)} KB gzip (${f.via})`)
      .join("\n");
    const summary =
      `First load, ${locale}: ${figures.gzipKB.toFixed(2)} KB gzip (JavaScript ${figures.jsGzipKB.toFixed(2)} KB + ` +
      `CSS ${figures.cssGzipKB.toFixed(2)} KB; budget ${INITIAL_LOAD_BUDGET_KB} KB)`;
    const over = figures.gzipKB - INITIAL_LOAD_BUDGET_KB;
    return {
      over,
      text: over > 0 ? `${summary}, ${over.toFixed(2)} KB over.\n${files}` : `${summary}.\n${files}`,
    };
  });
  if (report.some((r) => r.over > 0)) {
    const english = byLocale[0]?.figures;
    process.stderr.write(
      `check-bundle-size: FAILED.\n${report.map((r) => r.text).join("\n")}\n` +
        (english ? `Largest contributors to the JavaScript: ${describeContributors(english)}.\n` : "") +
        `${single}\n` +
        "Load what the first screen does not need with import() (views, zod, the simulator, a view's own CSS, words only a lazily drawn part shows), or raise the budget in bench/bundle-size.ts with a reason.\n",
    );
    process.exit(1);
  }
  process.stdout.write(`check-bundle-size: OK.\n${report.map((r) => r.text).join("\n")}\n${single}\n`);
} catch (e) {
  process.stderr.write(`check-bundle-size: FAILED. ${e instanceof Error ? e.message : String(e)}\n`);
  process.exit(1);
}
