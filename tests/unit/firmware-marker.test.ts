import { describe, expect, it } from "vitest";
import { declaredVersion, firmwareMarker, parseIntelHex } from "../../src/protocol/index.ts";

/**
 * The demo files' version mark (docs/firmware-update.md): `RBCFW M.mm` in the image. A real firmware file states
 * no version, so a file with the mark is flagged before a real robot (the panel asks twice, `rbc flash` needs
 * --demo-file).
 */
describe("the demo firmware mark", () => {
  it("reads RBCFW 2.50 from literal HEX records, wherever the mark sits", () => {
    // "RBCFW 2.50" = 52 42 43 46 57 20 32 2E 35 30, at address 0x0000 and then across a record boundary.
    const atStart = ":0A000000524243465720322E35309D\r\n:00000001FF\r\n";
    expect(declaredVersion(parseIntelHex(atStart))).toEqual({ major: 2, minor: 50 });
    const across =
      ":100000000000000000000000000000000052424319\r\n:07001000465720332E303764\r\n:00000001FF\r\n";
    expect(declaredVersion(parseIntelHex(across))).toEqual({ major: 3, minor: 7 });
  });

  it("finds nothing in a file without it, and refuses a major version over 255", () => {
    const plain = ":0400000001020304F2\r\n:00000001FF\r\n";
    expect(declaredVersion(parseIntelHex(plain))).toBeUndefined();
    expect(firmwareMarker(new TextEncoder().encode("xx RBCFW 256.00 xx"))).toBeUndefined();
    expect(firmwareMarker(new TextEncoder().encode("RBCFW 2.5"))).toBeUndefined();
  });
});
