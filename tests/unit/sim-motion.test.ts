import { describe, expect, it } from "vitest";
import { fromHex, toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { BUILT_IN_KEYFRAMES, SimulatedRbc, type SimulatedRbcOptions } from "../../src/sim/index.ts";

/**
 * The simulated robot moves over time (docs/protocol.md §9 "Added since", §10) and can be posed by hand. Every
 * expected position below is worked out by hand from the §10 formula
 * `start + round(k · (end − start) / frames) + zeroDelta`, frames `floor(timeMs / frames)` ms apart.
 */

const H = "FF FF AA 55 AA 55 37 BA";
const RUN_MOTION = (n: string) => `${H} 14 00 00 00 00 01 ${n} ${n}`;
const MOTION_REPLY = (n: string) => `${H} 14 01 00 00 00 01 ${n} ${n}`;
const DIRECT_ON = `${H} 10 00 00 00 00 01 01 01`;
const EXIT_DIRECT = "FF E0 FB 01 00 1A";
/** docs/protocol.md §5 examples: sync move of ids 0-15 to the basic posture; passive id 12. */
const SYNC_BASIC = "FF 9F 10 7D B3 C7 58 6C 7E 48 31 A3 8D 33 2F 31 C7 CD CD 7E";
const PASSIVE_12 = "FF CC 10 5C";
/** Read id 12: FF (A0|12) 00, checksum (AC ^ 00) & 7F = 2C. */
const READ_12 = "FF AC 00 2C";
/** Move id 0 to 100 (0x64) at torque 2: FF 40 64, checksum (40 ^ 64) & 7F = 24. */
const MOVE_0_TO_100 = "FF 40 64 24";
/** Passive id 0: FF C0 10, checksum (C0 ^ 10) & 7F = 50. */
const PASSIVE_0 = "FF C0 10 50";
/** The HUNO basic posture (docs/protocol.md §5). */
const BASIC = [125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205];
/** The simulator's default zeros are the factory table (docs/protocol.md §4): servo 0 → 124, servo 1 → 202. */
const FACTORY_ZERO_0 = 124;
const FACTORY_ZERO_1 = 202;

interface ImageScene {
  frames: number;
  timeMs: number;
  /** [start, end, torque] per servo of the image. */
  records: [number, number, number][];
}

/** A motion image laid out by hand as in docs/protocol.md §6.3 (little-endian, W servos, S scenes). */
function image(servos: { id: number; zero: number }[], scenes: ImageScene[]): Uint8Array {
  const w = servos.length;
  const size = 12 + 6 * w + scenes.length * (6 + 5 * w);
  const b = new Uint8Array(size);
  const u16 = (o: number, v: number) => {
    b[o] = v & 0xff;
    b[o + 1] = v >> 8;
  };
  b[0] = 1; // platform HUNO; motion index 0 and absolute index 0 stay 0
  u16(6, scenes.length);
  u16(8, w);
  servos.forEach((s, i) => {
    b.set([s.id, 20, 30, 0, 0, s.zero], 10 + 6 * i);
  });
  u16(10 + 6 * w, size);
  scenes.forEach((scene, k) => {
    const base = 12 + 6 * w + k * (6 + 5 * w);
    u16(base, k);
    u16(base + 2, scene.frames);
    u16(base + 4, scene.timeMs);
    scene.records.forEach(([start, end, torque], i) => {
      b.set([servos[i]!.id, start, end, torque, 0], base + 6 + 5 * i);
    });
  });
  return b;
}

function rig(options: SimulatedRbcOptions = {}) {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock, basicPostureDone: true, ...options });
  const out: string[] = [];
  sim.onTransmit((bytes) => out.push(toHex(bytes)));
  const send = (bytes: string | Uint8Array) =>
    sim.receive(typeof bytes === "string" ? fromHex(bytes) : bytes);
  const take = () => out.splice(0, out.length);
  return { clock, sim, send, take };
}
type Rig = ReturnType<typeof rig>;

/** Downloads `payload` as motion 1 (played as Run Motion 12), chunk by chunk (docs/protocol.md §6.2). */
async function download(r: Rig, payload: Uint8Array): Promise<void> {
  const first = fromHex(`${H} 01 00 00 00 00 00`);
  first[13] = payload.length & 0xff;
  first[12] = payload.length >> 8;
  r.send(first);
  for (let o = 0; o < payload.length; o += 64) {
    const part = payload.subarray(o, Math.min(o + 64, payload.length));
    r.send(Uint8Array.from([...part, part.reduce((x, v) => x ^ v, 0)]));
    await r.clock.advance(5);
  }
  expect(r.sim.motions).toHaveLength(1);
  r.take();
}

/** Starts Run Motion 12 and records [ms since the start, servo 0, servo 1] at every servo change. */
function play(r: Rig): [number, number, number][] {
  const seen: [number, number, number][] = [];
  const t0 = r.clock.now();
  r.sim.onServos((p) => seen.push([r.clock.now() - t0, p[0]!, p[1]!]));
  r.send(RUN_MOTION("0C"));
  expect(r.sim.playingMotion).toBe(12);
  return seen;
}

/** Two servos, ids 0 and 1, the first pose at the basic posture: no transition. */
const TWO_SCENES = (zero0 = FACTORY_ZERO_0, zero1 = FACTORY_ZERO_1) =>
  image(
    [
      { id: 0, zero: zero0 },
      { id: 1, zero: zero1 },
    ],
    [
      {
        frames: 5,
        timeMs: 500,
        records: [
          [125, 135, 1],
          [179, 169, 1],
        ],
      },
      {
        frames: 3,
        timeMs: 250,
        records: [
          [135, 130, 2],
          [169, 170, 2],
        ],
      },
    ],
  );

describe("SimulatedRbc: a downloaded motion moves the servos frame by frame (docs/protocol.md §10)", () => {
  it("passes through the frames of each scene at its frame interval, then replies after the scene times", async () => {
    const r = rig();
    await download(r, TWO_SCENES());
    const seen = play(r);
    await r.clock.advance(100);
    expect(r.sim.servos[0]).toMatchObject({ position: 127, torque: 1, passive: false });
    await r.clock.advance(649);
    expect(r.take()).toEqual([]);
    expect(seen).toEqual([
      // Scene 0: 5 frames, 100 ms apart: 125 → 135 and 179 → 169 in steps of 2.
      [100, 127, 177],
      [200, 129, 175],
      [300, 131, 173],
      [400, 133, 171],
      [500, 135, 169],
      // Scene 1: 3 frames, floor(250 / 3) = 83 ms apart. Servo 0: 135 + round(−5/3) = 133, 135 + round(−10/3)
      // = 132, 130. Servo 1: 169 + round(1/3) = 169, 169 + round(2/3) = 170, 170.
      [583, 133, 169],
      [666, 132, 170],
      [749, 130, 170],
    ]);
    expect(r.sim.servos[0]!.torque).toBe(2);
    await r.clock.advance(1);
    expect(r.take()).toEqual([MOTION_REPLY("0C")]);
    expect(r.sim.servoPositions().slice(0, 3)).toEqual([130, 170, 199]);
    expect(seen).toHaveLength(8);
  });

  it("shifts every frame by the robot's stored zero − the file's zero", async () => {
    // File zeros 120 and 205 against the robot's 124 and 202: servo 0 is shifted by +4, servo 1 by −3.
    const r = rig();
    await download(r, TWO_SCENES(120, 205));
    const seen = play(r);
    await r.clock.advance(500);
    expect(seen).toEqual([
      [100, 131, 174],
      [200, 133, 172],
      [300, 135, 170],
      [400, 137, 168],
      [500, 139, 166],
    ]);
  });

  it("applies no zero shift on platform 4", async () => {
    const r = rig({ platform: 4 });
    await download(r, TWO_SCENES(120, 205));
    const seen = play(r);
    await r.clock.advance(200);
    expect(seen).toEqual([
      [100, 127, 177],
      [200, 129, 175],
    ]);
  });

  it("first moves from the current pose in gap/3 frames 20 ms apart at torque 3 when a servo is > 10 away", async () => {
    const r = rig();
    // Servo 0 starts at 150, 25 counts from where it stands (125): floor(25 / 3) = 8 transition frames.
    await download(
      r,
      image(
        [
          { id: 0, zero: FACTORY_ZERO_0 },
          { id: 1, zero: FACTORY_ZERO_1 },
        ],
        [
          {
            frames: 2,
            timeMs: 200,
            records: [
              [150, 160, 0],
              [179, 179, 0],
            ],
          },
        ],
      ),
    );
    const seen = play(r);
    await r.clock.advance(20);
    expect(r.sim.servos[0]!.torque).toBe(3);
    await r.clock.advance(339);
    expect(r.take()).toEqual([]);
    expect(seen).toEqual([
      // 125 + round(j · 25 / 8): 3.125, 6.25, 9.375, 12.5, 15.625, 18.75, 21.875, 25.
      [20, 128, 179],
      [40, 131, 179],
      [60, 134, 179],
      [80, 138, 179],
      [100, 141, 179],
      [120, 144, 179],
      [140, 147, 179],
      [160, 150, 179],
      // The scene starts when the transition ends: 2 frames 100 ms apart.
      [260, 155, 179],
    ]);
    // The reply comes after the transition + the scene time, with the last frame already sent.
    await r.clock.advance(1);
    expect(r.take()).toEqual([MOTION_REPLY("0C")]);
    expect(seen.at(-1)).toEqual([360, 160, 179]);
    expect(r.sim.servos[0]!.torque).toBe(0);
  });

  it("a 7 mid-motion: the servos finish the current scene and hold its end pose, torque on", async () => {
    const r = rig();
    await download(
      r,
      image(
        [{ id: 0, zero: FACTORY_ZERO_0 }],
        [
          { frames: 4, timeMs: 400, records: [[125, 145, 1]] },
          { frames: 4, timeMs: 400, records: [[145, 125, 1]] },
        ],
      ),
    );
    const seen = play(r);
    await r.clock.advance(150);
    r.send(RUN_MOTION("07"));
    await r.clock.advance(499);
    expect(r.take()).toEqual([]);
    await r.clock.advance(1);
    expect(r.take()).toEqual([MOTION_REPLY("07")]);
    await r.clock.advance(2000);
    expect(seen.map(([t, p]) => [t, p])).toEqual([
      [100, 130],
      [200, 135],
      [300, 140],
      [400, 145],
    ]);
    expect(r.sim.servos[0]).toMatchObject({ position: 145, passive: false, torque: 1 });
    expect(r.sim.playingMotion).toBeUndefined();
  });

  it("a 7 in a long scene: the servos stop at the modelled stop time and hold", async () => {
    const r = rig();
    await download(
      r,
      image([{ id: 0, zero: FACTORY_ZERO_0 }], [{ frames: 10, timeMs: 2000, records: [[125, 145, 1]] }]),
    );
    const seen = play(r);
    await r.clock.advance(300);
    r.send(RUN_MOTION("07"));
    await r.clock.advance(3000);
    // Frames every 200 ms, 125 + 2k; the stop (STOP_SCENE_MS = 500) comes at 800 ms: frame 4 is the last.
    expect(seen.map(([t, p]) => [t, p])).toEqual([
      [200, 127],
      [400, 129],
      [600, 131],
      [800, 133],
    ]);
    expect(r.take()).toEqual([MOTION_REPLY("07")]);
    expect(r.sim.servos[0]).toMatchObject({ position: 133, passive: false });
  });

  it("a sound during the motion holds its frames back by the sound's length", async () => {
    const r = rig();
    await download(r, TWO_SCENES());
    const seen = play(r);
    await r.clock.advance(150);
    r.send(`${H} 15 00 00 00 00 01 04 04`); // sound 4: 200 + 365 ms
    await r.clock.advance(750);
    expect(seen.map(([t, p]) => [t, p])).toEqual([
      [100, 127],
      [765, 129],
      [865, 131],
    ]);
  });
});

describe("SimulatedRbc: built-in motions 1-11 move the demo robot [decision]", () => {
  const DURATIONS: Record<number, number> = {
    1: 5520,
    2: 6600,
    3: 1520,
    4: 1625,
    5: 1520,
    6: 1200,
    7: 1800,
    8: 1150,
    9: 1300,
    10: 2450,
    11: 1300,
  };

  it("their keyframe times add up to the catalogue durations of docs/protocol.md §3.1", () => {
    for (const [n, ms] of Object.entries(DURATIONS)) {
      expect(
        BUILT_IN_KEYFRAMES[+n]!.reduce((sum, k) => sum + k.ms, 0),
        `motion ${n}`,
      ).toBe(ms);
    }
  });

  it.each(Object.entries(DURATIONS))(
    "motion %s moves, replies after its duration and ends in the basic posture",
    async (n, ms) => {
      const r = rig();
      const hex = Number(n).toString(16).toUpperCase().padStart(2, "0");
      const seen: number[][] = [];
      r.sim.onServos((p) => seen.push([...p]));
      r.send(RUN_MOTION(hex));
      await r.clock.advance(ms - 1);
      expect(r.take()).toEqual([]);
      if (n !== "7") expect(seen.length).toBeGreaterThan(3);
      await r.clock.advance(1);
      expect(r.take()).toEqual([MOTION_REPLY(hex)]);
      expect(r.sim.servoPositions()).toEqual(BASIC);
      expect(r.sim.servos.every((s) => !s.passive)).toBe(true);
    },
  );

  it("7 moves from a hand-posed pose to the basic posture over 1,000 ms, then stands still", async () => {
    const r = rig({ basicPostureDone: false });
    r.send(DIRECT_ON);
    r.send(PASSIVE_0);
    expect(r.sim.poseByHand(0, 100)).toBe(true);
    r.send(EXIT_DIRECT);
    r.take();
    const seen: [number, number][] = [];
    r.sim.onServos((p) => seen.push([r.clock.now(), p[0]!]));
    r.send(RUN_MOTION("07"));
    await r.clock.advance(1800);
    // 25 frames 40 ms apart: 100 + round(k · 25 / 25) = 100 + k.
    expect(seen).toHaveLength(25);
    expect(seen[0]).toEqual([40, 101]);
    expect(seen[12]).toEqual([520, 113]);
    expect(seen[24]).toEqual([1000, 125]);
    expect(r.take()).toEqual([MOTION_REPLY("07")]);
    expect(r.sim.basicPostureDone).toBe(true);
  });
});

describe("SimulatedRbc: posing by hand and watching the servos", () => {
  it("poseByHand moves a passive servo only; reads report the posed position", () => {
    const r = rig();
    r.send(DIRECT_ON);
    r.take();
    expect(r.sim.poseByHand(12, 80)).toBe(false); // holding torque: resists
    expect(r.sim.servos[12]!.position).toBe(49);
    r.send(PASSIVE_12);
    expect(r.take()).toEqual(["00 31"]);
    expect(r.sim.poseByHand(12, 80.6)).toBe(true);
    r.send(READ_12);
    expect(r.take()).toEqual(["00 51"]); // 81
    expect(r.sim.servos[12]).toMatchObject({ position: 81, passive: true });
    expect(r.sim.poseByHand(12, 300)).toBe(true);
    expect(r.sim.servoPositions()[12]).toBe(254);
    expect(r.sim.poseByHand(12, -5)).toBe(true);
    expect(r.sim.servoPositions()[12]).toBe(0);
    expect(r.sim.poseByHand(12, Number.NaN)).toBe(false);
    expect(r.sim.poseByHand(16, 100)).toBe(false);
    expect(r.sim.poseByHand(-1, 100)).toBe(false);
    expect(r.sim.poseByHand(5, 100)).toBe(false);
    expect(r.sim.servos[5]!.position).toBe(126);
    // A sync move makes every servo hold again: no more posing.
    r.send(SYNC_BASIC);
    expect(r.sim.poseByHand(12, 80)).toBe(false);
    expect(r.sim.servoPositions()).toEqual(BASIC);
  });

  it("onServos fires once per command or hand pose that changes something, and stops after unsubscribe", async () => {
    const r = rig();
    const calls: { positions: number[]; passive: boolean[] }[] = [];
    const off = r.sim.onServos((positions, passive) =>
      calls.push({ positions: [...positions], passive: [...passive] }),
    );
    r.sim.onServos(() => {
      throw new Error("a broken watcher");
    });
    r.send(DIRECT_ON);
    expect(calls).toHaveLength(0);
    r.take();
    r.send(MOVE_0_TO_100);
    expect(r.take()).toEqual(["00 64"]); // the throwing watcher did not stop the reply
    expect(calls).toHaveLength(1);
    expect(calls[0]!.positions[0]).toBe(100);
    r.send(MOVE_0_TO_100); // nothing changes: nothing to tell
    expect(calls).toHaveLength(1);
    r.send(PASSIVE_0);
    expect(calls).toHaveLength(2);
    expect(calls[1]!.passive[0]).toBe(true);
    r.sim.poseByHand(0, 90);
    expect(calls).toHaveLength(3);
    expect(calls[2]!.positions[0]).toBe(90);
    r.send(SYNC_BASIC); // 16 servos move and servo 0 holds again: one call
    expect(calls).toHaveLength(4);
    expect(calls[3]).toEqual({ positions: BASIC, passive: BASIC.map(() => false) });
    r.sim.powerCycle();
    expect(calls).toHaveLength(5);
    off();
    r.send(DIRECT_ON);
    r.send(MOVE_0_TO_100);
    expect(calls).toHaveLength(5);
    expect(r.sim.servoPositions()[0]).toBe(100);
  });
});
