/**
 * The fault matrix (issues #5 and #10): every RbcClient operation against every injected link fault — a byte
 * dropped or corrupted, a reply late or lost, 1-byte reads, noise, a cable pull, a stray download `40`, a reply
 * delivered twice or repeated unasked, a corrupted size byte — plus rows for firmware that leaves 0x0C or 0x1E
 * unanswered (docs/protocol.md §3.5), on the whole stack
 * (RbcClient → WebSerialTransport → MockSerialPort with 115200 baud pacing and 16 ms adapter latency →
 * SimulatedRbc) under a VirtualClock. Each cell asserts:
 *
 * - the operation ends with a typed RbcError (with a string `code`) or succeeds, and with the outcome this table
 *   expects for that fault (idempotent reads ride out a single damaged reply by retrying, and so on);
 * - it ends in time: elapsed ≤ the operation's clean duration + its timeouts × attempts (summed over the steps a
 *   lost reply can stall) + a margin;
 * - nothing is left pending: with the link up, a follow-up readFirmwareVersion succeeds; after a disconnect the
 *   client is "disconnected" and the next call rejects at once with a typed error;
 * - the robot's stored state is the old or the new value, never a mix (zeros; downloaded motions, with the
 *   upload error's `outcome` and "acknowledged of total" message checked against what the simulator holds).
 */
import { beforeAll, describe, expect, it } from "vitest";
import { RbcError, type RbcErrorCode, type RbcEvent, RbcUploadError } from "../../src/device/index.ts";
import { DOWNLOAD_ACK, FACTORY_ZEROS, STANDARD_ZEROS } from "../../src/protocol/index.ts";
import type { SimulatedRbcOptions, StoredFile } from "../../src/sim/index.ts";
import { goldenImage } from "../data/project-data.ts";
import { armAtReply, LINE_NOISE } from "../support/faults.ts";
import { makeRig, type Rig } from "../support/rig.ts";

/** examples/wave.rbm's 624-byte image (tests/data/images/wave.img.hex): 9 chunks of 64 bytes and one of 48. */
const IMAGE = goldenImage("wave.rbm");
const CHUNKS = Math.ceil(IMAGE.length / 64);
const CHUNK_WIRE = 65;
const LAST_CHUNK_WIRE = IMAGE.length - 64 * (CHUNKS - 1) + 1;

/** Client defaults (RbcClient): quick reply timeout, retries of idempotent reads, download ack timeout. */
const Q = 400;
const TRIES = 3;
const ACK = Q + 100;
/** Wire time, adapter latency and simulator processing a cell may add beyond the timeouts. */
const MARGIN_MS = 100;
/** A request packet with one content byte (16 bytes on the wire); a version reply is 17. */
const REQUEST = 16;
/** The reply byte that holds the second-lowest byte of the packet's size field (docs/protocol.md §2). */
const SIZE_BYTE = 12;

const NEW_ZEROS = [...STANDARD_ZEROS];
const OLD_ZEROS = [...FACTORY_ZEROS];

type Outcome = "ok" | RbcErrorCode;

const FAULTS = [
  "drop a byte",
  "corrupt a byte",
  "delay past timeout",
  "no reply",
  "1-byte chunks",
  "garbage before header",
  "disconnect",
  "stray ack",
  "duplicate reply",
  "unsolicited repeats",
  "corrupt size byte",
] as const;
type FaultName = (typeof FAULTS)[number];

interface Settled {
  ok: boolean;
  value?: unknown;
  error?: unknown;
}

interface Op {
  name: string;
  /** A firmware variant of the simulated robot for this row (docs/protocol.md §3.5). */
  sim?: SimulatedRbcOptions;
  /** Starts the operation; the harness drives the clock until it settles. */
  run: (rig: Rig) => Promise<unknown>;
  /** The reply (1-based, counted from the operation's start) that the reply faults hit. */
  reply: number;
  /** The byte of that reply that "drop a byte" and "corrupt a byte" hit (14: first content byte). */
  byte: number;
  /** PC bytes into the operation after which "disconnect" unplugs the cable (mid-request). */
  cutAfter: number;
  /** How late "delay past timeout" makes the reply: past the timeout of the step that waits for it. */
  lateMs: number;
  /** Worst case a lost or late reply may add: the timeouts × attempts of the steps it can stall. */
  penaltyMs: number;
  /** Outcome per fault; an array lists the acceptable ones. */
  expect: Record<FaultName, Outcome | readonly Outcome[]>;
  /** Op-specific invariants, checked after the operation (before faults are cleared). */
  check?: (rig: Rig, before: Snapshot, settled: Settled) => void;
  /** Op-specific checks after the follow-up request (link still up). */
  after?: (rig: Rig, settled: Settled) => Promise<void>;
}

interface Snapshot {
  zeros: number[];
  motions: StoredFile[];
}

/**
 * Idempotent reads: one damaged reply costs a retry, not the read. A stray `40` in packet mode is line noise;
 * a reply that arrives again (once or five times) is counted and discarded, never taken as the answer to a
 * later request; a corrupted size byte is bounded by the type's reply size and costs that one reply.
 */
const READ: Op["expect"] = {
  "drop a byte": "ok",
  "corrupt a byte": "ok",
  "delay past timeout": "ok",
  "no reply": "timeout",
  "1-byte chunks": "ok",
  "garbage before header": "ok",
  disconnect: "disconnected",
  "stray ack": "ok",
  "duplicate reply": "ok",
  "unsolicited repeats": "ok",
  "corrupt size byte": "ok",
};

/** Requests that are not retried (they change something, or take long): a damaged or late reply is a timeout. */
const ONCE: Op["expect"] = {
  ...READ,
  "drop a byte": "timeout",
  "corrupt a byte": "timeout",
  "delay past timeout": "timeout",
  "corrupt size byte": "timeout",
};

function quickRead(name: string, run: Op["run"]): Op {
  return {
    name,
    run,
    reply: 1,
    byte: 14,
    cutAfter: 5,
    lateMs: Q + 50,
    penaltyMs: Q * TRIES,
    expect: READ,
  };
}

function sameFiles(a: readonly StoredFile[], b: readonly StoredFile[]): boolean {
  return (
    a.length === b.length && a.every((f, i) => f.start === b[i]!.start && equalBytes(f.bytes, b[i]!.bytes))
  );
}

function equalBytes(a: Uint8Array, b: Uint8Array): boolean {
  return a.length === b.length && a.every((v, i) => v === b[i]);
}

/** The zero table is the old one or the new one, and the error message agrees with it. */
function checkZeros(rig: Rig, _before: Snapshot, settled: Settled): void {
  const stored = rig.sim.zeros;
  const isOld = stored.every((v, i) => v === OLD_ZEROS[i]);
  const isNew = stored.every((v, i) => v === NEW_ZEROS[i]);
  expect(isOld || isNew, `sim.zeros is a mix: ${stored.join(",")}`).toBe(true);
  if (settled.ok) expect(isNew).toBe(true);
  const message = settled.error instanceof Error ? settled.error.message : "";
  if (/new values are stored/.test(message)) expect(isNew).toBe(true);
  if (/still holds its previous values/.test(message)) expect(isOld).toBe(true);
}

/** The motion memory holds what it held before, or that plus exactly the new file; the error says which. */
function checkMotions(rig: Rig, before: Snapshot, settled: Settled): void {
  const after = rig.sim.motions;
  const unchanged = sameFiles(after, before.motions);
  const added =
    after.length === before.motions.length + 1 &&
    sameFiles(after.slice(0, -1), before.motions) &&
    equalBytes(after.at(-1)!.bytes, IMAGE);
  expect(unchanged || added, "sim.motions is neither the old list nor the old list + the new file").toBe(
    true,
  );
  if (settled.ok) expect(added).toBe(true);
  const error = settled.error;
  if (error instanceof RbcUploadError) {
    expect(error.total).toBe(IMAGE.length);
    expect(error.message).toContain(`${error.acknowledged} of ${error.total} bytes`);
    if (error.outcome === "nothing-recorded")
      expect(unchanged, "outcome nothing-recorded, but recorded").toBe(true);
  }
}

const EVENTS = new WeakMap<Rig, RbcEvent[]>();

const OPS: Op[] = [
  quickRead("readFirmwareVersion", ({ client }) => client.readFirmwareVersion()),
  quickRead("readSerialNumber", ({ client }) => client.readSerialNumber()),
  quickRead("readZeros", ({ client }) => client.readZeros()),
  {
    name: "writeZeros (fault on the echo)",
    run: ({ client }) => client.writeZeros(NEW_ZEROS),
    reply: 1,
    byte: 14,
    cutAfter: 20,
    lateMs: Q + 50,
    // The write waits once (no retry); then a read-back with retries (after a timeout or to verify).
    penaltyMs: Q + Q * TRIES,
    expect: {
      ...ONCE,
      // The echo is lost, but the read-back shows the new table stored: verified, so it succeeds.
      "delay past timeout": "ok",
      // Every reply swallowed: neither the echo nor the read-back comes, so the state is unknown.
      "no reply": "timeout",
      "drop a byte": "ok",
      "corrupt a byte": "ok",
      "corrupt size byte": "ok",
    },
    check: checkZeros,
  },
  {
    name: "writeZeros (fault on the read-back)",
    run: ({ client }) => client.writeZeros(NEW_ZEROS),
    reply: 2,
    byte: 14,
    // The zero write is 31 bytes; cut inside the read-back request after it.
    cutAfter: 31 + 5,
    lateMs: Q + 50,
    penaltyMs: Q * TRIES,
    expect: { ...READ, "no reply": "timeout" },
    check: checkZeros,
  },
  quickRead("readAvailableMemory", ({ client }) => client.readAvailableMemory("motion")),
  quickRead("readErrorCode", ({ client }) => client.readErrorCode()),
  quickRead("readDistance", ({ client }) => client.readDistance()),
  quickRead("readAccelerometer", ({ client }) => client.readAccelerometer()),
  {
    ...quickRead("resetMemoryPointer", ({ client }) => client.resetMemoryPointer("motion")),
    penaltyMs: Q,
    expect: ONCE,
  },
  {
    name: "runMotion(7)",
    run: ({ client }) => client.runMotion(7),
    // Reply 1 answers the busy probe's distance read (docs/protocol.md §3.6); reply 2 the busy check's firmware
    // version read 250 ms into the Run (§3.1); reply 3 is the Run's.
    reply: 3,
    byte: 14,
    cutAfter: 5,
    lateMs: 1800 + 2000 + 50,
    penaltyMs: 1800 + 2000,
    expect: ONCE,
  },
  {
    name: "runSound(3)",
    run: ({ client }) => client.runSound(3),
    reply: 1,
    byte: 14,
    cutAfter: 5,
    lateMs: 200 + 832 + 2000 + 50,
    penaltyMs: 200 + 832 + 2000,
    expect: ONCE,
  },
  {
    name: "writeMotion (fault on the ack of chunk 4)",
    run: ({ client }) => client.writeMotion(IMAGE),
    // Replies: free memory, the first part's ack, then one ack per chunk.
    reply: 2 + 4,
    byte: 0,
    cutAfter: REQUEST + 14 + 3 * CHUNK_WIRE + 30,
    lateMs: ACK + 50,
    // One ack timeout, the pause before reading the error, then error code and free memory with retries.
    penaltyMs: ACK + Q + 2 * Q * TRIES,
    expect: {
      "drop a byte": "upload-failed",
      "corrupt a byte": "upload-failed",
      "delay past timeout": "upload-failed",
      "no reply": "upload-failed",
      "1-byte chunks": "ok",
      "garbage before header": "ok",
      disconnect: "disconnected",
      // A `40` that was not due stops the upload; the robot then records nothing (issue #10, item 1).
      "stray ack": "upload-failed",
      "duplicate reply": "upload-failed",
      "unsolicited repeats": "upload-failed",
      // A download acknowledgement is one bare byte: it has no size byte to corrupt.
      "corrupt size byte": "ok",
    },
    check: checkMotions,
  },
  {
    // The busy probe's own 0x16 reply (docs/protocol.md §3.6) damaged on an idle robot: never taken for "busy".
    // A garbled or partial frame is retried as a read; a late one makes the probe ask 0x12 (answered behind
    // it, the link being FIFO) and 0x16 once more, the late reply paying its debt by count; with every reply
    // swallowed, 0x12 goes unanswered too, so the link is gone: a timeout, not "not-idle".
    name: "enterDirectMode + servos.read(5) (fault on the busy probe's 0x16 reply)",
    run: async ({ client }) => {
      await client.enterDirectMode();
      return client.servos.read(5);
    },
    reply: 1,
    byte: 14,
    cutAfter: 5,
    lateMs: Q + 50,
    // A lost 0x16 waits its quick time, then 0x12 waits at most its own.
    penaltyMs: 2 * Q,
    expect: READ,
  },
  {
    name: "enterDirectMode + servos.read(5) (fault on the 0x10 reply)",
    run: async ({ client }) => {
      await client.enterDirectMode();
      return client.servos.read(5);
    },
    // Reply 1 is the busy probe's: on an idle robot its 0x16 is answered at once, so no 0x12 follows (direct
    // mode only when the robot is idle, docs/protocol.md §3.6). Reply 2 is the 0x10's; the cut falls inside it.
    reply: 2,
    byte: 14,
    cutAfter: REQUEST + 5,
    lateMs: Q + 50,
    penaltyMs: Q,
    // A copy of the 0x10 reply, or a stray byte after it, arrives once direct mode has begun, within the settle
    // time and before the first servo command: drained and logged, not judged (docs/protocol.md §3.6, old bytes
    // are not a motion), so the read answers. Bytes nobody asked for after the drain are stale-servo-bytes.test.ts's.
    expect: ONCE,
  },
  {
    name: "enterDirectMode + servos.read(5) (fault on the servo's answer)",
    run: async ({ client }) => {
      await client.enterDirectMode();
      return client.servos.read(5);
    },
    // Replies 1 and 2: the busy probe's 0x16 and the 0x10; reply 3 is the servo's; the cut falls inside the
    // wCK read after the two 16-byte requests.
    reply: 3,
    byte: 1,
    cutAfter: 2 * REQUEST + 2,
    lateMs: Q + 50,
    penaltyMs: Q,
    // A wCK answer is two bare bytes with no header or checksum: a corrupted byte is taken as the answer (the
    // client cannot tell; the cell "succeeds" with a wrong value). Noise before it is more bytes than the
    // command asked for: direct mode is left and the read fails, "the robot is still playing something" (§3.6).
    // A duplicated answer or a stray byte after it comes once the read has its answer: the read succeeds, and
    // those bytes, which nobody asked for, end direct mode. A wCK answer has no size byte.
    expect: {
      ...ONCE,
      "corrupt a byte": "ok",
      "garbage before header": "still-playing",
      "corrupt size byte": "ok",
    },
  },
  {
    // docs/protocol.md §3.5: the serial number is optional. Replies: the version, then 0x0C goes unanswered.
    name: "identify() on a robot that does not answer 0x0C",
    sim: { answersSerialNumber: false },
    run: ({ client }) => client.identify(),
    reply: 1,
    byte: 14,
    cutAfter: 5,
    lateMs: Q + 50,
    // The version read with retries, then one unanswered 0x0C (not retried).
    penaltyMs: Q * TRIES + Q,
    expect: READ,
    check: (_rig, _before, settled) => {
      if (settled.ok) expect(settled.value).toMatchObject({ serialNumber: undefined, platform: 1 });
    },
  },
  {
    // 0x1E unanswered costs its own request only: it times out, and the next request (the error code, which
    // the faults hit) is answered as usual.
    name: "executionStatus(12) unanswered (no 0x1E), then readErrorCode",
    sim: { answersExecutionStatus: false },
    run: async ({ client }) => {
      const answered = await client.executionStatus(12).then(
        () => true,
        (e: unknown) => {
          // A cut cable is reported as such; anything but a timeout fails the cell with its own error.
          if (e instanceof RbcError && e.code === "timeout") return false;
          throw e;
        },
      );
      expect(answered).toBe(false);
      return client.readErrorCode();
    },
    reply: 1,
    byte: 14,
    cutAfter: 5,
    lateMs: Q + 50,
    // The error read's tries, and the pauses between them.
    penaltyMs: Q * (TRIES + 1),
    expect: READ,
  },
  {
    name: 'subscribe("buttons") and a press of PF2',
    run: async (rig) => {
      const events: RbcEvent[] = [];
      EVENTS.set(rig, events);
      rig.client.events.on((e) => events.push(e));
      await rig.client.subscribe("buttons");
      rig.sim.pressButton(2, 450);
      await new Promise<void>((resolve) => rig.clock.setTimeout(resolve, 500));
      return events.length;
    },
    reply: 1,
    byte: 14,
    cutAfter: 5,
    lateMs: 1000,
    penaltyMs: 500,
    expect: { ...READ, "no reply": "ok" },
    check: (rig, _before, settled) => {
      const events = EVENTS.get(rig) ?? [];
      // Only real button events get through, whatever the line did to some of them.
      for (const e of events) expect(e).toMatchObject({ kind: "buttons", value: 2 });
      if (settled.ok) expect(rig.client.state.subscription).toBe("buttons");
    },
    after: async (rig) => {
      // The subscription survived the follow-up request (re-armed) and still delivers events.
      const events = EVENTS.get(rig) ?? [];
      events.length = 0;
      rig.sim.pressButton(1, 250);
      await rig.clock.advance(300);
      expect(events.map((e) => e.value)).toContain(1);
    },
  },
];

function applyFault(rig: Rig, op: Op, fault: FaultName): void {
  const { port } = rig;
  switch (fault) {
    case "drop a byte":
      armAtReply(port, op.reply, (f) => f.dropByte(op.byte));
      break;
    case "corrupt a byte":
      armAtReply(port, op.reply, (f) => f.corruptByte(op.byte, { xor: 0x01 }));
      break;
    case "delay past timeout":
      armAtReply(port, op.reply, (f) => f.delayReplies(op.lateMs));
      break;
    case "no reply":
      armAtReply(port, op.reply, (f) => f.swallowReplies(Number.POSITIVE_INFINITY));
      break;
    case "1-byte chunks":
      port.faults.splitReplies(1);
      break;
    case "garbage before header":
      armAtReply(port, op.reply, (f) => f.garbageBeforeReply(LINE_NOISE));
      break;
    case "disconnect":
      port.faults.disconnectAfterPcBytes(port.stats.bytesFromPc + op.cutAfter);
      break;
    case "stray ack":
      armAtReply(port, op.reply, (f) => f.strayAfterReply([DOWNLOAD_ACK], 2));
      break;
    case "duplicate reply":
      armAtReply(port, op.reply, (f) => f.duplicateReplies(3));
      break;
    case "unsolicited repeats":
      armAtReply(port, op.reply, (f) => f.duplicateReplies(2, 1, 5));
      break;
    case "corrupt size byte":
      // Byte 12 is the second-lowest byte of the 4-byte size: 00 00 00 n becomes 00 00 01 n (256 + n).
      armAtReply(port, op.reply, (f) => f.corruptByte(SIZE_BYTE, { xor: 0x01 }));
      break;
  }
}

async function newRig(op?: Op): Promise<Rig> {
  return makeRig({ port: { baudPacing: true, latencyMs: 16 }, sim: op?.sim });
}

async function settle(rig: Rig, p: Promise<unknown>): Promise<Settled> {
  try {
    return { ok: true, value: await rig.run(p) };
  } catch (error) {
    return { ok: false, error };
  }
}

function outcomeOf(settled: Settled): Outcome {
  if (settled.ok) return "ok";
  const e = settled.error;
  return e instanceof RbcError ? e.code : ("untyped" as RbcErrorCode);
}

/** Runs one cell: fault (or none) → operation → checks → follow-up. */
async function cell(
  op: Op,
  fault: FaultName | undefined,
  cleanMs: number,
): Promise<{ outcome: Outcome; elapsed: number }> {
  const rig = await newRig(op);
  const before: Snapshot = { zeros: rig.sim.zeros, motions: rig.sim.motions };
  if (fault) applyFault(rig, op, fault);
  const t0 = rig.clock.now();
  const settled = await settle(rig, op.run(rig));
  const elapsed = rig.clock.now() - t0;

  if (!settled.ok) {
    expect(settled.error, String(settled.error)).toBeInstanceOf(RbcError);
    expect(typeof (settled.error as RbcError).code).toBe("string");
    expect((settled.error as RbcError).message.length).toBeGreaterThan(20);
  }
  const outcome = outcomeOf(settled);
  if (fault) {
    const wanted = op.expect[fault];
    expect(Array.isArray(wanted) ? wanted : [wanted], `outcome of ${op.name} × ${fault}`).toContain(outcome);
    expect(elapsed, `elapsed on the virtual clock (clean: ${cleanMs} ms)`).toBeLessThanOrEqual(
      cleanMs + op.penaltyMs + MARGIN_MS,
    );
  } else {
    expect(outcome, String(settled.error)).toBe("ok");
  }
  op.check?.(rig, before, settled);

  rig.port.faults.clear();
  if (fault === "disconnect") {
    expect(rig.client.mode).toBe("disconnected");
    expect(["lost", "closed"]).toContain(rig.transport.status);
    const t1 = rig.clock.now();
    const next = await settle(rig, rig.client.readFirmwareVersion());
    expect(next.ok).toBe(false);
    expect(next.error).toBeInstanceOf(RbcError);
    // After a loss the reason stays: a typed "disconnected" error, at once.
    expect((next.error as RbcError).code).toBe("disconnected");
    expect(rig.clock.now() - t1).toBeLessThanOrEqual(1);
  } else {
    expect(rig.client.mode).not.toBe("disconnected");
    // The link is FIFO: a late reply holds back every reply behind it. Let it arrive before the follow-up.
    if (fault === "delay past timeout") await rig.clock.advance(op.lateMs);
    if (rig.client.mode === "direct") await rig.run(rig.client.exitDirectMode());
    expect(rig.client.mode).toBe("packet");
    const next = await settle(rig, rig.client.readFirmwareVersion());
    expect(next.error, "follow-up readFirmwareVersion").toBeUndefined();
    expect(next.value).toEqual({ major: 2, minor: 23 });
    await op.after?.(rig, settled);
    // Nothing left behind fires later: after 10 s of quiet the client is still in packet mode and answers.
    await rig.clock.advance(10_000);
    expect(rig.client.mode).toBe("packet");
    expect(await rig.run(rig.client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
  }
  return { outcome, elapsed };
}

describe.each(OPS)("fault matrix: $name", (op) => {
  let cleanMs = 0;

  beforeAll(async () => {
    cleanMs = (await cell(op, undefined, 0)).elapsed;
  });

  it("no fault: succeeds", async () => {
    expect((await cell(op, undefined, 0)).outcome).toBe("ok");
  });

  it.each(FAULTS)("× %s", async (fault) => {
    await cell(op, fault, cleanMs);
  });
});

/** The stages of an upload a link can fail at. */
interface UploadStage {
  name: string;
  fault: (rig: Rig) => void;
  expect: readonly Outcome[];
  /** The upload error's outcome, when it fails. */
  uploadOutcome?: readonly RbcUploadError["outcome"][];
  disconnects: boolean;
}

/** PC bytes before chunk k (1-based) of the upload: the free-memory request, the first part, chunks 1..k-1. */
const beforeChunk = (k: number) => REQUEST + 14 + (k - 1) * CHUNK_WIRE;
const cut = (rig: Rig, bytes: number) =>
  rig.port.faults.disconnectAfterPcBytes(rig.port.stats.bytesFromPc + bytes);
/** Reply number of the ack of chunk k (0: the first part's ack). */
const ackReply = (k: number) => 2 + k;

const STAGES: UploadStage[] = [
  {
    name: "disconnect during the first part",
    fault: (rig) => cut(rig, REQUEST + 7),
    expect: ["disconnected"],
    uploadOutcome: ["interrupted"],
    disconnects: true,
  },
  {
    name: "disconnect mid-chunks (inside chunk 5)",
    fault: (rig) => cut(rig, beforeChunk(5) + 30),
    expect: ["disconnected"],
    uploadOutcome: ["interrupted"],
    disconnects: true,
  },
  {
    name: "disconnect inside the last chunk",
    fault: (rig) => cut(rig, beforeChunk(CHUNKS) + 10),
    expect: ["disconnected"],
    uploadOutcome: ["interrupted", "unknown"],
    disconnects: true,
  },
  {
    name: "disconnect after the last chunk's bytes, before its ack",
    fault: (rig) => cut(rig, beforeChunk(CHUNKS) + LAST_CHUNK_WIRE),
    expect: ["disconnected"],
    uploadOutcome: ["unknown"],
    disconnects: true,
  },
  {
    name: "the first part's ack dropped",
    fault: (rig) => armAtReply(rig.port, ackReply(0), (f) => f.dropByte(0)),
    expect: ["upload-failed"],
    uploadOutcome: ["nothing-recorded"],
    disconnects: false,
  },
  {
    name: "a mid-upload ack dropped (chunk 5)",
    fault: (rig) => armAtReply(rig.port, ackReply(5), (f) => f.dropByte(0)),
    expect: ["upload-failed"],
    uploadOutcome: ["nothing-recorded"],
    disconnects: false,
  },
  {
    // The robot's free memory proves the file was recorded, so the upload succeeds (lastAckLost).
    name: "the last chunk's ack dropped",
    fault: (rig) => armAtReply(rig.port, ackReply(CHUNKS), (f) => f.dropByte(0)),
    expect: ["ok"],
    disconnects: false,
  },
  {
    name: "a mid-upload ack corrupted (40 → 41, chunk 5)",
    fault: (rig) => armAtReply(rig.port, ackReply(5), (f) => f.corruptByte(0, { xor: 0x01 })),
    expect: ["upload-failed"],
    uploadOutcome: ["nothing-recorded"],
    disconnects: false,
  },
  {
    name: "the last chunk's ack late (past the ack timeout)",
    fault: (rig) => armAtReply(rig.port, ackReply(CHUNKS), (f) => f.delayReplies(ACK + 50)),
    expect: ["ok"],
    disconnects: false,
  },
];

describe("fault matrix: writeMotion at each stage of an upload", () => {
  let cleanMs = 0;
  const upload = OPS.find((o) => o.name.startsWith("writeMotion"))!;

  beforeAll(async () => {
    cleanMs = (await cell(upload, undefined, 0)).elapsed;
  });

  it.each(STAGES)("$name", async (stage) => {
    const rig = await newRig();
    const before: Snapshot = { zeros: rig.sim.zeros, motions: rig.sim.motions };
    stage.fault(rig);
    const t0 = rig.clock.now();
    const settled = await settle(rig, rig.client.writeMotion(IMAGE));
    const elapsed = rig.clock.now() - t0;
    expect(stage.expect).toContain(outcomeOf(settled));
    expect(elapsed).toBeLessThanOrEqual(cleanMs + upload.penaltyMs + MARGIN_MS);
    if (!settled.ok) {
      expect(settled.error).toBeInstanceOf(RbcUploadError);
      const error = settled.error as RbcUploadError;
      if (stage.uploadOutcome) expect(stage.uploadOutcome).toContain(error.outcome);
    }
    checkMotions(rig, before, settled);
    rig.port.faults.clear();
    if (stage.disconnects) {
      expect(rig.client.mode).toBe("disconnected");
      const t1 = rig.clock.now();
      const next = await settle(rig, rig.client.readFirmwareVersion());
      // After a loss the reason stays: a typed "disconnected" error, at once.
      expect((next.error as RbcError).code).toBe("disconnected");
      expect(rig.clock.now() - t1).toBeLessThanOrEqual(1);
    } else {
      expect(rig.client.mode).toBe("packet");
      expect(await rig.run(rig.client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
      // The robot is back in packet mode and takes the next upload.
      const again = await settle(rig, rig.client.writeMotion(IMAGE));
      expect(again.error).toBeUndefined();
      expect(equalBytes(rig.sim.motions.at(-1)!.bytes, IMAGE)).toBe(true);
    }
  });
});
