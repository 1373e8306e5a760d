/** Types of scripts/build-cli.mjs (plain JavaScript so that `prepare` and bin/rbc.mjs run it with plain node). */

/** The repository root. */
export declare const ROOT: string;
/** Where the CLI is built: dist-cli/ (git-ignored). */
export declare const OUT_DIR: string;
/** The entry file in OUT_DIR: main.js. */
export declare const ENTRY: string;

/** "missing": no bundle (or no manifest); "stale": a file it was built from changed or went away since. */
export type BundleState = "fresh" | "missing" | "stale";
export declare function bundleState(outDir?: string): BundleState;

/** Bundles src/cli/main.ts into `outDir` (default OUT_DIR). */
export declare function buildCli(options?: { outDir?: string }): Promise<{ ms: number; files: string[] }>;
