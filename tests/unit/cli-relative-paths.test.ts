import { mkdtemp, readFile, rm } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterEach, beforeEach, describe, expect, it } from "vitest";
import { runInProcess } from "../cli/in-process.ts";
import { REPO } from "../cli/spawn-cli.ts";

/**
 * A file named on the command line is found where the user is (the command's working folder, `RunEnv.cwd`),
 * not wherever the process happens to run: in these tests the process runs in the repository and the user in a
 * fresh temporary folder, so a relative name resolved against the wrong one is not found (or lands elsewhere).
 */
describe("relative file names are resolved against the command's working folder", () => {
  let dir = "";
  beforeEach(async () => {
    dir = await mkdtemp(join(tmpdir(), "rbc-cwd-"));
  });
  afterEach(async () => {
    await rm(dir, { recursive: true, force: true });
  });

  it("zeros backup FILE writes the file in the working folder, and zeros restore FILE reads it from there", async () => {
    const backup = await runInProcess(["zeros", "backup", "mine.json", "--demo", "--json"], { cwd: dir });
    expect(backup.stderr).toBe("");
    expect(backup.code).toBe(0);
    const saved = JSON.parse(await readFile(join(dir, "mine.json"), "utf8")) as { zeros: number[] };
    expect(saved.zeros).toHaveLength(16);
    const restore = await runInProcess(["zeros", "restore", "mine.json", "--demo", "--json"], { cwd: dir });
    expect(restore.stderr).toBe("");
    expect(restore.code).toBe(0);
  });

  it("upload, play and flash find a relative file from the working folder (and not from the repository)", async () => {
    const fromRepo = await runInProcess(["upload", "examples/wave.rbm", "--demo", "--json"], { cwd: REPO });
    expect(fromRepo.code).toBe(0);
    for (const argv of [
      ["upload", "examples/wave.rbm", "--demo"],
      ["play", "examples/wave.rbm", "--demo", "--yes"],
      ["flash", "examples/firmware/demo-2.50.hex", "--demo", "--yes"],
    ]) {
      const result = await runInProcess(argv, { cwd: dir });
      expect(result.code, argv.join(" ")).toBe(1);
      expect(result.stderr, argv.join(" ")).toMatch(/^rbc: Cannot read examples\//);
    }
  });
});
