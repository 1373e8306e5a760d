import { type ChildProcess, spawn } from "node:child_process";
import { CliError } from "./errors.ts";

/** A pair of connected pseudo terminals made by socat: what is written to one end is read at the other. */
export interface PtyPair {
  /** The end `rbc sim` serves. */
  simPath: string;
  /** The end a client (rbc, the panel's serial tests, Motionbuilder under Wine, …) opens. */
  clientPath: string;
  process: ChildProcess;
  close(): Promise<void>;
}

/** Starts `socat -d -d pty,raw,echo=0 pty,raw,echo=0` and reads the two paths it prints. */
export function createPtyPair(timeoutMs = 5000): Promise<PtyPair> {
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
            `socat did not create a PTY pair within ${timeoutMs} ms: ${stderr.trim()}`,
          ),
        ),
      timeoutMs,
    );
    child.on("error", (e: NodeJS.ErrnoException) =>
      fail(
        new CliError(
          e.code === "ENOENT" ? "socat-missing" : "pty-failed",
          e.code === "ENOENT"
            ? "rbc sim --pty needs socat (e.g. sudo apt-get install socat); or make a pair yourself and pass one end with --port."
            : `Could not start socat: ${e.message}`,
        ),
      ),
    );
    child.on("exit", (code) => {
      if (paths.length < 2) fail(new CliError("pty-failed", `socat exited (code ${code}): ${stderr.trim()}`));
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
