/**
 * Tethered play (docs/protocol.md §10) through the whole stack: RbcClient → WebSerialTransport → MockSerialPort →
 * SimulatedRbc, on a virtual clock. Every expected byte is worked out by hand below from §5 (a synchronised
 * move is `FF (speed<<5 | 1F) N p0 … pN-1 cs`, cs = XOR of the positions AND 7F) and the §10 frame formula
 * `start + round(k·(end − start)/frames) + zeroDelta[i]` (round: halves away from zero).
 */
import { describe, expect, it } from "vitest";
import {
  type LogEntry,
  RbcClient,
  type TetheredPlayError,
  type TetheredPlayProgress,
  type TetheredPlayResult,
} from "../../src/device/index.ts";
import { errorText } from "../../src/i18n/index.ts";
import { type Transport, WebSerialTransport } from "../../src/link/index.ts";
import { type Motion, newMotion, openMotion } from "../../src/motion/index.ts";
import { FACTORY_ZEROS, parseRbm, toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { MockSerialPort, SimulatedRbc } from "../../src/sim/index.ts";
import { exampleText } from "../data/project-data.ts";
import { EX } from "../fixtures/protocol-examples.ts";
import { makeRig, type Rig } from "../support/rig.ts";

/**
 * Servos 0 and 2 (file zeros 125 and 160; the simulated robot stores the factory zeros 124 and 162, so the
 * zero deltas are −1 and +2). Servo 1 is not in the motion: the synchronised move of ids 0..2 holds it.
 *   scene 0 "A": 2 frames in 50 ms (25 ms apart): servo 0 126 → 120 torque 2; servo 2 197 → 201 torque 3
 *   scene 1 "B": 3 frames in 70 ms (23 ms apart): servo 0 120 → 130 torque 0; servo 2 201 → 205 torque 2
 * The motion's first pose on the robot is 126 − 1 = 125 and 197 + 2 = 199: the simulator's power-up pose
 * (basic posture 125 179 199 …), so no transition is needed.
 */
const PAIR =
  "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:4:Pair:0:1:2:2:2:4:" +
  "00:020:030:000:0:125:02:020:030:000:0:160:" +
  "000:01:A:2:50:0:00:126:120:2:0:0:02:197:201:3:0:" +
  "001:01:B:3:70:0:00:120:130:0:0:0:02:201:205:2:0:";

/**
 * With servo 1 held at 150 (0x96):
 *   scene 0, speed 2 (torques 2, 3; the strongest is 2): 5F
 *     k=1: servo 0 126 + round(−6·1/2) − 1 = 122 (7A); servo 2 197 + round(4·1/2) + 2 = 201 (C9)
 *          cs = 7A ^ 96 ^ C9 = 25
 *     k=2: 126 − 6 − 1 = 119 (77); 197 + 4 + 2 = 203 (CB); cs = 77 ^ 96 ^ CB = 2A
 *   scene 1, speed 0 (torques 0, 2): 1F
 *     k=1: 120 + round(3.33) − 1 = 122 (7A); 201 + round(1.33) + 2 = 204 (CC); cs = 20
 *     k=2: 120 + round(6.67) − 1 = 126 (7E); 201 + round(2.67) + 2 = 206 (CE); cs = 26
 *     k=3: 130 − 1 = 129 (81); 205 + 2 = 207 (CF); cs = 81 ^ 96 ^ CF = D8 & 7F = 58
 */
const PAIR_FRAMES = [
  "FF 5F 03 7A 96 C9 25",
  "FF 5F 03 77 96 CB 2A",
  "FF 1F 03 7A 96 CC 20",
  "FF 1F 03 7E 96 CE 26",
  "FF 1F 03 81 96 CF 58",
];
/** Frame k of a scene is sent k intervals after the scene starts: 25, 50, then 50 + 23·k. */
const PAIR_TIMES = [25, 50, 73, 96, 119];
/** The busy probe's requests (docs/protocol.md §2, §3.6): 0x12 and 0x16, contents `01`, checksum `01`. */
const PROBE_DISTANCE = "FF FF AA 55 AA 55 37 BA 16 00 00 00 00 01 01 01";

const pair = (): Motion => openMotion(PAIR);

/** The raw servo-bus writes of tethered play, in order, with their clock times. */
function frameWrites(log: readonly LogEntry[]) {
  return log
    .filter((e) => e.direction === "out" && e.kind === "raw" && e.name.startsWith("tethered play"))
    .map((e) => ({ hex: toHex(e.bytes), time: e.time }));
}

function record(rig: Rig): LogEntry[] {
  const log: LogEntry[] = [];
  rig.client.log.on((e) => log.push(e));
  return log;
}

describe("tethered play sends one synchronised move per frame", () => {
  it("sends the §5 bytes of every frame at its time, zero deltas applied, the unlisted servo held", async () => {
    const rig = await makeRig();
    const { client, run, sim } = rig;
    // Servo 1 somewhere else than its power-up pose, through servo control (the client is then in direct mode:
    // play leaves it to read the zeros, and comes back).
    await run(client.enterDirectMode());
    await run(client.servos.move(1, 150, 2));
    const log = record(rig);
    const progress: TetheredPlayProgress[] = [];
    const result = await run(client.playTethered(pair(), { onFrame: (p) => progress.push(p) }));

    const frames = frameWrites(log);
    expect(frames.map((f) => f.hex)).toEqual(PAIR_FRAMES);
    const t0 = frames[0]!.time - PAIR_TIMES[0]!;
    expect(frames.map((f) => f.time - t0)).toEqual(PAIR_TIMES);
    expect(progress.map((p) => p.elapsedMs)).toEqual(PAIR_TIMES);
    expect(progress.map((p) => [p.index, p.total, p.scene, p.frame.frame])).toEqual([
      [0, 5, 0, 1],
      [1, 5, 0, 2],
      [2, 5, 1, 1],
      [3, 5, 1, 2],
      [4, 5, 1, 3],
    ]);
    expect(progress[0]!.positions.slice(0, 4)).toEqual([122, 150, 201, undefined]);
    expect(progress[0]!.durationMs).toBe(119);

    // Before the frames: out of direct mode, the zeros read (0x0B), the busy probe (0x16 answered at once on
    // an idle robot, so no 0x12: direct mode only when the robot is idle, §3.6), direct mode again (§8
    // example 4), and the servos 0-2 read (`FF A0|id 00 cs`).
    const out = log.filter((e) => e.direction === "out").map((e) => toHex(e.bytes));
    expect(out.slice(0, 8)).toEqual([
      "FF E0 FB 01 00 1A",
      "FF FF AA 55 AA 55 37 BA 0B 00 00 00 00 01 01 01",
      PROBE_DISTANCE,
      EX.directOn,
      "FF A0 00 20",
      "FF A1 00 21",
      "FF A2 00 22",
      PAIR_FRAMES[0],
    ]);

    expect(result).toMatchObject({
      outcome: "finished",
      framesSent: 5,
      totalFrames: 5,
      transitionFrames: 0,
      lastFrame: { scene: 1, frame: 3 },
      plannedMs: 119,
      maxLateMs: 0,
    });
    expect(result.lastPositions.slice(0, 3)).toEqual([129, 150, 207]);
    expect(result.readBack).toEqual({
      positions: [129, 150, 207, ...Array(13).fill(undefined)],
      silent: [],
      maxDeviation: 0,
    });
    // The robot stays in servo control holding the last frame.
    expect(client.mode).toBe("direct");
    expect(sim.directMode).toBe(true);
    expect(sim.servos.slice(0, 3).map((s) => [s.position, s.passive])).toEqual([
      [129, false],
      [150, false],
      [207, false],
    ]);
    expect(client.state.tethered).toBeUndefined();
  });

  it("with the zeros and platform given, reads nothing in packet mode but the busy probe; platform 4 (PF2) applies no zero delta", async () => {
    const rig = await makeRig();
    const log = record(rig);
    const result = await rig.run(rig.client.playTethered(pair(), { robotZeros: FACTORY_ZEROS, platform: 4 }));
    const out = log.filter((e) => e.direction === "out").map((e) => toHex(e.bytes));
    // The busy probe is one 0x16, answered at once (idle): no 0x12 follows.
    expect(out.slice(0, 5)).toEqual([
      PROBE_DISTANCE,
      EX.directOn,
      "FF A0 00 20",
      "FF A1 00 21",
      "FF A2 00 22",
    ]);
    // No zero delta: the first pose is 126 / 197, within 10 counts of 125 / 199, so still no transition.
    // k=1: 126 − 3 = 123 (7B), servo 1 held at 179 (B3), 197 + 2 = 199 (C7): cs = 7B ^ B3 ^ C7 = 0F.
    expect(frameWrites(log)[0]!.hex).toBe("FF 5F 03 7B B3 C7 0F");
    expect(result.lastPositions.slice(0, 3)).toEqual([130, 179, 205]);
    expect(rig.sim.servos.slice(0, 3).map((s) => s.position)).toEqual([130, 179, 205]);
  });

  it("first moves to the first pose in gap/3 frames 20 ms apart at torque 3 when a servo is far from it", async () => {
    const rig = await makeRig();
    const { client, run } = rig;
    await run(client.enterDirectMode());
    await run(client.servos.move(0, 100, 2)); // 25 counts below the first pose (125): 25 / 3 = 8 frames
    const log = record(rig);
    const result = await run(client.playTethered(pair(), { robotZeros: FACTORY_ZEROS, platform: 1 }));
    const frames = frameWrites(log);
    expect(result.transitionFrames).toBe(8);
    expect(frames).toHaveLength(8 + 5);
    // Transition frame j: servo 0 at 100 + round(25·j/8), servos 1 and 2 where they are (179, 199), speed 3 (7F).
    // j=1: 103 (67) B3 C7, cs = 67 ^ B3 ^ C7 = 13;  j=8: 125 (7D) B3 C7, cs = 7D ^ B3 ^ C7 = 09.
    expect(frames[0]!.hex).toBe("FF 7F 03 67 B3 C7 13");
    expect(frames[7]!.hex).toBe("FF 7F 03 7D B3 C7 09");
    const t0 = frames[0]!.time - 20;
    expect(frames.map((f) => f.time - t0)).toEqual([
      20,
      40,
      60,
      80,
      100,
      120,
      140,
      160,
      ...PAIR_TIMES.map((t) => 160 + t),
    ]);
    // Then the scenes, as in the first test but with servo 1 at 179 (B3): k=1 7A B3 C9, cs = 7A ^ B3 ^ C9 = 00.
    expect(frames[8]!.hex).toBe("FF 5F 03 7A B3 C9 00");
    expect(rig.sim.servos.slice(0, 3).map((s) => s.position)).toEqual([129, 179, 207]);
  });

  it("plays a range of scenes of a 16-servo example and leaves the servos at its last frame", async () => {
    const rig = await makeRig({ sim: { basicPostureDone: true } });
    const wave = openMotion(exampleText("wave.rbm"));
    const log = record(rig);
    const result = await rig.run(rig.client.playTethered(wave, { range: { from: 1, to: 2 } }));
    // Scene 1 starts with the arm raised, far from the power-up pose: transition frames lead there first.
    expect(result.transitionFrames).toBeGreaterThan(0);
    const expected = result.transitionFrames + wave.scenes[1]!.frames + wave.scenes[2]!.frames;
    expect(result).toMatchObject({ outcome: "finished", framesSent: expected, totalFrames: expected });
    const frames = frameWrites(log);
    expect(frames).toHaveLength(expected);
    // 16 positions per frame: FF, speed|1F (3 for the transition, the scenes' torque 2 after), 10 (N = 16),
    // the positions, the checksum.
    const heads = frames.map((f) => f.hex.split(" ").slice(0, 3).join(" "));
    expect(heads.slice(0, result.transitionFrames).every((h) => h === "FF 7F 10")).toBe(true);
    expect(heads.slice(result.transitionFrames).every((h) => h === "FF 5F 10")).toBe(true);
    expect(frames.every((f) => f.hex.split(" ").length === 20)).toBe(true);
    // The last frame is scene 2's end pose plus the zero deltas (factory − standard), clamped to the safe range.
    const deltas = FACTORY_ZEROS.map((z, id) => z - wave.servos[id]!.zero);
    const end = wave.scenes[2]!.servos.map((r, id) => r.end + deltas[id]!);
    expect(rig.sim.servos.map((s) => s.position)).toEqual(end);
    expect(result.readBack?.maxDeviation).toBe(0);
  });
});

/** A link whose writes of tethered-play frames can be held up (a busy USB adapter, a stalled driver). */
class StallingTransport implements Transport {
  /** How long the write of the n-th frame (0-based) takes; 0 when not listed. */
  stalls = new Map<number, number>();
  #frames = 0;
  constructor(
    private readonly inner: Transport,
    private readonly clock: VirtualClock,
  ) {}
  get status() {
    return this.inner.status;
  }
  open() {
    return this.inner.open();
  }
  async write(bytes: Uint8Array) {
    // A synchronised move: FF, then speed << 5 | 1F with speed 0-4 (an RBC packet's header is FF FF).
    if (bytes[0] === 0xff && (bytes[1]! & 0x1f) === 0x1f && bytes[1]! >> 5 <= 4) {
      const ms = this.stalls.get(this.#frames++) ?? 0;
      if (ms > 0) await new Promise((resolve) => this.clock.setTimeout(() => resolve(undefined), ms));
    }
    return this.inner.write(bytes);
  }
  onData(listener: (bytes: Uint8Array) => void) {
    return this.inner.onData(listener);
  }
  onStatus(listener: Parameters<Transport["onStatus"]>[0]) {
    return this.inner.onStatus(listener);
  }
  close() {
    return this.inner.close();
  }
}

async function stallingRig() {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock });
  const port = new MockSerialPort(sim, { clock });
  const transport = new StallingTransport(new WebSerialTransport(port, { clock }), clock);
  const client = new RbcClient(transport, { clock });
  await clock.run(client.connect());
  const log: LogEntry[] = [];
  client.log.on((e) => log.push(e));
  return { clock, sim, transport, client, log };
}

describe("the schedule", () => {
  it("is absolute: a frame the link is late for goes out at once, the next ones on time, the lateness reported", async () => {
    const { clock, transport, client, log } = await stallingRig();
    transport.stalls.set(0, 40); // the first frame's write (at 25 ms) takes until 65 ms
    const result = await clock.run(client.playTethered(pair(), { robotZeros: FACTORY_ZEROS, platform: 1 }));
    const frames = frameWrites(log);
    const t0 = frames[0]!.time - 25;
    // Frame 2 was due at 50: sent at 65, 15 ms late. Frame 3 is due at 73 and goes then (no drift).
    expect(frames.map((f) => f.time - t0)).toEqual([25, 65, 73, 96, 119]);
    expect(result.maxLateMs).toBe(15);
    expect(result.outcome).toBe("finished");
  });

  it("a frame whose write never completes: a typed error, the robot's state unknown", async () => {
    const { clock, transport, client } = await stallingRig();
    transport.stalls.set(2, 60_000);
    const error = (await clock
      .run(client.playTethered(pair(), { robotZeros: FACTORY_ZEROS, platform: 1 }))
      .catch((e) => e)) as TetheredPlayError;
    expect(error).toMatchObject({
      name: "TetheredPlayError",
      code: "timeout",
      framesSent: 2,
      lastFrame: { scene: 0, frame: 2 },
      holds: "unknown",
    });
    expect(error.situation).toMatchObject({ kind: "play-link-lost", timedOut: true, framesSent: 2 });
    expect(errorText(error, "en")).toMatch(
      /^A frame could not be written within its time during tethered play, after 2 of 5/,
    );
  });
});

describe("Stop, Limp and failures", () => {
  /** wave.rbm from its first scene: 16 servos, about 3.2 s. */
  const wave = () => parseRbm(exampleText("wave.rbm")) as Motion;

  it("Stop mid-way: no frame after the one on the wire, nothing passive, outcome stopped, the client still works", async () => {
    const rig = await makeRig({ sim: { basicPostureDone: true } });
    const { client, run, clock, sim } = rig;
    const log = record(rig);
    const playing = client.playTethered(wave());
    await clock.advance(700);
    expect(client.state.tethered).toMatchObject({ totalFrames: expect.any(Number) });
    const sentBefore = frameWrites(log).length;
    expect(sentBefore).toBeGreaterThan(0);
    const stop = await run(client.stopActivity());
    const result: TetheredPlayResult = await run(playing);
    expect(result.outcome).toBe("stopped");
    expect(result.framesSent).toBe(sentBefore);
    expect(result.framesSent).toBeLessThan(result.totalFrames);
    expect(stop.tetheredPlay).toEqual({
      framesSent: result.framesSent,
      totalFrames: result.totalFrames,
      lastFrame: result.lastFrame,
    });
    expect(stop.servoMovesDropped).toBe(true);
    // Nothing more goes out, however long we wait; the servos hold the last frame sent, with torque.
    await clock.advance(5000);
    expect(frameWrites(log)).toHaveLength(sentBefore);
    expect(sim.servos.map((s) => s.position)).toEqual(result.lastPositions);
    expect(sim.servos.some((s) => s.passive)).toBe(false);
    // Stop leaves direct mode (issue 22 item 6); leaving changes no servo.
    expect(stop.leftDirectMode).toBe(true);
    expect(client.mode).toBe("packet");
    expect(sim.directMode).toBe(false);
    expect(await run(client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
  });

  it("an aborted signal stops it the same way", async () => {
    const rig = await makeRig({ sim: { basicPostureDone: true } });
    const stop = new AbortController();
    const log = record(rig);
    const playing = rig.client.playTethered(wave(), { signal: stop.signal });
    await rig.clock.advance(400);
    stop.abort();
    const result = await rig.run(playing);
    expect(result.outcome).toBe("stopped");
    await rig.clock.advance(5000);
    expect(frameWrites(log)).toHaveLength(result.framesSent);
    expect(rig.sim.servos.some((s) => s.passive)).toBe(false);
  });

  it("Stop while play waits its turn (a motion plays): the motion ends with 7, play resolves stopped, sends nothing", async () => {
    const rig = await makeRig({ sim: { basicPostureDone: true } });
    const log = record(rig);
    const walking = rig.client.runMotion(4).catch((e) => e);
    const playing = rig.client.playTethered(pair(), { robotZeros: FACTORY_ZEROS, platform: 1 });
    await rig.clock.advance(300);
    const stop = await rig.run(rig.client.stopActivity());
    expect(stop.motion).toEqual({ number: 4, outcome: "stopped" });
    expect(stop.tetheredPlay).toEqual({ framesSent: 0, totalFrames: 0, lastFrame: undefined });
    expect(await walking).toMatchObject({ code: "cancelled" });
    const result = await rig.run(playing);
    expect(result).toMatchObject({ outcome: "stopped", framesSent: 0 });
    await rig.clock.advance(1000);
    expect(log.filter((e) => e.direction === "out" && toHex(e.bytes) === EX.directOn)).toHaveLength(0);
    expect(frameWrites(log)).toHaveLength(0);
    expect(rig.client.mode).toBe("packet");
  });

  it("Limp during play stops play first, then makes every servo passive", async () => {
    const rig = await makeRig({ sim: { basicPostureDone: true } });
    const log = record(rig);
    const playing = rig.client.playTethered(wave());
    await rig.clock.advance(500);
    const limp = await rig.run(rig.client.limp());
    const result = await rig.run(playing);
    expect(result.outcome).toBe("stopped");
    expect(limp.confirmed).toHaveLength(16);
    expect(rig.sim.servos.every((s) => s.passive)).toBe(true);
    await rig.clock.advance(5000);
    expect(frameWrites(log)).toHaveLength(result.framesSent);
  });

  it("refuses a motion whose frames are closer than 20 ms (RBC error 6) before sending anything", async () => {
    const rig = await makeRig();
    const template = newMotion();
    // 500 ms in 30 frames: 16 ms apart (an edit would refuse it; a document built by a program may not).
    const tooFast: Motion = { ...template, scenes: [{ ...template.scenes[0]!, frames: 30 }] };
    const before = rig.port.stats.bytesFromPc;
    const error = (await rig.fail(rig.client.playTethered(tooFast))) as TetheredPlayError;
    expect(error).toMatchObject({
      name: "TetheredPlayError",
      code: "invalid-argument",
      holds: "nothing-sent",
    });
    expect(error.situation).toEqual({ kind: "play-refused" });
    expect(errorText(error, "en")).toMatch(/16 ms apart .*error 6.* Nothing was sent to the robot\.$/);
    expect(rig.port.stats.bytesFromPc).toBe(before);
    expect(rig.client.mode).toBe("packet");
    const badRange = await rig.fail(rig.client.playTethered(pair(), { range: { from: 1, to: 0 } }));
    expect(badRange).toMatchObject({ code: "invalid-argument" });
    expect(rig.port.stats.bytesFromPc).toBe(before);
  });

  it("a cable pull mid-play: a typed error that says how far it got and that the robot's state is unknown", async () => {
    const rig = await makeRig();
    const playing = rig.client.playTethered(pair(), { robotZeros: FACTORY_ZEROS, platform: 1 });
    // Frames go out 25 and 50 ms into the schedule; the cable is pulled 60 ms in, before the third (73 ms).
    let pulled = false;
    const off = rig.client.stateChanges.on((s) => {
      if (s.tethered && !pulled) {
        pulled = true;
        rig.clock.setTimeout(() => rig.port.unplug(), 60);
      }
    });
    const error = (await rig.fail(playing)) as TetheredPlayError;
    off();
    expect(error).toMatchObject({
      name: "TetheredPlayError",
      code: "disconnected",
      framesSent: 2,
      totalFrames: 5,
      lastFrame: { scene: 0, frame: 2 },
      holds: "unknown",
    });
    expect(errorText(error, "en")).toContain("after 2 of 5 frames (the last: scene 0, frame 2)");
    expect(errorText(error, "en")).toContain("state is unknown");
    expect(errorText(error, "ko")).toContain("프레임 5개 중 2개를 보낸 뒤 (마지막: 장면 0, 프레임 2)");
    expect(rig.client.mode).toBe("disconnected");
  });

  it("a robot that goes silent: the frames were sent, the servos hold the last one, nothing confirmed", async () => {
    const rig = await makeRig();
    const playing = rig.client.playTethered(pair(), { robotZeros: FACTORY_ZEROS, platform: 1 });
    const off = rig.client.stateChanges.on((s) => {
      if (s.tethered) rig.port.faults.swallowReplies(Number.POSITIVE_INFINITY);
    });
    const error = (await rig.fail(playing)) as TetheredPlayError;
    off();
    expect(error).toMatchObject({ code: "timeout", framesSent: 5, holds: "last-frame" });
    expect(errorText(error, "en")).toMatch(
      /All 5 frames were sent \(the last: scene 1, frame 3\), but no servo answered/,
    );
  });

  it("a servo that does not answer before play: nothing is moved", async () => {
    const rig = await makeRig();
    await rig.run(rig.client.enterDirectMode());
    rig.port.faults.swallowReplies(Number.POSITIVE_INFINITY);
    const log = record(rig);
    const error = (await rig.fail(
      rig.client.playTethered(pair(), { robotZeros: FACTORY_ZEROS, platform: 1 }),
    )) as TetheredPlayError;
    expect(error).toMatchObject({ code: "timeout", framesSent: 0, holds: "nothing-sent" });
    expect(error.situation).toEqual({ kind: "play-servos-silent", silent: [0, 1, 2], maxId: 2 });
    expect(errorText(error, "en")).toMatch(/^Servos 0, 1 and 2 did not answer/);
    expect(errorText(error, "ko")).toMatch(/^서보 0, 1, 2번이 서보 제어에서 응답하지 않아서/);
    expect(frameWrites(log)).toHaveLength(0);
  });
});
