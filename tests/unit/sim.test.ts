import { describe, expect, it } from "vitest";
import { fromHex, isChecksumAccepted, PacketParser, toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { SimulatedRbc, type SimulatedRbcOptions } from "../../src/sim/index.ts";

/** The 8-byte header, to keep the literal vectors below readable. */
const H = "FF FF AA 55 AA 55 37 BA";

/** docs/protocol.md §8, literally. */
const EX1_READ_VERSION = "FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01";
const EX2_VERSION = "FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 15";
const EX3_SERIAL = "FF FF AA 55 AA 55 37 BA 0C 01 00 00 00 0D 38 39 35 38 38 39 39 39 38 39 33 30 39 36";
const EX4_DIRECT_ON = "FF FF AA 55 AA 55 37 BA 10 00 00 00 00 01 01 01";
const EX5_EXIT_DIRECT = "FF E0 FB 01 00 1A";
const EX6_MOTION_7 = "FF FF AA 55 AA 55 37 BA 14 00 00 00 00 01 07 07";
const EX7_SOUND_3 = "FF FF AA 55 AA 55 37 BA 15 00 00 00 00 01 03 03";
const EX8_DISTANCE_10 = "FF FF AA 55 AA 55 37 BA 16 01 00 00 00 02 0A 00 0A";
const EX9_SOUND_THRESHOLD_30 = "FF FF AA 55 AA 55 37 BA 17 00 00 00 00 02 1E 1E 00";
const EX10_BUTTON_PF2 = "FF FF AA 55 AA 55 37 BA 18 01 00 00 00 02 02 00 02";
const EX11_ACCEL = "FF FF AA 55 AA 55 37 BA 1A 01 00 00 00 06 04 00 03 00 FA FF FD";
const EX12_FACTORY_ZEROS =
  "FF FF AA 55 AA 55 37 BA 0B 01 00 00 00 10 7C CA A2 41 6C 7D 2E 58 B8 8E 5A 28 7D A1 D2 7E 06";
const EX13_WRITE_STANDARD_ZEROS =
  "FF FF AA 55 AA 55 37 BA 0E 00 00 00 00 10 7D CA A2 42 6C 7C 30 58 B8 8E 5A 28 7D A1 D2 7F 1A";
const EX14_FREE_MOTION = "FF FF AA 55 AA 55 37 BA 0F 01 00 00 00 04 00 00 60 00 60";
const EX15_RESET_MOTION_POINTER = "FF FF AA 55 AA 55 37 BA 1F 00 00 00 00 01 01 01";
const EX16_ERROR_NONE = "FF FF AA 55 AA 55 37 BA 11 01 00 00 00 02 FF 01 FE";

const READ_ZEROS = `${H} 0B 00 00 00 00 01 01 01`;
const READ_SERIAL = `${H} 0C 00 00 00 00 01 01 01`;
const READ_ERROR = `${H} 11 00 00 00 00 01 01 01`;
const READ_FREE_MOTION = `${H} 0F 00 00 00 00 01 01 01`;
const READ_FREE_ACTION = `${H} 0F 00 00 00 00 01 02 02`;
const READ_DISTANCE = `${H} 16 00 00 00 00 01 01 01`;
const READ_ACCEL = `${H} 1A 00 00 00 00 01 01 01`;
const SUBSCRIBE_BUTTONS = `${H} 18 00 00 00 00 01 01 01`;
const SUBSCRIBE_REMOTE = `${H} 19 00 00 00 00 01 01 01`;
const RUN_MOTION = (n: string) => `${H} 14 00 00 00 00 01 ${n} ${n}`;
const STATUS = (n: string) => `${H} 1E 00 00 00 00 01 ${n} ${n}`;
const MOTION_REPLY = (n: string) => `${H} 14 01 00 00 00 01 ${n} ${n}`;

function rig(options: SimulatedRbcOptions = {}) {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock, ...options });
  const out: string[] = [];
  sim.onTransmit((bytes) => out.push(toHex(bytes)));
  const send = (hex: string) => sim.receive(fromHex(hex));
  /** The replies sent so far, emptied. */
  const take = () => out.splice(0, out.length);
  return { clock, sim, out, send, take };
}

describe("SimulatedRbc: packets (docs/protocol.md §2, §8)", () => {
  it("answers example 1 (read version) with exactly example 2", () => {
    const { send, take } = rig();
    send(EX1_READ_VERSION);
    expect(take()).toEqual([EX2_VERSION]);
  });

  it("scans for the header byte by byte, skipping garbage and partial headers", () => {
    const { sim, take } = rig();
    const bytes = fromHex(`00 FF FF AA 13 FF FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01`);
    for (const b of bytes) sim.receive(Uint8Array.of(b));
    expect(take()).toEqual([EX2_VERSION]);
    expect(sim.stats.garbageBytes).toBe(6);
    expect(sim.stats.packetsReceived).toBe(1);
  });

  it("answers the serial number (example 3), factory zeros (example 12), error code (example 16)", () => {
    const { send, take } = rig();
    send(READ_SERIAL);
    send(READ_ZEROS);
    send(READ_ERROR);
    expect(take()).toEqual([EX3_SERIAL, EX12_FACTORY_ZEROS, EX16_ERROR_NONE]);
  });

  it("carries its platform and firmware in replies", () => {
    const { send, take } = rig({ platform: 4, firmware: { major: 2, minor: 15 } });
    send(EX1_READ_VERSION);
    send(READ_ERROR);
    expect(take()).toEqual([`${H} 12 04 00 00 00 02 02 0F 0D`, `${H} 11 04 00 00 00 02 FF 04 FB`]);
  });

  it("silently drops a wrong size, a bad checksum, bad contents and unknown types", () => {
    const { sim, send, take } = rig();
    send(`${H} 12 00 00 00 00 02 01 01 00`); // size 2
    send(`${H} 12 00 00 00 00 01 01 02`); // checksum
    send(`${H} 12 00 00 00 00 01 02 02`); // contents must be 01
    send(`${H} 13 00 00 00 00 01 01 01`); // undocumented type
    send(`${H} 0F 00 00 00 00 01 03 03`); // area 3 does not exist
    expect(take()).toEqual([]);
    expect(sim.stats.drops).toEqual({ size: 1, checksum: 1, contents: 2, "unknown-type": 1 });
    send(EX1_READ_VERSION);
    expect(take()).toEqual([EX2_VERSION]);
  });

  it("like the firmware, compares only the least significant size byte", () => {
    const { send, take } = rig();
    send(`${H} 12 00 00 00 01 01 01 01`);
    expect(take()).toEqual([EX2_VERSION]);
  });

  it("treats FF (even a whole header) inside a matched packet as data", () => {
    const { sim, send, take } = rig();
    // A zero write whose 16 contents are example 1: one (refused) packet, not a version request.
    send(`${H} 0E 00 00 00 00 10 ${EX1_READ_VERSION} 9E`);
    expect(take()).toEqual([]);
    expect(sim.errorCode).toBe(7);
    expect(sim.stats.packetsReceived).toBe(1);
  });
});

describe("SimulatedRbc: zeros (docs/protocol.md §4)", () => {
  it("echoes an accepted write (example 13) and stores it", () => {
    const { sim, send, take } = rig();
    send(EX13_WRITE_STANDARD_ZEROS);
    expect(take()).toEqual([
      "FF FF AA 55 AA 55 37 BA 0E 01 00 00 00 10 7D CA A2 42 6C 7C 30 58 B8 8E 5A 28 7D A1 D2 7F 1A",
    ]);
    expect(sim.zeros).toEqual([125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127]);
    send(READ_ZEROS);
    expect(take()).toEqual([
      "FF FF AA 55 AA 55 37 BA 0B 01 00 00 00 10 7D CA A2 42 6C 7C 30 58 B8 8E 5A 28 7D A1 D2 7F 1A",
    ]);
  });

  it("does not answer a table with a value outside ±15 and sets error 7", () => {
    const { sim, send, take } = rig();
    // Servo 0 = 0x8D = 141 (standard 125 + 16).
    send(`${H} 0E 00 00 00 00 10 8D CA A2 42 6C 7C 30 58 B8 8E 5A 28 7D A1 D2 7F EA`);
    expect(take()).toEqual([]);
    expect(sim.errorCode).toBe(7);
    expect(sim.zeros).toEqual([124, 202, 162, 65, 108, 125, 46, 88, 184, 142, 90, 40, 125, 161, 210, 126]);
    send(READ_ERROR);
    expect(take()).toEqual([`${H} 11 01 00 00 00 02 07 01 06`]);
  });

  it("accepts the edges of the range (standard ± 15)", () => {
    const { sim, send, take } = rig();
    // Servo 0 = 140 (125 + 15), servo 15 = 112 (127 - 15).
    send(`${H} 0E 00 00 00 00 10 8C CA A2 42 6C 7C 30 58 B8 8E 5A 28 7D A1 D2 70 E4`);
    expect(take()).toHaveLength(1);
    expect(sim.zeros[0]).toBe(140);
    expect(sim.zeros[15]).toBe(112);
  });
});

describe("SimulatedRbc: sensors (docs/protocol.md §3)", () => {
  it("reads the accelerometer X=4 Y=3 Z=-6 as example 11, with the firmware checksum FD", () => {
    const { sim, send, out } = rig();
    sim.setAccelerometer(4, 3, -6);
    send(READ_ACCEL);
    expect(out).toEqual([EX11_ACCEL]);
    // The client-side parser accepts the quirky checksum for 0x1A.
    const packets = new PacketParser().push(fromHex(EX11_ACCEL));
    expect(packets).toHaveLength(1);
    expect(isChecksumAccepted(0x1a, fromHex("04 00 03 00 FA FF"), 0xfd)).toBe(true);
  });

  it("adds deterministic noise to the accelerometer only when asked", () => {
    const read = (seed: number) => {
      const { sim, send, out } = rig({ accelerometerNoise: { seed, amplitude: 3 } });
      sim.setAccelerometer(10, -10, 60);
      for (let i = 0; i < 5; i++) send(READ_ACCEL);
      return out;
    };
    const a = read(42);
    expect(read(42)).toEqual(a);
    expect(new Set(a).size).toBeGreaterThan(1);
    for (const hex of a) {
      const b = fromHex(hex);
      const x = ((b[14]! | (b[15]! << 8)) << 16) >> 16;
      expect(Math.abs(x - 10)).toBeLessThanOrEqual(3);
    }
  });

  it("reads the distance as example 8 and clamps to 10..50", () => {
    const { sim, send, take } = rig();
    send(READ_DISTANCE);
    expect(take()).toEqual([EX8_DISTANCE_10]);
    sim.setDistance(33);
    send(READ_DISTANCE);
    sim.setDistance(3);
    send(READ_DISTANCE);
    sim.setDistance(80);
    send(READ_DISTANCE);
    expect(take()).toEqual([
      `${H} 16 01 00 00 00 02 21 00 21`,
      EX8_DISTANCE_10,
      `${H} 16 01 00 00 00 02 32 00 32`,
    ]);
  });
});

describe("SimulatedRbc: subscriptions (docs/protocol.md §3.4)", () => {
  it("emits sound levels at or above the threshold about every 3.5 ms (the firmware's pace) until the next header", async () => {
    const { sim, clock, send, take } = rig();
    send(EX9_SOUND_THRESHOLD_30);
    sim.setSoundLevel(20);
    await clock.advance(300);
    expect(take()).toEqual([]);
    sim.setSoundLevel(40);
    await clock.advance(35);
    expect(take()).toEqual(Array(10).fill(`${H} 17 01 00 00 00 02 28 00 28`));
    expect(sim.state.sensors.subscription).toBe(0x17);
    send(EX1_READ_VERSION);
    await clock.advance(1000);
    expect(take()).toEqual([EX2_VERSION]);
    expect(sim.state.sensors.subscription).toBeUndefined();
  });

  it("reports a sound level already above the threshold at once, so frequent re-arming still hears it", async () => {
    const { sim, clock, send, take } = rig();
    sim.setSoundLevel(40);
    for (let i = 0; i < 5; i++) {
      send(EX9_SOUND_THRESHOLD_30);
      await clock.advance(3);
    }
    expect(take()).toEqual(Array(5).fill(`${H} 17 01 00 00 00 02 28 00 28`));
  });

  it("emits the held button (example 10) at once and every 200 ms while held", async () => {
    const { sim, clock, send, take } = rig();
    send(SUBSCRIBE_BUTTONS);
    sim.pressButton(2, 450);
    await clock.advance(1000);
    expect(take()).toEqual([EX10_BUTTON_PF2, EX10_BUTTON_PF2, EX10_BUTTON_PF2]);
    sim.pressButton(1, 100);
    expect(take()).toEqual([`${H} 18 01 00 00 00 02 01 00 01`]);
  });

  it("ends the button subscription when a header arrives, even of a dropped packet", async () => {
    const { sim, clock, send, take } = rig();
    send(SUBSCRIBE_BUTTONS);
    sim.pressButton(1, 5000);
    send(`${H} 13 00`); // a header (unknown type): the subscription ends here
    await clock.advance(1000);
    expect(take()).toEqual([`${H} 18 01 00 00 00 02 01 00 01`]);
  });

  it("reports remote keys while subscribed, until the next header, and nothing otherwise", async () => {
    const { sim, clock, send, take } = rig();
    sim.pressRemoteKey(7);
    expect(take()).toEqual([]);
    send(SUBSCRIBE_REMOTE);
    await clock.advance(60_000);
    sim.pressRemoteKey(7);
    sim.pressRemoteKey(0x2b);
    expect(take()).toEqual([`${H} 19 01 00 00 00 02 07 00 07`, `${H} 19 01 00 00 00 02 2B 00 2B`]);
    send(READ_DISTANCE);
    sim.pressRemoteKey(7);
    expect(take()).toEqual([EX8_DISTANCE_10]);
  });
});

describe("SimulatedRbc: motions and sounds (docs/protocol.md §3.1)", () => {
  it("ignores every motion but 7 after power-up, with no reply", async () => {
    const { sim, clock, send, take } = rig();
    send(RUN_MOTION("04"));
    await clock.advance(10_000);
    expect(take()).toEqual([]);
    expect(sim.stats.drops["needs-basic-posture"]).toBe(1);
    send(EX6_MOTION_7);
    expect(sim.playingMotion).toBe(7);
    await clock.advance(1799);
    expect(take()).toEqual([]);
    expect(sim.basicPostureDone).toBe(false);
    await clock.advance(1);
    expect(take()).toEqual([MOTION_REPLY("07")]);
    expect(sim.basicPostureDone).toBe(true);
    expect(sim.servos.map((s) => s.position)).toEqual([
      125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205,
    ]);
    send(RUN_MOTION("04"));
    await clock.advance(1624);
    expect(take()).toEqual([]);
    await clock.advance(1);
    expect(take()).toEqual([MOTION_REPLY("04")]);
  });

  it("replies to each built-in motion after its simulator duration", async () => {
    const durations: [string, number][] = [
      ["01", 5520],
      ["02", 6600],
      ["03", 1520],
      ["05", 1520],
      ["06", 1200],
      ["08", 1150],
      ["09", 1300],
      ["0A", 2450],
      ["0B", 1300],
    ];
    const { clock, send, take } = rig({ basicPostureDone: true });
    for (const [n, ms] of durations) {
      send(RUN_MOTION(n));
      await clock.advance(ms - 1);
      expect(take()).toEqual([]);
      await clock.advance(1);
      expect(take()).toEqual([MOTION_REPLY(n)]);
    }
  });

  it("answers the interrupt-handled requests at once while a motion plays; another Run replaces the reply's key (docs/protocol.md §3.1, §3.6)", async () => {
    const { sim, clock, send, take } = rig({ basicPostureDone: true });
    send(RUN_MOTION("03"));
    send(EX1_READ_VERSION);
    send(READ_ERROR);
    send(READ_FREE_MOTION);
    send(RUN_MOTION("04"));
    send(STATUS("03"));
    expect(take()).toEqual([
      EX2_VERSION,
      EX16_ERROR_NONE,
      EX14_FREE_MOTION,
      `${H} 1E 01 00 00 00 02 03 01 02`,
    ]);
    await clock.advance(1520);
    // Motion 3 ended; the reply carries the last key, 4, and the walk is not played.
    expect(take()).toEqual([MOTION_REPLY("04")]);
    expect(sim.playingMotion).toBeUndefined();
    send(STATUS("03"));
    expect(take()).toEqual([`${H} 1E 01 00 00 00 02 03 00 03`]);
  });

  it("answers a distance read sent during a motion only when the motion has ended (main loop)", async () => {
    const { clock, send, take } = rig({ basicPostureDone: true });
    send(RUN_MOTION("03"));
    await clock.advance(700);
    send(READ_DISTANCE);
    await clock.advance(819);
    expect(take()).toEqual([]);
    await clock.advance(1);
    expect(take()).toEqual([MOTION_REPLY("03"), EX8_DISTANCE_10]);
  });

  it("sends no events while a motion plays", async () => {
    const { sim, clock, send, take } = rig({ basicPostureDone: true });
    send(SUBSCRIBE_BUTTONS);
    sim.pressButton(2, 5000);
    expect(take()).toEqual([EX10_BUTTON_PF2]);
    send(RUN_MOTION("03")); // its header ends the subscription, and the main loop is busy
    await clock.advance(1000);
    expect(take()).toEqual([]);
  });

  it("a 7 during a motion ends it at the end of its scene with exactly one reply, 07, and no basic posture", async () => {
    const { sim, clock, send, take } = rig({ basicPostureDone: true });
    send(RUN_MOTION("02"));
    await clock.advance(1000);
    send(EX6_MOTION_7);
    send(EX6_MOTION_7); // a second 7 while stopping is dropped
    await clock.advance(499);
    expect(take()).toEqual([]);
    await clock.advance(1);
    expect(take()).toEqual([MOTION_REPLY("07")]);
    expect(sim.playingMotion).toBeUndefined();
    // The stopped motion's own reply never comes, and basic posture is not played.
    await clock.advance(10_000);
    expect(take()).toEqual([]);
  });

  it("a sound during a motion stretches the motion by the sound's length", async () => {
    const { clock, send, take } = rig({ basicPostureDone: true });
    send(RUN_MOTION("03")); // 1,520 ms
    await clock.advance(100);
    send(EX7_SOUND_3); // 200 + 832 ms
    await clock.advance(1032);
    expect(take()).toEqual([`${H} 15 01 00 00 00 01 03 03`]);
    await clock.advance(1520 - 100 - 1);
    expect(take()).toEqual([]);
    await clock.advance(1);
    expect(take()).toEqual([MOTION_REPLY("03")]);
  });

  it("ignores numbers that are neither built-in nor download slots (0, 0x2B, 0x31)", async () => {
    const { sim, clock, send, take } = rig({ basicPostureDone: true });
    send(RUN_MOTION("00"));
    send(RUN_MOTION("2B"));
    send(RUN_MOTION("31"));
    await clock.advance(10_000);
    expect(take()).toEqual([]);
    expect(sim.stats.drops["not-modelled"]).toBe(3);
  });

  it("sets error 3 and does not answer an empty download slot", async () => {
    const { sim, clock, send, take } = rig({ basicPostureDone: true });
    send(RUN_MOTION("0C"));
    send(RUN_MOTION("21"));
    await clock.advance(10_000);
    expect(take()).toEqual([]);
    expect(sim.errorCode).toBe(3);
  });

  it("answers a sound after 200 ms + its length and handles nothing else meanwhile", async () => {
    const { clock, send, take } = rig();
    send(EX7_SOUND_3);
    send(EX1_READ_VERSION);
    await clock.advance(200 + 832 - 1);
    expect(take()).toEqual([]);
    await clock.advance(1);
    expect(take()).toEqual([`${H} 15 01 00 00 00 01 03 03`]);
    send(EX1_READ_VERSION);
    expect(take()).toEqual([EX2_VERSION]);
  });

  it("drops sound numbers outside 1-25", async () => {
    const { clock, send, take } = rig();
    send(`${H} 15 00 00 00 00 01 00 00`);
    send(`${H} 15 00 00 00 00 01 1A 1A`);
    await clock.advance(10_000);
    expect(take()).toEqual([]);
  });
});

describe("SimulatedRbc: memory pointer and memory (docs/protocol.md §6.1)", () => {
  it("answers free memory (example 14) and echoes a pointer reset (example 15)", () => {
    const { send, take } = rig();
    send(READ_FREE_MOTION);
    send(READ_FREE_ACTION);
    send(EX15_RESET_MOTION_POINTER);
    send(`${H} 1F 00 00 00 00 01 00 00`);
    send(`${H} 1F 00 00 00 00 01 03 03`);
    send(`${H} 1F 00 00 00 00 01 04 04`);
    expect(take()).toEqual([
      EX14_FREE_MOTION,
      `${H} 0F 01 00 00 00 04 00 00 20 00 20`,
      `${H} 1F 01 00 00 00 01 01 01`,
      `${H} 1F 01 00 00 00 01 00 00`,
      `${H} 1F 01 00 00 00 01 03 03`,
    ]);
  });
});

describe("SimulatedRbc: direct mode (docs/protocol.md §5)", () => {
  it("enters with example 4, moves servo 5 to 125, reads, goes passive, brakes, syncs, exits", () => {
    const { sim, send, take } = rig();
    send(EX4_DIRECT_ON);
    expect(take()).toEqual([`${H} 10 01 00 00 00 01 01 01`]);
    expect(sim.directMode).toBe(true);

    send("FF 45 7D 38");
    expect(take()).toEqual(["00 7D"]);
    expect(sim.servos[5]).toMatchObject({ position: 125, passive: false, torque: 2 });

    send("FF A5 00 25");
    expect(take()).toEqual(["00 7D"]);

    send("FF CC 10 5C");
    expect(take()).toEqual(["00 31"]);
    expect(sim.servos[12]!.passive).toBe(true);

    send("FF DF 20 7F");
    expect(take()).toEqual(["1F 00"]);
    expect(sim.servos[12]!.passive).toBe(false);

    send("FF 9F 10 7D B3 C7 58 6C 7E 48 31 A3 8D 33 2F 31 C7 CD CD 7E");
    expect(take()).toEqual([]);
    expect(sim.servos.map((s) => s.position)).toEqual([
      125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205,
    ]);

    // RBC packets are not understood on the servo bus.
    send(EX1_READ_VERSION);
    expect(take()).toEqual([]);

    send(EX5_EXIT_DIRECT);
    expect(take()).toEqual([]);
    expect(sim.directMode).toBe(false);
    send(EX1_READ_VERSION);
    expect(take()).toEqual([EX2_VERSION]);
  });

  it("answers parameters with 2 bytes, ignores servos that do not exist and bad checksums", () => {
    const { sim, send, take } = rig();
    send(EX4_DIRECT_ON);
    take();
    // Bounds read of id 1 (d2 = 0x12): lower, upper = 1, 254 after power-up (docs/protocol.md §5).
    send("FF E1 12 00 00 73");
    expect(take()).toEqual(["01 FE"]);
    // Speed set of id 2 (d2 = 0x0D): speed 3, acceleration 2.
    send("FF E2 0D 03 02 6E");
    expect(take()).toEqual(["03 02"]);
    expect(sim.servos[2]).toMatchObject({ speed: 3, acceleration: 2 });
    // Move id 20 (no such servo) and a move with a bad checksum: no answer.
    send("FF 54 7D 29");
    send("FF 45 7D 39");
    expect(take()).toEqual([]);
    // The exit sequence works mid-stream, and a packet in the same chunk is understood.
    send(`${EX5_EXIT_DIRECT} ${EX1_READ_VERSION}`);
    expect(take()).toEqual([EX2_VERSION]);
  });
});

describe("SimulatedRbc: wCK parameters answered from stored values (docs/protocol.md §5)", () => {
  /** `FF (E0|id) d2 d3 d4 cs`, cs = XOR of the 4 bytes after FF, AND 7F. */
  const param = (id: number, d2: number, d3: number, d4: number) => {
    const b = [0xe0 | id, d2, d3, d4];
    const cs = b.reduce((x, v) => x ^ v, 0) & 0x7f;
    return toHex(Uint8Array.of(0xff, ...b, cs));
  };

  it("a speed set to 20/50 reads back 20/50, not 00 00", () => {
    const { send, take } = rig();
    send(EX4_DIRECT_ON);
    take();
    send(param(3, 0x0d, 20, 50));
    expect(take()).toEqual(["14 32"]);
    send(param(3, 0x0e, 0, 0));
    expect(take()).toEqual(["14 32"]);
  });

  it("I/O written 1 reads back 1; overload and bounds read back what was set", () => {
    const { send, take } = rig();
    send(EX4_DIRECT_ON);
    take();
    send(param(4, 0x64, 1, 1));
    expect(take()).toEqual(["01 01"]);
    send(param(4, 0x65, 0, 0));
    expect(take()).toEqual(["01 01"]);
    send(param(4, 0x0f, 3, 3));
    send(param(4, 0x10, 0, 0));
    expect(take()).toEqual(["03 03", "03 03"]);
    // Bounds: lower, upper (docs/protocol.md §5).
    send(param(4, 0x11, 50, 180));
    send(param(4, 0x12, 0, 0));
    expect(take()).toEqual(["32 B4", "32 B4"]);
  });

  it("0x09 WRITES servo 0's P/D gains (the manual, §5): `FF E0 09 05 05 cs` leaves them at 5/5", () => {
    const { sim, send, take } = rig();
    send(EX4_DIRECT_ON);
    take();
    send(param(0, 0x09, 5, 5));
    send(param(0, 0x0a, 0, 0));
    expect(take()).toEqual(["05 05", "05 05"]);
    expect(sim.servos[0]).toMatchObject({ pGain: 5, dGain: 5 });
    expect(sim.servos[5]).toMatchObject({ pGain: 20, dGain: 30 });
  });

  it("reads the P/D and I gains", () => {
    const { send, take } = rig();
    send(EX4_DIRECT_ON);
    take();
    send(param(2, 0x0a, 0, 0));
    send(param(2, 0x16, 0, 0));
    expect(take()).toEqual(["14 1E", "00 00"]);
  });
});

describe("SimulatedRbc: power cycle", () => {
  it("resets volatile state and keeps the zeros", async () => {
    const { sim, clock, send, take } = rig();
    send(EX13_WRITE_STANDARD_ZEROS);
    send(EX6_MOTION_7);
    await clock.advance(1800);
    send(`${H} 0E 00 00 00 00 10 8D CA A2 42 6C 7C 30 58 B8 8E 5A 28 7D A1 D2 7F EA`);
    send(SUBSCRIBE_BUTTONS);
    send(EX4_DIRECT_ON);
    take();
    expect(sim.errorCode).toBe(7);
    sim.powerCycle();
    expect(sim.state).toMatchObject({
      directMode: false,
      basicPostureDone: false,
      errorCode: 0xff,
      playingMotion: undefined,
      zeros: [125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127],
    });
    send(EX1_READ_VERSION);
    send(RUN_MOTION("03"));
    await clock.advance(5000);
    expect(take()).toEqual([EX2_VERSION]);
  });

  it("dispose() stops every timer", async () => {
    const { sim, clock, send, take } = rig();
    send(EX9_SOUND_THRESHOLD_30);
    sim.setSoundLevel(100);
    send(EX7_SOUND_3);
    sim.dispose();
    expect(clock.pending).toBe(0);
    await clock.advance(10_000);
    expect(take()).toEqual([]);
  });

  it("rejects a serial number that is not 13 characters", () => {
    expect(() => new SimulatedRbc({ serialNumber: "123" })).toThrow(RangeError);
  });
});
