import { spawn, spawnSync } from "node:child_process";
import { mkdtemp, readdir, readFile, rm } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterAll, afterEach, beforeAll, describe, expect, it } from "vitest";
import { createPtyPair, type PtyPair } from "../../src/cli/pty.ts";
import { RbcClient } from "../../src/device/index.ts";
import { NodeSerialTransport } from "../../src/link/node-serial-transport.ts";
import {
  DOWNLOAD_CHUNK,
  FACTORY_ZEROS,
  MOTION_AREA_BYTES,
  memoryFootprint,
  motionImage,
  parseRbm,
  STANDARD_ZEROS,
} from "../../src/protocol/index.ts";
import { type CliProcess, CliScope, cliEntry, EXAMPLES, REPO } from "../cli/spawn-cli.ts";

/**
 * NodeSerialTransport against a real serial device: a PTY pair made by socat, `rbc sim` serving one end (a
 * separate process), and RbcClient on the other end — the same code the CLI runs against a robot.
 *
 * The three groups below each have their own PTY pair and simulator, so they run at the same time (their
 * waits are on the link's real time: latency, 115200-baud pacing, timeouts); the tests within a group share
 * one simulator and run one after the other.
 */

interface Rig {
  pty: PtyPair;
  sim: CliProcess;
}

/** The simulators, apart from the commands each group runs (which it kills after every test). */
const sims = new CliScope();

/** A socat PTY pair with `rbc sim --port <one end> ARGS` running on it. */
async function startSim(args: readonly string[] = []): Promise<Rig> {
  const pty = await createPtyPair();
  const sim = sims.start(["sim", "--port", pty.simPath, ...args], { timeoutMs: 60_000 });
  await sim.waitFor("stdout", /listening on/);
  return { pty, sim };
}

async function stopSim(rig: Rig | undefined): Promise<void> {
  if (!rig) return;
  rig.sim.child.kill("SIGINT");
  await rig.sim.done;
  await rig.pty.close();
}

/** util-linux `script` runs a command on a pseudo terminal: the way to give rbc a terminal for its y/N prompt. */
const HAS_SCRIPT = spawnSync("script", ["--version"]).status === 0;

/**
 * Runs `rbc ARGS` with a terminal on stdin/stdout/stderr (through `script`), types `keys` once `prompt` shows,
 * and resolves with the exit code and everything the terminal showed.
 */
function runOnTerminal(args: readonly string[], prompt: RegExp, keys: string) {
  const command = [process.execPath, cliEntry(), ...args].map((a) => `'${a}'`).join(" ");
  const child = spawn("script", ["-qec", command, "/dev/null"], {
    cwd: REPO,
    env: { ...process.env, RBC_PORT: "", NO_COLOR: "1" },
    stdio: ["pipe", "pipe", "pipe"],
  });
  let screen = "";
  let typed = false;
  const onData = (d: Buffer) => {
    screen += d.toString();
    if (!typed && prompt.test(screen)) {
      typed = true;
      child.stdin.write(keys);
    }
  };
  child.stdout.on("data", onData);
  child.stderr.on("data", onData);
  const timer = setTimeout(() => child.kill("SIGKILL"), 60_000);
  return new Promise<{ code: number | null; screen: string }>((resolve) =>
    child.on("close", (code) => {
      clearTimeout(timer);
      resolve({ code, screen });
    }),
  );
}

describe.concurrent("rbc and NodeSerialTransport over PTY pairs", () => {
  describe.concurrent("requests and commands on one simulator", () => {
    describe.sequential("NodeSerialTransport ↔ rbc sim over a PTY pair", () => {
      const { start: startCli, killAll } = new CliScope();
      let rig: Rig | undefined;
      let client: RbcClient | undefined;

      beforeAll(async () => {
        rig = await startSim();
      }, 60_000);
      afterEach(async () => {
        await client?.close();
        client = undefined;
      });
      afterAll(async () => {
        await stopSim(rig);
        await killAll();
      });

      const connect = async () => {
        // These tests are about the bytes and the acknowledgements, not the speed: the simulator is a node process
        // behind socat on a machine that runs browser tests at the same time, so a reply may take far longer than
        // a robot's. A quick time of 2 s (not 400 ms) keeps a starved machine from failing a correct exchange.
        client = new RbcClient(new NodeSerialTransport(rig!.pty.clientPath), {
          timeouts: { quickMs: 2_000 },
        });
        return { client, identity: await client.connect() };
      };

      it("info: firmware version, serial number and platform", async () => {
        const { client, identity } = await connect();
        expect(identity).toEqual({ firmware: { major: 2, minor: 23 }, platform: 1 });
        expect(await client.readSerialNumber()).toBe("8958899989309");
        expect(await client.readAvailableMemory("motion")).toBe(24576);
        await rig!.sim.waitFor("stdout", /RBC→PC\s+0x0C Read serial number\s+FF FF AA 55 AA 55 37 BA 0C 01/);
      });

      it("zeros: write, echo, read back and verify", async () => {
        const { client } = await connect();
        expect(await client.readZeros()).toEqual([...FACTORY_ZEROS]);
        const result = await client.writeZeros(STANDARD_ZEROS);
        expect(result).toEqual({ written: [...STANDARD_ZEROS], readBack: [...STANDARD_ZEROS] });
        expect(await client.readZeros()).toEqual([...STANDARD_ZEROS]);
        await rig!.sim.waitFor(
          "stdout",
          /PC→RBC\s+0x0E Write zero positions\s+FF FF AA 55 AA 55 37 BA 0E 00 00 00 00 10 7D CA/,
        );
      });

      it("uploads wave.rbm: every chunk acknowledged, its footprint of memory used", async () => {
        const { client } = await connect();
        const motion = parseRbm(await readFile(join(REPO, EXAMPLES.wave), "utf8"));
        const image = motionImage(motion);
        // Expected from the file: 16 servos, so 108 + 86 bytes per scene, in chunks of 64 bytes.
        const total = 108 + 86 * motion.scenes.length;
        expect(image.length).toBe(total);
        const chunks = Math.ceil(total / DOWNLOAD_CHUNK);
        const last = total - (chunks - 1) * DOWNLOAD_CHUNK;
        expect(last).toBeLessThan(DOWNLOAD_CHUNK); // a short last chunk, as the trace below shows
        const footprint = memoryFootprint(total);
        const progress: number[] = [];
        const result = await client.writeMotion(image, { onProgress: (p) => progress.push(p.acknowledged) });
        expect(result).toMatchObject({
          total,
          chunks,
          footprint,
          freeBefore: MOTION_AREA_BYTES,
          freeAfter: MOTION_AREA_BYTES - footprint,
          errorCode: 0xff,
        });
        expect(progress.at(-1)).toBe(total);
        await rig!.sim.waitFor(
          "stdout",
          new RegExp(`motion chunk ${chunks}/${chunks} \\(${last} bytes \\+ checksum\\)`),
        );
      });

      it("rbc info --port works against the PTY", { timeout: 60_000 }, async () => {
        const info = startCli(["info", "--port", rig!.pty.clientPath, "--json"]);
        const result = await info.done;
        expect(result.code).toBe(0);
        expect(JSON.parse(result.stdout)).toMatchObject({ firmware: "2.23", serialNumber: "8958899989309" });
      });

      it.skipIf(!HAS_SCRIPT)(
        "Ctrl-C at the upload's y/N prompt exits 130 like any interrupt, and nothing is sent",
        { timeout: 60_000 },
        async () => {
          const { client } = await connect();
          const free = await client.readAvailableMemory("motion");
          await client.close(); // the port is rbc's now
          const result = await runOnTerminal(
            ["upload", EXAMPLES.wave, "--port", rig!.pty.clientPath],
            /\[y\/N\] /,
            "\x03",
          );
          expect(result.code, result.screen).toBe(130);
          expect(result.screen).toContain("rbc: interrupted. Nothing was sent.");
          const again = await connect();
          expect(await again.client.readAvailableMemory("motion")).toBe(free);
        },
      );
    });
  });

  describe("a PTY with no robot behind it", () => {
    const { start: startCli, killAll } = new CliScope();
    afterAll(killAll);

    it("rbc info --port times out cleanly, and names the busy robot as a possible reason", {
      timeout: 60_000,
    }, async () => {
      const lonely = await createPtyPair();
      try {
        const silent = await startCli(["info", "--port", lonely.clientPath]).done;
        expect(silent.code).toBe(1);
        expect(silent.stderr).toContain("no robot answered");
        expect(silent.stderr).toContain(
          "or the robot is busy playing a motion or a sound: wait until it ends and try again.",
        );
      } finally {
        await lonely.close();
      }
    });
  });

  describe("Ctrl-C during a zero write (rbc sim --latency-ms 250)", () => {
    const { start: startCli, killAll } = new CliScope();
    let rig: Rig | undefined;
    let dir: string;

    beforeAll(async () => {
      rig = await startSim(["--latency-ms", "250", "--quiet"]);
      dir = await mkdtemp(join(tmpdir(), "rbc-zeros-"));
    }, 60_000);
    afterEach(killAll);
    afterAll(async () => {
      await stopSim(rig);
      await killAll();
      await rm(dir, { recursive: true, force: true });
    });

    it("lets the write and its check finish, says what the robot holds, then exits 130", {
      timeout: 20_000,
    }, async () => {
      const write = startCli([
        "zeros",
        "write",
        STANDARD_ZEROS.join(","),
        "--port",
        rig!.pty.clientPath,
        "--backup-dir",
        dir,
        "--json",
      ]);
      // The 0x0E write goes out right after the backup is saved; its echo and the read-back take 500 ms here.
      await write.waitFor("stderr", /Backed up the current zeros/);
      write.child.kill("SIGINT");
      const result = await write.done;
      expect(result.code, result.stderr).toBe(130);
      expect(result.stderr).toContain("finishing the zero write");
      expect(result.stderr).toContain("interrupted after the write finished: the robot holds the new zeros");
      const [backup] = await readdir(dir);
      expect(JSON.parse(result.stdout)).toMatchObject({
        ok: false,
        error: { code: "interrupted" },
        previous: [...FACTORY_ZEROS],
        readBack: [...STANDARD_ZEROS],
        backupFile: join(dir, backup!),
        changed: true,
      });
      const client = new RbcClient(new NodeSerialTransport(rig!.pty.clientPath));
      try {
        await client.connect();
        expect(await client.readZeros()).toEqual([...STANDARD_ZEROS]);
      } finally {
        await client.close();
      }
    });
  });

  describe("Ctrl-C during an upload (rbc sim --baud-pacing --latency-ms 16)", () => {
    const { start: startCli, killAll } = new CliScope();
    let rig: Rig | undefined;

    beforeAll(async () => {
      rig = await startSim(["--baud-pacing", "--latency-ms", "16", "--quiet"]);
    }, 60_000);
    afterEach(killAll);
    afterAll(async () => {
      await stopSim(rig);
      await killAll();
    });

    it("stops cleanly: exit 130, says how many bytes were acknowledged, the robot recorded nothing", {
      timeout: 20_000,
    }, async () => {
      // long-walk.rbm: 284 scenes, a 24,532-byte image (108 + 86 per scene), many seconds over the paced link.
      const motion = parseRbm(await readFile(join(REPO, EXAMPLES.longWalk), "utf8"));
      const total = 108 + 86 * motion.scenes.length;
      const upload = startCli(["upload", EXAMPLES.longWalk, "--port", rig!.pty.clientPath, "--yes"]);
      await upload.waitFor("stderr", new RegExp(`\\b[1-9]\\d*/${total} bytes`));
      upload.child.kill("SIGINT");
      const result = await upload.done;
      expect(result.code).toBe(130);
      const m = result.stderr.match(
        new RegExp(
          `upload interrupted: (\\d+) of ${total} bytes were acknowledged \\(outcome: nothing-recorded\\)`,
        ),
      );
      expect(m, result.stderr).not.toBeNull();
      const acknowledged = Number(m![1]);
      expect(acknowledged).toBeGreaterThan(0);
      expect(acknowledged).toBeLessThan(total);
      // The port was closed and the robot is back in packet mode with its memory unchanged.
      const client = new RbcClient(new NodeSerialTransport(rig!.pty.clientPath));
      try {
        await client.connect();
        expect(await client.readAvailableMemory("motion")).toBe(24576);
      } finally {
        await client.close();
      }
    });
  });
});
