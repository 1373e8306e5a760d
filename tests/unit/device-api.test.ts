import { describe, expect, it } from "vitest";
import { RbcClient, RbcPortError, RbcUploadError, ZeroWriteFailedError } from "../../src/device/index.ts";
import { errorText, UPLOAD_NOTICES } from "../../src/i18n/index.ts";
import { LinkError, type Transport, WebSerialTransport } from "../../src/link/index.ts";
import {
  COMMANDS,
  EVENT_TYPES,
  HUNO_BASIC_POSTURE,
  memoryFootprint,
  motionImage,
  type RbmMotion,
  STANDARD_ZEROS,
  toHex,
} from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { MockSerialPort, SimulatedRbc } from "../../src/sim/index.ts";
import { REQUEST_CONTENT_LENGTH } from "../../src/sim/sim-receiver.ts";
import { makeRig } from "../support/rig.ts";

/** A small valid HUNO motion built here (two scenes out of and back into the basic posture). */
function twoSceneMotion(name = "TestBow"): RbmMotion {
  const bent = HUNO_BASIC_POSTURE.map((v, id) => (id === 1 || id === 6 ? v - 10 : v));
  const scene = (index: number, from: readonly number[], to: readonly number[]) => ({
    index,
    name: `Scene_${index}`,
    frames: 10,
    timeMs: 500,
    servos: from.map((start, id) => ({ id, start, end: to[id]!, torque: 2, port: 0 })),
  });
  return {
    format: 1,
    serialNumber: "0000000000000",
    text1: "XXXXXXXXXX",
    text2: "XXXXXXXXXXXXXXXXXXXX",
    name,
    motionIndex: 0,
    platform: 1,
    unknown10: 2,
    unknown12: 4,
    servos: STANDARD_ZEROS.map((zero, id) => ({ id, p: 20, d: 30, i: 0, portEnable: 0, zero })),
    scenes: [scene(0, HUNO_BASIC_POSTURE, bent), scene(1, bent, HUNO_BASIC_POSTURE)],
  };
}

describe("the command table is the single source of what a command is", () => {
  it("every row's request has the content size the row declares, and the simulator checks exactly that", () => {
    const sample: Record<string, unknown> = {
      writeZeros: STANDARD_ZEROS,
      readAvailableMemory: "motion",
      resetMemoryPointer: "action",
      runMotion: 7,
      runSound: 3,
      subscribeSound: 30,
      executionStatus: 7,
    };
    for (const [key, spec] of Object.entries(COMMANDS)) {
      const contents = (spec.request as (a: unknown) => Uint8Array)(sample[key]);
      expect(contents.length, key).toBe(spec.requestSize);
      expect(REQUEST_CONTENT_LENGTH.get(spec.type), key).toBe(spec.requestSize);
    }
  });

  it("event types are the subscribe rows, 0x17-0x19", () => {
    expect([...EVENT_TYPES].sort()).toEqual([0x17, 0x18, 0x19]);
  });

  it("a reply of another size than the row declares is refused by its decoder", () => {
    for (const [key, spec] of Object.entries(COMMANDS)) {
      const size = spec.replySize;
      if (size === undefined) continue;
      expect(() => spec.decode(new Uint8Array(size + 1)), key).toThrow(/expected/);
    }
  });

  it("timeouts come from the row: a built-in motion's and a sound's expected durations", () => {
    expect(COMMANDS.runMotion.expectedMs?.(7)).toBe(1800);
    expect(COMMANDS.runMotion.expectedMs?.(12)).toBeUndefined();
    expect(COMMANDS.runSound.expectedMs?.(3)).toBe(200 + 832);
  });
});

describe("RbcClient's public surface", () => {
  it("exposes operations only: the conversation underneath cannot be reached to send an unchecked request", async () => {
    const { client } = await makeRig();
    for (const name of [
      "exclusive",
      "transactDecoded",
      "request",
      "command",
      "setMode",
      "sleep",
      "raw",
      "parser",
    ]) {
      expect(name in client, name).toBe(false);
    }
    expect(Object.keys(client)).toEqual(["servos", "servoBus"]);
    expect(Object.keys(client.servos)).toEqual([]);
    // The servo doctor's bus access (src/device/servo-doctor) holds the conversation in private fields too.
    expect(Object.keys(client.servoBus)).toEqual([]);
  });

  it("copies a zero table once, checks the copy and sends the copy: a sparse array is refused", async () => {
    const { client, run, sim } = await makeRig();
    const before = sim.zeros;
    const sentBefore = sim.stats.bytesReceived;
    const sparse = [...STANDARD_ZEROS];
    delete sparse[3];
    const error = await run(client.writeZeros(sparse).catch((e) => e));
    expect(error).toMatchObject({ code: "invalid-argument" });
    expect(error.situation).toMatchObject({ kind: "zeros-not-written", problems: [{ id: 3 }] });
    expect(errorText(error, "en")).toMatch(/Servo 3: an empty value is not a whole number/);
    expect(sim.zeros).toEqual(before);
    expect(sim.stats.bytesReceived).toBe(sentBefore);
  });

  it("a value that changes after it was checked (a getter) never reaches the robot", async () => {
    const { client, run, sim } = await makeRig();
    let reads = 0;
    const shifty = [...STANDARD_ZEROS];
    Object.defineProperty(shifty, 5, {
      get: () => (reads++ === 0 ? STANDARD_ZEROS[5] : 0xff),
      enumerable: true,
    });
    const result = await run(client.writeZeros(shifty));
    expect(reads).toBe(1);
    expect(result.written).toEqual([...STANDARD_ZEROS]);
    expect(sim.zeros).toEqual([...STANDARD_ZEROS]);
  });

  it("a Proxy that answers differently on each read sends the values read once", async () => {
    const { client, run, sim } = await makeRig();
    let count = 0;
    const table = new Proxy([...STANDARD_ZEROS], {
      get(target, key, receiver) {
        if (key === "5") return count++ === 0 ? STANDARD_ZEROS[5] : 0xff;
        return Reflect.get(target, key, receiver);
      },
    });
    await run(client.writeZeros(table));
    expect(sim.zeros[5]).toBe(STANDARD_ZEROS[5]);
  });

  it("connect() turns a port that cannot open into an RbcPortError, with the link error as its cause", async () => {
    const failing: Transport = {
      status: "closed",
      open: () => Promise.reject(new LinkError("port-busy", "The port is already open in another program.")),
      write: () => Promise.reject(new LinkError("not-open", "The port is not open.")),
      onData: () => () => {},
      onStatus: () => () => {},
      close: () => Promise.resolve(),
    };
    const client = new RbcClient(failing, { clock: new VirtualClock() });
    const error = await client.connect().catch((e) => e);
    expect(error).toBeInstanceOf(RbcPortError);
    expect(error).toMatchObject({
      code: "port-busy",
      message: "The port is already open in another program.",
    });
    expect(error.cause).toBeInstanceOf(LinkError);
    expect(client.mode).toBe("disconnected");
  });
});

describe("uploadMotion: image, reset, free memory, download, verification", () => {
  it("uploads a motion's image and confirms it by the robot's own free-memory accounting", async () => {
    const { client, run, sim } = await makeRig();
    const motion = twoSceneMotion();
    const image = motionImage(motion);
    const phases: string[] = [];
    const result = await run(client.uploadMotion(motion, { onPhase: (p) => phases.push(p) }));
    // 108 + 86 · 2 = 280 bytes, 5 chunks of 64 and one of 24; footprint 320 (docs/protocol.md §6.1).
    expect(result).toMatchObject({
      area: "motion",
      total: 280,
      chunks: 5,
      footprint: 320,
      freeBefore: 24_576,
      freeAfter: 24_256,
      reset: false,
      slot: undefined,
      motionNumber: undefined,
    });
    expect(phases).toEqual(["checking", "sending", "verifying"]);
    expect(toHex(sim.motions[0]!.bytes)).toBe(toHex(image));
  });

  it("with resetFirst, forgets earlier downloads first and knows the file became motion 12", async () => {
    const { client, run, sim } = await makeRig();
    await run(client.uploadMotion(twoSceneMotion("First")));
    const result = await run(client.uploadMotion(twoSceneMotion("Second"), { resetFirst: true }));
    expect(result).toMatchObject({ reset: true, slot: 1, motionNumber: 12, freeBefore: 24_576 });
    expect(result.freeAfter).toBe(24_576 - memoryFootprint(280));
    expect(toHex(sim.motions[0]!.bytes)).toBe(toHex(motionImage(twoSceneMotion("Second"))));
  });

  it("refuses a motion with errors before anything is sent", async () => {
    const { client, run, sim } = await makeRig();
    const bad = twoSceneMotion();
    bad.scenes[0]!.frames = 100; // 500 ms / 100 frames = 5 ms per frame: error 6 on the RBC
    const sentBefore = sim.stats.bytesReceived;
    const error = await run(
      Promise.resolve()
        .then(() => client.uploadMotion(bad))
        .catch((e) => e),
    );
    expect(error).toMatchObject({ code: "invalid-argument" });
    expect(error.situation).toMatchObject({ kind: "motion-invalid", name: "TestBow", count: 1 });
    expect(errorText(error, "en")).toMatch(
      /^The motion "TestBow" has 1 error the robot would refuse \(first: .+\)\. Nothing was sent\.$/,
    );
    expect(errorText(error, "ko")).toMatch(
      /^모션 "TestBow"에 로봇이 거부할 오류가 1개 있어요 .+아무것도 보내지 않았어요\.$/,
    );
    expect(sim.stats.bytesReceived).toBe(sentBefore);
    expect(sim.motions).toHaveLength(0);
  });

  it("a duplicated acknowledgement never turns into a reported success", async () => {
    const clock = new VirtualClock();
    const sim = new SimulatedRbc({ clock });
    const port = new MockSerialPort(sim, { clock });
    const inner = new WebSerialTransport(port, { clock });
    let acks = 0;
    // Every third `40` from the robot arrives twice (a stray acknowledgement 0 ms later).
    const doubling: Transport = {
      get status() {
        return inner.status;
      },
      open: () => inner.open(),
      write: (b) => inner.write(b),
      close: () => inner.close(),
      onStatus: (l) => inner.onStatus(l),
      onData: (listener) =>
        inner.onData((bytes) => {
          if (bytes.length === 1 && bytes[0] === 0x40 && ++acks === 3) listener(Uint8Array.of(0x40, 0x40));
          else listener(bytes);
        }),
    };
    const client = new RbcClient(doubling, { clock });
    await clock.run(client.connect());
    const outcome = await clock.run(
      client.uploadMotion(twoSceneMotion()).then(
        (r) => ({ ok: true as const, r }),
        (e) => ({ ok: false as const, e }),
      ),
    );
    if (outcome.ok) {
      // Only acceptable if the robot really recorded it.
      expect(sim.motions).toHaveLength(1);
      expect(outcome.r.freeAfter).toBe(outcome.r.freeBefore - outcome.r.footprint);
    } else {
      expect(outcome.e).toBeInstanceOf(RbcUploadError);
      expect(sim.motions).toHaveLength(0);
      expect(["nothing-recorded", "unknown"]).toContain((outcome.e as RbcUploadError).outcome);
    }
  });

  it("has one wording for the experimental notice and the hold advice", () => {
    expect(UPLOAD_NOTICES.experimental).toMatch(/^Uploading to a real robot is experimental/);
    expect(UPLOAD_NOTICES.holdAdvice).toMatch(/held or lying down/);
  });
});

describe("writeZerosWithBackup: the one zero-write policy", () => {
  const target = STANDARD_ZEROS.map((v, id) => (id === 0 ? v + 3 : v));

  it("reads the current zeros, saves them before writing, then writes and verifies", async () => {
    const { client, run, sim } = await makeRig();
    const before = sim.zeros;
    const events: string[] = [];
    const result = await run(
      client.writeZerosWithBackup(target, {
        robot: { serialNumber: "8958899989309", firmware: "2.23" },
        now: new Date(2026, 10, 21, 12),
        saveBackup: (backup, name) => {
          events.push(`saved ${name}`);
          expect(backup.zeros).toEqual(before);
          expect(sim.zeros).toEqual(before); // not written yet
          return name;
        },
      }),
    );
    expect(events).toEqual(["saved rbc-zeros-8958899989309-2026-11-21.json"]);
    expect(result).toMatchObject({ changed: true, backupName: "rbc-zeros-8958899989309-2026-11-21.json" });
    expect(sim.zeros).toEqual(target);
  });

  it("refuses an out-of-range table before reading or saving anything", async () => {
    const { client, run } = await makeRig();
    let saved = 0;
    const bad = [...target];
    bad[2] = 250;
    const error = await run(
      client
        .writeZerosWithBackup(bad, {
          saveBackup: (_b, n) => {
            saved++;
            return n;
          },
        })
        .catch((e) => e),
    );
    expect(error).toMatchObject({ code: "invalid-argument" });
    expect(saved).toBe(0);
  });

  it("writes nothing when the backup cannot be saved", async () => {
    const { client, run, sim } = await makeRig();
    const before = sim.zeros;
    const error = await run(
      client
        .writeZerosWithBackup(target, {
          saveBackup: () => {
            throw new Error("disk full");
          },
        })
        .catch((e) => e),
    );
    expect(error.code).toBe("backup-failed");
    expect(errorText(error, "en")).toMatch(
      /Nothing was written: the backup .* could not be saved \(disk full\)/,
    );
    expect(sim.zeros).toEqual(before);
  });

  it("writes nothing and saves nothing when the robot already holds the table", async () => {
    const { client, run, sim } = await makeRig();
    let saved = 0;
    const result = await run(
      client.writeZerosWithBackup(sim.zeros, {
        saveBackup: (_b, n) => {
          saved++;
          return n;
        },
      }),
    );
    expect(result).toEqual({ changed: false, current: sim.zeros });
    expect(saved).toBe(0);
  });

  it("a write that fails after the backup says where the backup is", async () => {
    const { client, run, port } = await makeRig();
    let saves = 0;
    const error = await run(
      client
        .writeZerosWithBackup(target, {
          saveBackup: (_b, n) => {
            saves++;
            // From now on the robot answers nothing: the echo and the read-back are lost.
            port.faults.swallowReplies(10);
            return n;
          },
        })
        .catch((e) => e),
    );
    expect(saves).toBe(1);
    expect(error).toBeInstanceOf(ZeroWriteFailedError);
    expect(error.message).toMatch(/saved in rbc-zeros-unknown-/);
  });
});
