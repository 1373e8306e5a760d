import { describe, expect, it } from "vitest";
import { FirmwareUpdateError } from "../../src/device/firmware-update.ts";
import { errorText } from "../../src/i18n/index.ts";
import { firmwareBytes, firmwareHex, hexLines, makeBootloaderRig } from "../support/hex.ts";

/**
 * Issue 20 item 8: a firmware update never claims success over a hole (docs/protocol.md §11 [decision]). The whole
 * stack on a virtual clock against the simulated bootloader, whose page buffer starts erased.
 */

const SIZE = 1024; // 4 pages of 16-byte records: lines 1-16 page 0, 17-32 page 1, …

describe("a HEX file that returns to a flash page it left", () => {
  it("is sent sorted by page, each page once: the flash holds every byte, the version marker included", async () => {
    const bytes = firmwareBytes("2.50", SIZE);
    const lines = hexLines(bytes);
    // Page 0's records except its first (the marker, 0x000) and last (0x0F0), then page 1, then both back.
    const order = [...lines.slice(1, 15), ...lines.slice(16, 32), lines[0]!, lines[15]!, ...lines.slice(32)];
    const rig = await makeBootloaderRig();
    const result = await rig.run(rig.update(`${order.join("\r\n")}\r\n`));
    expect(rig.boot.flash(0, SIZE)).toEqual(bytes);
    expect(result.firmware).toEqual({ major: 2, minor: 50 });
    // Each page written once: in file order page 0 would have been written twice, the second time from an
    // erased buffer holding 32 bytes.
    expect(rig.boot.stats.pageWrites).toBe(SIZE / 256);
  });

  it("in page order, the file's own lines are sent as they are", async () => {
    const rig = await makeBootloaderRig();
    const text = firmwareHex("2.50", SIZE);
    const sent: string[] = [];
    rig.connection.log.on((entry) => {
      if (entry.direction === "out" && entry.name.startsWith("firmware line")) {
        sent.push(String.fromCharCode(...entry.bytes).trimEnd());
      }
    });
    await rig.run(rig.update(text));
    expect(sent).toEqual(text.trimEnd().split("\r\n"));
  });
});

describe("status characters are checked against the wire time of their line", () => {
  it("a stray '~' while the next line is crossing the wire ends the update as failed, naming the line", async () => {
    const rig = await makeBootloaderRig({
      boot: { faults: { strayStatus: { afterLine: 20 } } },
      port: { baudPacing: true, latencyMs: 16 },
    });
    const error = await rig.fail(rig.update(firmwareHex("2.50", SIZE)));
    expect(error).toBeInstanceOf(FirmwareUpdateError);
    expect(error).toMatchObject({
      failure: "early-status",
      holds: "incomplete-firmware",
      line: 21,
      code: "bad-reply",
    });
    expect(errorText(error, "en")).toMatch(
      /sooner than the line could have reached the robot at 115200 baud.*may now be incomplete.*run the update again/,
    );
  });

  it("the same file over the same paced link, with no stray byte, succeeds", async () => {
    const rig = await makeBootloaderRig({ port: { baudPacing: true, latencyMs: 16 } });
    const result = await rig.run(rig.update(firmwareHex("2.50", SIZE)));
    expect(result.firmware).toEqual({ major: 2, minor: 50 });
    expect(rig.boot.flash(0, SIZE)).toEqual(firmwareBytes("2.50", SIZE));
  });
});

describe("a bootloader that only toggles XOFF/XON", () => {
  it("fails the update 10 s after the line's last byte instead of hanging", async () => {
    const rig = await makeBootloaderRig({
      boot: { faults: { flowControlOnly: { fromLine: 30, periodMs: 300 } } },
    });
    let line30At: number | undefined;
    rig.connection.log.on((entry) => {
      if (entry.direction === "out" && entry.name === "firmware line 30 of 65") line30At ??= rig.clock.now();
    });
    const error = await rig.fail(rig.update(firmwareHex("2.50", SIZE)));
    expect(error).toMatchObject({
      failure: "line-deadline",
      holds: "incomplete-firmware",
      line: 30,
      code: "timeout",
    });
    expect(errorText(error, "en")).toMatch(
      /did not finish a line \(line 30 of the file\) within 10 s after its last byte/,
    );
    expect(line30At).toBeDefined();
    const waited = rig.clock.now() - line30At!;
    expect(waited).toBeGreaterThanOrEqual(10_000);
    expect(waited).toBeLessThan(10_010);
  });
});
