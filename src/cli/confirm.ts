import { createInterface } from "node:readline/promises";
import { localeOf, type RunEnv } from "./command.ts";

/** Yes at the prompt: y or yes in every language, and 예 or 네 in Korean ("[y/N]" stays as it is). */
const YES = { en: /^y(es)?$/i, ko: /^(y(es)?|예|네)$/i } as const;

/** The answer at a y/N prompt: "interrupted" for Ctrl-C (at the prompt, or a signal while it waits). */
export type ConfirmAnswer = "yes" | "no" | "interrupted";

/**
 * Asks a yes/no question on the terminal (stderr), default no. "yes" only for y/yes (and 예/네 in Korean: the
 * question is asked in the command's language); "no" for anything else,
 * for end of input, and when stdin is not a terminal (callers should ask for --yes instead); "interrupted"
 * for Ctrl-C — the terminal is in raw mode while the prompt reads, so Ctrl-C arrives here as a key, not as a
 * SIGINT to the process, and callers must exit 130 as on any other interrupt.
 */
export async function confirm(env: RunEnv, question: string): Promise<ConfirmAnswer> {
  if (env.signal.aborted) return "interrupted";
  if (!env.stdin.isTTY) return "no";
  const stderr = env.out.streams.stderr;
  const rl = createInterface({ input: env.stdin, output: stderr, terminal: true });
  const controller = new AbortController();
  let interrupted = false;
  const onAbort = () => {
    interrupted = true;
    controller.abort();
  };
  env.signal.addEventListener("abort", onAbort, { once: true });
  rl.on("SIGINT", onAbort);
  rl.on("close", () => controller.abort());
  try {
    const answer = await rl.question(`${question} [y/N] `, { signal: controller.signal });
    return YES[localeOf(env)].test(answer.trim().normalize("NFC")) ? "yes" : "no";
  } catch {
    env.out.err("\n");
    return interrupted ? "interrupted" : "no";
  } finally {
    env.signal.removeEventListener("abort", onAbort);
    rl.close();
  }
}
