import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import { parseRbm, RbmError, readRbm } from "../../src/protocol/index.ts";
import { RBM_MAX_TEXT_LENGTH } from "../../src/protocol/rbm.ts";
import { MockSerialPort, SimulatedRbc } from "../../src/sim/index.ts";

const wave = readFileSync(new URL("../../examples/wave.rbm", import.meta.url), "latin1");

function codeOf(text: string): string {
  try {
    readRbm(text);
  } catch (e) {
    if (e instanceof RbmError) return e.code;
    throw e;
  }
  return "accepted";
}

describe("the .rbm reader's own limits (bounded time and memory on any input)", () => {
  it("refuses 50 MB of ':' at once, before splitting it", () => {
    // The size is checked before anything else, so the 50 million fields are never made.
    expect(codeOf(":".repeat(50_000_000))).toBe("rbm-too-large");
  });

  it("accepts a file just under the limit's size class (the largest example is far below it)", () => {
    expect(RBM_MAX_TEXT_LENGTH).toBe(1_048_576);
    const longWalk = readFileSync(new URL("../../examples/long-walk.rbm", import.meta.url), "latin1");
    expect(longWalk.length).toBeLessThan(RBM_MAX_TEXT_LENGTH / 8);
    expect(parseRbm(longWalk).scenes).toHaveLength(284);
  });

  it("refuses a name longer than its field can hold", () => {
    const fields = wave.split(":");
    fields[5] = "200";
    fields[6] = "N".repeat(200);
    expect(codeOf(fields.join(":"))).toBe("rbm-field-too-long");
    const text2 = wave.split(":");
    text2[4] = "T".repeat(21);
    expect(codeOf(text2.join(":"))).toBe("rbm-field-too-long");
  });

  it("says that a README or a package.json is not a motion file at all", () => {
    for (const text of [
      "# RBC Panel\n\nA browser control panel…\n",
      '{ "name": "rbc-panel", "version": "0.1.0" }',
    ]) {
      let error: unknown;
      try {
        readRbm(text);
      } catch (e) {
        error = e;
      }
      expect(error).toBeInstanceOf(RbmError);
      expect((error as RbmError).code).toBe("rbm-not-motion");
      expect(errorText(error, "en")).toMatch(/^This is not a Motionbuilder motion file \(\.rbm\)/);
    }
  });
});

describe("the mock port keeps no history when asked not to (the demo robot)", () => {
  it("records nothing with record: false, and still counts every byte", async () => {
    const sim = new SimulatedRbc();
    const port = new MockSerialPort(sim, { record: false });
    await port.open({ baudRate: 115200 });
    const writer = port.writable!.getWriter();
    await writer.write(
      Uint8Array.of(0xff, 0xff, 0xaa, 0x55, 0xaa, 0x55, 0x37, 0xba, 0x12, 0, 0, 0, 0, 1, 1, 1),
    );
    writer.releaseLock();
    expect(port.written).toHaveLength(0);
    expect(port.delivered).toHaveLength(0);
    expect(port.stats.bytesFromPc).toBe(16);
    expect(port.stats.bytesToPc).toBe(17);
    sim.dispose();
  });
});
