/**
 * Fuzzing the zero-backup loader (src/protocol/zeros-backup.ts `parseZerosBackup`): arbitrary text, arbitrary JSON,
 * and valid backups with fields replaced, removed, added (including `__proto__`), zero tables of the wrong
 * length or with wrong values, and text-level damage. Every input runs in a time-boxed worker
 * (tests/support/time-box.ts). Verdicts (tests/support/fuzz-targets.ts `checkZerosBackup`): a refusal with one of
 * the documented problems and a message, or a backup that the zod schema accepts and whose zeros the RBC would
 * accept; a thrown exception of any kind is a violation.
 */
import fc from "fast-check";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { STANDARD_ZEROS, ZERO_TOLERANCE } from "../../src/protocol/zeros.ts";
import {
  createZerosBackup,
  parseZerosBackup,
  serializeZerosBackup,
} from "../../src/protocol/zeros-backup.ts";
import { TimeBox } from "../support/time-box.ts";

const HANG_MS = 3000;

const acceptedZeros = fc.tuple(
  ...STANDARD_ZEROS.map((v) => fc.integer({ min: v - ZERO_TOLERANCE, max: v + ZERO_TOLERANCE })),
);
const validBackup = fc
  .record({
    serialNumber: fc.oneof(fc.stringMatching(/^[0-9]{13}$/), fc.string({ maxLength: 64 })),
    firmware: fc.string({ maxLength: 16 }),
    zeros: acceptedZeros,
    savedAt: fc.date({
      min: new Date("1970-01-01T00:00:00Z"),
      max: new Date("2199-12-31T23:59:59Z"),
      noInvalidDate: true,
    }),
  })
  .map((args) => createZerosBackup(args));

const KEYS = [
  "format",
  "version",
  "serialNumber",
  "firmware",
  "savedAt",
  "zeros",
  "__proto__",
  "constructor",
  "extra",
];

type Mutation =
  | { op: "set"; key: string; value: unknown }
  | { op: "delete"; key: string }
  | { op: "zero"; index: number; value: unknown }
  | { op: "resize"; length: number };

const hostileNumber = fc.oneof(
  fc.integer({ min: -1000, max: 1000 }),
  fc.double({ noNaN: false }),
  fc.constantFrom(0, -0, 254, 255, 1e21, Number.MAX_SAFE_INTEGER + 2, 0.5),
);
const jsonish = fc.oneof(fc.jsonValue(), hostileNumber, fc.constantFrom("125", null, true, [], {}, [125]));
const mutation: fc.Arbitrary<Mutation> = fc.oneof(
  fc.record({ op: fc.constant("set" as const), key: fc.constantFrom(...KEYS), value: jsonish }),
  fc.record({ op: fc.constant("delete" as const), key: fc.constantFrom(...KEYS) }),
  fc.record({ op: fc.constant("zero" as const), index: fc.integer({ min: 0, max: 17 }), value: jsonish }),
  fc.record({ op: fc.constant("resize" as const), length: fc.integer({ min: 0, max: 40 }) }),
);

function mutate(backup: Record<string, unknown>, m: Mutation): Record<string, unknown> {
  const out: Record<string, unknown> = { ...backup };
  const zeros = Array.isArray(out.zeros) ? [...(out.zeros as unknown[])] : out.zeros;
  switch (m.op) {
    case "set":
      Object.defineProperty(out, m.key, {
        value: m.value,
        enumerable: true,
        writable: true,
        configurable: true,
      });
      return out;
    case "delete":
      delete out[m.key];
      return out;
    case "zero":
      if (Array.isArray(zeros)) zeros[m.index] = m.value;
      out.zeros = zeros;
      return out;
    case "resize":
      if (Array.isArray(zeros)) zeros.length = m.length;
      out.zeros = Array.isArray(zeros) ? Array.from(zeros, (v) => v ?? 125) : zeros;
      return out;
  }
}

type TextDamage = { op: "none" } | { op: "truncate"; at: number } | { op: "char"; at: number; text: string };
const textDamage: fc.Arbitrary<TextDamage> = fc.oneof(
  { arbitrary: fc.constant({ op: "none" as const }), weight: 4 },
  { arbitrary: fc.record({ op: fc.constant("truncate" as const), at: fc.nat() }), weight: 1 },
  {
    arbitrary: fc.record({
      op: fc.constant("char" as const),
      at: fc.nat(),
      text: fc.string({ unit: "binary", maxLength: 2 }),
    }),
    weight: 1,
  },
);

function damage(text: string, d: TextDamage): string {
  if (d.op === "none") return text;
  const at = d.at % (text.length + 1);
  return d.op === "truncate" ? text.slice(0, at) : text.slice(0, at) + d.text + text.slice(at + 1);
}

describe("parseZerosBackup fuzz (time-boxed)", () => {
  let box: TimeBox;
  beforeAll(async () => {
    box = await TimeBox.start();
  });
  afterAll(async () => {
    await box.stop();
  });

  const check = async (text: string) => {
    const { verdict } = await box.run("checkZerosBackup", text, HANG_MS);
    if (verdict.kind === "violation")
      throw new Error(`${verdict.detail} for ${JSON.stringify(text.slice(0, 300))}`);
    return verdict;
  };

  it("valid backups load back exactly", () => {
    fc.assert(
      fc.property(validBackup, (backup) => {
        const parsed = parseZerosBackup(serializeZerosBackup(backup));
        expect(parsed).toEqual({ ok: true, backup });
      }),
      { numRuns: 200 },
    );
  });

  it("mutated backups: a typed refusal or a table the RBC accepts, never an exception", async () => {
    const seen = new Map<string, number>();
    await fc.assert(
      fc.asyncProperty(
        validBackup,
        fc.array(mutation, { minLength: 1, maxLength: 4 }),
        textDamage,
        async (b, ms, d) => {
          const mutated = ms.reduce(mutate, { ...b } as Record<string, unknown>);
          const verdict = await check(damage(JSON.stringify(mutated), d));
          const key = verdict.kind === "typed-error" ? verdict.code : verdict.kind;
          seen.set(key, (seen.get(key) ?? 0) + 1);
        },
      ),
      { numRuns: 500 },
    );
    for (const problem of [
      "not-json",
      "wrong-format",
      "wrong-version",
      "wrong-count",
      "out-of-range",
      "invalid",
      "ok",
    ]) {
      expect(seen.get(problem) ?? 0, `no case ended as ${problem}`).toBeGreaterThan(0);
    }
  });

  it("arbitrary text and arbitrary JSON", async () => {
    await fc.assert(
      fc.asyncProperty(
        fc.oneof(
          fc.string({ unit: "binary", maxLength: 200 }),
          fc.json(),
          fc.jsonValue().map((v) => JSON.stringify(v) ?? ""),
        ),
        async (text) => {
          await check(text);
        },
      ),
      { numRuns: 400 },
    );
  });

  it("deeply nested and very large inputs", async () => {
    for (const text of [
      `${"[".repeat(100_000)}${"]".repeat(100_000)}`,
      JSON.stringify({
        format: "rbc-zeros",
        version: 1,
        zeros: Array.from({ length: 1_000_000 }, () => 125),
      }),
      JSON.stringify({ format: "rbc-zeros".repeat(100_000) }),
    ]) {
      expect((await check(text)).kind).toBe("typed-error");
    }
  });
});
