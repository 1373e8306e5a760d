import { describe, expect, it } from "vitest";
import { FirmwareUpdateError, type FirmwareUpdateProgress } from "../../src/device/firmware-update.ts";
import { errorText } from "../../src/i18n/index.ts";
import type { BootloaderFailure, RobotHolds } from "../../src/protocol/bootloader.ts";
import { IntelHexError } from "../../src/protocol/intel-hex.ts";
import type { BootloaderFaults } from "../../src/sim/sim-bootloader.ts";
import { type BootloaderRig, firmwareBytes, firmwareHex, makeBootloaderRig } from "../support/hex.ts";

/**
 * The whole stack on a virtual clock: the update (as RbcClient.updateFirmware is to run it) → RbcConnection →
 * WebSerialTransport → MockSerialPort → simulated bootloader → SimulatedRbc (firmware 2.23).
 */

const SIZE = 4096; // 256 data lines of 16 bytes + the end-of-file line
const LINES = 257;
const LINE_WIRE_BYTES = 45; // ":10" + 4 + "00" + 32 + 2 digits, CR LF
const NEW = firmwareHex("2.50", SIZE);

describe("firmware update on the simulated robot", () => {
  it("a flash changes the version the robot reports", async () => {
    const rig = await makeBootloaderRig();
    expect(await rig.run(rig.readVersion())).toEqual({ major: 2, minor: 23 });
    let asked = 0;
    const progress: FirmwareUpdateProgress[] = [];
    const result = await rig.run(
      rig.update(NEW, { onAskPowerCycle: () => asked++, onProgress: (p) => progress.push(p) }),
    );
    expect(result.firmware).toEqual({ major: 2, minor: 50 });
    expect(result).toMatchObject({ lines: LINES, bytes: 256 * LINE_WIRE_BYTES + 13, resends: 0 });
    expect(await rig.run(rig.readVersion())).toEqual({ major: 2, minor: 50 });
    expect(asked).toBe(1);
    // The flash holds the file, and the bootloader wrote 16 pages with XOFF … XON around each.
    expect(rig.boot.flash(0, SIZE)).toEqual(firmwareBytes("2.50", SIZE));
    expect(rig.boot.stats.pageWrites).toBe(SIZE / 256);
    const fromRobot = rig.port.delivered.flatMap((c) => Array.from(c));
    expect(fromRobot.filter((b) => b === 0x13)).toHaveLength(16);
    expect(fromRobot.filter((b) => b === 0x11)).toHaveLength(16);
    // Progress: waiting, entry, every line, then the new firmware starting.
    const phases = [...new Set(progress.map((p) => p.phase))];
    expect(phases).toEqual(["waiting-for-bootloader", "entering", "sending", "starting", "complete"]);
    const sending = progress.filter((p) => p.phase === "sending");
    expect(sending.at(-1)!.linesDone).toBe(LINES - 1);
    expect(sending.at(-1)!.bytesPerSecond).toBeGreaterThan(0);
    expect(sending.at(-1)!.msLeft).toBeGreaterThan(0);
    expect(progress.at(-1)).toMatchObject({ linesDone: LINES, bytesDone: result.bytes, msLeft: 0 });
  });

  it("never writes between the robot's XOFF and XON (status before the page write, paced wire)", async () => {
    const rig = await makeBootloaderRig({
      boot: { statusBeforePageWrite: true },
      port: { baudPacing: true, latencyMs: 16 },
    });
    const events: string[] = [];
    rig.transport.onData((bytes) => {
      for (const b of bytes) if (b === 0x13 || b === 0x11) events.push(b === 0x13 ? "XOFF" : "XON");
    });
    rig.connection.log.on((entry) => {
      if (entry.direction === "out" && entry.name.startsWith("firmware line")) events.push("line");
    });
    const result = await rig.run(rig.update(NEW));
    expect(result.firmware).toEqual({ major: 2, minor: 50 });
    expect(events.filter((e) => e === "XOFF")).toHaveLength(16);
    for (let i = 0; i < events.length; i++) {
      if (events[i] === "XOFF") expect(events[i + 1]).toBe("XON");
    }
    expect(events.filter((e) => e === "line")).toHaveLength(LINES);
  });

  it("resends a line answered '-' and completes", async () => {
    const rig = await makeBootloaderRig({ boot: { faults: { checksumError: { line: 40, times: 2 } } } });
    const result = await rig.run(rig.update(NEW));
    expect(result).toMatchObject({ firmware: { major: 2, minor: 50 }, resends: 2 });
    expect(rig.boot.stats.checksumErrors).toBe(2);
  });

  it("refuses a file with errors before sending anything or asking for a power cycle", async () => {
    const rig = await makeBootloaderRig();
    const before = rig.port.stats.bytesFromPc;
    let asked = false;
    // Line 6 moves to the second 64 KiB; line 7 then writes 0x1E000, the boot section.
    const lines = NEW.split("\r\n");
    lines.splice(5, 0, ":020000040001F9", ":02E00000AABBB9");
    const error = await rig.fail(
      rig.update(lines.join("\r\n"), {
        onAskPowerCycle: () => {
          asked = true;
        },
      }),
    );
    expect(error).toBeInstanceOf(IntelHexError);
    expect(error).toMatchObject({ code: "boot-section", line: 7 });
    expect(rig.port.stats.bytesFromPc).toBe(before);
    expect(asked).toBe(false);
  });

  it("after an interrupted update the robot does not answer, and the update run again recovers it", async () => {
    const rig = await makeBootloaderRig({ boot: { faults: { pageError: { line: 100 } } } });
    const error = await rig.fail(rig.update(NEW));
    expect(error).toMatchObject({ failure: "page-error", holds: "incomplete-firmware" });
    // Switched off and on without an update: the bootloader hands over to a firmware that is not whole.
    rig.boot.faults = {};
    rig.boot.powerCycle();
    await rig.clock.advance(1000);
    expect(rig.boot.mode).toBe("no-firmware");
    expect(await rig.fail(rig.readVersion())).toMatchObject({ code: "timeout" });
    // The recovery path needs no answering firmware: a bare port, the bootloader, the file.
    const result = await rig.run(rig.updateRaw(NEW));
    expect(result.firmware).toEqual({ major: 2, minor: 50 });
    await rig.connect();
    expect(await rig.run(rig.readVersion())).toEqual({ major: 2, minor: 50 });
  });
});

type Stage = "entry" | "mid-file" | "last line" | "after @";

interface FaultCase {
  stage: Stage;
  fault: string;
  faults?: BootloaderFaults;
  /** Sets up what the sim's faults cannot (a cable pull, Cancel); may return a progress hook for it. */
  arm?: (rig: BootloaderRig, abort: AbortController) => ((p: FirmwareUpdateProgress) => void) | undefined;
  failure: BootloaderFailure;
  holds: RobotHolds;
  line?: number;
}

/** PC→RBC bytes of the update up to and including line `n` (entry bytes first). */
const bytesThroughLine = (n: number) => 3 + n * LINE_WIRE_BYTES;

const disconnectAt = (offset: (base: number) => number) => (rig: BootloaderRig) => {
  rig.port.faults.disconnectAtPcBytes = offset(rig.port.stats.bytesFromPc);
  return undefined;
};

const abortWhen =
  (when: (p: FirmwareUpdateProgress) => boolean) =>
  (_rig: BootloaderRig, abort: AbortController) =>
  (p: FirmwareUpdateProgress) => {
    if (when(p)) abort.abort();
  };

const CASES: FaultCase[] = [
  {
    stage: "entry",
    fault: "no ^",
    faults: { silent: true },
    failure: "no-bootloader",
    holds: "previous-firmware",
  },
  {
    stage: "entry",
    fault: "no ?",
    faults: { noReady: true },
    failure: "not-ready",
    holds: "previous-firmware",
  },
  {
    stage: "entry",
    fault: "disconnect",
    arm: disconnectAt((base) => base + 2),
    failure: "disconnected",
    holds: "previous-firmware",
  },
  {
    stage: "entry",
    fault: "cancel",
    arm: abortWhen((p) => p.phase === "entering"),
    failure: "cancelled",
    holds: "previous-firmware",
  },
  {
    stage: "mid-file",
    fault: "checksum error",
    faults: { checksumError: { line: 100, times: "always" } },
    failure: "checksum",
    holds: "incomplete-firmware",
    line: 100,
  },
  {
    stage: "mid-file",
    fault: "page error",
    faults: { pageError: { line: 100 } },
    failure: "page-error",
    holds: "incomplete-firmware",
    line: 100,
  },
  {
    stage: "mid-file",
    fault: "disconnect",
    arm: disconnectAt((base) => base + bytesThroughLine(99) + 20),
    failure: "disconnected",
    holds: "incomplete-firmware",
  },
  {
    stage: "mid-file",
    fault: "cancel",
    arm: abortWhen((p) => p.linesDone === 100),
    failure: "cancelled",
    holds: "incomplete-firmware",
  },
  {
    stage: "last line",
    fault: "checksum error",
    faults: { checksumError: { line: LINES, times: "always" } },
    failure: "checksum",
    holds: "incomplete-firmware",
    line: LINES,
  },
  {
    stage: "last line",
    fault: "page error",
    faults: { pageError: { line: LINES } },
    failure: "page-error",
    holds: "incomplete-firmware",
    line: LINES,
  },
  {
    stage: "last line",
    fault: "complete with errors (#)",
    faults: { completeWithErrors: true },
    failure: "completed-with-errors",
    holds: "incomplete-firmware",
  },
  {
    stage: "last line",
    fault: "disconnect",
    arm: disconnectAt((base) => base + bytesThroughLine(LINES - 1) + 5),
    failure: "disconnected",
    holds: "incomplete-firmware",
  },
  {
    stage: "after @",
    fault: "the new firmware is silent",
    faults: { silentFirmware: true },
    failure: "no-answer",
    holds: "new-firmware",
  },
  {
    stage: "after @",
    fault: "disconnect",
    arm: (rig) => (p) => {
      if (p.phase === "starting") rig.port.unplug();
    },
    failure: "disconnected",
    holds: "new-firmware",
  },
  {
    stage: "after @",
    fault: "cancel",
    arm: abortWhen((p) => p.phase === "starting"),
    failure: "cancelled",
    holds: "new-firmware",
  },
];

const TODO: Record<RobotHolds, RegExp> = {
  "previous-firmware":
    /Nothing was written: the robot still holds its previous firmware\..*(run the update again)/,
  "incomplete-firmware":
    /may now be incomplete.*The bootloader is never overwritten: switch the robot off and on and run the update again\./,
  "new-firmware": /reported the new firmware written without errors\..*Switch the robot off and on/,
};

describe("firmware update fault matrix: every fault at every stage, then a second run", () => {
  for (const c of CASES) {
    it(`${c.stage}: ${c.fault} → ${c.failure}, robot holds ${c.holds}; a second run succeeds`, async () => {
      const rig = await makeBootloaderRig({ boot: { faults: c.faults } });
      const abort = new AbortController();
      const hook = c.arm?.(rig, abort);
      const error = await rig.fail(rig.update(NEW, { signal: abort.signal, onProgress: hook }));
      expect(error).toBeInstanceOf(FirmwareUpdateError);
      const e = error as FirmwareUpdateError;
      expect({ failure: e.failure, holds: e.holds }).toEqual({ failure: c.failure, holds: c.holds });
      if (c.line !== undefined) expect(e.line).toBe(c.line);
      expect(errorText(e, "en")).toMatch(TODO[c.holds]);
      if (c.holds === "previous-firmware" && c.failure !== "disconnected") {
        // Nothing written: after a power cycle the old firmware answers as before.
        rig.boot.faults = {};
        rig.boot.powerCycle();
        await rig.clock.advance(1000);
        expect(await rig.run(rig.readVersion())).toEqual({ major: 2, minor: 23 });
      }

      // The second run, with the fault gone: over the same connection if it is still up, else over a bare
      // port (the recovery path for a robot that does not answer).
      rig.boot.faults = {};
      rig.port.faults.disconnectAtPcBytes = undefined;
      const again =
        rig.connection.mode === "packet" ? await rig.run(rig.update(NEW)) : await rig.run(rig.updateRaw(NEW));
      expect(again.firmware).toEqual({ major: 2, minor: 50 });
      if (rig.connection.mode !== "packet") await rig.connect();
      expect(await rig.run(rig.readVersion())).toEqual({ major: 2, minor: 50 });
    });
  }
});
