import { createInterface } from "node:readline/promises";
import type { RunEnv } from "./command.ts";

/**
 * Asks a yes/no question on the terminal (stderr), default no. Resolves false on anything but y/yes, on
 * Ctrl-C, and when stdin is not a terminal (callers should ask for --yes instead).
 */
export async function confirm(env: RunEnv, question: string): Promise<boolean> {
  if (!env.stdin.isTTY || env.signal.aborted) return false;
  const rl = createInterface({ input: env.stdin, output: process.stderr, terminal: true });
  const controller = new AbortController();
  const onAbort = () => controller.abort();
  env.signal.addEventListener("abort", onAbort, { once: true });
  rl.on("SIGINT", () => controller.abort());
  try {
    const answer = await rl.question(`${question} [y/N] `, { signal: controller.signal });
    return /^y(es)?$/i.test(answer.trim());
  } catch {
    process.stderr.write("\n");
    return false;
  } finally {
    env.signal.removeEventListener("abort", onAbort);
    rl.close();
  }
}
