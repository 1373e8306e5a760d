import { describe, expect, it } from "vitest";
import { toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { ServoBus, SimulatedRbc, type SimulatedRbcOptions } from "../../src/sim/index.ts";

/**
 * The simulated servo bus (docs/protocol.md §5, §9): parameter sets and reads in the manual's byte order, the id
 * set, mode-7 framing by d2, and the faults of the servo doctor (issue 22). Every request and reply is literal
 * bytes: requests from §5's examples or worked out by hand from its checksum rule, replies from the HUNO basic
 * posture the simulated servos stand in (125 179 199 88 108 126 72 49 163 141 51 47 49 199 205 205) and the
 * defaults of `sim-servo-parameters.ts`.
 */

const ENTER_DIRECT = "FF FF AA 55 AA 55 37 BA 10 00 00 00 00 01 01 01";
const ENTER_DIRECT_REPLY = "FF FF AA 55 AA 55 37 BA 10 01 00 00 00 01 01 01";
const LEAVE_DIRECT = "FF E0 FB 01 00 1A";
const RUN_MOTION_7 = "FF FF AA 55 AA 55 37 BA 14 00 00 00 00 01 07 07";

const fromHex = (hex: string) => Uint8Array.from(hex.split(" "), (h) => Number.parseInt(h, 16));

/** A simulated RBC on a virtual clock, already in direct mode; `ask` sends bytes and returns the replies. */
function bus(options: SimulatedRbcOptions = {}) {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock, ...options });
  const out: string[] = [];
  sim.onTransmit((bytes) => out.push(toHex(bytes)));
  const send = (hex: string) => sim.receive(fromHex(hex));
  const ask = (hex: string) => {
    out.length = 0;
    send(hex);
    return out.splice(0);
  };
  expect(ask(ENTER_DIRECT)).toEqual([ENTER_DIRECT_REPLY]);
  return { clock, sim, send, ask };
}

describe("parameter reads answer the stored values in the manual's byte order", () => {
  it("after power-up: gains 20/30, speed 15/50, overload 199, bounds 1..254 (lower, upper), I 0, I/O 0", () => {
    const { ask } = bus();
    expect(ask("FF E2 0A 00 00 68")).toEqual(["14 1E"]);
    expect(ask("FF E2 0E 00 00 6C")).toEqual(["0F 32"]);
    expect(ask("FF E2 10 00 00 72")).toEqual(["C7 C7"]);
    expect(ask("FF E2 12 00 00 70")).toEqual(["01 FE"]);
    expect(ask("FF E2 16 00 00 74")).toEqual(["00 00"]);
    expect(ask("FF E2 65 00 00 07")).toEqual(["00 00"]);
  });

  it("bounds set as lower 40, upper 200 read back 28 C8, hold a move to 220 at 200, and fall back to 1..254 at power-up", () => {
    const { sim, ask } = bus();
    expect(ask("FF E2 11 28 C8 13")).toEqual(["28 C8"]);
    expect(ask("FF E2 12 00 00 70")).toEqual(["28 C8"]);
    // Move id 2 to 220 at torque 0: the servo stops at its upper bound.
    expect(ask("FF 02 DC 5E")).toEqual(["00 C8"]);
    sim.powerCycle();
    ask(ENTER_DIRECT);
    expect(ask("FF E2 12 00 00 70")).toEqual(["01 FE"]);
  });

  it("stored sets (0x09 gains, 0x15 I gain, 0x0F overload, 0x64 I/O) read back and last; power-up-only gains (0x0B) do not", () => {
    const { sim, ask } = bus();
    expect(ask("FF E2 0F 63 63 6D")).toEqual(["63 63"]);
    expect(ask("FF E2 10 00 00 72")).toEqual(["63 63"]);
    expect(ask("FF E2 15 07 07 77")).toEqual(["07 07"]);
    expect(ask("FF E2 16 00 00 74")).toEqual(["07 07"]);
    expect(ask("FF E2 64 03 03 06")).toEqual(["03 03"]);
    expect(ask("FF E2 65 00 00 07")).toEqual(["03 03"]);
    expect(ask("FF E2 0B 0A 0B 68")).toEqual(["0A 0B"]);
    expect(ask("FF E2 0A 00 00 68")).toEqual(["0A 0B"]);
    sim.powerCycle();
    ask(ENTER_DIRECT);
    expect(ask("FF E2 0A 00 00 68")).toEqual(["14 1E"]);
    expect(ask("FF E2 16 00 00 74")).toEqual(["07 07"]);
    expect(ask("FF E2 10 00 00 72")).toEqual(["63 63"]);
  });
});

describe("mode-7 framing by d2", () => {
  it("the 8-byte 10-bit move (0xC8) moves servo 5 to 130 and replies 08 10; the read after it is understood", () => {
    const { sim, ask } = bus();
    expect(ask("FF E0 C8 05 02 08 10 37 FF A5 00 25")).toEqual(["08 10", "00 82"]);
    expect(sim.servos[5]!.position).toBe(130);
    // The 10-bit read (0xC9) names its servo in d3: (08 << 6) | (10 >> 1) = 520 = 130 × 4.
    expect(ask("FF E0 C9 05 05 29")).toEqual(["08 10"]);
  });
});

describe("the id set (0x0C)", () => {
  it("FF E0 0C 1E 1E 6C makes servo 0 answer at 30 and not at 0, through a reconnect and a power cycle", () => {
    const { sim, ask } = bus();
    expect(ask("FF E0 0C 1E 1E 6C")).toEqual(["1E 1E"]);
    expect(ask("FF BE 00 3E")).toEqual(["00 7D"]);
    expect(ask("FF A0 00 20")).toEqual([]);
    expect(sim.servos[0]).toMatchObject({ id: 0, busId: 30 });
    // Leave direct mode and come back (a reconnect keeps the SimulatedRbc), then switch the robot off and on.
    expect(ask(LEAVE_DIRECT)).toEqual([]);
    expect(sim.directMode).toBe(false);
    ask(ENTER_DIRECT);
    expect(ask("FF BE 00 3E")).toEqual(["00 7D"]);
    sim.powerCycle();
    ask(ENTER_DIRECT);
    expect(ask("FF BE 00 3E")).toEqual(["00 7D"]);
    expect(ask("FF A0 00 20")).toEqual([]);
  });
});

describe("servos kept across RBCs (the demo robot keeps one ServoBus for the page)", () => {
  it("an id set on one connection is still there on the next; its bounds set is not (a new RBC is a power-up)", () => {
    const servoBus = new ServoBus({ replacement: [12] });
    const first = bus({ servoBus });
    expect(first.ask("FF AC 00 2C")).toEqual([]);
    first.sim.connectServo(0, false);
    expect(first.ask("FF E0 0C 0C 0C 6C")).toEqual(["0C 0C"]);
    expect(first.ask("FF EC 11 28 C8 1D")).toEqual(["28 C8"]);
    first.sim.connectServo(0, true);
    first.sim.dispose();
    const second = bus({ servoBus });
    expect(second.ask("FF AC 00 2C")).toEqual(["00 31"]);
    expect(second.ask("FF A0 00 20")).toEqual(["00 7D"]);
    expect(second.ask("FF EC 12 00 00 7E")).toEqual(["01 FE"]);
  });

  it("faults go to the ServoBus, not beside it", () => {
    expect(() => new SimulatedRbc({ servoBus: new ServoBus(), servoFaults: { missing: [1] } })).toThrow(
      RangeError,
    );
  });
});

describe("faults", () => {
  it("--servo-missing 7: id 7 is silent to reads, moves and parameter reads; its neighbours answer", () => {
    const { ask } = bus({ servoFaults: { missing: [7] } });
    expect(ask("FF A7 00 27")).toEqual([]);
    expect(ask("FF 47 31 76")).toEqual([]);
    expect(ask("FF E7 0A 00 00 6D")).toEqual([]);
    expect(ask("FF A6 00 26")).toEqual(["00 48"]);
    expect(ask("FF A8 00 28")).toEqual(["00 A3"]);
  });

  it("--servo-duplicate 3: two servos answer id 3 and their replies collide into 3 bytes, never a clean pair", () => {
    const { sim, ask } = bus({ servoFaults: { duplicate: [3] } });
    expect(ask("FF A3 00 23")).toEqual(["00 00 58"]);
    // Both take a move (to 100 = 64 at torque 2): the collided reply is 00 (00 & 64) 64.
    expect(ask("FF 43 64 27")).toEqual(["00 00 64"]);
    expect(sim.servos[3]!.position).toBe(100);
    expect(ask("FF A4 00 24")).toEqual(["00 6C"]);
  });

  it("a duplicate at every id 0-15 garbles that id's read (never exactly 2 bytes)", () => {
    for (let id = 0; id < 16; id++) {
      const { ask } = bus({ servoFaults: { duplicate: [id] } });
      const read = Uint8Array.of(0xff, 0xa0 | id, 0x00, (0xa0 | id) & 0x7f);
      const replies = ask(toHex(read));
      expect(replies).toHaveLength(1);
      expect(replies[0]!.split(" ")).toHaveLength(3);
    }
  });

  it("--servo-replacement 12: id 0 answered by two (garbled), id 12 by none; the guided fix (unplug joint 0, 0 → 12) makes both clean", () => {
    const { sim, ask } = bus({ servoFaults: { replacement: [12] } });
    // Servo 0 at 125 (7D) and the replacement in joint 12 at 49 (31): 00, 7D & 00, 31.
    expect(ask("FF A0 00 20")).toEqual(["00 00 31"]);
    expect(ask("FF AC 00 2C")).toEqual([]);
    expect(sim.connectServo(0, false)).toBe(true);
    expect(ask("FF A0 00 20")).toEqual(["00 31"]);
    expect(ask("FF E0 0C 0C 0C 6C")).toEqual(["0C 0C"]);
    expect(ask("FF A0 00 20")).toEqual([]);
    sim.connectServo(0, true);
    expect(ask("FF A0 00 20")).toEqual(["00 7D"]);
    expect(ask("FF AC 00 2C")).toEqual(["00 31"]);
  });

  it("a replacement servo at id 0 follows servo 0 in a motion: after motion 7, joint 12 stands at id 0's 125", async () => {
    const { clock, sim, ask } = bus({ servoFaults: { replacement: [12] } });
    ask(LEAVE_DIRECT);
    ask(RUN_MOTION_7);
    await clock.advance(10_000);
    expect(sim.playingMotion).toBeUndefined();
    expect(sim.servos[0]!.position).toBe(125);
    expect(sim.servos[12]!.position).toBe(125);
  });

  it("--servo-loaded 4: a high load at rest (B4), and a move of 10 counts gets only 4 of them", () => {
    const { sim, ask } = bus({ servoFaults: { loaded: [4] } });
    expect(ask("FF A4 00 24")).toEqual(["B4 6C"]);
    // Move id 4 from 108 to 118 at torque 2: it reaches 112 (70).
    expect(ask("FF 44 76 32")).toEqual(["B4 70"]);
    expect(sim.servos[4]!.position).toBe(112);
    // A free servo makes the whole move: id 5 from 126 to 136 (88).
    expect(ask("FF 45 88 4D")).toEqual(["00 88"]);
    // Passive, it carries no load.
    expect(ask("FF C4 10 54")).toEqual(["00 70"]);
    expect(ask("FF A4 00 24")).toEqual(["00 70"]);
  });

  it("bad fault ids are refused with a RangeError and no robot", () => {
    expect(() => new SimulatedRbc({ servoFaults: { missing: [16] } })).toThrow(RangeError);
    expect(() => new SimulatedRbc({ servoFaults: { duplicate: [-1] } })).toThrow(RangeError);
    expect(() => new SimulatedRbc({ servoFaults: { replacement: [0] } })).toThrow(/1-15/);
    expect(() => new SimulatedRbc({ servoFaults: { loaded: [2.5] } })).toThrow(RangeError);
    expect(() => new SimulatedRbc({ servoFaults: { missing: [3], replacement: [3] } })).toThrow(
      /both missing and a replacement/,
    );
  });
});

describe("the wheel mode (docs/protocol.md §5)", () => {
  it("servo 5 clockwise at speed 6, FF C5 46 03 ((C5 ^ 46) & 7F = 03): answered rotations 0, position 126", () => {
    const { ask } = bus();
    expect(ask("FF C5 46 03")).toEqual(["00 7E"]);
    // Counter-clockwise at speed 15: FF C5 3F 7A ((C5 ^ 3F) & 7F = 7A).
    expect(ask("FF C5 3F 7A")).toEqual(["00 7E"]);
  });

  it("a servo nobody has at the id does not answer, and passive (FF C5 10 55) is still passive", () => {
    const { ask } = bus({ servoFaults: { missing: [5] } });
    expect(ask("FF C5 46 03")).toEqual([]);
    const healthy = bus();
    expect(healthy.ask("FF C5 10 55")).toEqual(["00 7E"]);
  });
});

describe("direct mode during a motion started elsewhere (docs/protocol.md §3.6)", () => {
  it("the RBC relays the motion's servo traffic: each frame's position moves are answered (load, position), unasked", async () => {
    const { clock, sim, send, ask } = bus();
    ask(LEAVE_DIRECT);
    // Servo 0 stands at 100: basic posture moves it to 125 (the motion plays frames).
    sim.servos[0]!.position = 100;
    const out: string[] = [];
    sim.onTransmit((bytes) => out.push(toHex(bytes)));
    send(RUN_MOTION_7);
    await clock.advance(5);
    expect(sim.playingMotion).toBe(7);
    send(ENTER_DIRECT);
    expect(sim.directMode).toBe(true);
    out.length = 0;
    await clock.advance(200);
    // Nothing was sent to the servo bus by the PC, yet pairs arrive: one per servo per frame (16 servos).
    expect(out.length).toBeGreaterThanOrEqual(16);
    expect(out.every((hex) => /^[0-9A-F]{2} [0-9A-F]{2}$/.test(hex))).toBe(true);
    // Servo 7 holds 49 throughout (basic posture keeps it there): `00 31` is among them.
    expect(out).toContain("00 31");
  });

  it("out of direct mode the same motion sends nothing but its packets", async () => {
    const { clock, sim, send, ask } = bus();
    ask(LEAVE_DIRECT);
    const out: string[] = [];
    sim.onTransmit((bytes) => out.push(toHex(bytes)));
    send(RUN_MOTION_7);
    await clock.advance(200);
    expect(out.every((hex) => hex.startsWith("FF FF AA 55 AA 55 37 BA "))).toBe(true);
  });
});
