import { mkdtemp, readFile, rm, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterEach, beforeEach, describe, expect, it } from "vitest";
import { runInProcess } from "../cli/in-process.ts";

/**
 * `rbc upload` records what it stored on the robot's shelf; `rbc shelf` lists it, and with a robot checks it
 * against the robot's free memory (issue 23 item 2). The demo robot of `--demo` is a new robot each command, with
 * empty memory: what was recorded for it is forgotten when it is checked, as it must be.
 */
describe("rbc shelf", () => {
  let dir = "";
  let env: Record<string, string> = {};
  beforeEach(async () => {
    dir = await mkdtemp(join(tmpdir(), "rbc-shelf-"));
    env = { RBC_CONFIG_DIR: dir };
  });
  afterEach(async () => {
    await rm(dir, { recursive: true, force: true });
  });

  it("upload records slot 1 (Run 12, key 1) with name, duration, hash and footprint; rbc shelf lists it without a robot", async () => {
    const empty = await runInProcess(["shelf"], { env });
    expect(empty.code).toBe(0);
    expect(empty.stdout).toBe(
      `Nothing recorded yet: rbc upload records each motion it stores (${join(dir, "shelf.json")}).\n`,
    );

    const upload = await runInProcess(["upload", "examples/wave.rbm", "--demo"], { env });
    expect(upload.code, upload.stderr).toBe(0);
    const file = JSON.parse(await readFile(join(dir, "shelf.json"), "utf8"));
    expect(file).toMatchObject({
      format: "rbc-shelf",
      version: 1,
      robots: [
        {
          robot: "serial:8958899989309",
          slots: [{ slot: 1, motionNumber: 12, name: "RbcPanel_Wave", durationMs: 3200, footprint: 640 }],
        },
      ],
    });
    expect(file.robots[0].slots[0].hash).toMatch(/^[0-9a-f]{64}$/);

    const listed = await runInProcess(["shelf"], { env });
    expect(listed.stdout).toMatch(/not read from the robots/);
    expect(listed.stdout).toMatch(
      /Robot 8958899989309:\n {2}12 {2}key 1 {7}RbcPanel_Wave {2}3\.2 s {2}stored 20\d\d-/,
    );
    const json = JSON.parse((await runInProcess(["shelf", "--json"], { env })).stdout);
    expect(json.robots[0].slots[0]).toMatchObject({ motionNumber: 12, remoteKey: { star: false, key: "1" } });
  });

  it("checked against a robot whose memory is empty (a new demo robot): the slot is forgotten, and the file says so", async () => {
    await runInProcess(["upload", "examples/wave.rbm", "--demo"], { env });
    const checked = await runInProcess(["shelf", "--demo", "--json"], { env });
    expect(checked.code, checked.stderr).toBe(0);
    expect(JSON.parse(checked.stdout)).toMatchObject({
      robot: "serial:8958899989309",
      slots: [],
      freeMotionBytes: 24_576,
      dropped: [1],
      checked: true,
    });
    const text = await runInProcess(["shelf", "--demo"], { env });
    // Already forgotten: nothing left to drop.
    expect(text.stdout).toContain("Nothing recorded that this robot may still hold.");
    const file = JSON.parse(await readFile(join(dir, "shelf.json"), "utf8"));
    expect(file.robots).toEqual([]);
  });

  it("a file that is not a shelf is never overwritten: rbc shelf refuses it, an upload still succeeds and says it was not recorded", async () => {
    const path = join(dir, "shelf.json");
    await writeFile(path, "{ not json");
    const listed = await runInProcess(["shelf"], { env });
    expect(listed.code).toBe(1);
    expect(listed.stderr).toBe(
      `rbc: ${path} is not an rbc shelf file; it was left as it is and nothing is recorded until it is moved away.\n`,
    );
    const upload = await runInProcess(["upload", "examples/wave.rbm", "--demo"], { env });
    expect(upload.code).toBe(0);
    expect(upload.stderr).toContain("The motion is stored, but rbc could not record it on its shelf:");
    expect(await readFile(path, "utf8")).toBe("{ not json");
  });
});
