import { describe, expect, it } from "vitest";
import type { LogEntry, StopActivityResult } from "../../src/device/index.ts";
import { scanServos, wiggleServo } from "../../src/device/servo-doctor/index.ts";
import { openMotion } from "../../src/motion/index.ts";
import { toHex } from "../../src/protocol/index.ts";
import { bluetoothLinkOptions } from "../../src/sim/index.ts";
import { makeRig, type Rig } from "../support/rig.ts";

/**
 * Stop wins at every instant of a servo-doctor operation (docs/protocol.md §3.6): pressed at any step of entering
 * direct mode, of the work in it, or of leaving it, on a wired and a Bluetooth link model, it resolves (never a
 * mode error), the operation sends no servo command after the press, and the robot ends in packet mode with its
 * servos holding (none passive). A step is one line of the packet log (every write and every reply is an await
 * point of the operation); Stop is pressed right after line k, for every k of the operation's own run.
 */

const LINKS = [
  { link: "wired", port: { latencyMs: 16, baudPacing: true } },
  { link: "Bluetooth", port: bluetoothLinkOptions({ baudPacing: true }) },
] as const;

const OPERATIONS: {
  op: string;
  start: (r: Rig) => Promise<{ stopped?: unknown } | { outcome: string }>;
  /** The bytes the operation must not send after Stop (default: any servo command). */
  watched?: (e: LogEntry) => boolean;
}[] = [
  { op: "wiggle", start: (r) => wiggleServo(r.client, 4) },
  { op: "scan", start: (r) => scanServos(r.client, { ids: [0, 1, 2] }) },
];

/** A two-scene motion of servos 0 and 2 (tests/unit/tethered-play.test.ts's PAIR), for tethered play. */
const PAIR =
  "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:4:Pair:0:1:2:2:2:4:" +
  "00:020:030:000:0:125:02:020:030:000:0:160:" +
  "000:01:A:2:50:0:00:126:120:2:0:0:02:197:201:3:0:" +
  "001:01:B:3:70:0:00:120:130:0:0:0:02:201:205:2:0:";
/**
 * Tethered play: no frame after Stop. (Its read-back after the last frame, a read that moves nothing, is asked
 * for with no cancel: a play Stop comes after its last frame has finished, and confirms it.)
 */
const PLAY = {
  op: "tethered play",
  start: (r: Rig) => r.client.playTethered(openMotion(PAIR)),
  watched: (e: LogEntry) => servoCommand(e) && e.name.startsWith("tethered play"),
};

/** A servo command on the bus: raw bytes written, but not the leave sequence (FF E0 FB 01 00 1A). */
const servoCommand = (e: LogEntry) =>
  e.direction === "out" && e.kind === "raw" && toHex(e.bytes) !== "FF E0 FB 01 00 1A";

async function stepsOf(port: (typeof LINKS)[number]["port"], start: (r: Rig) => Promise<unknown>) {
  const rig = await makeRig({ port });
  let steps = 0;
  rig.client.log.on(() => steps++);
  await rig.run(start(rig));
  return steps;
}

describe.each(LINKS)("Stop at every step on the $link link", ({ port }) => {
  it.each([...OPERATIONS, PLAY])(
    "of a $op: resolves, nothing more is sent to the servos, packet mode, servos holding",
    async ({ start, watched }: (typeof OPERATIONS)[number]) => {
      const n = await stepsOf(port, start);
      expect(n).toBeGreaterThan(4);
      for (let k = 0; k <= n; k++) {
        const rig = await makeRig({ port });
        const { client, sim, run } = rig;
        const log: LogEntry[] = [];
        let pressedAt = -1;
        let stop: Promise<StopActivityResult> | undefined;
        const press = () => {
          pressedAt = log.length;
          stop = client.stopActivity();
        };
        client.log.on((e) => {
          log.push(e);
          if (log.length === k && !stop) press();
        });
        const operation = start(rig);
        if (k === 0) press();
        const outcome = await run(operation);
        if (!stop) press();
        await run(stop!);
        // The leave sequence has no reply: give its bytes the time to cross the wire.
        await rig.clock.advance(1000);
        const after = log.slice(pressedAt).filter(watched ?? servoCommand);
        expect({ k, servoCommandsAfterStop: after.map((e) => toHex(e.bytes)) }).toEqual({
          k,
          servoCommandsAfterStop: [],
        });
        expect({ k, mode: client.mode, direct: sim.directMode }).toEqual({
          k,
          mode: "packet",
          direct: false,
        });
        expect({ k, passive: sim.servos.filter((s) => s.passive).length }).toEqual({ k, passive: 0 });
        // Stopped before its end, the operation says Stop stopped it (never a mode error, never "cancelled").
        const code =
          "stopped" in outcome ? (outcome.stopped as { code: string } | undefined)?.code : undefined;
        const wiggleCode = "code" in outcome ? outcome.code : undefined;
        for (const c of [code, wiggleCode])
          if (c !== undefined) expect({ k, code: c }).toEqual({ k, code: "stop-pressed" });
      }
    },
  );
});

/** A doctor command (a mode-5 read FF Ax or a move FF 8x), not Limp's passive commands (FF Cx). */
const doctorCommand = (e: LogEntry) =>
  servoCommand(e) && (e.bytes[1]! & 0xe0) !== 0xc0 && e.bytes[0] === 0xff && e.bytes.length === 4;

describe.each(LINKS)("Limp at every step on the $link link", ({ port }) => {
  it.each(OPERATIONS)(
    "of a $op: every servo passive, the operation sends nothing more",
    async ({ start }) => {
      const n = await stepsOf(port, start);
      for (let k = 0; k <= n; k++) {
        const rig = await makeRig({ port });
        const { client, sim, run } = rig;
        const log: LogEntry[] = [];
        let pressedAt = -1;
        let limp: ReturnType<typeof client.limp> | undefined;
        const press = () => {
          pressedAt = log.length;
          limp = client.limp();
        };
        client.log.on((e) => {
          log.push(e);
          if (log.length === k && !limp) press();
        });
        const operation = start(rig);
        if (k === 0) press();
        await run(operation);
        if (!limp) press();
        const result = await run(limp!);
        await rig.clock.advance(1000);
        expect({ k, confirmed: result.confirmed.length }).toEqual({ k, confirmed: 16 });
        expect({ k, passive: sim.servos.filter((s) => s.passive).length }).toEqual({ k, passive: 16 });
        const after = log.slice(pressedAt).filter(doctorCommand);
        expect({ k, doctorCommandsAfterLimp: after.map((e) => toHex(e.bytes)) }).toEqual({
          k,
          doctorCommandsAfterLimp: [],
        });
      }
    },
  );
});
