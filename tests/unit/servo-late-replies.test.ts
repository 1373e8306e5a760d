import { describe, expect, it } from "vitest";
import { type LogEntry, type RbcClientOptions, RbcError } from "../../src/device/index.ts";
import { openMotion } from "../../src/motion/index.ts";
import { FACTORY_ZEROS } from "../../src/protocol/index.ts";
import { seededRandom } from "../../src/shared/random.ts";
import { bluetoothLinkOptions, type MockSerialPortOptions } from "../../src/sim/index.ts";
import { exampleText } from "../data/project-data.ts";
import { armAtReply } from "../support/faults.ts";
import { makeRig, type Rig } from "../support/rig.ts";

/**
 * Issue 20, item 4: a late servo reply can never answer a servo command sent after it (docs/protocol.md §3.6,
 * §5: the wCK protocol has no sequence numbers). Every servo operation — read, move, passive, teach-in's read
 * of all servos, tethered play's pose read — runs with one of its replies delayed by a seeded random time (some
 * within the wait, most past it), on a wired and on a Bluetooth link. Whatever fails must fail with a typed
 * error; whatever is reported must be the right servo's: each servo stands at its own position, so a reply taken
 * for the wrong servo shows.
 */

/** A distinct position for each servo 0-15, inside its safe range (§5). */
const POSITIONS = [100, 150, 200, 60, 110, 130, 40, 20, 170, 90, 240, 180, 10, 220, 70, 250];
const IDS = POSITIONS.map((_, id) => id);
const TRIALS = 10;

interface Link {
  name: string;
  port: MockSerialPortOptions;
  client: RbcClientOptions;
  /** Delays drawn from 0 to this many ms. */
  maxDelayMs: number;
}

const LINKS: Link[] = [
  { name: "wired", port: { baudPacing: true, latencyMs: 16 }, client: {}, maxDelayMs: 2000 },
  {
    name: "Bluetooth",
    port: bluetoothLinkOptions({ baudPacing: true, seed: 5 }),
    client: { link: "bluetooth" },
    maxDelayMs: 4000,
  },
];

/** What an operation reported: the position it says each servo has. */
type Claims = Array<{ id: number; position: number }>;

interface Op {
  name: string;
  run: (rig: Rig) => Promise<Claims>;
}

/** Runs `each` for every id; a typed failure ends nothing (the next id is tried), anything else throws. */
async function perServo(each: (id: number) => Promise<{ position: number }>): Promise<Claims> {
  const claims: Claims = [];
  for (const id of IDS) {
    try {
      claims.push({ id, position: (await each(id)).position });
    } catch (e) {
      if (!(e instanceof RbcError)) throw e;
    }
  }
  return claims;
}

const OPS: Op[] = [
  { name: "servos.read", run: ({ client }) => perServo((id) => client.servos.read(id)) },
  {
    name: "servos.move",
    run: ({ client }) => perServo((id) => client.servos.move(id, POSITIONS[id]!, 2)),
  },
  { name: "servos.passive", run: ({ client }) => perServo((id) => client.servos.passive(id)) },
  {
    name: "teach-in's read of all servos (readAll)",
    run: async ({ client }) => {
      try {
        return (await client.servos.readAll()).servos.map(({ id, position }) => ({ id, position }));
      } catch (e) {
        if (e instanceof RbcError) return [];
        throw e;
      }
    },
  },
  {
    name: "tethered play's pose read",
    run: async (rig) => {
      // The pose read decides where the transition starts: its first frame must start from where the servos
      // really stand (within the 10 counts that need no transition, §10, and one transition step).
      const frames: number[][] = [];
      const off = rig.client.log.on((e: LogEntry) => {
        const wck = e.direction === "out" && e.kind === "raw" && e.bytes[0] === 0xff && e.bytes[1] !== 0xff;
        if (wck && (e.bytes[1]! & 0x1f) === 0x1f) {
          frames.push(Array.from(e.bytes.slice(3, 3 + e.bytes[2]!)));
        }
      });
      try {
        const wave = openMotion(exampleText("wave.rbm"));
        await rig.client.playTethered(wave, { robotZeros: FACTORY_ZEROS, platform: 1 });
      } catch (e) {
        if (!(e instanceof RbcError)) throw e;
      } finally {
        off();
      }
      const first = frames[0];
      if (!first) return [];
      // A frame claims nothing about a servo's position, but a pose read wrong shows as a first frame far
      // from where the servo stands: report the frame's position for a servo more than 15 counts away.
      return first
        .map((p, id) => ({ id, position: Math.abs(p - POSITIONS[id]!) <= 15 ? POSITIONS[id]! : p }))
        .filter(({ id }) => id < POSITIONS.length);
    },
  },
];

async function rigAt(link: Link): Promise<Rig> {
  const rig = await makeRig({ port: link.port, client: link.client });
  await rig.run(rig.client.enterDirectMode("teach-in"));
  for (const id of IDS) await rig.run(rig.client.servos.move(id, POSITIONS[id]!, 2));
  return rig;
}

describe.each(LINKS)("late servo replies on a $name link never answer a later command", (link) => {
  it.each(OPS)("$name, one reply delayed at random (seeded)", async (op) => {
    const random = seededRandom(20 + op.name.length);
    let late = 0;
    let claimed = 0;
    for (let trial = 0; trial < TRIALS; trial++) {
      const rig = await rigAt(link);
      const reply = 1 + Math.floor(random() * IDS.length);
      const delayMs = Math.round(random() * link.maxDelayMs);
      if (delayMs > rig.client.timeouts.quickMs) late++;
      armAtReply(rig.port, reply, (f) => f.delayReplies(delayMs));
      const claims = await rig.run(op.run(rig));
      const where = `${link.name}, trial ${trial}: reply ${reply} delayed ${delayMs} ms`;
      for (const { id, position } of claims) expect(position, `${where}, servo ${id}`).toBe(POSITIONS[id]);
      claimed += claims.length;
      // Whatever happened, the client is still usable: back in packet mode, the robot answers.
      await rig.clock.advance(link.maxDelayMs + 1000);
      if (rig.client.mode === "direct") await rig.run(rig.client.exitDirectMode());
      expect(await rig.run(rig.client.readFirmwareVersion()), where).toEqual({ major: 2, minor: 23 });
    }
    // The draw put replies past their wait, and answers still came in several trials.
    expect(late).toBeGreaterThan(TRIALS / 3);
    expect(claimed).toBeGreaterThanOrEqual(3 * IDS.length);
  });
});
