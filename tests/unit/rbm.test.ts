import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { HUNO_JOINT_NAMES } from "../../src/i18n/joint-names/huno-joint-names.ts";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import { rbmIssueText } from "../../src/i18n/outcomes/rbm/rbm-issue-text.ts";
import { ProtocolError } from "../../src/protocol/errors.ts";
import {
  motionDurationMs,
  parseRbm,
  RbmError,
  type RbmMotion,
  rbmFieldCount,
  serializeRbm,
  validateRbm,
} from "../../src/protocol/rbm.ts";
import { HUNO_BASIC_POSTURE, SAFE_LOWER, SAFE_UPPER } from "../../src/protocol/servo-limits.ts";
import { EXAMPLE_NAMES, exampleText } from "../data/project-data.ts";

// The project's own motions (examples/, MIT). Checks on the third-party Motionbuilder samples are in
// tests/interop/ (run only where those files are present beside the repository).
/** examples/wave.rbm: 16 servos, 6 scenes; the file most tests below edit. */
const WAVE = exampleText("wave.rbm");
const W = 16;

/** Field numbers in a W = 16 file: header h, servo record i field j, scene k header j, scene k record i field j. */
const servoField = (i: number, j: number) => 13 + 6 * i + j;
const sceneField = (k: number, j: number) => 13 + 6 * W + k * (5 + 6 * W) + j;
const recordField = (k: number, i: number, j: number) => sceneField(k, 5 + 6 * i + j);

/** Replaces fields of an .rbm text: edit(text, [index, value], ...). */
function edit(text: string, ...changes: [number, string][]): string {
  const f = text.split(":");
  for (const [index, value] of changes) f[index] = value;
  return f.join(":");
}

function parseError(text: string): RbmError {
  try {
    parseRbm(text);
  } catch (e) {
    expect(e).toBeInstanceOf(RbmError);
    return e as RbmError;
  }
  throw new Error("parseRbm accepted the text");
}

const parseWave = (): RbmMotion => parseRbm(WAVE);
const codes = (issues: { code: string }[]) => issues.map((i) => i.code);

describe("parseRbm on the examples", () => {
  it("finds the five examples", () => {
    expect(EXAMPLE_NAMES).toHaveLength(5);
  });

  it.each(EXAMPLE_NAMES)(
    "%s parses, has 13 + 6W + S(5 + 6W) fields and round-trips byte for byte",
    (name) => {
      const text = exampleText(name);
      const motion = parseRbm(text);
      const w = motion.servos.length;
      expect(w).toBe(name === "arms-only.rbm" ? 6 : 16);
      expect(motion.servoCount).toBe(w);
      expect(motion.sceneCount).toBe(motion.scenes.length);
      expect(text.split(":").length - 1).toBe(rbmFieldCount(w, motion.scenes.length));
      expect(text.split(":").length - 1).toBe(13 + 6 * w + motion.scenes.length * (5 + 6 * w));
      expect(motion.raw).toBeUndefined(); // every example uses the canonical widths
      expect(validateRbm(motion).errors).toEqual([]);
      expect(serializeRbm(motion)).toBe(text);
    },
  );

  it("reads wave.rbm's fields", () => {
    const m = parseWave();
    expect(m).toMatchObject({
      format: 1,
      serialNumber: "0000000000000",
      text1: "RBC_Panel_",
      text2: "RBC Panel examples",
      name: "RbcPanel_Wave",
      motionIndex: 0,
      platform: 1,
      sceneCount: 6,
      unknown10: 2,
      servoCount: 16,
      unknown12: 4,
    });
    expect(m.servos[0]).toEqual({ id: 0, p: 30, d: 50, i: 0, portEnable: 0, zero: 125 });
    expect(m.servos[10]).toEqual({ id: 10, p: 20, d: 30, i: 0, portEnable: 0, zero: 90 });
    expect(m.servos.map((s) => s.id)).toEqual([...Array(16).keys()]);
    const s1 = m.scenes[1]!;
    expect(s1).toMatchObject({ index: 1, name: "WaveOut", frames: 10, timeMs: 400 });
    expect(s1.servos[11]).toEqual({ id: 11, start: 80, end: 110, torque: 2, port: 0, reserved: 0 });
    expect(m.scenes[0]!.servos[10]).toEqual({ id: 10, start: 51, end: 160, torque: 2, port: 0, reserved: 0 });
    expect(m.scenes[0]!.servos.map((r) => r.start)).toEqual(HUNO_BASIC_POSTURE);
    expect(motionDurationMs(m)).toBe(3200);
  });

  it("keeps texts as they are (a trailing space in field 3, a 19-character field 4)", () => {
    const text = edit(WAVE, [3, "Panel HQ  "], [4, "www.example.invalid"]);
    const m = parseRbm(text);
    expect(m.text1).toBe("Panel HQ  ");
    expect(m.text2).toBe("www.example.invalid");
    expect(serializeRbm(m)).toBe(text);
  });

  // Playback time = the sum of the scenes' times (docs/protocol.md §7).
  it.each([
    ["wave.rbm", 6, 3200],
    ["bow.rbm", 4, 3200],
    ["squat.rbm", 8, 7200],
    ["long-walk.rbm", 284, 18_600],
    ["arms-only.rbm", 7, 4800],
  ] as const)("%s (%i scenes) lasts %i ms", (name, scenes, ms) => {
    const m = parseRbm(exampleText(name));
    expect(m.name.startsWith("RbcPanel_")).toBe(true);
    expect(m.scenes).toHaveLength(scenes);
    expect(motionDurationMs(m)).toBe(ms);
  });

  it("accepts the interval limits exactly (20 ms and 4,550 ms a frame)", () => {
    expect(() => parseRbm(edit(WAVE, [sceneField(0, 3), "1"], [sceneField(0, 4), "20"]))).not.toThrow();
    expect(() => parseRbm(edit(WAVE, [sceneField(0, 3), "1"], [sceneField(0, 4), "4550"]))).not.toThrow();
  });
});

describe("round trip of non-canonical texts", () => {
  it("keeps digits written with other widths, and trailing whitespace", () => {
    const text = `${edit(WAVE, [servoField(3, 0), "3"], [recordField(2, 5, 2), "0126"], [sceneField(1, 4), "0400"], [9, "06"])}\r\n`;
    const m = parseRbm(text);
    expect(m.servos[3]!.id).toBe(3);
    expect(m.scenes[2]!.servos[5]!.start).toBe(126);
    expect(m.scenes[1]!.timeMs).toBe(400);
    expect(m.raw).toEqual({
      fields: { h9: "06", "s3.id": "3", "c1.timeMs": "0400", "c2.r5.start": "0126" },
      trailing: "\r\n",
    });
    expect(serializeRbm(m)).toBe(text);
  });

  it("writes the canonical width once a value changes", () => {
    const m = parseRbm(edit(WAVE, [recordField(2, 5, 2), "0126"]));
    m.scenes[2]!.servos[5]!.start = 7;
    expect(serializeRbm(m).split(":")[recordField(2, 5, 2)]).toBe("007");
  });

  it("writes a motion built in code with the canonical widths and derived lengths", () => {
    const m = parseWave();
    const built: RbmMotion = {
      ...m,
      sceneCount: undefined,
      servoCount: undefined,
      scenes: m.scenes.map((s) => ({ ...s, servos: s.servos.map(({ reserved: _r, ...rest }) => rest) })),
    };
    expect(serializeRbm(built)).toBe(WAVE);
  });

  it("refuses to write what an .rbm file cannot hold", () => {
    const m = parseWave();
    m.name = "a:b";
    expect(() => serializeRbm(m)).toThrow(RbmError);
    const n = parseWave();
    n.scenes[0]!.timeMs = -5;
    try {
      serializeRbm(n);
      expect.unreachable();
    } catch (e) {
      expect((e as RbmError).code).toBe("rbm-unwritable");
    }
  });
});

describe("parseRbm errors", () => {
  const cases: [string, string, string, RegExp][] = [
    ["empty text", "rbm-empty", "", /empty/],
    ["no final colon", "rbm-end", WAVE.slice(0, -1), /end/],
    ["header only", "rbm-field-count", "1:13:0000000000000:", /only 3 fields/],
    [
      "truncated mid-record",
      "rbm-field-count",
      WAVE.slice(0, WAVE.lastIndexOf("0:0:15:205")),
      /truncated or damaged/,
    ],
    [
      "an extra field",
      "rbm-field-count",
      `${WAVE}0:`,
      /has 716 fields, but a motion with 16 servos and 6 scenes has 715/,
    ],
    ["letter in frames", "rbm-not-a-number", edit(WAVE, [sceneField(1, 3), "4O"]), /scene 1: frames.*"4O"/],
    ["negative start", "rbm-not-a-number", edit(WAVE, [recordField(0, 0, 2), "-12"]), /start position/],
    ["space before a number", "rbm-not-a-number", edit(WAVE, [recordField(0, 0, 2), " 125"]), /whole number/],
    ["serial length field", "rbm-length-mismatch", edit(WAVE, [1, "12"]), /serial number/],
    ["name length field", "rbm-length-mismatch", edit(WAVE, [5, "12"]), /motion name/],
    ["scene name length field", "rbm-length-mismatch", edit(WAVE, [sceneField(2, 1), "08"]), /scene 2/],
    ["W = 0", "rbm-servo-count", edit(WAVE, [11, "0"]), /0 servos; a motion has 1 to 31/],
    ["W = 32", "rbm-servo-count", edit(WAVE, [11, "32"]), /32 servos/],
    ["servo id 31", "rbm-servo-id", edit(WAVE, [servoField(4, 0), "31"]), /id 31; servo ids go from 0 to 30/],
    ["servo id repeated", "rbm-servo-id", edit(WAVE, [servoField(4, 0), "03"]), /listed twice/],
    [
      "scene record id out of order",
      "rbm-servo-id",
      edit(WAVE, [recordField(3, 7, 1), "08"]),
      /scene records must follow the servo list/,
    ],
    [
      "end position 255",
      "rbm-position",
      edit(WAVE, [recordField(2, 3, 3), "255"]),
      /Scene 2: the end position of servo 3 .* is 255/,
    ],
    ["zero position 300", "rbm-position", edit(WAVE, [servoField(2, 5), "300"]), /zero position/],
    ["torque 5", "rbm-torque", edit(WAVE, [recordField(1, 0, 4), "5"]), /torque/],
    ["port 4", "rbm-port", edit(WAVE, [recordField(1, 0, 5), "4"]), /port/],
    ["0 frames", "rbm-frames", edit(WAVE, [sceneField(0, 3), "0"]), /Scene 0 has 0 frames/],
    [
      "8 ms frames",
      "rbm-frame-interval-short",
      edit(WAVE, [sceneField(2, 4), "80"]),
      /frames 8 ms apart.*at least 20 ms/,
    ],
    ["16.7 ms frames", "rbm-frame-interval-short", edit(WAVE, [sceneField(1, 3), "24"]), /16\.7 ms apart/],
    [
      "4,551 ms frames",
      "rbm-frame-interval-long",
      edit(WAVE, [sceneField(0, 3), "1"], [sceneField(0, 4), "4551"]),
      /4,?550/,
    ],
    [
      "scene index skipped",
      "rbm-scene-index",
      edit(WAVE, [sceneField(3, 0), "004"]),
      /Scene 3 is numbered 4/,
    ],
    ["P gain 256", "rbm-out-of-range", edit(WAVE, [servoField(0, 1), "256"]), /one byte/],
  ];

  it.each(cases)("%s → %s", (_label, code, text, message) => {
    const e = parseError(text);
    expect(e).toBeInstanceOf(ProtocolError);
    expect(e.name).toBe("RbmError");
    expect(e.code).toBe(code);
    expect(errorText(e, "en")).toMatch(message);
    expect(e.message).toMatch(new RegExp(`^${code}\\b`));
    expect(e.issues.length).toBeGreaterThan(0);
  });

  it("lists every problem in the error's issues", () => {
    const e = parseError(edit(WAVE, [recordField(1, 0, 4), "5"], [recordField(1, 1, 5), "9"]));
    expect(codes([...e.issues])).toEqual(["rbm-torque", "rbm-port"]);
    expect(e.issues[1]).toMatchObject({ scene: 1, servo: 1 });
    expect(errorText(e, "en")).toMatch(/\(1 more problem found\)$/);
    expect(e.message).toMatch(/\(\+1 more\)$/);
  });
});

describe("validateRbm", () => {
  const warningsOf = (text: string, connectedSerialNumber?: string) =>
    validateRbm(parseRbm(text), connectedSerialNumber === undefined ? {} : { connectedSerialNumber })
      .warnings;

  it("finds nothing wrong with wave.rbm", () => {
    expect(validateRbm(parseWave(), { connectedSerialNumber: "8958899989309" })).toEqual({
      errors: [],
      warnings: [],
    });
  });

  it("warns when a scene starts where the previous one did not end", () => {
    const w = warningsOf(edit(WAVE, [recordField(1, 10, 2), "060"]));
    expect(w).toEqual([
      {
        code: "rbm-scene-jump",
        scene: 1,
        servo: 10,
        message: "rbm-scene-jump (scene 1, servo 10, start 60, previous 0, end 160)",
        values: { scene: 1, servo: 10, start: 60, previous: 0, end: 160 },
      },
    ]);
    expect(rbmIssueText(w[0]!, "en")).toBe(
      "Scene 1 starts servo 10 (Left shoulder pitch) at 60, but scene 0 ended it at 160; the servo will jump.",
    );
  });

  it("warns about positions outside the safe ranges", () => {
    const w = warningsOf(edit(WAVE, [recordField(0, 2, 3), "100"]));
    expect(w[0]).toMatchObject({ code: "rbm-unsafe-position", scene: 0, servo: 2 });
    expect(rbmIssueText(w[0]!, "en")).toMatch(/Left knee\) goes to 100, outside its safe range 124-254/);
    expect(codes(w)).toContain("rbm-scene-jump"); // scene 1 starts at 199 again
  });

  it("warns about header fields 0, 8, 10, 12 that are not 1, 1, 2, 4", () => {
    const w = warningsOf(edit(WAVE, [0, "2"], [8, "3"], [10, "5"], [12, "7"]));
    expect(codes(w)).toEqual(Array(4).fill("rbm-header-constant"));
    expect(w.map((x) => rbmIssueText(x, "en")).join(" ")).toMatch(/Field 0.*Field 8.*Field 10.*Field 12/);
  });

  it("warns about scenes beyond Motionbuilder's limits", () => {
    expect(warningsOf(edit(WAVE, [sceneField(1, 3), "120"], [sceneField(1, 4), "3000"]))).toEqual([
      expect.objectContaining({ code: "rbm-many-frames", scene: 1 }),
    ]);
    expect(warningsOf(edit(WAVE, [sceneField(1, 4), "12000"]))).toEqual([
      expect.objectContaining({ code: "rbm-long-scene", scene: 1 }),
    ]);
  });

  it("warns when the serial number is neither zeros nor the connected robot's", () => {
    const text = edit(WAVE, [2, "8958899989309"]); // made for 8958899989309
    expect(codes(warningsOf(text, "8958899989300"))).toEqual(["rbm-serial-mismatch"]);
    expect(warningsOf(text, "8958899989309")).toEqual([]);
    expect(warningsOf(text)).toEqual([]);
    expect(warningsOf(WAVE, "8958899989300")).toEqual([]); // zeros: made for any robot
    expect(codes(warningsOf(edit(WAVE, [1, "5"], [2, "12345"])))).toEqual(["rbm-serial-format"]);
  });

  it("warns when a HUNO motion does not have 16 servos", () => {
    const m = parseWave();
    const fewer: RbmMotion = {
      ...m,
      servoCount: 15,
      servos: m.servos.slice(0, 15),
      scenes: m.scenes.map((s) => ({ ...s, servos: s.servos.slice(0, 15) })),
    };
    const v = validateRbm(fewer);
    expect(v.errors).toEqual([]);
    expect(codes(v.warnings)).toEqual(["rbm-huno-servo-count"]);
    expect(parseRbm(serializeRbm(fewer))).toEqual(fewer);
  });

  it("reports the errors of a motion built in code", () => {
    const m = parseWave();
    m.servoCount = 17;
    m.sceneCount = 4;
    m.name = "Wave:there";
    m.scenes[4]!.servos.pop();
    expect(codes(validateRbm(m).errors)).toEqual([
      "rbm-text",
      "rbm-servo-count",
      "rbm-scene-count",
      "rbm-servo-count",
    ]);
    const empty = { ...parseWave(), servos: [], servoCount: undefined, scenes: [], sceneCount: undefined };
    // No servos and no scenes: both are errors (docs/protocol.md §7: S = 0 is one).
    expect(codes(validateRbm(empty).errors)).toEqual(["rbm-servo-count", "rbm-no-scenes"]);
  });

  it("reports values of the wrong type in words instead of throwing", () => {
    const m = parseWave();
    (m.scenes[2]!.servos[3] as { end: unknown }).end = 12.5;
    (m as { text1: unknown }).text1 = 5;
    const { errors } = validateRbm(m);
    const notANumber = {
      code: "rbm-not-a-number",
      scene: 2,
      message: "rbm-not-a-number (kind shape, path scenes.2.servos.3.end, got value, value 12.5)",
      values: { kind: "shape", path: "scenes.2.servos.3.end", got: "value", value: "12.5" },
    };
    expect(errors).toContainEqual(notANumber);
    expect(rbmIssueText(notANumber, "en")).toBe(
      "scene 2, servo record 3, end must be a whole number of 0 or more (it is 12.5).",
    );
    const text1 = errors.find((e) => e.code === "rbm-shape");
    expect(text1 && rbmIssueText(text1, "en")).toMatch(/text1 must be text/);
    expect(codes(validateRbm(null as unknown as RbmMotion).errors)).toEqual(["rbm-shape"]);
    const n = parseWave();
    (n.scenes[0] as { timeMs: unknown }).timeMs = "500";
    (n as { format: unknown }).format = 1n;
    expect(validateRbm(n).errors.map((e) => rbmIssueText(e, "en"))).toEqual([
      "format must be a whole number of 0 or more (it is 1).",
      'scene 0, timeMs must be a whole number of 0 or more (it is "500").',
    ]);
  });
});

describe("servo limits", () => {
  it("has 16 entries per table, lower below upper, and the basic posture inside", () => {
    for (const table of [SAFE_UPPER, SAFE_LOWER, HUNO_BASIC_POSTURE, HUNO_JOINT_NAMES])
      expect(table).toHaveLength(16);
    HUNO_BASIC_POSTURE.forEach((p, id) => {
      expect(p).toBeGreaterThanOrEqual(SAFE_LOWER[id]!);
      expect(p).toBeLessThanOrEqual(SAFE_UPPER[id]!);
    });
  });
});

describe("parseRbm on damaged input (fuzz)", () => {
  const texts = EXAMPLE_NAMES.map(exampleText);
  const mutation = fc.oneof(
    fc.record({
      op: fc.constant("replace" as const),
      at: fc.nat(),
      ch: fc.constantFrom(":", "0", "9", "x", " ", "-", "\n"),
    }),
    fc.record({
      op: fc.constant("insert" as const),
      at: fc.nat(),
      ch: fc.constantFrom(":", "0", "1", "5", "Z", "\r"),
    }),
    fc.record({ op: fc.constant("delete" as const), at: fc.nat() }),
    fc.record({ op: fc.constant("truncate" as const), at: fc.nat() }),
    fc.record({ op: fc.constant("swap" as const), a: fc.nat(), b: fc.nat() }),
  );
  type Mutation = typeof mutation extends fc.Arbitrary<infer T> ? T : never;

  function apply(text: string, m: Mutation): string {
    const at = "at" in m ? m.at % (text.length + 1) : 0;
    switch (m.op) {
      case "replace":
        return text.slice(0, at) + m.ch + text.slice(at + 1);
      case "insert":
        return text.slice(0, at) + m.ch + text.slice(at);
      case "delete":
        return text.slice(0, at) + text.slice(at + 1);
      case "truncate":
        return text.slice(0, at);
      case "swap": {
        const f = text.split(":");
        const i = m.a % f.length;
        const j = m.b % f.length;
        [f[i], f[j]] = [f[j]!, f[i]!];
        return f.join(":");
      }
    }
  }

  function check(text: string): void {
    let motion: RbmMotion;
    try {
      motion = parseRbm(text);
    } catch (e) {
      expect(e).toBeInstanceOf(RbmError);
      expect(typeof (e as RbmError).code).toBe("string");
      expect((e as RbmError).code).toMatch(/^rbm-/);
      return;
    }
    // Whatever parses is usable and reproduces its text exactly.
    expect(validateRbm(motion).errors).toEqual([]);
    expect(serializeRbm(motion)).toBe(text);
  }

  it("returns a motion or throws an RbmError for mutated examples", () => {
    fc.assert(
      fc.property(
        fc.constantFrom(...texts),
        fc.array(mutation, { minLength: 1, maxLength: 4 }),
        (text, ms) => {
          check(ms.reduce(apply, text));
        },
      ),
      { numRuns: 300 },
    );
  });

  it("returns a motion or throws an RbmError for arbitrary strings", () => {
    fc.assert(fc.property(fc.oneof(fc.string(), fc.stringMatching(/^[0-9:]{0,200}$/)), check), {
      numRuns: 300,
    });
  });

  it("handles long runs of whitespace and separators quickly", () => {
    const start = Date.now();
    for (const text of [`${" ".repeat(200_000)}x`, ":".repeat(200_000), `1:13:${"9".repeat(100_000)}:`])
      check(text);
    expect(Date.now() - start).toBeLessThan(2000);
  });
});
