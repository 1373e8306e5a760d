import { PassThrough } from "node:stream";
import { Cleanups } from "../../src/cli/cleanups.ts";
import type { CommandDef, RunEnv } from "../../src/cli/command.ts";
import { Output } from "../../src/cli/output.ts";
import { REPO } from "../cli/spawn-cli.ts";

/**
 * Runs one `rbc` command in process (no child, no built bundle) against what its arguments name (`--demo` for
 * the demo robot), with its stdout and stderr collected and its clean-ups (closing the port) run at the end.
 */
export async function runInProcess(
  command: CommandDef,
  argv: string[],
  env: Record<string, string> = {},
): Promise<{ code: number; stdout: string; stderr: string; error?: unknown }> {
  const text = { stdout: "", stderr: "" };
  const stdout = new PassThrough();
  const stderr = new PassThrough();
  stdout.on("data", (d: Buffer) => {
    text.stdout += d.toString();
  });
  stderr.on("data", (d: Buffer) => {
    text.stderr += d.toString();
  });
  const cleanups = new Cleanups();
  const out = new Output(argv.includes("--json"), { stdout, stderr });
  const runEnv: RunEnv = {
    argv,
    signal: new AbortController().signal,
    onCleanup: (fn) => cleanups.add(fn),
    out,
    setExitNote: () => {},
    stdin: process.stdin,
    cwd: REPO,
    env,
  };
  let code: number;
  let error: unknown;
  try {
    code = await command.run(runEnv);
  } catch (e) {
    // What main.ts prints for a thrown error is its English line; the error itself is returned as well.
    error = e;
    text.stderr += `rbc: ${e instanceof Error ? e.message : String(e)}\n`;
    code = -1;
  } finally {
    await cleanups.run();
  }
  await new Promise((r) => setImmediate(r));
  return { code, ...text, error };
}
