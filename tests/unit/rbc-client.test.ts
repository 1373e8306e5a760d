import { describe, expect, it } from "vitest";
import { type LogEntry, RbcClient, type RbcEvent, type UploadProgress } from "../../src/device/index.ts";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import { type Transport, WebSerialTransport } from "../../src/link/index.ts";
import { FACTORY_ZEROS, motionImage, parseRbm, STANDARD_ZEROS, toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { MockSerialPort, SimulatedRbc } from "../../src/sim/index.ts";
import { exampleText, goldenImage } from "../data/project-data.ts";
import { EX } from "../fixtures/protocol-examples.ts";
import { makeRig } from "../support/rig.ts";

/** examples/wave.rbm's golden 624-byte image (tests/data/images/wave.img.hex). */
const waveImage = () => goldenImage("wave.rbm");

describe("RbcClient against the simulated RBC", () => {
  it("connects: opens at 115200 with a 4 KiB buffer, abandons any download, leaves direct mode blindly, reads the version", async () => {
    const clock = new VirtualClock();
    const sim = new SimulatedRbc({ clock });
    const port = new MockSerialPort(sim, { clock });
    const client = new RbcClient(new WebSerialTransport(port, { clock }), { clock });
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    const identity = await clock.run(client.connect());
    expect(identity).toEqual({ firmware: { major: 2, minor: 23 }, platform: 1 });
    expect(port.openOptions).toMatchObject({ baudRate: 115200, dataBits: 8, stopBits: 1, parity: "none" });
    expect(port.openOptions?.bufferSize).toBeGreaterThanOrEqual(4096);
    const out = log.filter((e) => e.direction === "out").map((e) => toHex(e.bytes));
    // 64 payload bytes and a checksum that cannot match (abandons a download left half done), then the
    // direct-mode exit (docs/protocol.md §5, example 5).
    expect(out[0]).toBe(`00 01 ${Array(63).fill("00").join(" ")} FF E0 FB 01 00 1A`);
    expect(out[1]).toBe(EX.readVersion);
    expect(toHex(log.find((e) => e.direction === "in")!.bytes)).toBe(EX.version223);
    expect(client.mode).toBe("packet");
  });

  it("reads serial number, zeros, memory, error code, distance, accelerometer", async () => {
    const { client, run, sim } = await makeRig();
    expect(await run(client.readSerialNumber())).toBe("8958899989309");
    expect(await run(client.readZeros())).toEqual([...FACTORY_ZEROS]);
    expect(await run(client.readAvailableMemory("motion"))).toBe(24576);
    expect(await run(client.readAvailableMemory("action"))).toBe(8192);
    expect(await run(client.readErrorCode())).toBe(0xff);
    sim.setDistance(33);
    expect(await run(client.readDistance())).toBe(33);
    sim.setDistance(3);
    expect(await run(client.readDistance())).toBe(10);
    sim.setAccelerometer(4, 3, -6);
    expect(await run(client.readAccelerometer())).toEqual({ x: 4, y: 3, z: -6 });
    expect(Array.from(await run(client.executionStatus(7)))).toEqual([7, 0]);
  });

  it("writes zeros, checks the echo and verifies by reading back", async () => {
    const { client, run, sim } = await makeRig();
    const zeros = [...STANDARD_ZEROS];
    zeros[4] = 120;
    const result = await run(client.writeZeros(zeros));
    expect(result.readBack).toEqual(zeros);
    expect(sim.zeros).toEqual(zeros);
  });

  it("refuses a zero table the RBC would drop, without sending a byte", async () => {
    const { client, run, sim, port } = await makeRig();
    const before = port.stats.bytesFromPc;
    const zeros = [...STANDARD_ZEROS];
    zeros[0] = 141; // standard 125 + 16
    const error = await run(client.writeZeros(zeros).catch((e) => e));
    expect(error).toMatchObject({ code: "invalid-argument" });
    // Facts on the error (its message a technical line); the catalogue's sentence from them.
    expect(error.situation).toMatchObject({ kind: "zeros-not-written", problems: [{ id: 0, value: 141 }] });
    expect(errorText(error, "en")).toMatch(/Servo 0: 141 is outside 110-140/);
    expect(port.stats.bytesFromPc).toBe(before);
    expect(sim.zeros).toEqual([...FACTORY_ZEROS]);
  });

  it("runs basic posture, then other motions, replying after their duration", async () => {
    const { client, clock, run, sim } = await makeRig();
    const t0 = clock.now();
    expect(await run(client.runMotion(7))).toBe(7);
    expect(clock.now() - t0).toBeGreaterThanOrEqual(1800);
    expect(client.state.basicPostureConfirmed).toBe(true);
    expect(sim.basicPostureDone).toBe(true);
    const t1 = clock.now();
    expect(await run(client.runMotion(3))).toBe(3);
    expect(clock.now() - t1).toBeGreaterThanOrEqual(1520);
    expect(clock.now() - t1).toBeLessThan(1520 + 100);
  });

  it("explains that motion 7 must run first after power-up", async () => {
    const { client, run } = await makeRig();
    const error = await run(client.runMotion(4).catch((e) => e));
    expect(error).toMatchObject({ code: "motion-ignored" });
    expect(errorText(error, "en")).toMatch(/Basic posture \(7\)/);
  });

  it("refuses motion numbers outside 0-63 and sounds outside 1-25 before sending", async () => {
    const { client, run, port } = await makeRig();
    const before = port.stats.bytesFromPc;
    await expect(run(client.runMotion(64))).rejects.toMatchObject({ code: "invalid-argument" });
    await expect(run(client.runSound(0))).rejects.toMatchObject({ code: "invalid-argument" });
    await expect(run(client.runSound(26))).rejects.toMatchObject({ code: "invalid-argument" });
    expect(port.stats.bytesFromPc).toBe(before);
  });

  it("plays a sound and resolves after 200 ms + its length", async () => {
    const { client, clock, run } = await makeRig();
    const t0 = clock.now();
    expect(await run(client.runSound(3))).toBe(3);
    expect(clock.now() - t0).toBeGreaterThanOrEqual(200 + 832);
  });

  it("resets the memory pointer", async () => {
    const { client, run } = await makeRig();
    expect(await run(client.resetMemoryPointer("motion"))).toBe(1);
    expect(await run(client.resetMemoryPointer("action"))).toBe(2);
  });

  it("uploads wave.rbm's image in 10 chunks with progress, and the simulator holds the bytes", async () => {
    const { client, run, sim } = await makeRig();
    const image = motionImage(parseRbm(exampleText("wave.rbm")));
    expect(toHex(image)).toBe(toHex(waveImage()));
    const progress: UploadProgress[] = [];
    const result = await run(client.writeMotion(image, { onProgress: (p) => progress.push(p) }));
    expect(result).toMatchObject({
      total: 624,
      chunks: 10,
      footprint: 640,
      freeBefore: 24576,
      freeAfter: 23936,
    });
    expect(result.errorCode).toBe(0xff);
    expect(progress.map((p) => p.acknowledged)).toEqual([0, 64, 128, 192, 256, 320, 384, 448, 512, 576, 624]);
    expect(sim.motions).toHaveLength(1);
    expect(toHex(sim.motions[0]!.bytes)).toBe(toHex(image));
  });

  it("refuses an upload that does not fit, before the first byte", async () => {
    const { client, run, sim } = await makeRig();
    const big = new Uint8Array(6000);
    await run(client.writeAction(big.subarray(0, 5000)));
    const error = await run(client.writeAction(big.subarray(0, 4000)).catch((e) => e));
    expect(error).toMatchObject({ code: "rejected" });
    expect(error.situation).toEqual({ kind: "not-enough-memory", area: "action", total: 4000, free: 3136 });
    expect(errorText(error, "en")).toMatch(/has 4000 bytes, 3136 are free/);
    expect(sim.actions).toHaveLength(1);
    // Client and simulator agree on the edge: a file exactly as large as the free memory fits.
    const exact = await run(client.writeAction(big.subarray(0, 3136)));
    expect(exact).toMatchObject({ freeBefore: 3136, freeAfter: 0 });
    expect(sim.actions).toHaveLength(2);
  });

  it("cancels an upload between chunks, leaves nothing recorded and says so", async () => {
    const { client, run, sim } = await makeRig();
    const controller = new AbortController();
    const image = waveImage();
    const error = await run(
      client
        .writeMotion(image, {
          signal: controller.signal,
          onProgress: (p) => {
            if (p.acknowledged >= 192) controller.abort();
          },
        })
        .catch((e) => e),
    );
    expect(error).toMatchObject({
      code: "cancelled",
      acknowledged: 192,
      total: 624,
      outcome: "nothing-recorded",
    });
    expect(error.facts).toMatchObject({ stop: "cancelled", acknowledged: 192, total: 624 });
    expect(errorText(error, "en")).toMatch(/192 of 624 bytes/);
    expect(errorText(error, "en")).toMatch(/recorded nothing/);
    expect(sim.motions).toHaveLength(0);
    // Usable afterwards: the next upload succeeds.
    expect((await run(client.writeMotion(image))).freeAfter).toBe(23936);
  });

  it("routes subscription events by type and keeps the subscription armed across requests", async () => {
    const { client, run, sim, clock } = await makeRig();
    const events: RbcEvent[] = [];
    client.events.on((e) => events.push(e));
    await run(client.subscribe("buttons"));
    sim.pressButton(2, 450);
    await clock.advance(500);
    expect(events.length).toBeGreaterThanOrEqual(2);
    expect(events.every((e) => e.kind === "buttons" && e.value === 2)).toBe(true);
    expect(await run(client.readDistance())).toBe(10);
    events.length = 0;
    sim.pressButton(1, 250);
    await clock.advance(300);
    expect(events.map((e) => e.value)).toContain(1);
    await run(client.unsubscribe());
    events.length = 0;
    sim.pressButton(1, 250);
    await clock.advance(300);
    expect(events).toEqual([]);
  });

  it("drives servos in direct mode and refuses RBC commands until it leaves", async () => {
    const { client, run, sim } = await makeRig();
    await run(client.enterDirectMode());
    expect(sim.directMode).toBe(true);
    const moved = await run(client.servos.move(5, 125, 2));
    expect(moved.id).toBe(5);
    expect(sim.servos[5]!.position).toBe(125);
    await expect(run(client.servos.move(0, 200, 2))).rejects.toMatchObject({ code: "invalid-argument" });
    await expect(run(client.readZeros())).rejects.toMatchObject({ code: "wrong-mode" });
    const all = await run(client.servos.readAll());
    expect(all.servos).toHaveLength(16);
    await run(client.servos.basicPosture());
    await run(client.exitDirectMode());
    expect(sim.directMode).toBe(false);
    expect(await run(client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
  });

  it("Limp makes every servo limp, from normal mode and from direct servo control", async () => {
    const { client, run, sim } = await makeRig();
    const result = await run(client.limp());
    expect(result.confirmed).toEqual(Array.from({ length: 16 }, (_, i) => i));
    expect(sim.servos.slice(0, 16).every((s) => s.passive)).toBe(true);
    const again = await makeRig();
    await again.run(again.client.enterDirectMode());
    expect(again.client.activity.doing).toMatchObject({ kind: "direct", use: "servo-control" });
    expect((await again.run(again.client.limp())).confirmed).toHaveLength(16);
    expect(again.client.activity.doing).toMatchObject({ kind: "direct", use: "limp" });
    expect(again.sim.servos.slice(0, 16).every((s) => s.passive)).toBe(true);
  });

  it("Stop with nothing running asks the robot (one distance read), sends no 7 and makes no servo passive", async () => {
    const { client, run, sim, port } = await makeRig();
    const before = port.stats.bytesFromPc;
    const result = await run(client.stopActivity());
    expect(result).toEqual({ uploadCancelled: false, servoMovesDropped: false, found: { kind: "idle" } });
    // The busy probe's 0x16 (one 16-byte packet), answered at once: nothing else (docs/protocol.md §3.6).
    expect(port.stats.bytesFromPc).toBe(before + 16);
    expect(sim.directMode).toBe(false);
    expect(sim.servos.slice(0, 16).some((s) => s.passive)).toBe(false);
  });
});

describe("Stop (stopActivity) keeps the robot standing", () => {
  it("ends a motion with one 7, reports the robot's 07, and leaves the servos holding in packet mode", async () => {
    const { client, run, sim, clock } = await makeRig({ sim: { basicPostureDone: true } });
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    const walking = client.runMotion(4).catch((e) => e);
    await clock.advance(300);
    expect(sim.playingMotion).toBe(4);
    const result = await run(client.stopActivity());
    expect(result.motion).toEqual({ number: 4, outcome: "stopped" });
    expect(await walking).toMatchObject({ code: "cancelled" });
    expect(sim.playingMotion).toBeUndefined();
    expect(sim.directMode).toBe(false);
    expect(client.mode).toBe("packet");
    expect(sim.servos.slice(0, 16).some((s) => s.passive)).toBe(false);
    // Exactly one Run Motion 7 went out (the literal bytes of docs/protocol.md §8).
    const sevens = log.filter((e) => e.direction === "out" && toHex(e.bytes) === EX.runMotion7);
    expect(sevens).toHaveLength(1);
    // No second motion (basic posture) is played afterwards.
    await clock.advance(3000);
    expect(sim.playingMotion).toBeUndefined();
  });

  it("waits a sound out (the RBC takes nothing meanwhile) and sends nothing", async () => {
    const { client, run, sim, clock, port } = await makeRig();
    const sound = client.runSound(8); // 5,916 ms + 200
    await clock.advance(300);
    const before = port.stats.bytesFromPc;
    const result = await run(client.stopActivity());
    expect(result.sound).toMatchObject({ number: 8, confirmed: true });
    expect(result.sound!.endsInMs).toBe(200 + 5916 - 300);
    expect(await sound).toBe(8);
    expect(port.stats.bytesFromPc).toBe(before);
    expect(sim.servos.slice(0, 16).some((s) => s.passive)).toBe(false);
  });

  it("in servo control drops the moves not yet sent; no servo is made passive and direct mode is left", async () => {
    const { client, run, sim, clock } = await makeRig({ port: { latencyMs: 5 } });
    await run(client.enterDirectMode());
    const first = client.servos.move(5, 140, 2);
    const queued = client.servos.move(6, 100, 2).catch((e) => e);
    await clock.advance(1); // the first move is on the wire, the second waits its turn
    const result = await run(client.stopActivity());
    expect(result.servoMovesDropped).toBe(true);
    expect((await run(first)).position).toBe(140);
    expect(await run(queued)).toMatchObject({ code: "cancelled" });
    expect(sim.servos[5]!.position).toBe(140);
    expect(sim.servos[6]!.position).not.toBe(100);
    expect(sim.servos.slice(0, 16).some((s) => s.passive)).toBe(false);
    // Issue 22 item 6: Stop leaves direct mode (docs/protocol.md §5's leave sequence); the servos hold.
    expect(result.leftDirectMode).toBe(true);
    expect(sim.directMode).toBe(false);
  });

  it("cancels an upload as its Cancel does: the download is abandoned and nothing is recorded", async () => {
    const { client, run, sim, clock } = await makeRig({ port: { baudPacing: true } });
    const upload = client.writeMotion(waveImage()).catch((e) => e);
    // Until the download has started.
    for (let i = 0; i < 100 && client.mode !== "download"; i++) await clock.advance(1);
    expect(client.mode).toBe("download");
    const result = await run(client.stopActivity());
    expect(result.uploadCancelled).toBe(true);
    const error = await upload;
    expect(error).toMatchObject({ code: "cancelled", outcome: "nothing-recorded" });
    expect(sim.motions).toHaveLength(0);
    expect(client.mode).toBe("packet");
    expect(sim.servos.slice(0, 16).some((s) => s.passive)).toBe(false);
  });
});

describe("Limp while a motion plays", () => {
  it("ends the motion with 7 (the only request the RBC takes while playing), then makes every servo limp", async () => {
    const { client, run, sim, clock } = await makeRig({ sim: { basicPostureDone: true } });
    const walking = client.runMotion(4).catch((e) => e);
    await clock.advance(300);
    expect(sim.playingMotion).toBe(4);
    const result = await run(client.limp());
    expect(await walking).toMatchObject({ code: "cancelled" });
    expect(result.confirmed).toHaveLength(16);
    expect(sim.playingMotion).toBeUndefined();
    expect(sim.directMode).toBe(true);
    expect(sim.servos.slice(0, 16).every((s) => s.passive)).toBe(true);
  });
});

describe("connect on a port that takes no bytes", () => {
  it("gives up with a no-robot error instead of hanging on the blind exit sequence", async () => {
    const clock = new VirtualClock();
    let status: Transport["status"] = "closed";
    const transport: Transport = {
      get status() {
        return status;
      },
      open: async () => {
        status = "open";
      },
      write: () => new Promise<void>(() => {}),
      onData: () => () => {},
      onStatus: () => () => {},
      close: async () => {
        status = "closed";
      },
    };
    const client = new RbcClient(transport, { clock });
    const error = await clock.run(client.connect().catch((e) => e));
    expect(error).toMatchObject({ code: "no-robot" });
    expect(client.mode).toBe("disconnected");
    expect(status).toBe("closed");
  });
});

describe("Stop motion", () => {
  it("sends 7 ahead of the queue; the motion ends at its scene's end with one reply, 07, and holds its pose (docs/protocol.md §3.6)", async () => {
    const { client, run, sim, clock } = await makeRig({ sim: { basicPostureDone: true } });
    const t0 = clock.now();
    const walking = client.runMotion(10); // walk backward, 2,450 ms
    await clock.advance(300);
    const stopping = client.stopMotion();
    // The running motion resolves with the robot's single reply: 7, not 10.
    expect(await run(walking)).toBe(7);
    await run(stopping);
    expect(clock.now() - t0).toBeLessThan(300 + 500 + 50);
    expect(client.state.playing).toBeUndefined();
    expect(sim.playingMotion).toBeUndefined();
    // No second reply is awaited, none comes, and basic posture is not played.
    await clock.advance(5000);
    expect(sim.playingMotion).toBeUndefined();
    expect(await run(client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
  });

  it("refuses to subscribe in direct mode instead of writing a packet onto the servo bus", async () => {
    const { client, run, port } = await makeRig();
    await run(client.enterDirectMode());
    const before = port.stats.bytesFromPc;
    await expect(run(client.subscribe("buttons"))).rejects.toMatchObject({ code: "wrong-mode" });
    expect(port.stats.bytesFromPc).toBe(before);
  });
});

describe("Limp pressed twice", () => {
  it("joins the Stop under way instead of cancelling its wait for the motion to end", async () => {
    const { client, run, sim, clock } = await makeRig({ sim: { basicPostureDone: true } });
    const motion = client.runMotion(2).catch((e) => e);
    await clock.advance(300);
    const first = client.limp();
    await clock.advance(30);
    const second = client.limp();
    expect(second).toBe(first);
    const result = await run(second);
    expect(result.confirmed).toHaveLength(16);
    expect(await motion).toMatchObject({ code: "cancelled" });
    expect(sim.servos.slice(0, 16).every((s) => s.passive)).toBe(true);
  });
});

describe("Limp while a sound plays", () => {
  it("waits for the sound to end (the RBC takes nothing meanwhile), then makes every servo limp", async () => {
    const { client, run, sim, clock } = await makeRig();
    const sound = client.runSound(8).catch((e) => e); // 5,916 ms
    await clock.advance(300);
    const t0 = clock.now();
    const result = await run(client.limp());
    expect(result.confirmed).toHaveLength(16);
    expect(clock.now() - t0).toBeGreaterThanOrEqual(200 + 5916 - 300);
    expect(await sound).toMatchObject({ code: "cancelled" });
    expect(sim.servos.slice(0, 16).every((s) => s.passive)).toBe(true);
  });
});

describe("subscriptions across other operations", () => {
  it("re-arms the subscription after a motion, whose packet ended it on the RBC", async () => {
    const { client, run, sim, clock } = await makeRig();
    const events: RbcEvent[] = [];
    client.events.on((e) => events.push(e));
    await run(client.subscribe("buttons"));
    await run(client.runMotion(7));
    sim.pressButton(1, 250);
    await clock.advance(300);
    expect(events.map((e) => e.value)).toContain(1);
  });
});

describe("a robot left in the middle of a download by a program that died", () => {
  it("is brought back to packet mode by the next connect, which records nothing", async () => {
    const { client, run, sim, port, clock } = await makeRig();
    const image = waveImage();
    // The link dies after the first part and one chunk: the RBC waits for the rest.
    const upload = client.writeMotion(image, {
      onProgress: (p) => {
        if (p.acknowledged >= 64) port.unplug();
      },
    });
    await run(upload.catch((e) => e));
    expect(sim.state.download).toBeDefined();
    port.replug();
    const again = new RbcClient(new WebSerialTransport(port, { clock }), { clock });
    expect(await run(again.connect())).toMatchObject({ firmware: { major: 2, minor: 23 } });
    expect(sim.state.download).toBeUndefined();
    expect(sim.motions).toHaveLength(0);
    expect(await run(again.readAvailableMemory("motion"))).toBe(24576);
  });
});

describe("a motion the robot ignores, told from one that plays (docs/protocol.md §3.6)", () => {
  it("an empty download slot: error 3 in words after about a second, not after the whole wait", async () => {
    const { client, run, clock } = await makeRig({ sim: { basicPostureDone: true } });
    const t0 = clock.now();
    const error = await run(client.runMotion(12).catch((e) => e));
    expect(error).toMatchObject({ code: "rejected", deviceErrorCode: 3, motion: 12 });
    // One number per motion: the one Run took, never the download slot's own count.
    expect(errorText(error, "en")).toBe(
      "Motion 12 did not run: the robot holds no motion under that number (it reports error 3). Upload a motion first.",
    );
    expect(errorText(error, "ko")).toBe(
      "모션 12은(는) 실행되지 않았어요. 로봇에 그 번호로 저장된 모션이 없어요 (오류 3을 알려 줬어요). 먼저 모션을 업로드해 주세요.",
    );
    expect(clock.now() - t0).toBeLessThan(1500);
    expect(client.state.playing).toBeUndefined();
    expect(await run(client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
  });

  it("motion 4 right after power-up: no reply within its duration and margin, then the 7-first guidance", async () => {
    const { client, run, clock } = await makeRig();
    const t0 = clock.now();
    const error = await run(client.runMotion(4).catch((e) => e));
    expect(error).toMatchObject({ code: "motion-ignored" });
    expect(error.facts).toMatchObject({ motion: 4, cause: "power-up" });
    expect(errorText(error, "en")).toMatch(/probably ignored it.*Run motion 7 first/);
    expect(clock.now() - t0).toBeGreaterThanOrEqual(1625 + 2000);
  });

  it("a motion that plays is not declared ignored although the robot answers reads meanwhile", async () => {
    const { client, run, clock } = await makeRig({ sim: { basicPostureDone: true } });
    const t0 = clock.now();
    expect(await run(client.runMotion(2))).toBe(2);
    expect(clock.now() - t0).toBeGreaterThanOrEqual(6600);
  });

  it("a slot that was already in error 3 is not called empty: the wait runs its course and says what is not known", async () => {
    const { client, run } = await makeRig({ sim: { basicPostureDone: true } });
    await run(client.runMotion(7));
    await run(client.runMotion(12).catch(() => undefined)); // sets error 3
    const error = await run(client.runMotion(13, { expectedMs: 1000 }).catch((e) => e));
    expect(error).toMatchObject({ code: "timeout" });
    expect(error.facts).toMatchObject({ motion: 13 });
    expect(errorText(error, "en")).toMatch(/whether it played is not known/);
  });
});
