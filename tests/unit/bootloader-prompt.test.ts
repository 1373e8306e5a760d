import { describe, expect, it } from "vitest";
import { flashCommand } from "../../src/cli/commands/flash.ts";
import { infoCommand } from "../../src/cli/commands/info.ts";
import { CliError } from "../../src/cli/errors.ts";
import { RbcInBootloaderError } from "../../src/device/bootloader-prompt.ts";
import { transportFirmwareIo, updateFirmware } from "../../src/device/firmware-update.ts";
import { RbcClient } from "../../src/device/rbc-client.ts";
import { errorText } from "../../src/i18n/index.ts";
import { WebSerialTransport } from "../../src/link/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { MockSerialPort, SimulatedRbc } from "../../src/sim/index.ts";
import { BootloaderRbc } from "../../src/sim/sim-bootloader.ts";
import { runInProcess } from "../support/cli-env.ts";
import { firmwareHex } from "../support/hex.ts";

/** Issue 20 item 11: a robot waiting in its bootloader is recognised on connect and sent to the recovery. */

function robot(faults: { waiting?: boolean } = { waiting: true }) {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock });
  const boot = new BootloaderRbc(sim, { faults });
  const port = new MockSerialPort(boot, { clock, latencyMs: 2 });
  const client = () => new RbcClient(new WebSerialTransport(port, { clock }), { clock });
  return { clock, boot, port, client };
}

async function failure(clock: VirtualClock, p: Promise<unknown>): Promise<unknown> {
  try {
    await clock.run(p);
  } catch (e) {
    return e;
  }
  throw new Error("expected the connect to fail");
}

describe("connecting to a robot waiting in its bootloader", () => {
  it("is a distinct outcome: code in-bootloader, with the prompts counted, not 'no robot answered'", async () => {
    const r = robot();
    expect(r.boot.mode).toBe("entry");
    const e = await failure(r.clock, r.client().connect());
    expect(e).toBeInstanceOf(RbcInBootloaderError);
    const error = e as RbcInBootloaderError;
    expect(error.code).toBe("in-bootloader");
    expect(error.facts.prompts).toBeGreaterThanOrEqual(2);
    expect(error.facts.overMs).toBeGreaterThanOrEqual(300); // one prompt every 300 ms (the sim's window)
    expect(errorText(error, "en")).toMatch(
      /waiting in its bootloader.*Run the firmware update again, in recovery mode/,
    );
  });

  it("the recovery path then gives it a firmware, and it answers again", async () => {
    const r = robot();
    await failure(r.clock, r.client().connect());
    const transport = new WebSerialTransport(r.port, { clock: r.clock });
    await r.clock.run(transport.open());
    const result = await r.clock.run(
      updateFirmware(transportFirmwareIo(transport, { clock: r.clock }), firmwareHex("2.50", 1024), {
        wireTimed: false,
      }),
    );
    expect(result.firmware).toEqual({ major: 2, minor: 50 });
    await r.clock.run(transport.close());
    const client = r.client();
    expect((await r.clock.run(client.connect())).firmware).toEqual({ major: 2, minor: 50 });
  });

  it("a robot that sends nothing is still 'no robot answered'", async () => {
    const r = robot({});
    r.port.faults.swallowReplies(Number.POSITIVE_INFINITY);
    const e = await failure(r.clock, r.client().connect());
    expect(e).not.toBeInstanceOf(RbcInBootloaderError);
    expect(e).toMatchObject({ code: "no-robot" });
  });
});

describe("rbc info and rbc flash on a demo robot waiting in its bootloader", () => {
  const env = { RBC_DEMO_TIME_SCALE: "50", RBC_DEMO_VARIANT: "--in-bootloader" };

  it("rbc info points to rbc flash FILE --recover", { timeout: 30_000 }, async () => {
    const r = await runInProcess(infoCommand, ["--demo"], env);
    expect(r.code).not.toBe(0);
    expect(r.stderr).toMatch(
      /The robot is waiting in its bootloader: it sent the bootloader's prompt \(\^\) \d+ times and answered no request\..*rbc flash FILE\.hex --recover --demo/,
    );
    expect(r.stderr).not.toMatch(/no robot answered/);
  });

  it("rbc info --json: the error's code and its facts", { timeout: 30_000 }, async () => {
    const r = await runInProcess(infoCommand, ["--demo", "--json"], env);
    expect(r.error).toBeInstanceOf(CliError);
    const e = r.error as CliError;
    expect(e.code).toBe("in-bootloader");
    expect(e.details.prompts).toBeGreaterThanOrEqual(2);
  });

  it("rbc flash (without --recover) says the same", { timeout: 30_000 }, async () => {
    const r = await runInProcess(flashCommand, ["examples/firmware/demo-2.50.hex", "--demo"], env);
    expect(r.code).not.toBe(0);
    expect(r.stderr).toMatch(/waiting in its bootloader.*rbc flash FILE\.hex --recover --demo/);
  });
});
