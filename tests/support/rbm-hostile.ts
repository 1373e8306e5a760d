/**
 * Hostile `.rbm` texts that stress the motion file check by their size rather than their content: huge declared
 * scene and servo counts, a count thousands of digits long, half a million empty fields, a million digits in
 * one field, and every example joined into one text. The fuzz test (tests/unit/fuzz-rbm.test.ts) checks each one
 * ends in a typed error or a valid motion; the bench (bench/rbm-check.ts) measures how long that takes.
 */

/** One hostile input: what it is, and its text. */
export interface HostileRbm {
  readonly name: string;
  readonly text: string;
}

/** The inputs, made from wave.rbm's text (`wave`) and every example's (`examples`). */
export function hostileRbmInputs(wave: string, examples: readonly string[]): HostileRbm[] {
  const fields = wave.split(":");
  const withField = (index: number, value: string) => {
    const f = [...fields];
    f[index] = value;
    return f.join(":");
  };
  return [
    { name: "scene count 999,999,999", text: withField(9, "999999999") },
    { name: "servo count 999,999,999", text: withField(11, "999999999") },
    { name: "scene count of 5,000 digits", text: withField(9, "9".repeat(5000)) },
    { name: "field 1 = 99,999,999", text: withField(1, "99999999") },
    { name: "field 5 = 4,294,967,295", text: withField(5, "4294967295") },
    { name: "500,000 empty fields", text: "0:".repeat(500_000) },
    { name: "a field of 1,000,000 digits", text: `1:13:${"9".repeat(1_000_000)}:` },
    { name: "every example in one text", text: examples.join("") },
  ];
}
