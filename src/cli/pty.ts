import { type ChildProcess, spawn } from "node:child_process";
import { said } from "../i18n/said.ts";
import { CliError } from "./errors.ts";
import { cliMessages } from "./messages.ts";

/** A pair of connected pseudo terminals made by socat: what is written to one end is read at the other. */
export interface PtyPair {
  /** The end `rbc sim` serves. */
  simPath: string;
  /** The end a client (rbc, the panel's serial tests, Motionbuilder under Wine, …) opens. */
  clientPath: string;
  process: ChildProcess;
  close(): Promise<void>;
}

/**
 * Starts `socat -d -d pty,raw,echo=0 pty,raw,echo=0` and reads the two paths it prints. socat prints them within
 * milliseconds; the generous bound is for a machine so busy that starting a process takes seconds (it took more
 * than 5 s with two test suites running on two cores).
 */
export function createPtyPair(timeoutMs = 20_000): Promise<PtyPair> {
  return new Promise((resolve, reject) => {
    const child = spawn("socat", ["-d", "-d", "pty,raw,echo=0", "pty,raw,echo=0"], {
      stdio: ["ignore", "ignore", "pipe"],
    });
    const paths: string[] = [];
    let stderr = "";
    const fail = (e: CliError) => {
      clearTimeout(timer);
      child.kill();
      reject(e);
    };
    const timer = setTimeout(
      () =>
        fail(
          new CliError(
            "pty-failed",
            said(cliMessages, "cli.pty.timeout", { ms: String(timeoutMs), output: stderr.trim() }),
          ),
        ),
      timeoutMs,
    );
    child.on("error", (e: NodeJS.ErrnoException) =>
      fail(
        e.code === "ENOENT"
          ? new CliError("socat-missing", said(cliMessages, "cli.pty.noSocat"))
          : new CliError("pty-failed", said(cliMessages, "cli.pty.notStarted", { reason: e.message })),
      ),
    );
    child.on("exit", (code) => {
      if (paths.length < 2) {
        const output = stderr.trim();
        fail(new CliError("pty-failed", said(cliMessages, "cli.pty.exited", { code: String(code), output })));
      }
    });
    child.stderr?.setEncoding("utf8");
    child.stderr?.on("data", (text: string) => {
      stderr += text;
      for (const m of text.matchAll(/PTY is (\S+)/g)) paths.push(m[1]!);
      if (paths.length === 2 && !pairMade) {
        pairMade = true;
        clearTimeout(timer);
        resolve({ simPath: paths[0]!, clientPath: paths[1]!, process: child, close: () => stop(child) });
      }
    });
    let pairMade = false;
  });
}

function stop(child: ChildProcess): Promise<void> {
  if (child.exitCode !== null || child.signalCode !== null) return Promise.resolve();
  return new Promise((resolve) => {
    child.once("exit", () => resolve());
    child.kill("SIGTERM");
  });
}
