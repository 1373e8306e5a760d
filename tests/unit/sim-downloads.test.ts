import { describe, expect, it } from "vitest";
import { fromHex, toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { SimulatedRbc, type SimulatedRbcOptions } from "../../src/sim/index.ts";
import { goldenImage } from "../data/project-data.ts";

const H = "FF FF AA 55 AA 55 37 BA";
/** docs/protocol.md §6.3: the first part of examples/wave.rbm's 624-byte image. */
const WAVE_FIRST_PART = "FF FF AA 55 AA 55 37 BA 01 00 00 00 02 70";
const WAVE_CHUNK_CHECKSUMS = ["A4", "ED", "84", "9A", "BC", "5E", "C1", "94", "73", "ED"];
const READ_FREE_MOTION = `${H} 0F 00 00 00 00 01 01 01`;
const READ_FREE_ACTION = `${H} 0F 00 00 00 00 01 02 02`;
const READ_ERROR = `${H} 11 00 00 00 00 01 01 01`;
const READ_VERSION = `${H} 12 00 00 00 00 01 01 01`;
const VERSION_REPLY = `${H} 12 01 00 00 00 02 02 17 15`;

/** tests/data/images/wave.img.hex: the golden image of examples/wave.rbm (16 hex bytes a line). */
const WAVE_IMAGE = goldenImage("wave.rbm");

function rig(options: SimulatedRbcOptions = {}) {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock, ...options });
  const out: string[] = [];
  sim.onTransmit((bytes) => out.push(toHex(bytes)));
  const send = (bytes: string | Uint8Array) =>
    sim.receive(typeof bytes === "string" ? fromHex(bytes) : bytes);
  const take = () => out.splice(0, out.length);
  return { clock, sim, send, take };
}

/** `payload` as download chunks: up to 64 bytes, each followed by its XOR. */
function chunks(payload: Uint8Array): Uint8Array[] {
  const out: Uint8Array[] = [];
  for (let o = 0; o < payload.length; o += 64) {
    const part = payload.subarray(o, Math.min(o + 64, payload.length));
    const chunk = new Uint8Array(part.length + 1);
    chunk.set(part);
    chunk[part.length] = part.reduce((x, b) => x ^ b, 0);
    out.push(chunk);
  }
  return out;
}

/** First part for a download of `size` bytes of type 01 (motion) or 02 (action). */
function firstPart(type: 1 | 2, size: number): Uint8Array {
  const out = fromHex(`${H} 0${type} 00 00 00 00 00`);
  out[10] = size >>> 24;
  out[11] = (size >>> 16) & 0xff;
  out[12] = (size >>> 8) & 0xff;
  out[13] = size & 0xff;
  return out;
}

/** Runs a complete download on the virtual clock; returns the acks received. */
async function download(r: ReturnType<typeof rig>, type: 1 | 2, payload: Uint8Array): Promise<string[]> {
  r.send(firstPart(type, payload.length));
  const acks = r.take();
  for (const chunk of chunks(payload)) {
    r.send(chunk);
    await r.clock.advance(5);
    acks.push(...r.take());
  }
  return acks;
}

function freeMemory(r: ReturnType<typeof rig>, area: 1 | 2): number {
  r.send(area === 1 ? READ_FREE_MOTION : READ_FREE_ACTION);
  const reply = fromHex(r.take()[0]!);
  return ((reply[14]! << 24) | (reply[15]! << 16) | (reply[16]! << 8) | reply[17]!) >>> 0;
}

describe("SimulatedRbc downloads (docs/protocol.md §6.2)", () => {
  it("downloads wave.rbm's image: 40 to the first part, 10 chunks acknowledged, 23,936 bytes left", async () => {
    const r = rig();
    const { sim, clock, send, take } = r;
    expect(WAVE_IMAGE.length).toBe(624);
    const parts = chunks(WAVE_IMAGE);
    expect(parts.map((c) => c.length)).toEqual([65, 65, 65, 65, 65, 65, 65, 65, 65, 49]);
    expect(parts.map((c) => toHex(c.subarray(c.length - 1)))).toEqual(WAVE_CHUNK_CHECKSUMS);

    send(WAVE_FIRST_PART);
    expect(take()).toEqual(["40"]);
    for (const chunk of parts) {
      // Sent in two pieces: chunking does not matter.
      send(chunk.subarray(0, 10));
      send(chunk.subarray(10));
      await clock.advance(4.9);
      expect(take()).toEqual([]);
      await clock.advance(0.1);
      expect(take()).toEqual(["40"]);
    }
    send(READ_FREE_MOTION);
    expect(take()).toEqual([`${H} 0F 01 00 00 00 04 00 00 5D 80 DD`]);
    expect(sim.motions).toHaveLength(1);
    expect(sim.motions[0]).toMatchObject({ slot: 1, start: 0, size: 624 });
    expect(toHex(sim.motions[0]!.bytes)).toBe(toHex(WAVE_IMAGE));
    expect(sim.state).toMatchObject({
      motionCount: 1,
      nextFreeMotion: 640,
      download: undefined,
      errorCode: 0xff,
    });
    send(READ_ERROR);
    expect(take()).toEqual([`${H} 11 01 00 00 00 02 FF 01 FE`]);
  });

  it("plays the downloaded motion as 12 for the sum of its scene times, ending on its last scene", async () => {
    const r = rig({ basicPostureDone: true });
    await download(r, 1, WAVE_IMAGE);
    r.send(`${H} 14 00 00 00 00 01 0C 0C`);
    expect(r.sim.playingMotion).toBe(12);
    await r.clock.advance(3199); // scenes of 800 + 400 + 400 + 400 + 400 + 800 ms
    expect(r.take()).toEqual([]);
    await r.clock.advance(1);
    expect(r.take()).toEqual([`${H} 14 01 00 00 00 01 0C 0C`]);
    // The last scene ends in the basic posture, shifted by the robot's factory zeros − the file's standard zeros:
    // servo 6 ends at 72 + (46 − 48), servo 15 at 205 + (126 − 127), servo 10 at 51 + (90 − 90).
    expect(r.sim.servos[6]!.position).toBe(70);
    expect(r.sim.servos[15]!.position).toBe(204);
    expect(r.sim.servos[10]!.position).toBe(51);
  });

  it("a chunk with a wrong checksum gets no 40, sets error 2 and records nothing", async () => {
    const r = rig();
    const parts = chunks(WAVE_IMAGE);
    r.send(WAVE_FIRST_PART);
    r.send(parts[0]!);
    await r.clock.advance(5);
    expect(r.take()).toEqual(["40", "40"]);
    const bad = parts[1]!.slice();
    bad[64] = bad[64]! ^ 0x01;
    r.send(bad);
    await r.clock.advance(100);
    expect(r.take()).toEqual([]);
    expect(r.sim.errorCode).toBe(2);
    expect(r.sim.motions).toHaveLength(0);
    expect(r.sim.state.download).toBeUndefined();
    // Back to packets at once.
    r.send(READ_ERROR);
    expect(r.take()).toEqual([`${H} 11 01 00 00 00 02 02 01 03`]);
    expect(freeMemory(r, 1)).toBe(0x6000);
  });

  it("refuses a 21st motion and an 11th action with no 40 and error 3 / 4", async () => {
    const r = rig();
    for (let i = 0; i < 20; i++) expect(await download(r, 1, Uint8Array.of(i))).toEqual(["40", "40"]);
    expect(freeMemory(r, 1)).toBe(0x6000 - 20 * 64);
    r.send(firstPart(1, 1));
    expect(r.take()).toEqual([]);
    expect(r.sim.errorCode).toBe(3);
    for (let i = 0; i < 10; i++) expect(await download(r, 2, Uint8Array.of(i))).toEqual(["40", "40"]);
    r.send(firstPart(2, 1));
    expect(r.take()).toEqual([]);
    expect(r.sim.errorCode).toBe(4);
    expect(r.sim.state).toMatchObject({ motionCount: 20, actionCount: 10 });
    // The refused first part left the RBC in packet mode.
    r.send(READ_VERSION);
    expect(r.take()).toEqual([VERSION_REPLY]);
  });

  it("refuses a file that does not fit", async () => {
    const r = rig();
    r.send(firstPart(1, 0x6001));
    expect(r.take()).toEqual([]);
    expect(r.sim.errorCode).toBe(3);
    r.send(firstPart(2, 0x2001));
    expect(r.take()).toEqual([]);
    expect(r.sim.errorCode).toBe(4);
    // Exactly the area fits (and its 64-multiple size then claims one block more than exists).
    expect(await download(r, 2, new Uint8Array(0x2000))).toHaveLength(1 + 128);
    expect(freeMemory(r, 2)).toBe(0);
    r.send(firstPart(2, 1));
    expect(r.take()).toEqual([]);
  });

  it("reproduces the 64-multiple quirk: a 64-byte file takes 128 bytes", async () => {
    const r = rig();
    await download(r, 1, new Uint8Array(64));
    expect(freeMemory(r, 1)).toBe(0x6000 - 128);
    await download(r, 1, new Uint8Array(65));
    expect(freeMemory(r, 1)).toBe(0x6000 - 256);
    await download(r, 1, new Uint8Array(63));
    expect(freeMemory(r, 1)).toBe(0x6000 - 320);
    expect(r.sim.motions.map((f) => f.start)).toEqual([0, 128, 256]);
    await download(r, 2, new Uint8Array(100));
    expect(freeMemory(r, 2)).toBe(0x2000 - 128);
    expect(r.sim.actions[0]).toMatchObject({ start: 0x6000, size: 100 });
  });

  it("0x1F resets the count and pointer but keeps the bytes; power cycle does the same", async () => {
    const r = rig({ basicPostureDone: true });
    await download(r, 1, WAVE_IMAGE);
    r.send(`${H} 1F 00 00 00 00 01 01 01`);
    r.take();
    expect(freeMemory(r, 1)).toBe(0x6000);
    expect(r.sim.state.motionCount).toBe(0);
    r.send(`${H} 14 00 00 00 00 01 0C 0C`);
    await r.clock.advance(3200);
    expect(r.take()).toEqual([`${H} 14 01 00 00 00 01 0C 0C`]);
    await download(r, 1, new Uint8Array(10));
    expect(r.sim.motions.map((f) => f.size)).toEqual([10]);
    await download(r, 1, WAVE_IMAGE);
    r.sim.powerCycle();
    expect(freeMemory(r, 1)).toBe(0x6000);
    expect(r.sim.motions.map((f) => f.size)).toEqual([10, 624]);
  });

  it("waits for the rest of a download by default, however long", async () => {
    const r = rig();
    r.send(WAVE_FIRST_PART);
    r.send(chunks(WAVE_IMAGE)[0]!.subarray(0, 30));
    await r.clock.advance(60_000);
    expect(r.sim.state.download).toMatchObject({ area: "motion", size: 624, received: 0 });
  });

  it("with an idle timeout, abandons a download after that silence and understands packets again", async () => {
    const r = rig({ downloadIdleTimeoutMs: 1000 });
    r.send(WAVE_FIRST_PART);
    r.send(chunks(WAVE_IMAGE)[0]!.subarray(0, 30));
    await r.clock.advance(999);
    expect(r.sim.state.download).toMatchObject({ area: "motion", size: 624, received: 0 });
    await r.clock.advance(1);
    expect(r.sim.state.download).toBeUndefined();
    r.take();
    r.send(READ_VERSION);
    expect(r.take()).toEqual([VERSION_REPLY]);
    expect(r.sim.motions).toHaveLength(0);
  });

  it("treats header bytes inside chunk data as data", async () => {
    const r = rig();
    const payload = fromHex(`${READ_VERSION} ${READ_VERSION}`);
    expect(await download(r, 1, payload)).toEqual(["40", "40"]);
    expect(toHex(r.sim.motions[0]!.bytes)).toBe(toHex(payload));
  });

  it("drops a first part while a sound plays", async () => {
    const r = rig();
    r.send(`${H} 15 00 00 00 00 01 04 04`);
    r.send(firstPart(1, 10));
    expect(r.take()).toEqual([]);
    expect(r.sim.stats.drops.busy).toBe(1);
  });
});
