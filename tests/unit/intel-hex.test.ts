import { describe, expect, it } from "vitest";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import {
  encodeIntelHex,
  IntelHexError,
  MAX_HEX_TEXT_CHARS,
  parseIntelHex,
} from "../../src/protocol/intel-hex.ts";

// Literal records (the first four are the classic Intel HEX example, 64 bytes at 0x0100).
const EXAMPLE = [
  ":10010000214601360121470136007EFE09D2190140",
  ":100110002146017E17C20001FF5F16002148011928",
  ":10012000194E79234623965778239EDA3F01B2CAA7",
  ":100130003F0156702B5E712B722B732146013421C7",
  ":00000001FF",
];

function problem(text: string): IntelHexError {
  try {
    parseIntelHex(text);
  } catch (e) {
    if (e instanceof IntelHexError) return e;
    throw e;
  }
  throw new Error("expected an IntelHexError");
}

describe("parseIntelHex", () => {
  it("reads records and summarises the file", () => {
    const image = parseIntelHex(`${EXAMPLE.join("\r\n")}\r\n`);
    expect(image.summary).toEqual({
      bytes: 64,
      firstAddress: 0x100,
      lastAddress: 0x13f,
      pages: 1,
      lines: 5,
      wireBytes: 4 * (43 + 2) + 11 + 2,
      reordered: false,
    });
    expect(image.records[0]).toMatchObject({ line: 1, type: 0, address: 0x100, text: EXAMPLE[0] });
    expect(Array.from(image.records[0]!.data.subarray(0, 4))).toEqual([0x21, 0x46, 0x01, 0x36]);
    expect(image.records[4]).toMatchObject({ line: 5, type: 1, text: ":00000001FF" });
  });

  it("accepts lower case, LF or CR line ends, blank lines, spaces and a BOM; sends upper case", () => {
    const text = `\uFEFF  ${EXAMPLE[0]!.toLowerCase()}  \n\n${EXAMPLE[1]}\r${EXAMPLE[4]}\n\n`;
    const image = parseIntelHex(text);
    expect(image.records.map((r) => r.line)).toEqual([1, 3, 4]);
    expect(image.records[0]!.text).toBe(EXAMPLE[0]);
    expect(image.summary.lines).toBe(3);
  });

  it("applies extended linear (04) and extended segment (02) addresses", () => {
    const linear = parseIntelHex([":020000040001F9", ":02000000AABB99", ":00000001FF"].join("\n"));
    expect(linear.records[1]!.address).toBe(0x10000);
    expect(linear.summary).toMatchObject({ bytes: 2, firstAddress: 0x10000, lastAddress: 0x10001, pages: 1 });
    const segment = parseIntelHex([":020000021000EC", ":020010001122BB", ":00000001FF"].join("\n"));
    expect(segment.records[1]!.address).toBe(0x10010);
  });

  it("counts every 256-byte page touched", () => {
    // 0x0100-0x013F and 0x1DFFE-0x1DFFF (the last two bytes below the boot section).
    const image = parseIntelHex([EXAMPLE[0], ":020000040001F9", ":02DFFE00AABBBC", ":00000001FF"].join("\n"));
    expect(image.summary).toMatchObject({ pages: 2, firstAddress: 0x100, lastAddress: 0x1dfff, bytes: 18 });
  });

  const cases: Array<[string, string[], string, number | undefined, RegExp]> = [
    [
      "a wrong checksum",
      [EXAMPLE[0]!, `${EXAMPLE[1]!.slice(0, -2)}29`, EXAMPLE[4]!],
      "checksum",
      2,
      /checksum is 29.*need 28/,
    ],
    ["no colon", [EXAMPLE[0]!.slice(1), EXAMPLE[4]!], "no-colon", 1, /starts with ':'/],
    ["a non-hex digit", [":02000000AAZZ99", EXAMPLE[4]!], "not-hex", 1, /hex digits/],
    ["an odd number of digits", [":02000000AABB9", EXAMPLE[4]!], "not-hex", 1, /pairs/],
    [
      "a count that does not match",
      [":03000000AABB98", EXAMPLE[4]!],
      "length-mismatch",
      1,
      /says 3 data bytes but holds 2/,
    ],
    [
      "record type 03",
      [":0400000300003800C1", EXAMPLE[4]!],
      "record-type",
      1,
      /type 03 \(start segment address\).*00, 01, 02 and 04/,
    ],
    [
      "record type 05",
      [":04000005000000CD2A", EXAMPLE[4]!],
      "record-type",
      1,
      /type 05 \(start linear address\)/,
    ],
    ["record type 06", [":00000006FA", EXAMPLE[4]!], "record-type", 1, /type 06 is not accepted/],
    [
      "an end-of-file record with data",
      [EXAMPLE[0]!, ":01000001AA54"],
      "bad-record",
      2,
      /end-of-file record carries no data/,
    ],
    ["an extended address record of 1 byte", [":0100000400FB", EXAMPLE[4]!], "bad-record", 1, /2 data bytes/],
    [
      "a record past its 64 KiB segment",
      [":02FFFF00AABB9B", EXAMPLE[4]!],
      "crosses-64k",
      1,
      /64 KiB segment/,
    ],
    [
      "an address beyond 128 KiB",
      [":020000040002F8", ":02000000AABB99", EXAMPLE[4]!],
      "outside-flash",
      2,
      /0x20000-0x20001, outside .*128 KiB/,
    ],
    [
      "the boot section",
      [":020000040001F9", ":02E00000AABBB9", EXAMPLE[4]!],
      "boot-section",
      2,
      /0x1E000-0x1E001, inside the boot section/,
    ],
    [
      "the same address twice",
      [EXAMPLE[0]!, ":020108000102F2", EXAMPLE[4]!],
      "overlap",
      2,
      /writes 0x00108 again/,
    ],
    [
      "a record after the end",
      [EXAMPLE[0]!, EXAMPLE[4]!, "", EXAMPLE[1]!],
      "after-end",
      4,
      /after the end-of-file record on line 2/,
    ],
    ["no end-of-file record", [EXAMPLE[0]!, EXAMPLE[1]!, ""], "no-end", 2, /without an end-of-file record/],
  ];
  for (const [what, lines, code, line, message] of cases) {
    it(`refuses ${what}, naming the line`, () => {
      const e = problem(lines.join("\r\n"));
      expect(e.code).toBe(code);
      expect(e.line).toBe(line);
      expect(errorText(e, "en")).toMatch(message);
      if (line !== undefined) expect(errorText(e, "en").startsWith(`Line ${line}: `)).toBe(true);
      expect(e.message).toMatch(line === undefined ? `hex: ${code}` : `hex line ${line}: ${code}`);
    });
  }

  it("refuses a file without data, an empty file and an oversized text", () => {
    expect(problem(":00000001FF").code).toBe("no-records");
    expect(problem(":00123400BA\n:00000001FF").code).toBe("no-records");
    expect(problem("").code).toBe("no-end");
    const big = problem(" ".repeat(MAX_HEX_TEXT_CHARS + 1));
    expect(big.code).toBe("too-large");
    expect(big.line).toBeUndefined();
  });
});

describe("encodeIntelHex", () => {
  it("writes 16-byte records and the end-of-file record", () => {
    const bytes = Uint8Array.of(
      0x21,
      0x46,
      0x01,
      0x36,
      0x01,
      0x21,
      0x47,
      0x01,
      0x36,
      0x00,
      0x7e,
      0xfe,
      0x09,
      0xd2,
      0x19,
      0x01,
    );
    expect(encodeIntelHex(bytes, { address: 0x100 })).toBe(`${EXAMPLE[0]}\r\n:00000001FF\r\n`);
  });

  it("splits at a 64 KiB boundary with an extended linear address record", () => {
    const bytes = Uint8Array.from({ length: 16 }, (_, i) => i);
    expect(encodeIntelHex(bytes, { address: 0xfff8 }).split("\r\n")).toEqual([
      ":08FFF8000001020304050607E5",
      ":020000040001F9",
      ":0800000008090A0B0C0D0E0F9C",
      ":00000001FF",
      "",
    ]);
  });
});

describe("a file that returns to a flash page it left (docs/protocol.md §11 [decision])", () => {
  // Page 0, page 1, page 0 again, pages 1-2, the second 64 KiB, page 0 once more, end. Literal records.
  const FILE = [
    ":020000000102FB", // 1: 0x00000 01 02
    ":0401000003040506E9", // 2: 0x00100 03 04 05 06
    ":0200FE000708F1", // 3: 0x000FE 07 08 — back to page 0
    ":0401FE00090A0B0CD3", // 4: 0x001FE 09 0A | 0x00200 0B 0C
    ":020000040001F9", // 5: segment 0x10000
    ":010000000DF2", // 6: 0x10000 0D
    ":020000040000FA", // 7: segment 0
    ":010002000EEF", // 8: 0x00002 0E — page 0 a third time
    ":00000001FF", // 9
  ];

  it("is sent sorted by address, each page's bytes once, no line holding two pages", () => {
    const image = parseIntelHex(FILE.join("\r\n"));
    expect(image.records.map((r) => [r.text, r.line])).toEqual([
      [":020000000102FB", 1],
      [":010002000EEF", 8],
      [":0200FE000708F1", 3],
      [":0401000003040506E9", 2],
      [":0201FE00090AEC", 4],
      [":020200000B0CE5", 4],
      [":020000040001F9", 6],
      [":010000000DF2", 6],
      [":00000001FF", 9],
    ]);
    expect(image.summary).toMatchObject({ bytes: 14, pages: 4, lines: 9, reordered: true });
    expect(image.summary.wireBytes).toBe(image.records.reduce((n, r) => n + r.text.length + 2, 0));
  });

  it("a file in page order (even descending pages) keeps its own records", () => {
    const image = parseIntelHex(
      [":0200FE000708F1", ":020000000102FB", ":0401000003040506E9", ":00000001FF"].join("\n"),
    );
    expect(image.summary.reordered).toBe(false);
    expect(image.records.map((r) => r.text)).toEqual([
      ":0200FE000708F1",
      ":020000000102FB",
      ":0401000003040506E9",
      ":00000001FF",
    ]);
  });
});
