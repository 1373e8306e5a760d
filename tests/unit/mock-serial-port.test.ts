import { describe, expect, it } from "vitest";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import { linkReasonText } from "../../src/i18n/outcomes/link-words.ts";
import { LinkError, WebSerialTransport } from "../../src/link/index.ts";
import { fromHex, toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import {
  BYTE_TIME_MS,
  FakeSerial,
  MockSerialPort,
  type MockSerialPortOptions,
  SimulatedRbc,
} from "../../src/sim/index.ts";

const READ_VERSION = "FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01";
const VERSION_REPLY = "FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 15";
const OPTIONS: SerialOptions = {
  baudRate: 115200,
  dataBits: 8,
  stopBits: 1,
  parity: "none",
  flowControl: "none",
  bufferSize: 4096,
};

function rig(options: MockSerialPortOptions = {}) {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock });
  const port = new MockSerialPort(sim, { clock, ...options });
  return { clock, sim, port };
}

/** Opens the port and reads everything into `chunks` in the background. */
async function openAndRead(port: MockSerialPort, options: SerialOptions = OPTIONS) {
  await port.open(options);
  const reader = port.readable!.getReader();
  const writer = port.writable!.getWriter();
  const chunks: string[] = [];
  const state: { error: unknown; done: boolean } = { error: undefined, done: false };
  const loop = (async () => {
    try {
      for (;;) {
        const { value, done } = await reader.read();
        if (done) break;
        chunks.push(toHex(value));
      }
      state.done = true;
    } catch (e) {
      state.error = e;
    }
  })();
  const write = (hex: string) => writer.write(fromHex(hex));
  return { reader, writer, chunks, state, loop, write };
}

describe("MockSerialPort: lifecycle (Web Serial rules)", () => {
  it("opens with the given options, refuses a second open, closes, and opens again", async () => {
    const { port } = rig();
    expect(port.readable).toBeNull();
    expect(port.writable).toBeNull();
    await port.open(OPTIONS);
    expect(port.openOptions).toEqual(OPTIONS);
    await expect(port.open(OPTIONS)).rejects.toMatchObject({ name: "InvalidStateError" });
    expect(port.readable).toBeInstanceOf(ReadableStream);
    expect(port.writable).toBeInstanceOf(WritableStream);
    await port.close();
    expect(port.readable).toBeNull();
    await expect(port.close()).rejects.toMatchObject({ name: "InvalidStateError" });
    await port.open({ baudRate: 115200 });
    expect(port.openOptions).toMatchObject({ baudRate: 115200, bufferSize: 255, dataBits: 8, stopBits: 1 });
    expect(port.stats).toMatchObject({ opens: 2, closes: 1 });
  });

  it("rejects bad options with a TypeError", async () => {
    const { port } = rig();
    await expect(port.open({ baudRate: 0 })).rejects.toBeInstanceOf(TypeError);
    await expect(port.open({ baudRate: 115200, bufferSize: 0 })).rejects.toBeInstanceOf(TypeError);
    expect(port.isOpen).toBe(false);
  });

  it("refuses to close while a stream is locked (TypeError), closes after release", async () => {
    const { port } = rig();
    await port.open(OPTIONS);
    const reader = port.readable!.getReader();
    await expect(port.close()).rejects.toBeInstanceOf(TypeError);
    expect(port.isOpen).toBe(true);
    reader.releaseLock();
    const writer = port.writable!.getWriter();
    await expect(port.close()).rejects.toBeInstanceOf(TypeError);
    writer.releaseLock();
    await port.close();
    expect(port.isOpen).toBe(false);
  });

  it("gives a new readable after the reader cancels (like Chrome), and keeps bytes that arrived meanwhile", async () => {
    const { port, sim } = rig();
    await port.open(OPTIONS);
    const first = port.readable!;
    await first.getReader().cancel();
    sim.receive(fromHex(READ_VERSION)); // the reply arrives with no readable
    const second = port.readable!;
    expect(second).not.toBe(first);
    const { value } = await second.getReader().read();
    expect(toHex(value!)).toBe(VERSION_REPLY);
  });

  it("answers getInfo with an FTDI adapter by default", () => {
    expect(rig().port.getInfo()).toEqual({ usbVendorId: 0x0403, usbProductId: 0x6001 });
    expect(rig({ info: { usbVendorId: 0x10c4 } }).port.getInfo()).toEqual({ usbVendorId: 0x10c4 });
  });

  it("has harmless signals while open", async () => {
    const { port } = rig();
    await expect(port.getSignals()).rejects.toMatchObject({ name: "InvalidStateError" });
    await port.open(OPTIONS);
    await port.setSignals({ dataTerminalReady: false });
    expect(port.outputSignals.dataTerminalReady).toBe(false);
    expect((await port.getSignals()).clearToSend).toBe(true);
  });
});

describe("MockSerialPort: traffic and timing", () => {
  it("carries a request to the robot and its reply back, counting bytes and logging chunks", async () => {
    const { port, clock } = rig();
    const io = await openAndRead(port);
    await io.write(READ_VERSION);
    await clock.advance(0);
    expect(io.chunks).toEqual([VERSION_REPLY]);
    expect(port.stats).toMatchObject({ bytesFromPc: 16, bytesToPc: 17 });
    expect(port.written.map(toHex)).toEqual([READ_VERSION]);
    expect(port.delivered.map(toHex)).toEqual([VERSION_REPLY]);
  });

  it("paces bytes at 86.8 µs each way and adds the adapter latency", async () => {
    const { port, sim, clock } = rig({ baudPacing: true, latencyMs: 16 });
    const io = await openAndRead(port);
    // 84 garbage bytes then the 16-byte request: 100 bytes take 8.68 ms to reach the robot.
    await io.write(`${"00 ".repeat(84)}${READ_VERSION}`);
    await clock.advance(8.6);
    expect(sim.stats.bytesReceived).toBe(0);
    await clock.advance(0.1);
    expect(sim.stats.bytesReceived).toBe(100);
    // The 17-byte reply takes 1.48 ms on the wire, then 16 ms of adapter latency: 26.16 ms in all.
    expect(100 * BYTE_TIME_MS + 17 * BYTE_TIME_MS + 16).toBeCloseTo(26.16, 2);
    await clock.advance(26.1 - 8.7);
    expect(io.chunks).toEqual([]);
    await clock.advance(0.1);
    expect(io.chunks).toEqual([VERSION_REPLY]);
  });

  it("serializes writes on the wire", async () => {
    const { port, sim, clock } = rig({ baudPacing: true });
    const io = await openAndRead(port);
    await io.write(READ_VERSION);
    await io.write(READ_VERSION);
    await clock.advance(16 * BYTE_TIME_MS + 0.001);
    expect(sim.stats.bytesReceived).toBe(16);
    await clock.advance(16 * BYTE_TIME_MS);
    expect(sim.stats.bytesReceived).toBe(32);
  });

  it("delivers nothing either way at a baud rate other than 115200, and counts it", async () => {
    const { port, sim, clock } = rig();
    const io = await openAndRead(port, { ...OPTIONS, baudRate: 57600 });
    await io.write(READ_VERSION);
    sim.receive(fromHex(READ_VERSION)); // even if the robot did answer, nothing would get through
    await clock.advance(100);
    expect(sim.stats.bytesReceived).toBe(16);
    expect(io.chunks).toEqual([]);
    expect(port.stats).toMatchObject({ baudMismatchBytes: 16, bytesLost: 17, bytesToPc: 0 });
  });
});

describe("MockSerialPort: faults (docs/protocol.md §9)", () => {
  async function withFault(setUp: (port: MockSerialPort) => void, advance = 0) {
    const { port, clock } = rig();
    setUp(port);
    const io = await openAndRead(port);
    await io.write(READ_VERSION);
    await clock.advance(advance);
    const first = [...io.chunks];
    io.chunks.length = 0;
    await io.write(READ_VERSION);
    await clock.advance(advance);
    return { first, second: io.chunks, port, clock, io };
  }

  it("drops one byte of the next reply", async () => {
    const { first, second } = await withFault((p) => p.faults.dropByte(8));
    expect(first).toEqual(["FF FF AA 55 AA 55 37 BA 01 00 00 00 02 02 17 15"]);
    expect(second).toEqual([VERSION_REPLY]);
  });

  it("corrupts one byte (XOR 01 by default, or a set value)", async () => {
    expect((await withFault((p) => p.faults.corruptByte(16))).first).toEqual([
      "FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 14",
    ]);
    expect((await withFault((p) => p.faults.corruptByte(15, { value: 0x0f }))).first).toEqual([
      "FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 0F 15",
    ]);
  });

  it("splits replies into chunks until cleared", async () => {
    const { first, second, port } = await withFault((p) => p.faults.splitReplies(1));
    expect(first).toEqual(VERSION_REPLY.split(" "));
    expect(second).toEqual(VERSION_REPLY.split(" "));
    expect(port.faults.active).toHaveLength(1);
    port.faults.clear();
    expect(port.faults.active).toEqual([]);
    const { first: sixes } = await withFault((p) => p.faults.splitReplies(6, 1));
    expect(sixes.map((c) => c.split(" ").length)).toEqual([6, 6, 5]);
  });

  it("delays a reply, and later replies do not overtake it", async () => {
    const { port, sim, clock } = rig();
    port.faults.delayReplies(50);
    const io = await openAndRead(port);
    await io.write(READ_VERSION);
    sim.setDistance(20);
    await io.write("FF FF AA 55 AA 55 37 BA 16 00 00 00 00 01 01 01");
    await clock.advance(49);
    expect(io.chunks).toEqual([]);
    await clock.advance(1);
    expect(io.chunks).toEqual([VERSION_REPLY, "FF FF AA 55 AA 55 37 BA 16 01 00 00 00 02 14 00 14"]);
  });

  it("swallows the next N replies", async () => {
    const { port, clock } = rig();
    port.faults.swallowReplies(2);
    const io = await openAndRead(port);
    for (let i = 0; i < 3; i++) await io.write(READ_VERSION);
    await clock.advance(0);
    expect(io.chunks).toEqual([VERSION_REPLY]);
  });

  it("sends garbage before the next reply's header", async () => {
    const { first, second } = await withFault((p) => p.faults.garbageBeforeReply([0x00, 0xff, 0x55]));
    expect(first).toEqual([`00 FF 55 ${VERSION_REPLY}`]);
    expect(second).toEqual([VERSION_REPLY]);
  });

  it("delivers a stray byte unasked a set time after the next reply, without holding later replies", async () => {
    const { port, clock } = rig();
    port.faults.strayAfterReply([0x40], 5);
    const io = await openAndRead(port);
    await io.write(READ_VERSION);
    await clock.advance(4);
    expect(io.chunks).toEqual([VERSION_REPLY]);
    await io.write(READ_VERSION);
    await clock.advance(0);
    // The second reply is not held back behind the stray.
    expect(io.chunks).toEqual([VERSION_REPLY, VERSION_REPLY]);
    await clock.advance(1);
    expect(io.chunks).toEqual([VERSION_REPLY, VERSION_REPLY, "40"]);
    expect(port.faults.active).toEqual([]);
  });

  it("delivers the next reply twice, the copy a set time later (as sent, damage included)", async () => {
    const { port, clock } = rig();
    port.faults.duplicateReplies(3).corruptByte(16);
    const io = await openAndRead(port);
    await io.write(READ_VERSION);
    await clock.advance(2);
    const damaged = "FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 14";
    expect(io.chunks).toEqual([damaged]);
    await clock.advance(1);
    expect(io.chunks).toEqual([damaged, damaged]);
    await io.write(READ_VERSION);
    await clock.advance(10);
    expect(io.chunks).toEqual([damaged, damaged, VERSION_REPLY]);
  });

  it("repeats a reply unasked: copies at every interval", async () => {
    const { port, clock } = rig();
    port.faults.duplicateReplies(2, 1, 3);
    const io = await openAndRead(port);
    await io.write(READ_VERSION);
    await clock.advance(0);
    expect(io.chunks).toHaveLength(1);
    await clock.advance(4);
    expect(io.chunks).toHaveLength(3);
    await clock.advance(2);
    expect(io.chunks).toEqual([VERSION_REPLY, VERSION_REPLY, VERSION_REPLY, VERSION_REPLY]);
    expect(port.stats.bytesToPc).toBe(4 * 17);
  });

  it("a download acknowledgement duplicated at once arrives as a second 40", async () => {
    const { port, clock } = rig();
    port.faults.duplicateReplies(0);
    const io = await openAndRead(port);
    // The first part of a 538-byte motion download (docs/protocol.md §6.3): the robot answers one 40.
    await io.write("FF FF AA 55 AA 55 37 BA 01 00 00 00 02 1A");
    await clock.advance(0);
    expect(io.chunks).toEqual(["40", "40"]);
  });

  it("injects bytes to the PC at a chosen moment, whatever the robot does", async () => {
    const { port, clock } = rig();
    const io = await openAndRead(port);
    port.injectToPc([0x40, 0x40], 7);
    await clock.advance(6);
    expect(io.chunks).toEqual([]);
    await clock.advance(1);
    expect(io.chunks).toEqual(["40 40"]);
    expect(() => port.injectToPc([0x40], -1)).toThrow(RangeError);
    expect(() => port.faults.duplicateReplies(1, 1, 0)).toThrow(RangeError);
    expect(() => port.faults.strayAfterReply([0x40], -2)).toThrow(RangeError);
  });

  it("unplugs once the PC has written a given byte count (mid-write)", async () => {
    const { port, sim, clock } = rig();
    const disconnects: Event[] = [];
    port.addEventListener("disconnect", (e) => disconnects.push(e));
    port.faults.disconnectAfterPcBytes(20);
    const io = await openAndRead(port);
    await io.write(READ_VERSION);
    await expect(io.write(READ_VERSION)).rejects.toMatchObject({ name: "NetworkError" });
    await clock.advance(0);
    expect(sim.stats.bytesReceived).toBe(20);
    expect(port.stats.bytesFromPc).toBe(20);
    expect(port.connected).toBe(false);
    expect(disconnects).toHaveLength(1);
    expect(io.state.error).toMatchObject({ name: "NetworkError", message: "The device has been lost." });
  });
});

describe("MockSerialPort: cable pull", () => {
  it("errors the pending read, rejects writes, fires disconnect; replug lets it open again", async () => {
    const { port, clock } = rig();
    const events: string[] = [];
    port.addEventListener("disconnect", () => events.push("disconnect listener"));
    port.addEventListener("connect", () => events.push("connect listener"));
    port.ondisconnect = () => events.push("ondisconnect");
    const io = await openAndRead(port);
    port.unplug();
    await clock.advance(0);
    expect(io.state.error).toBeInstanceOf(DOMException);
    expect(io.state.error).toMatchObject({ name: "NetworkError", message: "The device has been lost." });
    await expect(io.write(READ_VERSION)).rejects.toMatchObject({ name: "NetworkError" });
    expect(port.connected).toBe(false);
    expect(port.readable).toBeNull();
    expect(events).toEqual(["disconnect listener", "ondisconnect"]);
    // Like Chrome: the port is closed by the loss, so close() says so, and open() fails while unplugged.
    await expect(port.close()).rejects.toMatchObject({ name: "InvalidStateError" });
    await expect(port.open(OPTIONS)).rejects.toMatchObject({ name: "NetworkError" });
    port.replug();
    expect(events.at(-1)).toBe("connect listener");
    const again = await openAndRead(port);
    await again.write(READ_VERSION);
    await clock.advance(0);
    expect(again.chunks).toEqual([VERSION_REPLY]);
  });

  it("drops replies that were in flight when the cable was pulled", async () => {
    const { port, clock } = rig({ latencyMs: 16 });
    await openAndRead(port);
    port.sim.receive(fromHex(READ_VERSION)); // the reply is due 16 ms later
    expect(port.stats.bytesToPc).toBe(0);
    port.unplug();
    await clock.advance(100);
    expect(port.stats.bytesToPc).toBe(0);
  });
});

describe("FakeSerial", () => {
  it("grants a matching port, lists it, and rejects when nothing matches or the user cancels", async () => {
    const { port } = rig();
    const serial = new FakeSerial([port]);
    expect(await serial.getPorts()).toEqual([]);
    expect(await serial.requestPort({ filters: [{ usbVendorId: 0x0403 }] })).toBe(port);
    expect(await serial.getPorts()).toEqual([port]);
    await expect(serial.requestPort({ filters: [{ usbVendorId: 0x2341 }] })).rejects.toMatchObject({
      name: "NotFoundError",
      message: "No port selected by the user.",
    });
    serial.rejectNextRequest();
    await expect(serial.requestPort()).rejects.toMatchObject({ name: "NotFoundError" });
    expect(await serial.requestPort()).toBe(port);
    serial.userCancels = true;
    await expect(serial.requestPort()).rejects.toMatchObject({ name: "NotFoundError" });
    await port.forget();
    expect(await serial.getPorts()).toEqual([]);
  });

  it("re-dispatches the ports' connect and disconnect events", () => {
    const { port } = rig();
    const serial = new FakeSerial([port], { granted: true });
    const seen: string[] = [];
    serial.addEventListener("disconnect", (e) => seen.push(e.type));
    serial.onconnect = (e) => seen.push(`on${e.type}`);
    port.unplug();
    port.replug();
    expect(seen).toEqual(["disconnect", "onconnect"]);
  });
});

describe("the Web Serial transport's failures: a code and facts, worded by the outcome catalogue", () => {
  it("opening an open port, and writing to a closed one", async () => {
    const { port } = rig();
    const link = new WebSerialTransport(port);
    await link.open();
    const again = await link.open().catch((e: unknown) => e);
    expect(again).toBeInstanceOf(LinkError);
    expect(again).toMatchObject({ code: "open-failed", facts: { reason: "already-open" } });
    expect((again as LinkError).message).toBe("link: open-failed (already-open)");
    expect(errorText(again, "en")).toBe("The port is already open.");
    expect(errorText(again, "ko")).toBe("포트가 이미 열려 있어요.");
    await link.close();
    const closed = await link.write(Uint8Array.of(1)).catch((e: unknown) => e);
    expect(closed).toMatchObject({ code: "not-open", facts: { reason: "not-open" } });
    expect(errorText(closed, "en")).toBe("The port is not open.");
  });

  it("a lost link says why as a cause the device words", async () => {
    const { port, clock } = rig();
    const link = new WebSerialTransport(port);
    const events: unknown[] = [];
    link.onStatus((e) => events.push(e));
    await link.open();
    port.unplug();
    await clock.advance(0);
    const lost = events.find((e) => (e as { status: string }).status === "lost");
    expect(lost).toMatchObject({
      cause: { reason: "usb-unplugged" },
      reason: "link: disconnected (usb-unplugged)",
    });
    expect(linkReasonText({ reason: "usb-unplugged" }, "en")).toBe(
      "The USB cable was unplugged or the adapter was removed.",
    );
    expect(
      linkReasonText({ reason: "busy-or-denied", path: "/dev/ttyUSB0", detail: "Resource busy" }, "ko"),
    ).toBe(
      "/dev/ttyUSB0을(를) 다른 프로그램이 쓰고 있거나 사용 권한이 없어요 (Resource busy). 그 포트를 쓰는 다른 프로그램을 닫아 주세요. Linux에서는 사용자를 dialout 그룹에 추가해 주세요.",
    );
  });
});
