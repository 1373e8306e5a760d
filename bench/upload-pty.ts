import { type ChildProcess, spawn, spawnSync } from "node:child_process";
import { join } from "node:path";
import { createInterface } from "node:readline";
import { RbcClient } from "../src/device/index.ts";
import { PROJECT_ROOT } from "./bundle-size.ts";
import { benchMotion } from "./motion.ts";
import { median } from "./stats.ts";
import { checkBytes } from "./upload-efficiency.ts";
import { ADAPTER_LATENCY_MS, idealUpload, type UploadIdeal } from "./upload-ideal.ts";
import { type TimedUpload, timedUpload } from "./upload-timing.ts";

/**
 * The same upload over the Node serial path: `node bin/rbc.mjs sim --pty --baud-pacing --latency-ms 16` in a
 * child process serves the simulated RBC on one end of a socat PTY pair (pacing, latency and the 5 ms page
 * write are applied there, in real time); this process opens the other end with NodeSerialTransport (the
 * `serialport` package, as `rbc --port` does) and uploads through RbcClient. The bytes cross two pseudo
 * terminals and socat. Efficiency = the same first-principles ideal ÷ the real download-phase time, median of
 * `runs` uploads on one connection (the motion memory is reset before each).
 *
 * Skipped, with the reason, when socat is missing or the simulator does not start.
 */

export class PtySkip extends Error {}

export interface PtyUploadFigures {
  motion: string;
  ideal: UploadIdeal;
  runs: TimedUpload[];
  downloadMs: number;
  efficiency: number;
  startupMs: number;
}

function socatAvailable(): boolean {
  const r = spawnSync("socat", ["-V"], { stdio: "ignore" });
  return !r.error;
}

interface Ready {
  clientPath: string;
}

/** Waits for the simulator's `{"event":"ready",...}` line on stdout. */
function waitReady(child: ChildProcess, timeoutMs: number): Promise<Ready> {
  return new Promise((resolve, reject) => {
    let stderr = "";
    child.stderr?.setEncoding("utf8");
    child.stderr?.on("data", (t: string) => {
      stderr = (stderr + t).slice(-2000);
    });
    const lines = createInterface({ input: child.stdout! });
    const timer = setTimeout(() => {
      finish();
      reject(new PtySkip(`rbc sim --pty printed no ready line within ${timeoutMs} ms ${stderr.trim()}`));
    }, timeoutMs);
    const onExit = (code: number | null) => {
      finish();
      const why = stderr.trim().split("\n").slice(-3).join(" ");
      reject(new PtySkip(`rbc sim --pty exited (code ${code}) before it was ready${why ? `: ${why}` : ""}`));
    };
    const finish = () => {
      clearTimeout(timer);
      child.off("exit", onExit);
      lines.close();
    };
    child.on("exit", onExit);
    lines.on("line", (line) => {
      try {
        const event = JSON.parse(line) as { event?: string; clientPath?: string | null };
        if (event.event === "ready" && event.clientPath) {
          finish();
          resolve({ clientPath: event.clientPath });
        }
      } catch {
        // Not a JSON line.
      }
    });
  });
}

/** Ctrl-C (the CLI then stops socat), then SIGKILL to the child's process group if it lingers. */
async function stopChild(child: ChildProcess): Promise<void> {
  if (child.exitCode !== null || child.signalCode !== null) return;
  const exited = new Promise<void>((resolve) => child.once("exit", () => resolve()));
  child.kill("SIGINT");
  const late = await Promise.race([exited.then(() => false), new Promise((r) => setTimeout(r, 3000, true))]);
  if (late && child.pid !== undefined) {
    try {
      process.kill(-child.pid, "SIGKILL");
    } catch {
      child.kill("SIGKILL");
    }
    await exited;
  }
}

export async function measurePtyUpload(runs = 7): Promise<PtyUploadFigures> {
  if (!socatAvailable()) {
    throw new PtySkip("socat is not installed (apt-get install socat); rbc sim --pty needs it");
  }
  const { file, image } = benchMotion();
  const ideal = idealUpload(image.length);
  const t0 = performance.now();
  // Its own process group, so that socat goes too if the CLI has to be killed.
  const child = spawn(
    process.execPath,
    [
      join(PROJECT_ROOT, "bin", "rbc.mjs"),
      "sim",
      "--pty",
      "--baud-pacing",
      "--latency-ms",
      String(ADAPTER_LATENCY_MS),
      "--quiet",
      "--json",
    ],
    { cwd: PROJECT_ROOT, stdio: ["ignore", "pipe", "pipe"], detached: true },
  );
  try {
    const { clientPath } = await waitReady(child, 30_000);
    const startupMs = performance.now() - t0;
    // Loaded here only: the native serialport binding is needed for this figure alone.
    const { NodeSerialTransport } = await import("../src/link/node-serial-transport.ts");
    const transport = new NodeSerialTransport(clientPath);
    const client = new RbcClient(transport);
    await client.connect();
    const timed: TimedUpload[] = [];
    try {
      await client.readAvailableMemory("motion");
      for (let i = 0; i < runs; i++) {
        await client.resetMemoryPointer("motion");
        const run = await timedUpload(client, transport, image);
        checkBytes(run, ideal, "PTY");
        timed.push(run);
      }
    } finally {
      await client.close();
    }
    const downloadMs = median(timed.map((r) => r.downloadMs));
    return {
      motion: file,
      ideal,
      runs: timed,
      downloadMs,
      efficiency: ideal.download.totalMs / downloadMs,
      startupMs,
    };
  } finally {
    await stopChild(child);
  }
}
