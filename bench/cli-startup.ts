import { spawnSync } from "node:child_process";
import { join } from "node:path";
import { PROJECT_ROOT } from "./bundle-size.ts";
import { median } from "./stats.ts";

/**
 * Start-up cost of the `rbc` command: wall time of `node bin/rbc.mjs --help` against `node -e 0` (Node's own
 * start-up), run side by side — the two commands alternate, so both see the same machine load — after one
 * untimed run of each. Each run is a fresh process (spawnSync), timed from spawn to exit with
 * `performance.now()`. Ratio = median(cli) ÷ median(node). What bin/rbc.mjs runs is measured: the prebuilt
 * bundle (a missing or stale one makes rbc exit with 1, and this figure fails saying so).
 */

export interface CliStartupFigures {
  cliMs: number;
  nodeMs: number;
  ratio: number;
  cliRunsMs: number[];
  nodeRunsMs: number[];
  command: string;
  /** What the CLI printed on stderr in its untimed first run if anything. */
  stderr: string;
}

const CLI = join(PROJECT_ROOT, "bin", "rbc.mjs");

function timeRun(args: string[]): { ms: number; stderr: string } {
  const t0 = performance.now();
  const r = spawnSync(process.execPath, args, { cwd: PROJECT_ROOT, stdio: ["ignore", "pipe", "pipe"] });
  const ms = performance.now() - t0;
  if (r.error) throw r.error;
  if (r.status !== 0) {
    const why = r.stderr.toString().trim().split("\n").slice(-2).join(" ");
    throw new Error(`node ${args.join(" ")} exited with ${r.status}${why ? `: ${why}` : ""}`);
  }
  return { ms, stderr: r.stderr.toString().trim() };
}

export function measureCliStartup(runs = 10): CliStartupFigures {
  const cliArgs = [CLI, "--help"];
  const nodeArgs = ["-e", "0"];
  const first = timeRun(cliArgs);
  timeRun(nodeArgs);
  const cliRunsMs: number[] = [];
  const nodeRunsMs: number[] = [];
  for (let i = 0; i < runs; i++) {
    // Alternate which goes first, so neither always follows the other.
    if (i % 2 === 0) {
      cliRunsMs.push(timeRun(cliArgs).ms);
      nodeRunsMs.push(timeRun(nodeArgs).ms);
    } else {
      nodeRunsMs.push(timeRun(nodeArgs).ms);
      cliRunsMs.push(timeRun(cliArgs).ms);
    }
  }
  const cliMs = median(cliRunsMs);
  const nodeMs = median(nodeRunsMs);
  return {
    cliMs,
    nodeMs,
    ratio: cliMs / nodeMs,
    cliRunsMs,
    nodeRunsMs,
    command: "node bin/rbc.mjs --help",
    stderr: first.stderr,
  };
}
