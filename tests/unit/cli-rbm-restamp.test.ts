/**
 * `rbc rbm restamp` in process (issue 23 item 4): the serial number written from --serial, --zeros and the demo
 * robot (virtual clock), the output file compared with literal bytes, FILE never overwritten unless -o names it,
 * and the refusals (bad serial, corrupt file, conflicting or missing flags, a robot without a serial number, an
 * existing output) with nothing written. Help and a refusal in Korean.
 */
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterEach, beforeEach, describe, expect, it } from "vitest";
import { runInProcess } from "../cli/in-process.ts";

/** A one-servo, one-scene motion made for robot 1111122222333, with a Latin-1 byte (0xE9) in field 4. */
const FOR_ANOTHER = Buffer.from(
  "1:13:1111122222333:XXXXXXXXXX:Caf\u00e9XXXXXXXXXXXXXXXX:2:Hi:0:1:1:2:1:4:00:020:030:000:0:125:000:07:Scene_0:10:500:0:00:125:125:2:0:\r\n",
  "latin1",
);
const WITH = (serial: string) =>
  Buffer.from(FOR_ANOTHER.toString("latin1").replace("1111122222333", serial), "latin1");

let dir: string;
beforeEach(() => {
  dir = mkdtempSync(join(tmpdir(), "rbc-restamp-"));
  writeFileSync(join(dir, "dance.rbm"), FOR_ANOTHER);
});
afterEach(() => rmSync(dir, { recursive: true, force: true }));

const rbc = (argv: string[], env: NodeJS.ProcessEnv = {}) => runInProcess(argv, { cwd: dir, env });
const bytes = (name: string) => [...readFileSync(join(dir, name))];

describe("rbc rbm restamp", () => {
  it("--zeros: writes dance-zeros.rbm beside the file, only field 2 changed; the file itself untouched", async () => {
    const r = await rbc(["rbm", "restamp", "dance.rbm", "--zeros"]);
    expect(r.code).toBe(0);
    expect(bytes("dance-zeros.rbm")).toEqual([...WITH("0000000000000")]);
    expect(bytes("dance.rbm")).toEqual([...FOR_ANOTHER]);
    expect(r.stdout).toContain("Wrote dance-zeros.rbm (from dance.rbm).");
    expect(r.stdout).toContain(
      "Only the serial number (field 2) changed, from 1111122222333 to 0000000000000; every other byte of the file is as it was.",
    );
  });

  it("--serial N -o OUT, with --json", async () => {
    const r = await rbc([
      "rbm",
      "restamp",
      "dance.rbm",
      "--serial",
      "8958899989309",
      "-o",
      "mine.rbm",
      "--json",
    ]);
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout)).toEqual({
      ok: true,
      file: "dance.rbm",
      before: "1111122222333",
      after: "8958899989309",
      changed: true,
      source: "option",
      output: "mine.rbm",
    });
    expect(bytes("mine.rbm")).toEqual([...WITH("8958899989309")]);
  });

  it("--demo: takes the demo robot's serial number (8958899989309)", async () => {
    const r = await rbc(["rbm", "restamp", "dance.rbm", "--demo", "--json"]);
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout)).toMatchObject({ after: "8958899989309", source: "robot" });
    expect(bytes("dance-8958899989309.rbm")).toEqual([...WITH("8958899989309")]);
    expect(r.stderr).toContain("The serial number of the demo robot: 8958899989309.");
  });

  it("-o naming FILE itself replaces it; a file that already carries the serial is left as it is", async () => {
    const first = await rbc(["rbm", "restamp", "dance.rbm", "--zeros", "-o", "dance.rbm"]);
    expect(first.code).toBe(0);
    expect(bytes("dance.rbm")).toEqual([...WITH("0000000000000")]);
    const again = await rbc(["rbm", "restamp", "dance.rbm", "--zeros", "--json"]);
    expect(again.code).toBe(0);
    expect(JSON.parse(again.stdout)).toMatchObject({ changed: false, output: null });
    expect(readdirSync(dir)).toEqual(["dance.rbm"]);
  });
});

describe("rbc rbm restamp: refused, nothing written", () => {
  const untouched = () => {
    expect(readdirSync(dir)).toEqual(["dance.rbm"]);
    expect(bytes("dance.rbm")).toEqual([...FOR_ANOTHER]);
  };

  it("a serial number that is not 13 digits (exit 1, restamp-bad-serial)", async () => {
    const r = await rbc(["rbm", "restamp", "dance.rbm", "--serial", "12345", "--json"]);
    expect(r.code).toBe(1);
    expect(JSON.parse(r.stdout).error).toMatchObject({
      code: "restamp-bad-serial",
      message:
        'The serial number "12345" cannot be written into a motion file: it must be 13 digits (0-9). Nothing was written.',
    });
    untouched();
  });

  it("a corrupt file (truncated): exit 1 with the reader's code", async () => {
    writeFileSync(join(dir, "broken.rbm"), FOR_ANOTHER.subarray(0, 70));
    const r = await rbc(["rbm", "restamp", "broken.rbm", "--zeros", "--json"]);
    expect(r.code).toBe(1);
    expect(JSON.parse(r.stdout).error.code).toBe("rbm-end");
    expect(readdirSync(dir).sort()).toEqual(["broken.rbm", "dance.rbm"]);
  });

  it("a file that does not exist", async () => {
    const r = await rbc(["rbm", "restamp", "nope.rbm", "--zeros"]);
    expect(r.code).toBe(1);
    expect(r.stderr).toContain("Cannot read nope.rbm: no such file.");
  });

  it("--serial and --zeros together, neither (and no robot), no file, no action: usage errors (exit 2)", async () => {
    for (const argv of [
      ["rbm", "restamp", "dance.rbm", "--zeros", "--serial", "8958899989309"],
      ["rbm", "restamp", "dance.rbm"],
      ["rbm", "restamp"],
      ["rbm"],
      ["rbm", "stamp", "dance.rbm"],
    ]) {
      const r = await rbc(argv);
      expect(r.code, argv.join(" ")).toBe(2);
    }
    const neither = await rbc(["rbm", "restamp", "dance.rbm"]);
    expect(neither.stderr).toContain("Say which serial number to write");
    untouched();
  });

  it("a robot that reports no serial number: exit 1, says to use zeros", async () => {
    const r = await rbc(["rbm", "restamp", "dance.rbm", "--demo"], { RBC_DEMO_VARIANT: "--no-serial" });
    expect(r.code).toBe(1);
    expect(r.stderr).toContain("The robot does not report a serial number");
    untouched();
  });

  it("an existing file of the default name is left alone", async () => {
    writeFileSync(join(dir, "dance-zeros.rbm"), "keep me");
    const r = await rbc(["rbm", "restamp", "dance.rbm", "--zeros"]);
    expect(r.code).toBe(1);
    expect(r.stderr).toContain("dance-zeros.rbm exists already");
    expect(readFileSync(join(dir, "dance-zeros.rbm"), "utf8")).toBe("keep me");
  });
});

describe("rbc rbm in Korean", () => {
  it("help and a refusal", async () => {
    const help = await rbc(["rbm", "--help", "--lang", "ko"]);
    expect(help.stdout).toContain("restamp FILE: Motionbuilder는 시리얼 번호(2번 필드)가");
    const en = await rbc(["rbm", "--help"]);
    expect(en.stdout).toContain("--zeros");
    expect(en.stdout).toContain("FILE is never overwritten unless -o names it.");
    const r = await rbc(["rbm", "restamp", "dance.rbm", "--serial", "12", "--lang", "ko"]);
    expect(r.code).toBe(1);
    expect(r.stderr).toContain(
      '시리얼 번호 "12"은(는) 모션 파일에 쓸 수 없어요. 숫자(0-9) 13자리여야 해요. 아무것도 쓰지 않았어요.',
    );
    const ok = await rbc(["rbm", "restamp", "dance.rbm", "--zeros", "--lang", "ko"]);
    expect(ok.stdout).toContain("시리얼 번호(2번 필드)만 1111122222333에서 0000000000000(으)로 바뀌었어요.");
    expect(existsSync(join(dir, "dance-zeros.rbm"))).toBe(true);
  });
});
