import { describe, expect, it } from "vitest";
import { fromHex, toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { ServoBus, SimulatedRbc, type SimulatedRbcOptions, servoBusFromMemory } from "../../src/sim/index.ts";
import { goldenImage } from "../data/project-data.ts";

/**
 * The simulated robot's lasting memory (issue 23 item 2: the demo robot keeps its EEPROM, its memory counts and
 * its servos' ids while the cable is out, and across page loads). Requests and replies are literal bytes of
 * docs/protocol.md §4-§6 (the same ones tests/unit/sim.test.ts and sim-downloads.test.ts use).
 */

const H = "FF FF AA 55 AA 55 37 BA";
/** docs/protocol.md §8 example 13: write the standard zeros. */
const WRITE_STANDARD_ZEROS = `${H} 0E 00 00 00 00 10 7D CA A2 42 6C 7C 30 58 B8 8E 5A 28 7D A1 D2 7F 1A`;
const READ_ZEROS = `${H} 0B 00 00 00 00 01 01 01`;
/** The read-back: the same 16 bytes, so the same checksum (the contents' XOR, docs/protocol.md §2). */
const STANDARD_ZEROS_REPLY = `${H} 0B 01 00 00 00 10 7D CA A2 42 6C 7C 30 58 B8 8E 5A 28 7D A1 D2 7F 1A`;
const READ_FREE_MOTION = `${H} 0F 00 00 00 00 01 01 01`;
/** 23,936 bytes free (0x5D80) after wave.rbm's 624-byte image. */
const FREE_AFTER_WAVE = `${H} 0F 01 00 00 00 04 00 00 5D 80 DD`;
/** docs/protocol.md §8 example 14: the whole motion area free. */
const FREE_ALL = `${H} 0F 01 00 00 00 04 00 00 60 00 60`;
const RUN_12 = `${H} 14 00 00 00 00 01 0C 0C`;
const RUN_12_REPLY = `${H} 14 01 00 00 00 01 0C 0C`;
const RESET_MOTION_POINTER = `${H} 1F 00 00 00 00 01 01 01`;
const WAVE_FIRST_PART = `${H} 01 00 00 00 02 70`;
const ENTER_DIRECT = `${H} 10 00 00 00 00 01 01 01`;
const LEAVE_DIRECT = "FF E0 FB 01 00 1A";
const WAVE_IMAGE = goldenImage("wave.rbm");

function rig(options: SimulatedRbcOptions = {}) {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock, ...options });
  const out: string[] = [];
  sim.onTransmit((bytes) => out.push(toHex(bytes)));
  const ask = (hex: string | Uint8Array) => {
    out.length = 0;
    sim.receive(typeof hex === "string" ? fromHex(hex) : hex);
    return out.splice(0);
  };
  return { clock, sim, ask, out };
}

/** wave.rbm's image downloaded as docs/protocol.md §6.2 says: chunks of 64 bytes, each with its XOR. */
async function downloadWave(r: ReturnType<typeof rig>): Promise<void> {
  expect(r.ask(WAVE_FIRST_PART)).toEqual(["40"]);
  for (let o = 0; o < WAVE_IMAGE.length; o += 64) {
    const part = WAVE_IMAGE.subarray(o, Math.min(o + 64, WAVE_IMAGE.length));
    const chunk = Uint8Array.of(
      ...part,
      part.reduce((x, b) => x ^ b, 0),
    );
    r.ask(chunk);
    await r.clock.advance(5);
  }
  expect(r.out.splice(0)).toEqual(["40"]);
}

describe("a simulated robot's lasting memory", () => {
  it("a new robot given an old one's memory has its zeros, its download (free memory, Run 12) and its servo ids", async () => {
    const first = rig({ basicPostureDone: true });
    expect(first.ask(WRITE_STANDARD_ZEROS)).toEqual([WRITE_STANDARD_ZEROS.replace("0E 00", "0E 01")]);
    await downloadWave(first);
    expect(first.ask(READ_FREE_MOTION)).toEqual([FREE_AFTER_WAVE]);
    // Servo 0 takes id 30 (docs/protocol.md §5's id set), on a bus whose servo 12 is a replacement at id 0.
    expect(first.ask(ENTER_DIRECT)).toHaveLength(1);
    const memory = first.sim.lastingMemory();
    expect(memory.servos.busIds[0]).toBe(0);
    first.sim.connectServo(12, false);
    expect(first.ask("FF E0 0C 1E 1E 6C")).toEqual(["1E 1E"]);
    first.sim.connectServo(12, true);
    first.ask(LEAVE_DIRECT);
    const later = first.sim.lastingMemory();
    // A memory taken earlier does not change afterwards.
    expect(memory.servos.busIds[0]).toBe(0);
    expect(later.servos.busIds[0]).toBe(30);

    // Through structured cloning, as IndexedDB keeps it.
    const kept = structuredClone(later);
    const second = rig({ servoBus: servoBusFromMemory(kept.servos) });
    second.sim.restoreLastingMemory(kept);
    expect(second.ask(READ_ZEROS)).toEqual([STANDARD_ZEROS_REPLY]);
    expect(second.ask(READ_FREE_MOTION)).toEqual([FREE_AFTER_WAVE]);
    // Basic posture had run: the robot stayed on, so motion 12 plays at once (3,200 ms of scenes).
    expect(second.ask(RUN_12)).toEqual([]);
    await second.clock.advance(3200);
    expect(second.out.splice(0)).toEqual([RUN_12_REPLY]);
    expect(second.ask(ENTER_DIRECT)).toHaveLength(1);
    expect(second.ask("FF BE 00 3E")).toEqual(["00 7D"]);
    expect(second.ask("FF A0 00 20")).toEqual([]);
  });

  it("a memory reset (0x1F) before the memory was taken comes back as a whole free area", async () => {
    const first = rig({ basicPostureDone: true });
    await downloadWave(first);
    expect(first.ask(RESET_MOTION_POINTER)).toEqual([`${H} 1F 01 00 00 00 01 01 01`]);
    const second = rig();
    second.sim.restoreLastingMemory(first.sim.lastingMemory());
    expect(second.ask(READ_FREE_MOTION)).toEqual([FREE_ALL]);
    // The bytes stay in EEPROM (docs/protocol.md §6.1): slot 1 still holds them.
    expect(toHex(second.sim.motions[0]!.bytes)).toBe(toHex(WAVE_IMAGE));
  });

  it("refuses what is not this robot's memory, naming why, and changes nothing", async () => {
    const first = rig({ basicPostureDone: true });
    await downloadWave(first);
    const good = first.sim.lastingMemory();
    const target = rig();
    const cases: [unknown, RegExp][] = [
      [{ ...good, format: "other" }, /another format or version/],
      [{ ...good, zeros: [...good.zeros.slice(0, 15), 0] }, /zero table the robot would refuse/],
      [{ ...good, motion: { ...good.motion, count: 2 } }, /motion count is wrong/],
      [
        { ...good, motion: { ...good.motion, files: [{ ...good.motion.files[0]!, start: 0x6000 }] } },
        /motion slot 1 lies outside its area/,
      ],
      [{ ...good, servos: { ...good.servos, busIds: [31] } }, /servo ids are missing/],
      [{ ...good, serialNumber: "0000000000001" }, /belongs to robot 0000000000001/],
    ];
    for (const [value, why] of cases) {
      expect(() => target.sim.restoreLastingMemory(value)).toThrow(why);
      expect(target.ask(READ_FREE_MOTION)).toEqual([FREE_ALL]);
      expect(target.sim.motions).toHaveLength(0);
    }
  });

  it("servo faults come back with the servos: a missing servo stays missing", () => {
    const first = rig({ servoBus: new ServoBus({ missing: [7] }) });
    const kept = structuredClone(first.sim.lastingMemory());
    expect(kept.servos.faults.missing).toEqual([7]);
    const bus = servoBusFromMemory(kept.servos);
    expect(bus.servos[7]!.connected).toBe(false);
    expect(bus.servos[6]!.connected).toBe(true);
  });
});
