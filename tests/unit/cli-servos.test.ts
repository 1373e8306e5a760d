import { describe, expect, it } from "vitest";
import { runInProcess } from "../cli/in-process.ts";

/**
 * `rbc servos` in process on the demo robot (virtual clock), with the servo-bus faults of RBC_DEMO_VARIANT
 * (issue 22 item 4): the scan's JSON shape and exit code on each fault, the guided id fix refused and done.
 */

const variant = (v: string) => ({ env: { RBC_DEMO_VARIANT: v } });

describe("rbc servos scan", () => {
  it("a healthy demo robot: JSON with 16 answered servos and no findings, exit 0", async () => {
    const r = await runInProcess(["servos", "scan", "--demo", "--json"]);
    expect(r.code).toBe(0);
    const json = JSON.parse(r.stdout);
    expect(Object.keys(json)).toEqual(["servos", "findings"]);
    expect(json.servos).toHaveLength(16);
    expect(json.servos[0]).toEqual({ id: 0, status: "answered", position: 125, load: 0 });
    expect(json.findings).toEqual([]);
  });

  it("--repeat-replies (the homebrew build): the scan says the firmware repeats its reply and reads no servo, exit 1", async () => {
    const r = await runInProcess(["servos", "scan", "--demo", "--json"], variant("--repeat-replies"));
    expect(r.code).toBe(1);
    const json = JSON.parse(r.stdout);
    expect(json.servos).toEqual([]);
    expect(json.findings).toEqual([]);
    expect(json.stopped).toMatchObject({ code: "firmware-sends-packets", type: 0x16 });
    expect(json.stopped.message).toContain("keeps sending packets nobody asked for (type 0x16)");
    expect(json.stopped.message).not.toContain("two servos");
    const human = await runInProcess(["servos", "scan", "--demo"], variant("--repeat-replies"));
    expect(human.stdout).toContain("The scan stopped: The robot's firmware keeps sending packets");
    expect(human.stdout).not.toContain("answered by two servos");
  });

  it("--servo-missing 7: silent, the finding worded with the robot's own right, exit 1", async () => {
    const r = await runInProcess(["servos", "scan", "--demo", "--json"], variant("--servo-missing 7"));
    expect(r.code).toBe(1);
    const json = JSON.parse(r.stdout);
    expect(json.servos[7]).toEqual({ id: 7, status: "silent" });
    expect(json.findings).toEqual([
      {
        code: "servo-missing",
        ids: [7],
        message: "Servo 7 (Right knee) does not answer: check its cable and the one before it in the chain.",
      },
    ]);
  });

  it("--servo-duplicate 3: garbled with its bytes, servo-duplicate, exit 1; the table shows the bytes", async () => {
    const r = await runInProcess(["servos", "scan", "--demo", "--json"], variant("--servo-duplicate 3"));
    expect(r.code).toBe(1);
    const json = JSON.parse(r.stdout);
    expect(json.servos[3]).toEqual({ id: 3, status: "garbled", bytes: [0, 0, 88] });
    expect(json.findings.map((f: { code: string }) => f.code)).toEqual(["servo-duplicate"]);
    const human = await runInProcess(["servos", "scan", "--demo"], variant("--servo-duplicate 3"));
    expect(human.stdout).toMatch(/^ {3}3 {2}Left ankle pitch {6}garbled \(00 00 58\)$/m);
    expect(human.stdout).toMatch(/^ {3}4 {2}Left ankle roll {7}answered {17}108 {5}0$/m);
    expect(human.stdout).toContain("Id 3 is answered by two servos at once");
  });

  it("--servo-replacement 12 then set-id 0 12: refused while two servos answer at id 0 (exit 1, the reason)", async () => {
    const scan = await runInProcess(
      ["servos", "scan", "--demo", "--json"],
      variant("--servo-replacement 12"),
    );
    expect(scan.code).toBe(1);
    expect(
      JSON.parse(scan.stdout).findings.map((f: { code: string; ids: number[] }) => [f.code, f.ids]),
    ).toEqual([["servo-replacement", [0, 12]]]);
    const fix = await runInProcess(
      ["servos", "set-id", "0", "12", "--yes", "--demo"],
      variant("--servo-replacement 12"),
    );
    expect(fix.code).toBe(1);
    expect(fix.stdout).toContain("Not changed: more than one servo answers at id 0");
  });

  it("--servo-loaded 4: answered (exit 0) with the high-load finding; Korean table headers", async () => {
    const r = await runInProcess(["servos", "scan", "--demo", "--lang", "ko"], variant("--servo-loaded 4"));
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(/ID\s+관절\s+상태\s+위치\s+부하/);
    expect(r.stdout).toContain("서보 4번(왼쪽 발목 좌우)이 쉬고 있는데도 부하가 높아요 (180)");
  });

  it("bad --ids: a usage error (exit 2), nothing sent", async () => {
    const r = await runInProcess(["servos", "scan", "--ids", "3-40", "--demo"]);
    expect(r.code).toBe(2);
  });
});

describe("rbc servos set-id, info, wiggle", () => {
  it("set-id 0 30 --yes: done, with what was read", async () => {
    const r = await runInProcess(["servos", "set-id", "0", "30", "--yes", "--demo", "--json"]);
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout)).toMatchObject({ outcome: "done", from: 0, to: 30 });
  });

  it("set-id 1 2: refused, a servo answers at id 2 (exit 1)", async () => {
    const r = await runInProcess(["servos", "set-id", "1", "2", "--yes", "--demo"]);
    expect(r.code).toBe(1);
    expect(r.stdout).toContain("Not changed: a servo already answers at id 2.");
  });

  it("set-id without --yes and no terminal: refused before connecting", async () => {
    const r = await runInProcess(["servos", "set-id", "0", "30", "--demo"]);
    expect(r.code).toBe(1);
    expect(r.stderr).toContain("Add --yes");
  });

  it("info 2: the parameters in the manual's byte order", async () => {
    const r = await runInProcess(["servos", "info", "2", "--demo"]);
    expect(r.code).toBe(0);
    expect(r.stdout).toContain("bounds (lower, upper): 1, 254");
    expect(r.stdout).toContain("P and D gains: P 20, D 30");
  });

  it("wiggle 4 on a loaded servo: not followed, exit 1", async () => {
    const r = await runInProcess(["servos", "wiggle", "4", "--yes", "--demo"], variant("--servo-loaded 4"));
    expect(r.code).toBe(1);
    expect(r.stdout).toContain("Servo 4 (Left ankle roll) did not follow the wiggle");
  });
});

describe("the servo doctor's words", () => {
  it("name servos 0-15 by the joint-name catalogue (the robot's own left and right), in both languages", async () => {
    const { servoText } = await import("../../src/i18n/outcomes/servos/servo-words.ts");
    expect(servoText(7, "en")).toBe("Servo 7 (Right knee)");
    expect(servoText(7, "ko")).toBe("서보 7번(오른쪽 무릎)");
    expect(servoText(10, "ko")).toBe("서보 10번(왼쪽 어깨 앞뒤)");
    expect(servoText(16, "en")).toBe("Servo 16");
  });
});
