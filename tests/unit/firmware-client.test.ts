import { describe, expect, it } from "vitest";
import { FirmwareUpdateError, RbcClient } from "../../src/device/index.ts";
import { errorText } from "../../src/i18n/index.ts";
import { WebSerialTransport } from "../../src/link/index.ts";
import { IntelHexError } from "../../src/protocol/intel-hex.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { BootloaderRbc, MockSerialPort, SimulatedRbc } from "../../src/sim/index.ts";
import { firmwareHex, firmwareHexWithBadChecksum } from "../support/hex.ts";

/**
 * `RbcClient.updateFirmware`: the client's own method on the whole stack (RbcClient → WebSerialTransport →
 * MockSerialPort paced at 115200 baud → simulated bootloader → SimulatedRbc, firmware 2.23) on a virtual clock, with the robot
 * switched off and on 1.5 s after the client asks for it.
 */

async function rig(options: { powerCycle?: boolean } = {}) {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock });
  const boot = new BootloaderRbc(sim);
  // Paced at 115200 baud, as a real line is: the update checks that no status comes sooner than its line's bytes.
  const port = new MockSerialPort(boot, { clock, baudPacing: true });
  const client = new RbcClient(new WebSerialTransport(port, { clock }), { clock });
  await clock.run(client.connect());
  let asked = 0;
  const onAskPowerCycle = () => {
    asked++;
    if (options.powerCycle !== false) clock.setTimeout(() => boot.powerCycle(), 1500);
  };
  const fail = async (p: Promise<unknown>) => {
    try {
      await clock.run(p);
    } catch (e) {
      return e;
    }
    throw new Error("expected the operation to fail, but it succeeded");
  };
  return { clock, sim, boot, port, client, onAskPowerCycle, asked: () => asked, fail };
}

describe("RbcClient.updateFirmware", () => {
  it("flashes the file, reports the new version, and no longer counts Basic posture as done", async () => {
    const r = await rig();
    await r.clock.run(r.client.runMotion(7));
    await r.clock.run(r.client.subscribe("buttons"));
    expect(r.client.state).toMatchObject({ basicPostureConfirmed: true, subscription: "buttons" });

    const result = await r.clock.run(
      r.client.updateFirmware(firmwareHex("2.50", 2048), { onAskPowerCycle: r.onAskPowerCycle }),
    );
    expect(result.firmware).toEqual({ major: 2, minor: 50 });
    expect(result.lines).toBe(129);
    expect(r.asked()).toBe(1);
    expect(r.boot.stats.updates).toBe(1);
    // The robot was restarted: Basic posture must run again, and no subscription runs on it.
    expect(r.client.state.basicPostureConfirmed).toBe(false);
    expect(r.client.state.subscription).toBeUndefined();
    expect(r.client.mode).toBe("packet");
    // The same client goes on talking to the new firmware.
    expect(await r.clock.run(r.client.readFirmwareVersion())).toEqual({ major: 2, minor: 50 });
    // A motion before Basic posture is ignored by the restarted robot, and the client says why.
    const ignored = await r.fail(r.client.runMotion(1));
    expect(ignored).toMatchObject({ code: "motion-ignored" });
  });

  it("refuses a bad file before queueing anything: nothing sent, nothing forgotten", async () => {
    const r = await rig();
    await r.clock.run(r.client.runMotion(7));
    const sent = r.port.stats.bytesFromPc;
    const error = await r.fail(
      r.client.updateFirmware(firmwareHexWithBadChecksum(4), { onAskPowerCycle: r.onAskPowerCycle }),
    );
    expect(error).toBeInstanceOf(IntelHexError);
    expect(error).toMatchObject({ code: "checksum", line: 4 });
    expect(errorText(error, "en")).toMatch(/^Line 4: the checksum is /);
    expect(r.port.stats.bytesFromPc).toBe(sent);
    expect(r.asked()).toBe(0);
    expect(r.client.state.basicPostureConfirmed).toBe(true);
  });

  it("a robot never switched off and on ends in a typed error saying nothing was written", async () => {
    const r = await rig({ powerCycle: false });
    const error = await r.fail(
      r.client.updateFirmware(firmwareHex("2.50", 512), {
        onAskPowerCycle: r.onAskPowerCycle,
        timeouts: { powerCycleMs: 5000 },
      }),
    );
    expect(error).toBeInstanceOf(FirmwareUpdateError);
    expect(error).toMatchObject({ failure: "no-bootloader", holds: "previous-firmware" });
    expect(errorText(error, "en")).toContain("Nothing was written");
    // The connection is still usable and the robot still runs its old firmware.
    expect(await r.clock.run(r.client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
  });

  it("Cancel mid-file says the firmware may be incomplete; a second run recovers", async () => {
    const r = await rig();
    const abort = new AbortController();
    const error = await r.fail(
      r.client.updateFirmware(firmwareHex("2.50", 4096), {
        signal: abort.signal,
        onAskPowerCycle: r.onAskPowerCycle,
        onProgress: (p) => {
          if (p.linesDone >= 100) abort.abort();
        },
      }),
    );
    expect(error).toMatchObject({ failure: "cancelled", holds: "incomplete-firmware" });
    expect(errorText(error, "en")).toContain("may now be incomplete");
    const result = await r.clock.run(
      r.client.updateFirmware(firmwareHex("2.51", 4096), { onAskPowerCycle: r.onAskPowerCycle }),
    );
    expect(result.firmware).toEqual({ major: 2, minor: 51 });
  });

  it("is the activity machine's `firmware` from its first byte; its Cancel makes it `cancelling`; idle after", async () => {
    const r = await rig();
    const seen: string[] = [];
    r.client.activityChanges.on(({ doing }) => {
      const cancelling = "cancelling" in doing && doing.cancelling ? " cancelling" : "";
      seen.push(`${doing.kind}${cancelling}`);
    });
    const abort = new AbortController();
    let cancelledAt = -1;
    const error = await r.fail(
      r.client.updateFirmware(firmwareHex("2.50", 4096), {
        signal: abort.signal,
        onAskPowerCycle: r.onAskPowerCycle,
        onProgress: (p) => {
          if (p.linesDone < 10 || abort.signal.aborted) return;
          expect(r.client.activity.doing).toMatchObject({ kind: "firmware" });
          cancelledAt = r.clock.now();
          abort.abort();
          expect(r.client.activity.doing).toMatchObject({
            kind: "firmware",
            cancelling: { since: cancelledAt },
          });
        },
      }),
    );
    expect(error).toMatchObject({ failure: "cancelled" });
    expect(cancelledAt).toBeGreaterThan(0);
    expect(seen).toEqual(["firmware", "firmware cancelling", "idle"]);
    expect(r.client.activity.doing.kind).toBe("idle");
  });
});
