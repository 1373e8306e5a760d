import { describe, expect, it } from "vitest";
import { fromHex, toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { SimulatedRbc, type SimulatedRbcOptions } from "../../src/sim/index.ts";

/**
 * The simulator's models of what real firmwares do (docs/protocol.md §3.1, §3.5, §3.6, §9), each on a virtual
 * clock, with the bytes written out literally.
 */

const H = "FF FF AA 55 AA 55 37 BA";
const READ_VERSION = `${H} 12 00 00 00 00 01 01 01`;
const VERSION_2_23 = `${H} 12 01 00 00 00 02 02 17 15`;
const READ_ERROR = `${H} 11 00 00 00 00 01 01 01`;
const ERROR_NONE = `${H} 11 01 00 00 00 02 FF 01 FE`;
const ERROR_11 = `${H} 11 01 00 00 00 02 0B 01 0A`;
const READ_ZEROS = `${H} 0B 00 00 00 00 01 01 01`;
const FACTORY_ZEROS = `${H} 0B 01 00 00 00 10 7C CA A2 41 6C 7D 2E 58 B8 8E 5A 28 7D A1 D2 7E 06`;
const READ_FREE_MOTION = `${H} 0F 00 00 00 00 01 01 01`;
const FREE_MOTION_24576 = `${H} 0F 01 00 00 00 04 00 00 60 00 60`;
const RESET_POINTER = `${H} 1F 00 00 00 00 01 01 01`;
const POINTER_RESET = `${H} 1F 01 00 00 00 01 01 01`;
const READ_ACCEL = `${H} 1A 00 00 00 00 01 01 01`;
const ACCEL_ZERO = `${H} 1A 01 00 00 00 06 00 00 00 00 00 00 00`;
const DIRECT_ON = `${H} 10 00 00 00 00 01 01 01`;
const DIRECT_ON_REPLY = `${H} 10 01 00 00 00 01 01 01`;
const READ_DISTANCE = `${H} 16 00 00 00 00 01 01 01`;
const DISTANCE_10 = `${H} 16 01 00 00 00 02 0A 00 0A`;
const DISTANCE_12 = `${H} 16 01 00 00 00 02 0C 00 0C`;
const SOUND_THRESHOLD_30 = `${H} 17 00 00 00 00 02 1E 1E 00`;
const SOUND_LEVEL_40 = `${H} 17 01 00 00 00 02 28 00 28`;
const SUBSCRIBE_BUTTONS = `${H} 18 00 00 00 00 01 01 01`;
const BUTTON_PF1 = `${H} 18 01 00 00 00 02 01 00 01`;
const SOUND_3 = `${H} 15 00 00 00 00 01 03 03`;
const SOUND_3_REPLY = `${H} 15 01 00 00 00 01 03 03`;
const RUN = (n: string) => `${H} 14 00 00 00 00 01 ${n} ${n}`;
const RAN = (n: string) => `${H} 14 01 00 00 00 01 ${n} ${n}`;
/** wCK read position of servo 0 (docs/protocol.md §5): header FF, mode 5 << 5 | id 0 = A0, 00, checksum 20. */
const WCK_READ_SERVO_0 = "FF A0 00 20";

function rig(options: SimulatedRbcOptions = {}) {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock, basicPostureDone: true, ...options });
  const out: string[] = [];
  sim.onTransmit((bytes) => out.push(toHex(bytes)));
  const send = (hex: string) => sim.receive(fromHex(hex));
  const take = () => out.splice(0, out.length);
  return { clock, sim, out, send, take };
}

describe("events at the firmware's pace (docs/protocol.md §3.6)", () => {
  it("a 0x17 subscription whose threshold the level meets sends a packet about every 3.5 ms", async () => {
    const { sim, clock, send, take } = rig({ firmwareEventPace: true });
    sim.setSoundLevel(40);
    send(SOUND_THRESHOLD_30);
    expect(take()).toEqual([SOUND_LEVEL_40]);
    await clock.advance(1000);
    const second = take();
    // 1,000 / 3.5 = 285.7: 285 more packets in the first second, every one the same literal event.
    expect(second).toHaveLength(285);
    expect(new Set(second)).toEqual(new Set([SOUND_LEVEL_40]));
    // Below the threshold nothing comes; the next header ends the subscription.
    sim.setSoundLevel(20);
    await clock.advance(100);
    expect(take()).toEqual([]);
    sim.setSoundLevel(40);
    send(READ_VERSION);
    await clock.advance(100);
    expect(take()).toEqual([VERSION_2_23]);
  });

  it("the firmware's pace is the default; firmwareEventPace: false keeps a gentler one packet every 100 ms", async () => {
    const byDefault = rig();
    byDefault.sim.setSoundLevel(40);
    byDefault.send(SOUND_THRESHOLD_30);
    await byDefault.clock.advance(1000);
    expect(byDefault.take()).toHaveLength(286);
    const { sim, clock, send, take } = rig({ firmwareEventPace: false });
    sim.setSoundLevel(40);
    send(SOUND_THRESHOLD_30);
    await clock.advance(1000);
    expect(take()).toHaveLength(11);
  });

  it("0x18 repeats about every 200 ms while a button is held", async () => {
    const { sim, clock, send, take } = rig({ firmwareEventPace: true });
    send(SUBSCRIBE_BUTTONS);
    sim.pressButton(1, 1000);
    expect(take()).toEqual([BUTTON_PF1]);
    await clock.advance(999);
    expect(take()).toEqual([BUTTON_PF1, BUTTON_PF1, BUTTON_PF1, BUTTON_PF1]);
    await clock.advance(1000);
    expect(take()).toEqual([]);
  });
});

describe("0x16 from the main loop, the rest from the interrupt (docs/protocol.md §3.6)", () => {
  it("answers 0x11/0x12/0x0B/0x0F/0x1A/0x1F/0x10 at once during a motion; 0x16 only when it ends", async () => {
    const { sim, clock, send, take } = rig();
    send(RUN("02")); // get up B, 6,600 ms
    await clock.advance(1700);
    sim.setDistance(12);
    send(READ_DISTANCE);
    send(READ_ERROR);
    send(READ_VERSION);
    send(READ_ZEROS);
    send(READ_FREE_MOTION);
    send(READ_ACCEL);
    send(RESET_POINTER);
    expect(take()).toEqual([
      ERROR_NONE,
      VERSION_2_23,
      FACTORY_ZEROS,
      FREE_MOTION_24576,
      ACCEL_ZERO,
      POINTER_RESET,
    ]);
    await clock.advance(6600 - 1700 - 1);
    expect(take()).toEqual([]);
    await clock.advance(1);
    // The motion's reply, then the distance owed since 1.7 s, with the value of when it is answered.
    expect(take()).toEqual([RAN("02"), DISTANCE_12]);
  });

  it("answers 0x10 at once during a motion (it is taken in the interrupt)", () => {
    const { send, take } = rig();
    send(RUN("03"));
    send(DIRECT_ON);
    expect(take()).toEqual([DIRECT_ON_REPLY]);
  });

  it("a write of zeros (0x0E) is echoed at once during a motion", () => {
    const { send, take } = rig();
    const write = `${H} 0E 00 00 00 00 10 7D CA A2 42 6C 7C 30 58 B8 8E 5A 28 7D A1 D2 7F 1A`;
    send(RUN("03"));
    send(write);
    expect(take()).toEqual([`${H} 0E 01 00 00 00 10 7D CA A2 42 6C 7C 30 58 B8 8E 5A 28 7D A1 D2 7F 1A`]);
  });
});

describe("0x14 replies carry the last key received (docs/protocol.md §3.1)", () => {
  it("a Run during another motion replaces the pending key: one reply with the new number, the new motion not played", async () => {
    const { sim, clock, send, take } = rig();
    send(RUN("01")); // 5,520 ms
    await clock.advance(1000);
    send(RUN("04"));
    send(RUN("0A"));
    expect(sim.playingMotion).toBe(1);
    await clock.advance(4519);
    expect(take()).toEqual([]);
    await clock.advance(1);
    expect(take()).toEqual([RAN("0A")]);
    expect(sim.playingMotion).toBeUndefined();
    // Neither 4 nor 10 plays afterwards.
    await clock.advance(10_000);
    expect(take()).toEqual([]);
    expect(sim.playingMotion).toBeUndefined();
  });

  it("7 during a motion stops it at the end of its scene: exactly one reply 14 07, no basic posture", async () => {
    const { sim, clock, send, take } = rig();
    send(RUN("0A")); // walk backward, 2,450 ms
    await clock.advance(300);
    send(RUN("07"));
    const stoppedAt = clock.now();
    await clock.advance(600);
    expect(take()).toEqual([RAN("07")]);
    expect(sim.playingMotion).toBeUndefined();
    expect(clock.now() - stoppedAt).toBeLessThan(2450 - 300);
    await clock.advance(10_000);
    expect(take()).toEqual([]);
  });
});

describe("a robot busy with a motion started elsewhere (docs/protocol.md §3.6)", () => {
  it("a motion from the remote keeps the main loop busy, and ends with no reply of its own", async () => {
    const { sim, clock, send, take } = rig();
    expect(sim.playFromRemote(1)).toBe(true);
    expect(sim.playFromRemote(3)).toBe(false); // something plays already
    send(READ_VERSION);
    send(READ_DISTANCE);
    expect(take()).toEqual([VERSION_2_23]);
    await clock.advance(5520);
    expect(take()).toEqual([DISTANCE_10]);
  });

  it("a Run sent meanwhile is answered at its end, with the Run's number, though it never played", async () => {
    const { sim, clock, send, take } = rig();
    sim.playFromRemote(1);
    await clock.advance(2000);
    send(RUN("04"));
    await clock.advance(3519);
    expect(take()).toEqual([]);
    await clock.advance(1);
    expect(take()).toEqual([RAN("04")]);
    await clock.advance(5000);
    expect(take()).toEqual([]);
  });

  it("busyMotion starts the motion when the first byte from the PC arrives", async () => {
    const { sim, clock, send, take } = rig({ busyMotion: 10 });
    await clock.advance(10_000);
    expect(sim.playingMotion).toBeUndefined();
    send(READ_VERSION);
    expect(sim.playingMotion).toBe(10);
    send(READ_DISTANCE);
    expect(take()).toEqual([VERSION_2_23]);
    await clock.advance(2450);
    expect(take()).toEqual([DISTANCE_10]);
  });

  it("busyMotion refuses what is not a built-in motion", () => {
    expect(() => new SimulatedRbc({ clock: new VirtualClock(), busyMotion: 12 })).toThrow(RangeError);
  });
});

describe("the official 'user' firmware's keys (docs/protocol.md §3.1)", () => {
  it("12-19 and 33-42 reply at once and nothing moves", () => {
    const { sim, send, take } = rig({ userFirmware: true });
    const before = sim.servoPositions();
    send(RUN("0C"));
    send(RUN("13"));
    send(RUN("21"));
    send(RUN("2A"));
    expect(take()).toEqual([RAN("0C"), RAN("13"), RAN("21"), RAN("2A")]);
    expect(sim.playingMotion).toBeUndefined();
    expect(sim.servoPositions()).toEqual(before);
    expect(sim.errorCode).toBe(0xff);
  });

  it("20 walks for ever: no reply, 7 does not stop it, the main loop never answers 0x16", async () => {
    const { sim, clock, send, take } = rig({ userFirmware: true });
    send(RUN("14"));
    expect(sim.playingMotion).toBe(20);
    await clock.advance(2000);
    const moved = sim.servoPositions();
    send(RUN("07"));
    send(READ_DISTANCE);
    send(READ_VERSION);
    expect(take()).toEqual([VERSION_2_23]);
    await clock.advance(60_000);
    expect(take()).toEqual([]);
    expect(sim.playingMotion).toBe(20);
    // Still walking: the servos keep moving, round after round.
    await clock.advance(333);
    expect(sim.servoPositions()).not.toEqual(moved);
    sim.powerCycle();
    expect(sim.playingMotion).toBeUndefined();
  });

  it("21 plays a demo motion from flash, then replies 14 15", async () => {
    const { sim, clock, send, take } = rig({ userFirmware: true });
    send(RUN("15"));
    expect(sim.playingMotion).toBe(21);
    await clock.advance(1299);
    expect(take()).toEqual([]);
    await clock.advance(1);
    expect(take()).toEqual([RAN("15")]);
  });

  it("the standard firmware sets error 3 and stays silent for an empty slot instead", async () => {
    const { sim, clock, send, take } = rig();
    send(RUN("0C"));
    await clock.advance(5000);
    expect(take()).toEqual([]);
    expect(sim.errorCode).toBe(3);
  });
});

describe("firmware variants (docs/protocol.md §3.1, §3.5)", () => {
  it("no 0x0F: free memory goes unanswered, everything else is answered", () => {
    const { sim, send, take } = rig({ answersMemoryRead: false });
    send(READ_FREE_MOTION);
    send(READ_VERSION);
    expect(take()).toEqual([VERSION_2_23]);
    expect(sim.stats.drops["unknown-type"]).toBe(1);
  });

  it("servos silent: a Run holds error 11 for 4.5 s, then replies and clears it to FF", async () => {
    const { sim, clock, send, take } = rig({ servosSilent: true, basicPostureDone: false });
    const before = sim.servoPositions();
    send(RUN("07"));
    send(READ_ERROR);
    expect(take()).toEqual([ERROR_11]);
    await clock.advance(4499);
    send(READ_ERROR);
    expect(take()).toEqual([ERROR_11]);
    await clock.advance(1);
    expect(take()).toEqual([RAN("07")]);
    send(READ_ERROR);
    expect(take()).toEqual([ERROR_NONE]);
    expect(sim.servoPositions()).toEqual(before);
    // 7 counts as run: another number is accepted now.
    expect(sim.basicPostureDone).toBe(true);
  });

  it("servos silent: no servo answers in direct mode", () => {
    const { send, take } = rig({ servosSilent: true });
    send(DIRECT_ON);
    expect(take()).toEqual([DIRECT_ON_REPLY]);
    send(WCK_READ_SERVO_0);
    expect(take()).toEqual([]);
  });

  it("the standard servos answer the same wCK read (the test above can fail)", () => {
    const { send, take } = rig();
    send(DIRECT_ON);
    take();
    send(WCK_READ_SERVO_0);
    expect(take()).toHaveLength(1);
  });

  it("Run Sound replied at once; nothing else is received while the sound plays", async () => {
    const { clock, send, take } = rig({ soundReplyAtOnce: true });
    send(SOUND_3);
    expect(take()).toEqual([SOUND_3_REPLY]);
    send(READ_VERSION);
    await clock.advance(200 + 832 - 1);
    expect(take()).toEqual([]);
    await clock.advance(1);
    expect(take()).toEqual([]);
    send(READ_VERSION);
    expect(take()).toEqual([VERSION_2_23]);
  });

  it("the homebrew port's endless 0x16 repeat", async () => {
    const { clock, send, take } = rig({ repeatReplies: { type: 0x16, intervalMs: 1 } });
    send(READ_DISTANCE);
    await clock.advance(10);
    const sent = take();
    expect(sent).toHaveLength(11);
    expect(new Set(sent)).toEqual(new Set([DISTANCE_10]));
  });
});
