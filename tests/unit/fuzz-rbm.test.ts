/**
 * Fuzzing parseRbm (docs/protocol.md §7) harder than rbm.test.ts's fuzz section, which mutates a handful of
 * examples with a seven-character alphabet and times only three long inputs. Here: all the project's example
 * motions (examples/*.rbm, from 6 to 284 scenes, 6 or 16 servos); field-level
 * mutations with hostile tokens (huge and negative numbers, exponents, hex, non-ASCII digits, NUL, thousands of
 * digits), the scene and servo counts and the length fields in particular; numeric nudges that keep a file
 * parseable but break a rule; structural edits (fields deleted, duplicated, swapped, inserted); character
 * edits over the whole of Unicode; arbitrary text. Every input runs in a worker with a hard time limit
 * (tests/support/time-box.ts), so a hang fails the test instead of freezing it.
 *
 * Verdicts (tests/support/fuzz-targets.ts `checkRbm`): an RbmError with an "rbm-" code, or a motion that
 * validates without errors, serializes back to the very same text and encodes as a motion image (or refuses
 * with an RbmError). Anything else — another exception, an accepted invalid motion — is a violation. The hard
 * limit only tells a hang from an answer; how long the check takes is measured by bench/rbm-check.ts.
 */
import fc from "fast-check";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { EXAMPLE_NAMES, exampleText } from "../data/project-data.ts";
import { hostileRbmInputs } from "../support/rbm-hostile.ts";
import { TimeBox } from "../support/time-box.ts";

/** The seeds: the project's example motions (wave.rbm first). */
const TEXTS = EXAMPLE_NAMES.map(exampleText);

/** Hard limit per input: an input still running after it is a hang (a speed is the bench's to measure). */
const HANG_MS = 3000;
/**
 * A property's whole run: hundreds of parses, CPU-bound, so its time follows the machine's load (the 600
 * mutated examples took 4.5 s alone and over 10 s with two suites on a 2-core machine). A hang is caught per
 * input by HANG_MS; this only bounds the whole.
 */
const PROPERTY_MS = 60_000;

const HOSTILE = [
  "",
  "0",
  "-1",
  "+1",
  "1e3",
  "1.5",
  "0x1F",
  " 7",
  "7 ",
  "NaN",
  "Infinity",
  "4294967296",
  "18446744073709551616",
  "9".repeat(400),
  "0".repeat(50),
  "\u0000",
  "٣",
  "１６",
  "𝟙",
  "é",
  "\r\n",
  "::",
  "31",
  "32",
  "255",
  "99999",
];

/** Field numbers worth aiming at: the header's counts and lengths, and a few record fields. */
const TARGET_FIELDS = [
  0, 1, 2, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 18, 109, 110, 112, 113, 114, 115, 116, 117, 118,
];

type Edit =
  | { op: "token"; field: number; token: string }
  | { op: "nudge"; field: number; by: number }
  | { op: "delete" | "duplicate"; field: number }
  | { op: "swap"; a: number; b: number }
  | { op: "insert"; field: number; token: string }
  | { op: "char"; at: number; text: string }
  | { op: "truncate"; at: number };

const field = fc.oneof(fc.constantFrom(...TARGET_FIELDS), fc.nat());
const edit: fc.Arbitrary<Edit> = fc.oneof(
  {
    arbitrary: fc.record({ op: fc.constant("token" as const), field, token: fc.constantFrom(...HOSTILE) }),
    weight: 4,
  },
  {
    arbitrary: fc.record({
      op: fc.constant("nudge" as const),
      field,
      by: fc.integer({ min: -300, max: 300 }),
    }),
    weight: 4,
  },
  {
    arbitrary: fc.record({ op: fc.constantFrom("delete" as const, "duplicate" as const), field }),
    weight: 2,
  },
  { arbitrary: fc.record({ op: fc.constant("swap" as const), a: field, b: field }), weight: 1 },
  {
    arbitrary: fc.record({ op: fc.constant("insert" as const), field, token: fc.constantFrom(...HOSTILE) }),
    weight: 1,
  },
  {
    arbitrary: fc.record({
      op: fc.constant("char" as const),
      at: fc.nat(),
      text: fc.string({ unit: "binary", minLength: 0, maxLength: 3 }),
    }),
    weight: 2,
  },
  { arbitrary: fc.record({ op: fc.constant("truncate" as const), at: fc.nat() }), weight: 1 },
);

function apply(text: string, e: Edit): string {
  if (e.op === "char") {
    const at = e.at % (text.length + 1);
    return text.slice(0, at) + e.text + text.slice(at + 1);
  }
  if (e.op === "truncate") return text.slice(0, e.at % (text.length + 1));
  const f = text.split(":");
  const i = (n: number) => n % f.length;
  switch (e.op) {
    case "token":
      f[i(e.field)] = e.token;
      break;
    case "nudge": {
      const k = i(e.field);
      const v = Number(f[k]);
      if (Number.isFinite(v)) f[k] = String(Math.max(0, v + e.by)).padStart(f[k]!.length, "0");
      break;
    }
    case "delete":
      f.splice(i(e.field), 1);
      break;
    case "duplicate":
      f.splice(i(e.field), 0, f[i(e.field)]!);
      break;
    case "insert":
      f.splice(i(e.field), 0, e.token);
      break;
    case "swap": {
      const a = i(e.a);
      const b = i(e.b);
      [f[a], f[b]] = [f[b]!, f[a]!];
      break;
    }
  }
  return f.join(":");
}

describe("parseRbm fuzz (time-boxed)", () => {
  let box: TimeBox;
  beforeAll(async () => {
    box = await TimeBox.start();
  });
  afterAll(async () => {
    await box.stop();
  });

  const check = async (text: string) => {
    const { verdict } = await box.run("checkRbm", text, HANG_MS);
    if (verdict.kind === "violation")
      throw new Error(`${verdict.detail} for ${JSON.stringify(text.slice(0, 300))}`);
    return verdict;
  };

  it("every example parses (control)", async () => {
    for (const text of TEXTS) expect((await check(text)).kind).toBe("ok");
  });

  it("mutated examples: an RbmError with an rbm- code, or a motion that validates and round-trips", {
    timeout: PROPERTY_MS,
  }, async () => {
    const seen = new Map<string, number>();
    await fc.assert(
      fc.asyncProperty(
        fc.constantFrom(...TEXTS),
        fc.array(edit, { minLength: 1, maxLength: 5 }),
        async (text, edits) => {
          const verdict = await check(edits.reduce(apply, text));
          const key = verdict.kind === "typed-error" ? verdict.code : verdict.kind;
          seen.set(key, (seen.get(key) ?? 0) + 1);
        },
      ),
      { numRuns: 600 },
    );
    // The mutations reach deep into the validator, and some mutants are still good files.
    expect(seen.size).toBeGreaterThanOrEqual(8);
    expect(seen.get("ok") ?? 0).toBeGreaterThan(0);
  });

  it("arbitrary text, including whole-Unicode and digit-colon soup", { timeout: PROPERTY_MS }, async () => {
    await fc.assert(
      fc.asyncProperty(
        fc.oneof(
          fc.string({ unit: "binary", maxLength: 300 }),
          fc.stringMatching(/^[0-9:]{0,300}$/),
          fc.array(fc.constantFrom(...HOSTILE), { maxLength: 60 }).map((f) => `${f.join(":")}:`),
        ),
        async (text) => {
          await check(text);
        },
      ),
      { numRuns: 400 },
    );
  });

  it("huge declared counts and huge inputs: a typed error, never a hang or another exception", {
    timeout: PROPERTY_MS,
  }, async () => {
    for (const { name, text } of hostileRbmInputs(TEXTS[0]!, TEXTS)) {
      // None of them is a motion the robot could hold: each is refused with its code.
      expect((await check(text)).kind, name).toBe("typed-error");
    }
  });

  it("the time box itself catches a hang", async () => {
    const spinBox = await TimeBox.start();
    await expect(spinBox.run("spin", "5000", 200)).rejects.toThrow(/did not finish within 200 ms/);
    await spinBox.stop();
  });
});
