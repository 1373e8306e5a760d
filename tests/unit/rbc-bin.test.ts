/**
 * bin/rbc.mjs, the installed `rbc` command: it runs the bundle in dist-cli/ when that is up to date, and when
 * the bundle is missing or older than its sources it runs nothing, says "run `npm run build:cli`" in one line
 * and exits with 1 (it no longer falls back to running the sources through tsx, a dev dependency).
 *
 * Each case runs a copy of bin/rbc.mjs and scripts/build-cli.mjs in a temporary folder with a dist-cli/ made
 * for the case, so the repository's own bundle is never touched (other test workers may be using it). The
 * folder has no node_modules, so a fallback that imported tsx would fail here too.
 */
import { execFile } from "node:child_process";
import { cpSync, mkdirSync, mkdtempSync, rmSync, utimesSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { fileURLToPath } from "node:url";
import { afterEach, describe, expect, it } from "vitest";

const REPO = fileURLToPath(new URL("../../", import.meta.url));

interface Run {
  code: number | null;
  stdout: string;
  stderr: string;
}

function run(dir: string): Promise<Run> {
  return new Promise((resolve) => {
    execFile(
      process.execPath,
      [join(dir, "bin/rbc.mjs"), "--version"],
      { cwd: dir },
      (error, stdout, stderr) => {
        resolve({ code: error ? (typeof error.code === "number" ? error.code : null) : 0, stdout, stderr });
      },
    );
  });
}

const dirs: string[] = [];
afterEach(() => {
  for (const dir of dirs.splice(0)) rmSync(dir, { recursive: true, force: true });
});

/** A folder with the command and its staleness check, one source file, and (optionally) a bundle. */
function install(bundle?: { builtAt: number }): string {
  const dir = mkdtempSync(join(tmpdir(), "rbc-bin-"));
  dirs.push(dir);
  for (const file of ["bin/rbc.mjs", "scripts/build-cli.mjs"]) {
    cpSync(join(REPO, file), join(dir, file), { recursive: true });
  }
  writeFileSync(join(dir, "package.json"), '{ "type": "module" }\n');
  mkdirSync(join(dir, "src"));
  writeFileSync(join(dir, "src/main.ts"), "export {};\n");
  const modified = new Date(Date.UTC(2026, 0, 1));
  utimesSync(join(dir, "src/main.ts"), modified, modified);
  if (bundle) {
    mkdirSync(join(dir, "dist-cli"));
    writeFileSync(join(dir, "dist-cli/main.js"), 'process.stdout.write("the bundle ran\\n");\n');
    const manifest = { entry: "main.js", builtAt: bundle.builtAt, inputs: ["src/main.ts"] };
    writeFileSync(join(dir, "dist-cli/manifest.json"), JSON.stringify(manifest));
  }
  return dir;
}

const SOURCE_TIME = Date.UTC(2026, 0, 1);

describe("bin/rbc.mjs", { timeout: 30_000 }, () => {
  it("runs the bundle when it is newer than every source", async () => {
    const r = await run(install({ builtAt: SOURCE_TIME + 60_000 }));
    expect(r).toEqual({ code: 0, stdout: "the bundle ran\n", stderr: "" });
  });

  it("runs nothing and asks for npm run build:cli when a source is newer than the bundle", async () => {
    const r = await run(install({ builtAt: SOURCE_TIME - 60_000 }));
    expect(r).toEqual({
      code: 1,
      stdout: "",
      stderr:
        "rbc: the built CLI in dist-cli/ is older than its sources: run `npm run build:cli`, then try again.\n",
    });
  });

  it("runs nothing and asks for npm run build:cli when there is no bundle", async () => {
    const r = await run(install());
    expect(r).toEqual({
      code: 1,
      stdout: "",
      stderr: "rbc: the built CLI in dist-cli/ is missing: run `npm run build:cli`, then try again.\n",
    });
  });
});
