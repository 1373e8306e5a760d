import { describe, expect, it } from "vitest";
import type { LogEntry } from "../../src/device/index.ts";
import { fromHex } from "../../src/protocol/index.ts";
import {
  DISCARD_PREVIEW_BYTES,
  ENTRY_BYTES,
  formatLogLine,
  logAsText,
  PacketLog,
} from "../../src/ui/features/log/packet-log.ts";
import { EX } from "../fixtures/protocol-examples.ts";
import { makeRig } from "../support/rig.ts";

/**
 * The packet log keeps bytes and coalesces garbage (issue #10 item 6). Discards are fed the way the panel feeds
 * them: the client's parser reports them on `client.log`, and the session pushes every entry into the PacketLog.
 * Heap figures are in the bench (bench/log-memory.ts), not here.
 */

const MiB = 1024 * 1024;

/** A connected client whose log feeds a PacketLog, as src/ui/session.ts does. */
async function loggedRig(log = new PacketLog()) {
  const rig = await makeRig({ port: { record: false } });
  rig.client.log.on((entry) => log.push(entry));
  return { ...rig, log };
}

/**
 * 1 MiB of nested bad frames: a header with a size far above what type 0x1F may carry (rejected as oversize), a
 * distance-shaped frame with a bad checksum whose contents start another header, and bare repeated
 * `FF FF AA 55 AA 55` runs; zero padding to exactly 1 MiB so no frame is left open when the real reply comes.
 */
function nestedGarbage(): { bytes: Uint8Array; oversize: number; badChecksum: number } {
  const oversizeFrame = fromHex("FF FF AA 55 AA 55 37 BA 1F 01 00 00 0F 00");
  const badFrame = fromHex("FF FF AA 55 AA 55 37 BA 16 01 00 00 00 02 FF FF AA");
  const bare = fromHex("FF FF AA 55 AA 55 FF FF AA 55 AA 55");
  const patterns = [oversizeFrame, badFrame, bare];
  const bytes = new Uint8Array(MiB);
  let at = 0;
  let oversize = 0;
  let badChecksum = 0;
  for (let i = 0; ; i++) {
    const p = patterns[i % patterns.length]!;
    if (at + p.length + 64 > bytes.length) break;
    bytes.set(p, at);
    at += p.length;
    if (p === oversizeFrame) oversize++;
    if (p === badFrame) badChecksum++;
  }
  return { bytes, oversize, badChecksum }; // the rest stays 00
}

describe("the packet log coalesces discarded bytes", () => {
  it("1 MiB of nested bad frames before a reply makes at most 100 entries, one of them the whole run", async () => {
    const { client, run, port, sim, log } = await loggedRig();
    log.clear();
    sim.setDistance(23);
    const garbage = nestedGarbage();
    port.faults.garbageBeforeReply(garbage.bytes).splitReplies(4096, 1);
    expect(await run(client.readDistance())).toBe(23);

    expect(log.size).toBeLessThanOrEqual(100);
    const lines = log.lines();
    expect(lines.map((l) => `${l.direction} ${l.kind} ${l.name}`)).toEqual([
      "out packet Distance sensor",
      "in discard Discarded bytes",
      "in packet Distance sensor",
    ]);
    const run1 = lines[1]!;
    // Every byte that reached the PC before the reply, counted once although the parser rescans rejected frames.
    expect(run1.byteCount).toBe(MiB);
    expect(run1.tally).toMatchObject({ oversize: garbage.oversize, badChecksum: garbage.badChecksum });
    // The preview is the first bytes exactly as they arrived, though the parser reported many of them twice.
    expect(run1.bytes).toEqual(garbage.bytes.subarray(0, DISCARD_PREVIEW_BYTES));
    expect(run1.hex.startsWith("FF FF AA 55 AA 55 37 BA 1F 01 00 00 0F 00 FF FF")).toBe(true);
    expect(run1.hex.endsWith(" …")).toBe(true);
    expect(formatLogLine(run1)).toContain("(1,048,576 bytes)");
    expect(run1.note).toContain(`${garbage.oversize.toLocaleString("en-US")} frames too long for their type`);
    expect(lines[2]!.hex).toBe(EX.distance10.replace("0A 00 0A", "17 00 17"));
  });

  it("counts stray bytes, a bad frame and more stray bytes as one run of their exact size, in wire order", async () => {
    const { client, run, port, log } = await loggedRig();
    log.clear();
    const stray = fromHex("01 02 03 04 05");
    const badFrame = fromHex("FF FF AA 55 AA 55 37 BA 16 01 00 00 00 02 1E 00 00"); // checksum should be 1E
    const tail = fromHex("06 07");
    port.faults.garbageBeforeReply([...stray, ...badFrame, ...tail]);
    await run(client.readDistance());
    port.faults.garbageBeforeReply(fromHex("09 09 09"));
    await run(client.readDistance());

    const discards = log.lines().filter((l) => l.kind === "discard");
    expect(discards.map((l) => l.byteCount)).toEqual([24, 3]);
    expect(discards[0]!.hex).toBe(
      `01 02 03 04 05 ${"FF FF AA 55 AA 55 37 BA 16 01 00 00 00 02 1E 00 00"} 06 07`,
    );
    expect(discards[0]!.tally).toMatchObject({ badChecksum: 1, oversize: 0 });
    expect(discards[0]!.note).toBe("1 frame with a bad checksum, stray bytes");
    expect(discards[1]!.hex).toBe("09 09 09");
    expect(discards[1]!.note).toBe("stray bytes");
    // A packet between two runs keeps them apart: 2 reads = 2 requests, 2 runs, 2 replies.
    expect(log.lines().map((l) => l.kind)).toEqual([
      "packet",
      "discard",
      "packet",
      "packet",
      "discard",
      "packet",
    ]);
  });
});

describe("the packet log shows what crossed the wire", () => {
  it("keeps the raw frames: the request and the version reply as docs/protocol.md §8 writes them", async () => {
    const { client, run, log } = await loggedRig();
    log.clear();
    await run(client.readFirmwareVersion());
    expect(log.lines().map((l) => l.hex)).toEqual([EX.readVersion, EX.version223]);
    expect(log.lines().map((l) => l.byteCount)).toEqual([16, 17]);
  });

  it("keeps the accelerometer's firmware checksum FD as it arrived", async () => {
    const { client, run, sim, log } = await loggedRig();
    log.clear();
    sim.setAccelerometer(4, 3, -6);
    await run(client.readAccelerometer());
    const reply = log.lines()[1]!;
    expect(reply.hex).toBe(EX.accel);
    expect(logAsText([reply])).toContain(`Accelerometer (21 bytes)  ${EX.accel}\n`);
  });

  it("keeps bytes, not text: no entry holds its hex", async () => {
    const { client, run, log } = await loggedRig();
    await run(client.readFirmwareVersion());
    for (const line of log.lines()) {
      const strings = Object.values(line).filter((v): v is string => typeof v === "string");
      expect(strings.some((s) => /[0-9A-F]{2} [0-9A-F]{2}/.test(s))).toBe(false);
      expect(line.bytes).toBeInstanceOf(Uint8Array);
    }
  });
});

function packet(n: number, size = 2, direction: "in" | "out" = "out"): LogEntry {
  return {
    time: n,
    direction,
    kind: "packet",
    type: 0x12,
    name: `packet ${n}`,
    bytes: new Uint8Array(size).fill(n),
  };
}

describe("the packet log is bounded", () => {
  it("holds at most its capacity, drops the oldest and counts them", () => {
    const log = new PacketLog(10);
    for (let i = 1; i <= 25; i++) log.push(packet(i));
    expect(log.size).toBe(10);
    expect(log.dropped).toBe(15);
    expect(log.lines().map((l) => l.name)).toEqual(Array.from({ length: 10 }, (_, i) => `packet ${i + 16}`));
  });

  it("holds at most its byte budget, dropping the oldest entries", () => {
    const log = new PacketLog(100, (ms) => ms, 1000);
    for (let i = 1; i <= 10; i++) log.push(packet(i, 300));
    expect(log.bytesKept).toBe(900);
    expect(log.size).toBe(3);
    expect(log.dropped).toBe(7);
    expect(log.lines()[0]!.name).toBe("packet 8");
  });

  it("keeps the first 4,111 bytes of a larger raw chunk and says so, counting all of them", () => {
    const log = new PacketLog();
    log.push({
      time: 0,
      direction: "in",
      kind: "raw",
      name: "download",
      bytes: new Uint8Array(10_000).fill(0x40),
    });
    const [line] = log.lines();
    expect(line!.bytes.length).toBe(ENTRY_BYTES);
    expect(line!.byteCount).toBe(10_000);
    expect(line!.note).toBe("first 4,111 bytes shown");
    expect(formatLogLine(line!)).toContain("download — first 4,111 bytes shown (10,000 bytes)  40 40");
  });

  it("keeps every entry's bytes intact while its byte store is compacted and entries are dropped", () => {
    const log = new PacketLog(50, (ms) => ms, 4096);
    const bytesOf = (i: number) => Uint8Array.from({ length: 1 + (i % 97) }, (_, k) => (i * 7 + k) & 0xff);
    for (let i = 1; i <= 3000; i++) {
      log.push({ time: i, direction: "out", kind: "packet", name: `p${i}`, bytes: bytesOf(i) });
      if (i % 500 === 0)
        log.push({ time: i, direction: "in", kind: "discard", name: "garbage", bytes: bytesOf(i) });
    }
    expect(log.bytesKept).toBeLessThanOrEqual(4096);
    expect(log.size).toBeLessThanOrEqual(50);
    for (const line of log.lines()) {
      const i = Number(line.name.slice(1));
      if (line.kind === "packet") expect(line.bytes).toEqual(bytesOf(i));
      else expect(line.bytes).toEqual(bytesOf(3000));
    }
    expect(log.lines().at(-1)?.kind).toBe("discard");
  });

  it("copies what it keeps, so a caller reusing its buffer does not change the log", () => {
    const log = new PacketLog();
    const bytes = fromHex("01 02 03");
    log.push({ time: 0, direction: "out", kind: "raw", name: "chunk", bytes });
    bytes[0] = 0xee;
    expect(log.lines()[0]!.hex).toBe("01 02 03");
  });

  it("pages newest first, and a page anchored to an entry does not move when new entries come", () => {
    const log = new PacketLog();
    for (let i = 1; i <= 250; i++) log.push(packet(i));
    expect(log.window(undefined, 0, 100).map((l) => l.seq)).toEqual(range(250, 151));
    const anchor = log.newestSeq;
    for (let i = 251; i <= 260; i++) log.push(packet(i));
    expect(log.countUpTo(anchor)).toBe(250);
    expect(log.window(anchor, 100, 100).map((l) => l.seq)).toEqual(range(150, 51));
    expect(log.window(anchor, 200, 100).map((l) => l.seq)).toEqual(range(50, 1));
    expect(log.newest(3).map((l) => l.seq)).toEqual([260, 259, 258]);
  });

  it("refuses a capacity or byte budget that makes no sense", () => {
    expect(() => new PacketLog(0)).toThrow(RangeError);
    expect(() => new PacketLog(10, (ms) => ms, 0)).toThrow(RangeError);
  });
});

function range(from: number, to: number): number[] {
  return Array.from({ length: from - to + 1 }, (_, i) => from - i);
}
