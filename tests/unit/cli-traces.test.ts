import { describe, expect, it } from "vitest";
import { limpCommand } from "../../src/cli/commands/limp.ts";
import { SimTrace, type SimTraceLine } from "../../src/cli/sim-trace.ts";
import { fromHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { SimulatedRbc } from "../../src/sim/index.ts";
import { runInProcess } from "../support/cli-env.ts";

/** Issue 20 item 12: the packet traces show every packet sent, and never call an answer "unasked". */

describe("rbc limp --log", () => {
  it("shows the 'leave direct mode' bytes it sends when it closes the port", {
    timeout: 30_000,
  }, async () => {
    const r = await runInProcess(limpCommand, ["--demo", "--yes", "--log"], { RBC_DEMO_TIME_SCALE: "50" });
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toContain("Limp: all 16 servos confirmed passive.");
    const lines = r.stderr.trimEnd().split("\n");
    // The last packet of the session: the wCK exit of docs/protocol.md §5, after servo 15's answer.
    expect(lines.at(-1)).toMatch(/^\s*[\d.]+ {2}PC→RBC {2}leave direct mode\s+FF E0 FB 01 00 1A$/);
    expect(lines.at(-3)).toMatch(/PC→RBC {2}servo 15 limp\s+FF CF 10 5F$/);
  });
});

describe("rbc sim's trace: a reply to a request is never folded as unasked", () => {
  function traced() {
    let send: (bytes: Uint8Array) => void = () => {};
    const sim = new SimulatedRbc({ clock: new VirtualClock() });
    const lines: SimTraceLine[] = [];
    const trace = new SimTrace(sim, (l) => lines.push(l));
    sim.onTransmit((b) => trace.reply(b, undefined));
    send = (b) => trace.reply(b, undefined);
    const feed = (hex: string) => {
      const bytes = fromHex(hex);
      trace.incoming(bytes);
      sim.receive(bytes);
      trace.afterReceive();
    };
    return { lines, feed, send, shown: () => lines.map((l) => [l.direction, l.label, l.hex]) };
  }

  it("two reads of servo 5 in one write: two request lines and two answers", () => {
    const { feed, shown } = traced();
    feed("FF FF AA 55 AA 55 37 BA 10 00 00 00 00 01 01 01"); // 0x10: direct mode on
    feed("FF A5 00 25 FF A5 00 25"); // wCK: read servo 5's position, twice
    const answer = shown()[4]?.[2];
    expect(answer).toMatch(/^00 [0-9A-F]{2}$/);
    expect(shown().slice(2)).toEqual([
      ["pc-to-rbc", "servo bus (direct mode)", "FF A5 00 25"],
      ["pc-to-rbc", "servo bus (direct mode)", "FF A5 00 25"],
      ["rbc-to-pc", "servo bus reply", answer],
      ["rbc-to-pc", "servo bus reply", answer],
    ]);
  });

  it("two version reads in one write: two answers, and a third identical one unasked is still folded", () => {
    const { lines, feed, send } = traced();
    const read = "FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01";
    feed(`${read} ${read}`);
    send(fromHex("FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 15")); // the same reply, nobody asked
    feed(read);
    expect(lines.map((l) => `${l.direction} ${l.label}`)).toEqual([
      "pc-to-rbc 0x12 Read firmware version",
      "pc-to-rbc 0x12 Read firmware version",
      "rbc-to-pc 0x12 Read firmware version",
      "rbc-to-pc 0x12 Read firmware version",
      "note 0x12 Read firmware version: the same reply 1 more time, unasked",
      "pc-to-rbc 0x12 Read firmware version",
      "rbc-to-pc 0x12 Read firmware version",
    ]);
  });
});
