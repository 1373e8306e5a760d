/**
 * The robot over Bluetooth (issue #14, item 2). The RBC's Bluetooth module is a serial port (Serial Port
 * Profile) whose replies come 100-400 ms late, in bursts. The whole flow — connect and identify, read and
 * write zeros, upload examples/wave.rbm, run it, read the distance sensor and the accelerometer, a button
 * subscription — runs on the whole stack (RbcClient → WebSerialTransport → MockSerialPort → SimulatedRbc)
 * under a VirtualClock, over a link with 300 ± 150 ms latency (seeded) and 20 ms bursts: no timeout, no
 * unasked or stale reply, and the results the robot holds. The same flow with the fixed timeouts of before
 * times out; a USB-like link keeps exactly its fixed timeouts. Also: the round-trip estimator's arithmetic
 * (RFC 6298), the mock's link model, and the chooser's Bluetooth filter.
 */
import { describe, expect, it } from "vitest";
import {
  type LinkTiming,
  MAX_BACKOFF,
  type RbcClientOptions,
  type RbcEvent,
  RbcUnexpectedAckError,
  RbcUploadError,
  RoundTripEstimator,
} from "../../src/device/index.ts";
import { errorText } from "../../src/i18n/index.ts";
import { fromHex, STANDARD_ZEROS, toHex } from "../../src/protocol/index.ts";
import { parseRbm } from "../../src/protocol/rbm.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import {
  bluetoothLinkOptions,
  FakeSerial,
  MockSerialPort,
  type MockSerialPortOptions,
  SimulatedRbc,
  SPP_SERVICE_CLASS_ID,
} from "../../src/sim/index.ts";
import {
  choosePort,
  chooserOptions,
  describePort,
  linkKindOf,
  PORT_FILTERS,
  SERIAL_PORT_PROFILE,
} from "../../src/ui/serial-ports.ts";
import { exampleText, goldenImage } from "../data/project-data.ts";
import { armAtReply } from "../support/faults.ts";
import { makeRig, type Rig } from "../support/rig.ts";

/** The SPP service class UUID, as the Web Serial spec and Chrome's article give it. */
const SPP = "00001101-0000-1000-8000-00805f9b34fb";
const WAVE_TEXT = exampleText("wave.rbm");
const WAVE_IMAGE = goldenImage("wave.rbm");
/** wave.rbm plays for 3.2 s (scenes of 800, 400, 400, 400, 400 and 800 ms). */
const WAVE_MS = 3200;
const FIXED = { quickMs: 400, marginMs: 2000, settleMs: 50 };

// ---- The round-trip estimator -------------------------------------------------------------------------

describe("the round-trip estimator (Jacobson/Karels, RFC 6298)", () => {
  const limits = { floorMs: 400, ceilingMs: 5000, firstMs: 1500 };

  it("starts at the floor on a wired link and at the generous first value on a Bluetooth or unknown one", () => {
    expect(new RoundTripEstimator("wired", limits).timeoutMs).toBe(400);
    expect(new RoundTripEstimator("bluetooth", limits).timeoutMs).toBe(1500);
    expect(new RoundTripEstimator("unknown", limits).timeoutMs).toBe(1500);
  });

  it("first sample: srtt = R, rttvar = R/2; then rttvar = 3/4 rttvar + 1/4 |srtt - R|, srtt = 7/8 srtt + 1/8 R", () => {
    const rt = new RoundTripEstimator("bluetooth", limits);
    rt.sample(300);
    // 300 + max(4 × 150, 300) = 900.
    expect(rt.snapshot()).toMatchObject({ samples: 1, srttMs: 300, rttvarMs: 150, quickTimeoutMs: 900 });
    rt.sample(200);
    // rttvar = 112.5 + 25 = 137.5; srtt = 262.5 + 25 = 287.5; 287.5 + max(550, 287.5) = 837.5 → 838.
    expect(rt.snapshot()).toMatchObject({
      srttMs: 287.5,
      rttvarMs: 137.5,
      quickTimeoutMs: 838,
      extraMs: 438,
    });
    rt.sample(450);
    // rttvar = 103.125 + 40.625 = 143.75; srtt = 251.5625 + 56.25 = 307.8125; + 575 = 882.8 → 883.
    expect(rt.snapshot()).toMatchObject({ srttMs: 307.8125, rttvarMs: 143.75, quickTimeoutMs: 883 });
  });

  it("never goes below twice the smoothed round trip once the variation has died down", () => {
    const rt = new RoundTripEstimator("bluetooth", limits);
    for (let i = 0; i < 60; i++) rt.sample(300);
    expect(rt.snapshot().rttvarMs).toBeLessThan(1);
    expect(rt.timeoutMs).toBe(600);
  });

  it("keeps a fast link at the floor: 20 ms round trips give 400 ms, as before", () => {
    const rt = new RoundTripEstimator("wired", limits);
    for (let i = 0; i < 10; i++) rt.sample(20 + (i % 3));
    expect(rt.timeoutMs).toBe(400);
    expect(rt.extraMs).toBe(0);
  });

  it("backs off on timeouts in a row (doubling, at most MAX_BACKOFF times, within the ceiling) and recovers on the next reply", () => {
    expect(MAX_BACKOFF).toBe(2);
    const rt = new RoundTripEstimator("bluetooth", limits);
    rt.sample(300); // 900
    rt.timedOut();
    expect(rt.timeoutMs).toBe(1800);
    rt.timedOut();
    expect(rt.timeoutMs).toBe(3600);
    rt.timedOut();
    expect(rt.snapshot()).toMatchObject({ backoff: 2, quickTimeoutMs: 3600 });
    rt.sample(300);
    // rttvar = 112.5, srtt = 300: 300 + max(450, 300) = 750, no back-off.
    expect(rt.snapshot()).toMatchObject({ backoff: 0, quickTimeoutMs: 750 });
    // Before any sample, the first value backs off too, up to the ceiling.
    const fresh = new RoundTripEstimator("unknown", limits);
    fresh.timedOut();
    fresh.timedOut();
    expect(fresh.timeoutMs).toBe(5000);
  });

  it("a wired link's back-off of a small estimate stays under the floor: a lost reply there is not a slow link", () => {
    const rt = new RoundTripEstimator("wired", limits);
    rt.sample(20);
    rt.timedOut();
    rt.timedOut();
    // (20 + max(40, 20)) × 4 = 240 < 400.
    expect(rt.timeoutMs).toBe(400);
    const unmeasured = new RoundTripEstimator("wired", limits);
    unmeasured.timedOut();
    expect(unmeasured.timeoutMs).toBe(400);
  });

  it("with adaptation off, every timeout is the floor whatever was measured", () => {
    const rt = new RoundTripEstimator("bluetooth", limits, false);
    expect(rt.timeoutMs).toBe(400);
    rt.sample(1000);
    rt.timedOut();
    expect(rt.snapshot()).toMatchObject({ adaptive: false, quickTimeoutMs: 400, extraMs: 0 });
  });
});

// ---- The mock's Bluetooth link ----------------------------------------------------------------------

const READ_VERSION = "FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01";
const VERSION_REPLY = "FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 15";

/** Writes `count` version reads, `gapMs` apart, on a raw mock port; returns every read with its time. */
async function deliveries(options: MockSerialPortOptions, count: number, gapMs: number) {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock });
  const port = new MockSerialPort(sim, { clock, ...options });
  await port.open({ baudRate: 115200, bufferSize: 4096 });
  const reader = port.readable!.getReader();
  const writer = port.writable!.getWriter();
  const reads: { at: number; hex: string }[] = [];
  const sent: number[] = [];
  void (async () => {
    for (;;) {
      const { value, done } = await reader.read();
      if (done) return;
      reads.push({ at: clock.now(), hex: toHex(value) });
    }
  })().catch(() => {});
  for (let i = 0; i < count; i++) {
    sent.push(clock.now());
    await writer.write(fromHex(READ_VERSION));
    await clock.advance(gapMs);
  }
  await clock.advance(1000);
  return { reads, sent, port };
}

describe("MockSerialPort as a Bluetooth link", () => {
  it("reports the Serial Port Profile in getInfo()", () => {
    const sim = new SimulatedRbc({ clock: new VirtualClock() });
    const port = new MockSerialPort(sim, bluetoothLinkOptions());
    expect(port.getInfo()).toEqual({ bluetoothServiceClassId: SPP });
    expect(SPP_SERVICE_CLASS_ID).toBe(SPP);
  });

  it("delays each reply by 300 ± 150 ms, the same on every run with the same seed, and keeps their order", async () => {
    const options = { latencyMs: 300, jitterMs: 150, seed: 7 };
    const a = await deliveries(options, 40, 500);
    expect(a.reads).toHaveLength(40);
    const delays = a.reads.map((r, i) => r.at - a.sent[i]!);
    for (const d of delays) {
      expect(d).toBeGreaterThanOrEqual(150);
      expect(d).toBeLessThanOrEqual(450);
    }
    // Really spread over the range, not one value.
    expect(Math.max(...delays) - Math.min(...delays)).toBeGreaterThan(200);
    for (const r of a.reads) expect(r.hex).toBe(VERSION_REPLY);
    const again = await deliveries(options, 40, 500);
    expect(again.reads.map((r) => r.at)).toEqual(a.reads.map((r) => r.at));
    const other = await deliveries({ ...options, seed: 8 }, 40, 500);
    expect(other.reads.map((r) => r.at)).not.toEqual(a.reads.map((r) => r.at));
  });

  it("never lets a reply overtake an earlier one, however the jitter falls", async () => {
    // Requests 5 ms apart with ±150 ms of jitter: many would overtake; none does.
    const { reads, sent } = await deliveries({ latencyMs: 300, jitterMs: 150, seed: 3 }, 30, 5);
    const bytes = reads.map((r) => r.hex).join(" ");
    expect(bytes).toBe(Array(30).fill(VERSION_REPLY).join(" "));
    for (let i = 1; i < reads.length; i++) expect(reads[i]!.at).toBeGreaterThanOrEqual(reads[i - 1]!.at);
    expect(reads[0]!.at - sent[0]!).toBeGreaterThanOrEqual(150);
  });

  it("delivers in bursts: bytes are held to the next 20 ms boundary, and what is due together comes in one read", async () => {
    // Two requests 1 ms apart, 5 ms of latency: both replies are due before the 20 ms boundary.
    const { reads } = await deliveries({ latencyMs: 5, burstMs: 20 }, 2, 1);
    expect(reads).toEqual([{ at: 20, hex: `${VERSION_REPLY} ${VERSION_REPLY}` }]);
    const spread = await deliveries({ ...bluetoothLinkOptions(), seed: 5 }, 20, 100);
    for (const r of spread.reads) expect(r.at % 20).toBe(0);
    expect(spread.reads.map((r) => r.hex).join(" ")).toBe(Array(20).fill(VERSION_REPLY).join(" "));
  });
});

// ---- The whole flow ---------------------------------------------------------------------------------

interface FlowResult {
  error?: unknown;
  /** `client.timeouts` after each step (connect, zeros, upload, run, sensors). */
  timeouts: { quickMs: number; marginMs: number; settleMs: number }[];
  link?: LinkTiming;
}

/** A robot behind a port with `port` options; the client made with `client` options. Not yet connected. */
function rigOver(port: MockSerialPortOptions, client: RbcClientOptions = {}): Promise<Rig> {
  return makeRig({ port, client, connect: false });
}

/**
 * The panel's flow: connect and identify, read the zeros, write a table and read it back, upload wave.rbm
 * (memory reset first), run basic posture then wave, read the distance and the accelerometer, and hold a button
 * subscription across a read. Every result is checked against what the simulated robot holds.
 */
async function flow(rig: Rig): Promise<FlowResult> {
  const { client, sim, run, clock } = rig;
  const timeouts: FlowResult["timeouts"] = [];
  const step = () => {
    const { quickMs, marginMs, settleMs } = client.timeouts;
    timeouts.push({ quickMs, marginMs, settleMs });
  };
  try {
    const identity = await run(client.identify(await run(client.connect())));
    expect(identity).toMatchObject({
      firmware: { major: 2, minor: 23 },
      platform: 1,
      serialNumber: "8958899989309",
    });
    step();

    expect(await run(client.readZeros())).toEqual(sim.zeros);
    const table = STANDARD_ZEROS.map((v, i) => (i === 3 ? v - 4 : v));
    const written = await run(client.writeZeros(table));
    expect(written.readBack).toEqual(table);
    expect(sim.zeros).toEqual(table);
    step();

    const upload = await run(client.uploadMotion(parseRbm(WAVE_TEXT), { resetFirst: true }));
    expect(upload).toMatchObject({ motionNumber: 12, total: WAVE_IMAGE.length, chunks: 10 });
    expect(sim.motions).toHaveLength(1);
    expect(toHex(sim.motions[0]!.bytes)).toBe(toHex(WAVE_IMAGE));
    step();

    expect(await run(client.runMotion(7))).toBe(7);
    expect(await run(client.runMotion(12, { expectedMs: WAVE_MS }))).toBe(12);
    step();

    sim.setDistance(37);
    expect(await run(client.readDistance())).toBe(37);
    sim.setAccelerometer(4, 3, -6);
    expect(await run(client.readAccelerometer())).toEqual({ x: 4, y: 3, z: -6 });
    const events: RbcEvent[] = [];
    const off = client.events.on((e) => events.push(e));
    await run(client.subscribe("buttons"));
    sim.pressButton(2, 800);
    await clock.advance(1500);
    expect(events.length).toBeGreaterThan(0);
    for (const e of events) expect(e).toMatchObject({ kind: "buttons", value: 2 });
    // A read while subscribed: the subscription is armed again after it, and still delivers.
    sim.setDistance(22);
    expect(await run(client.readDistance())).toBe(22);
    events.length = 0;
    sim.pressButton(1, 600);
    await clock.advance(1500);
    expect(events.map((e) => e.value)).toContain(1);
    off();
    await run(client.unsubscribe());
    step();
  } catch (error) {
    return { error, timeouts, link: client.link };
  }
  return { timeouts, link: client.link };
}

describe("the whole flow over a Bluetooth link (300 ± 150 ms, 20 ms bursts)", () => {
  it("completes with no timeout, no unasked or stale reply, and the robot's own results", async () => {
    const rig = await rigOver(bluetoothLinkOptions({ seed: 1 }), { link: "bluetooth" });
    // Nothing measured yet: the first request gets the generous first value.
    expect(rig.client.timeouts.quickMs).toBe(1500);
    const result = await flow(rig);
    expect(result.error).toBeUndefined();
    expect(rig.client.stats).toEqual({ timeouts: 0, unansweredReplies: 0, unaskedReplies: 0, fences: 0 });
    // The link was measured and the timeouts follow it: well above 400 ms, below the ceiling.
    const link = result.link!;
    expect(link.kind).toBe("bluetooth");
    expect(link.samples).toBeGreaterThan(10);
    expect(link.srttMs).toBeGreaterThan(150);
    expect(link.srttMs).toBeLessThan(500);
    for (const t of result.timeouts) {
      expect(t.quickMs).toBeGreaterThan(450);
      expect(t.quickMs).toBeLessThan(5000);
      expect(t.marginMs).toBe(2000 + t.quickMs - 400);
    }
    // The link is still in order for more.
    expect(await rig.run(rig.client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
  });

  it.each([2, 3, 4])("completes the same way with the link's random delays seeded %i", async (seed) => {
    const rig = await rigOver(bluetoothLinkOptions({ seed, baudPacing: true }), { link: "bluetooth" });
    const result = await flow(rig);
    expect(result.error).toBeUndefined();
    expect(rig.client.stats).toEqual({ timeouts: 0, unansweredReplies: 0, unaskedReplies: 0, fences: 0 });
  });

  it("completes on a port that does not say what it is (an unknown link starts generous too)", async () => {
    const rig = await rigOver(bluetoothLinkOptions({ info: {} }), { link: "unknown" });
    const result = await flow(rig);
    expect(result.error).toBeUndefined();
    expect(rig.client.stats.timeouts).toBe(0);
  });

  it("with the fixed timeouts of before (adaptation off), the same flow times out", async () => {
    const rig = await rigOver(bluetoothLinkOptions({ seed: 1 }), {
      link: "bluetooth",
      adaptiveTimeouts: false,
    });
    expect(rig.client.timeouts.quickMs).toBe(400);
    const result = await flow(rig);
    expect(rig.client.stats.timeouts).toBeGreaterThan(0);
    expect(result.link).toMatchObject({ adaptive: false, quickTimeoutMs: 400 });
    for (const t of result.timeouts) expect(t).toEqual(FIXED);
  });

  it("the upload still refuses an acknowledgement sooner than its chunk's wire time", async () => {
    const rig = await rigOver(bluetoothLinkOptions({ seed: 1, baudPacing: true }), { link: "bluetooth" });
    await rig.run(rig.client.connect());
    // A stray `40` 2 ms after chunk 3's own: chunk 4 (65 bytes, 5.6 ms on the wire) has only just been written.
    armAtReply(rig.port, 2 + 3, (f) => f.strayAfterReply([0x40], 2));
    const e = await rig.fail(rig.client.writeMotion(WAVE_IMAGE));
    expect(e).toBeInstanceOf(RbcUploadError);
    expect((e as RbcUploadError).outcome).toBe("nothing-recorded");
    expect((e as RbcUploadError).cause).toBeInstanceOf(RbcUnexpectedAckError);
    expect((e as RbcUploadError).facts?.stop).toBe("early-ack");
    expect(errorText(e, "en")).toMatch(/sooner than its part could have reached the robot/);
    expect(rig.sim.motions).toHaveLength(0);
    // And a clean upload over the same link is confirmed by the robot's memory.
    rig.port.faults.clear();
    const ok = await rig.run(rig.client.writeMotion(WAVE_IMAGE));
    expect(ok.freeAfter).toBe(24_576 - 640);
  });
});

describe("a USB-like link (115200 baud, 16 ms adapter latency) keeps its fixed timeouts", () => {
  it("runs the same flow with quick 400 ms, margin 2,000 ms and settle 50 ms at every step", async () => {
    const rig = await rigOver({ baudPacing: true, latencyMs: 16 });
    expect(rig.client.timeouts).toMatchObject(FIXED);
    const result = await flow(rig);
    expect(result.error).toBeUndefined();
    expect(rig.client.stats).toEqual({ timeouts: 0, unansweredReplies: 0, unaskedReplies: 0, fences: 0 });
    expect(result.timeouts).toHaveLength(5);
    for (const t of result.timeouts) expect(t).toEqual(FIXED);
    expect(result.link).toMatchObject({ kind: "wired", quickTimeoutMs: 400, extraMs: 0 });
    expect(result.link!.srttMs).toBeLessThan(30);
  });
});

// ---- The chooser ------------------------------------------------------------------------------------

describe("the chooser offers Bluetooth serial ports", () => {
  const usbPort = () => new MockSerialPort(new SimulatedRbc({ clock: new VirtualClock() }));
  const btPort = (options: MockSerialPortOptions = {}) =>
    new MockSerialPort(new SimulatedRbc({ clock: new VirtualClock() }), bluetoothLinkOptions(options));

  it("asks for the USB adapters and the Serial Port Profile, and lists a paired module", async () => {
    expect(SERIAL_PORT_PROFILE).toBe(SPP);
    const bt = btPort();
    const serial = new FakeSerial([bt]);
    expect(await choosePort(serial, false)).toBe(bt);
    expect(serial.requests).toEqual([
      {
        filters: [...PORT_FILTERS, { bluetoothServiceClassId: SPP }],
        allowedBluetoothServiceClassIds: [SPP],
      },
    ]);
    expect(chooserOptions(true)).toEqual({ allowedBluetoothServiceClassIds: [SPP] });
  });

  it("on a browser before Chrome 117 (the Bluetooth filter is empty to it), opens the USB chooser instead", async () => {
    const usb = usbPort();
    const serial = new FakeSerial([btPort(), usb]);
    serial.bluetoothSupported = false;
    expect(await choosePort(serial, false)).toBe(usb);
    expect(serial.requests).toHaveLength(2);
    expect(serial.requests[1]).toEqual({ filters: PORT_FILTERS });
  });

  it("does not retry when the person cancels the chooser", async () => {
    const serial = new FakeSerial([usbPort()]);
    serial.userCancels = true;
    await expect(choosePort(serial, false)).rejects.toMatchObject({ name: "NotFoundError" });
    expect(serial.requests).toHaveLength(1);
  });

  it("lists a Bluetooth port of another service class only when the page allows that class", async () => {
    const custom = "01234567-89ab-cdef-0123-456789abcdef";
    const serial = new FakeSerial([btPort({ info: { bluetoothServiceClassId: custom } })]);
    await expect(serial.requestPort()).rejects.toMatchObject({ name: "NotFoundError" });
    await expect(serial.requestPort({ allowedBluetoothServiceClassIds: [custom] })).resolves.toBeDefined();
  });

  it("names ports and tells their link", () => {
    expect(describePort({ bluetoothServiceClassId: SPP })).toBe("Bluetooth serial port");
    expect(describePort({ usbVendorId: 0x0403, usbProductId: 0x6001 })).toBe(
      "FTDI USB serial adapter (0403:6001)",
    );
    expect(linkKindOf({ bluetoothServiceClassId: SPP })).toBe("bluetooth");
    expect(linkKindOf({ usbVendorId: 0x1a86, usbProductId: 0x7523 })).toBe("wired");
    expect(linkKindOf({})).toBe("unknown");
  });
});
