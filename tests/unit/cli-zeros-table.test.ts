import { describe, expect, it } from "vitest";
import { alignColumns, zerosTable } from "../../src/cli/commands/zeros.ts";
import { FACTORY_ZEROS } from "../../src/protocol/index.ts";

/** The text column where each right-aligned header ends (its last character). */
function headerEnds(header: string, names: readonly string[]): number[] {
  return names.map((name) => {
    const at = header.indexOf(` ${name}`);
    if (at < 0) throw new Error(`no column ${name} in ${header}`);
    return at + name.length;
  });
}

describe("rbc zeros read: the table", () => {
  // The factory zeros differ from the reference zeros by -1 (servos 0, 3, 15) and -2 (servo 6); two more
  // values give a two-digit difference and a plus sign.
  const zeros = [...FACTORY_ZEROS];
  zeros[4] = 95; // reference 108: -13
  zeros[5] = 139; // reference 124: +15

  it("lines every value up under its header, with or without a sign (issue #11: '(-1)' shifted the columns)", () => {
    const lines = zerosTable(zeros);
    const header = lines[0]!;
    const right = ["servo", "zero", "reference", "difference", "allowed", "factory"];
    const ends = headerEnds(header, right);
    const rows = lines.slice(1, 17);
    expect(rows).toHaveLength(16);
    for (const row of rows) {
      for (const end of ends) {
        // The cell's last character sits under the header's last character, and the next is a gap or the end.
        expect(row[end], `${JSON.stringify(row)} at ${end}`).toMatch(/\S/);
        expect(row[end + 1] ?? " ", `${JSON.stringify(row)} after ${end}`).toBe(" ");
      }
    }
    expect(rows[0]).toMatch(/^\s+0\s+Left hip roll\s+124\s+125\s+-1\s+110-140\s+124$/);
    expect(rows[4]).toMatch(/^\s+4\s+Left ankle roll\s+95\s+108\s+-13\s+93-123\s+108$/);
    expect(rows[5]).toMatch(/^\s+5\s+Right hip roll\s+139\s+124\s+\+15\s+109-139\s+125$/);
  });

  it("says which table is which, with the names the panel uses", () => {
    const text = zerosTable(zeros).join("\n");
    expect(text).toContain("reference: the table the RBC checks every write against");
    expect(text).toContain("factory: the zeros the firmware holds when new");
    expect(text).not.toMatch(/standard/i);
  });

  it("pads left and right aligned cells to the widest of header and cells", () => {
    expect(
      alignColumns([
        { header: "n", align: "right", cells: ["1", "100"] },
        { header: "name", align: "left", cells: ["a", "longer"] },
        { header: "v", align: "right", cells: ["(-1)", "2"] },
      ]),
    ).toEqual(["    n  name       v", "    1  a       (-1)", "  100  longer     2"]);
  });
});
