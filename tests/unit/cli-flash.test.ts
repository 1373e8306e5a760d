import { spawnSync } from "node:child_process";
import { mkdtemp, readFile, rm, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterAll, afterEach, beforeAll, describe, expect, it } from "vitest";
import { DEMO_FIRMWARE_FILE, demoFirmwareExample } from "../../scripts/make-firmware-example.ts";
import { createPtyPair } from "../../src/cli/pty.ts";
import { demoFirmwareHex } from "../../src/sim/index.ts";
import { runInProcess } from "../cli/in-process.ts";
import { CliScope, killAll, REPO, runCli, startCli } from "../cli/spawn-cli.ts";
import { firmwareHex } from "../support/hex.ts";

/**
 * `rbc flash`: in this process against the demo robot on a virtual clock (its bootloader restarts by itself),
 * and the built CLI against `rbc sim` over a socat PTY pair (power-cycled with SIGUSR1). Every firmware file is made here, by the project.
 */

let dir: string;
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), "rbc-flash-"));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});
afterEach(killAll);

const write = async (name: string, text: string) => {
  const path = join(dir, name);
  await writeFile(path, text);
  return path;
};

describe("rbc flash --demo", () => {
  it("writes the example file and reports the version the robot reads back (2.23 → 2.50)", {
    timeout: 30_000,
  }, async () => {
    const r = await runInProcess(["flash", DEMO_FIRMWARE_FILE, "--demo"]);
    expect(r.code, r.stderr).toBe(0);
    const out = r.stdout.split("\n");
    expect(out[0]).toBe(
      "demo-2.50.hex: 16,384 bytes at 0x00000-0x03FFF: 64 flash pages, 1,025 lines (46,093 bytes to send).",
    );
    expect(out[1]).toBe("The demo robot reports firmware 2.23.");
    expect(out[2]).toMatch(
      /^Firmware updated: the robot now reports 2\.50 \(was 2\.23\)\. 1,025 lines in [\d.]+ s\.$/,
    );
    // Asked to switch the robot off and on, said the demo does it itself, and showed progress on stderr.
    expect(r.stderr).toContain("Switch the robot off and on now");
    expect(r.stderr).toContain("The demo robot restarts by itself.");
    expect(r.stderr).toMatch(/\[#{20}\] 1,025\/1,025 lines {2}46,093\/46,093 bytes 100% .* done/);
    expect(r.stderr).toMatch(/ 10% .*B\/s .* s left/);
  });

  it("--json: the version read back after the flash, and the file's summary", {
    timeout: 30_000,
  }, async () => {
    const file = await write("fw-3.07.hex", demoFirmwareHex({ major: 3, minor: 7 }, 2048));
    const r = await runInProcess(["flash", file, "--demo", "--json"]);
    expect(r.code, r.stderr).toBe(0);
    expect(JSON.parse(r.stdout)).toMatchObject({
      ok: true,
      demo: true,
      before: "2.23",
      firmware: "3.07",
      lines: 129,
      resends: 0,
      summary: { bytes: 2048, firstAddress: 0, lastAddress: 2047, pages: 8, lines: 129 },
    });
  });

  it("--recover: a bare port (no handshake), the same update", { timeout: 30_000 }, async () => {
    const file = await write("fw-2.60.hex", firmwareHex("2.60", 1024));
    const r = await runInProcess(["flash", file, "--demo", "--recover"]);
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toContain("without asking the robot anything (--recover)");
    expect(r.stdout).toMatch(/^Firmware updated: the robot now reports 2\.60\. 65 lines in/m);
  });

  it("says a file that is not Intel HEX at all is not an Intel HEX firmware file, the parser's line second", async () => {
    const file = await write("photo.bin", "\u0089PNG\r\n\u001a\n\u0000\u0000binary");
    const r = await runInProcess(["flash", file, "--port", "/dev/rbc-no-such-port", "--yes"]);
    expect(r.code).toBe(1);
    const notHex =
      "photo.bin is not an Intel HEX firmware file: the RBC's firmware is a text file (.hex) of lines that start with ':'.";
    expect(r.stderr).toContain(notHex);
    expect(r.stderr.indexOf("Line 1: a record starts with ':'.")).toBeGreaterThan(r.stderr.indexOf(notHex));
    expect(r.stderr).toContain("Nothing was sent.");
    expect(r.stderr).not.toContain("bootloader can take");
  });

  it("refuses a bad file naming the line, before opening any port", async () => {
    const lines = firmwareHex("2.50", 512).split("\r\n");
    // Line 5 moves to the second 64 KiB; line 6 writes 0x1E000, inside the bootloader's section.
    lines.splice(4, 0, ":020000040001F9", ":02E00000AABBB9");
    const file = await write("boot-section.hex", lines.join("\r\n"));
    // --port names a device that does not exist: the file is refused before rbc tries to open it.
    const r = await runInProcess(["flash", file, "--port", "/dev/rbc-no-such-port", "--yes"]);
    expect(r.code).toBe(1);
    expect(r.stdout).toBe("");
    expect(r.stderr).toContain("boot-section.hex is not a firmware file the RBC's bootloader can take.");
    expect(r.stderr).toContain("Line 6: the record writes 0x1E000-0x1E001, inside the boot section");
    expect(r.stderr).toContain("Nothing was sent.");
    expect(r.stderr).not.toMatch(/rbc-no-such-port/);

    const json = await runInProcess(["flash", file, "--demo", "--json"]);
    expect(json.code).toBe(1);
    expect(JSON.parse(json.stdout)).toMatchObject({
      ok: false,
      error: { code: "hex-invalid", reason: "boot-section", line: 6 },
    });
  });

  it("a real robot needs --yes when there is no terminal to ask on; nothing is sent", async () => {
    const file = await write("ok.hex", firmwareHex("2.50", 256));
    const r = await runCli(["flash", file, "--port", "/dev/rbc-no-such-port", "--demo-file"]);
    expect(r.code).toBe(1);
    expect(r.stderr).toContain("Add --yes to update anyway (nothing was sent).");
  });

  it("a demo file (the RBCFW mark) is refused for a robot on a port without --demo-file, even with --yes", async () => {
    const file = await write("demo-mark.hex", firmwareHex("2.50", 256));
    // The port does not exist: the file is refused before rbc tries to open it.
    const r = await runInProcess(["flash", file, "--port", "/dev/rbc-no-such-port", "--yes"]);
    expect(r.code).toBe(1);
    expect(r.stderr).toContain("A demo file: not firmware a real robot can run.");
    expect(r.stderr).toContain("(RBCFW 2.50)");
    expect(r.stderr).toContain("Nothing was sent.");
    expect(r.stderr).toContain("add --demo-file");
    expect(r.stderr).not.toMatch(/rbc-no-such-port/);
    const json = await runInProcess(["flash", file, "--port", "/dev/rbc-no-such-port", "--yes", "--json"]);
    expect(JSON.parse(json.stdout)).toMatchObject({
      ok: false,
      error: { code: "demo-file", declaredVersion: "2.50" },
    });
    const ko = await runInProcess([
      "flash",
      file,
      "--port",
      "/dev/rbc-no-such-port",
      "--yes",
      "--lang",
      "ko",
    ]);
    expect(ko.stderr).toContain("데모 파일이에요. 실제 로봇이 실행할 수 있는 펌웨어가 아니에요.");
  });

  it("Ctrl-C mid-file says the firmware may be incomplete and how to recover; exit 130", {
    timeout: 30_000,
  }, async () => {
    const file = await write("big.hex", demoFirmwareHex({ major: 2, minor: 50 }, 64 * 1024));
    // At real speed (scale 1) the 4,097 lines take several seconds: time to interrupt.
    const p = startCli(["flash", file, "--demo"]);
    await p.waitFor("stderr", / 10% /, 20_000);
    p.child.kill("SIGINT");
    const r = await p.done;
    expect(r.code).toBe(130);
    expect(r.stderr).toContain("rbc: firmware update interrupted. The firmware update was cancelled.");
    expect(r.stderr).toContain("The robot's firmware may now be incomplete");
    expect(r.stderr).toContain("switch the robot off and on and run the update again");
    expect(r.stdout).not.toContain("Firmware updated");
  });
});

describe("the example firmware file", () => {
  it(`${DEMO_FIRMWARE_FILE} is what scripts/make-firmware-example.ts writes, byte for byte`, async () => {
    const committed = await readFile(join(REPO, DEMO_FIRMWARE_FILE), "latin1");
    expect(committed).toBe(demoFirmwareExample());
    // 16 KiB declaring 2.50 with the marker, in 16-byte records with CR LF line ends.
    expect(committed.startsWith(":10000000524243465720322E3530")).toBe(true); // "RBCFW 2.50"
    expect(committed.split("\r\n")).toHaveLength(1026);
  });
});

const HAS_SOCAT = spawnSync("socat", ["-V"]).status === 0;

describe("rbc flash over a socat PTY pair against rbc sim", () => {
  it.skipIf(!HAS_SOCAT)(
    "flashes when the simulator is power-cycled (SIGUSR1), and rbc info then reports the new version",
    { timeout: 60_000 },
    async ({ onTestFinished }) => {
      const scope = new CliScope();
      onTestFinished(scope.killAll);
      const pty = await createPtyPair();
      onTestFinished(() => pty.close());
      const sim = scope.start(["sim", "--port", pty.simPath, "--quiet", "--baud-pacing"], {
        timeoutMs: 60_000,
      });
      const [help] = await sim.waitFor("stdout", /^Power cycle \(for rbc flash\): kill -USR1 (\d+)/m);
      expect(help).toContain(`kill -USR1 ${sim.child.pid}`);

      const file = await write("pty-2.50.hex", firmwareHex("2.50", 4096));
      const flash = scope.start(["flash", file, "--port", pty.clientPath, "--yes", "--demo-file"], {
        timeoutMs: 60_000,
      });
      await flash.waitFor("stderr", /Switch the robot off and on now/, 20_000);
      sim.child.kill("SIGUSR1");
      const r = await flash.done;
      expect(r.code, r.stderr).toBe(0);
      expect(r.stdout).toContain(`The robot on ${pty.clientPath} reports firmware 2.23.`);
      expect(r.stdout).toMatch(
        /^Firmware updated: the robot now reports 2\.50 \(was 2\.23\)\. 257 lines in/m,
      );
      expect(r.stderr).toContain("Updating the firmware is experimental on real robots");
      expect(sim.stdout).toContain("Power cycle: the simulated robot was switched off and on");

      const info = await scope.run(["info", "--port", pty.clientPath, "--json"]);
      expect(info.code, info.stderr).toBe(0);
      expect(JSON.parse(info.stdout)).toMatchObject({ firmware: "2.50" });
      sim.child.kill("SIGINT");
      expect((await sim.done).code).toBe(0);
    },
  );
});
