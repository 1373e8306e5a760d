import { describe, expect, it } from "vitest";
import { addEvent, describeEvent, FOLD_MS } from "../../src/ui/features/sensors/events.ts";
import { RingSeries } from "../../src/ui/features/sensors/ring-series.ts";
import { effectiveRate } from "../../src/ui/features/sensors/watch.ts";
import { LatestMoveSender } from "../../src/ui/features/servos/move-sender.ts";
import { checkTypedTarget, clampToSafe } from "../../src/ui/features/servos/state.ts";

describe("rolling chart data", () => {
  it("keeps the last window of samples and gives x relative to the newest", () => {
    const s = new RingSeries(2, 30_000);
    for (let t = 0; t <= 60_000; t += 1000) s.push(t, [t / 1000, -t / 1000]);
    expect(s.size).toBe(31);
    expect(s.t[0]).toBe(30_000);
    expect(s.relativeSeconds().slice(0, 2)).toEqual([-30, -29]);
    expect(s.relativeSeconds().at(-1)).toBe(0);
    expect(s.latest()).toEqual([60, -60]);
    s.clear();
    expect(s.latest()).toBeUndefined();
  });
});

describe("sensor events", () => {
  it("folds a held button and a steady sound, but lists each IR key", () => {
    let list = addEvent([], { at: 0, kind: "buttons", value: 2 });
    list = addEvent(list, { at: 200, kind: "buttons", value: 2 });
    list = addEvent(list, { at: 400, kind: "buttons", value: 2 });
    expect(list).toHaveLength(1);
    expect(list[0]).toMatchObject({ count: 3, at: 400 });
    list = addEvent(list, { at: 500, kind: "buttons", value: 1 });
    expect(list).toHaveLength(2);
    list = addEvent(list, { at: 600, kind: "remote", value: 7 });
    list = addEvent(list, { at: 650, kind: "remote", value: 7 });
    expect(list).toHaveLength(4);
    list = addEvent(list, { at: 700, kind: "sound", value: 40 });
    list = addEvent(list, { at: 800, kind: "sound", value: 44 });
    expect(list[0]).toMatchObject({ kind: "sound", value: 44, count: 2 });
    list = addEvent(list, { at: 800 + FOLD_MS + 1, kind: "sound", value: 44 });
    expect(list[0]?.count).toBe(1);
  });

  it("keeps the newest 12", () => {
    let list = addEvent([], { at: 0, kind: "remote", value: 1 });
    for (let i = 1; i < 20; i++) list = addEvent(list, { at: i, kind: "remote", value: i });
    expect(list).toHaveLength(12);
    expect(list[0]?.value).toBe(19);
  });

  it("describes events in words", () => {
    expect(describeEvent({ kind: "buttons", value: 2 })).toBe("PF2 pressed");
    expect(describeEvent({ kind: "remote", value: 7 })).toBe("IR key 7 (Basic posture)");
    expect(describeEvent({ kind: "remote", value: 200 })).toBe("IR key 200");
    expect(describeEvent({ kind: "sound", value: 42 })).toBe("Sound level 42");
  });

  it("reads at most 5 times a second while listening to sound", () => {
    expect(effectiveRate({ rateHz: 10, listen: "sound" })).toBe(5);
    expect(effectiveRate({ rateHz: 2, listen: "sound" })).toBe(2);
    expect(effectiveRate({ rateHz: 10, listen: "buttons" })).toBe(10);
  });
});

describe("servo moves", () => {
  it("has at most one move in flight; waiting moves are replaced by newer ones for the same servo", async () => {
    const sent: [number, number][] = [];
    let release: () => void = () => {};
    const sender = new LatestMoveSender<number>(
      (id, value) =>
        new Promise<void>((resolve) => {
          sent.push([id, value]);
          release = resolve;
        }),
    );
    sender.request(3, 100);
    for (let v = 101; v <= 150; v++) sender.request(3, v);
    sender.request(4, 60);
    expect(sent).toEqual([[3, 100]]);
    expect(sender.waiting).toBe(2);
    release();
    await new Promise((r) => setTimeout(r, 0));
    expect(sent).toEqual([
      [3, 100],
      [3, 150],
    ]);
    release();
    await new Promise((r) => setTimeout(r, 0));
    release();
    await new Promise((r) => setTimeout(r, 0));
    expect(sent.at(-1)).toEqual([4, 60]);
    expect(sender.busy).toBe(false);
  });

  it("drops waiting moves on clear and goes on after a failed move", async () => {
    const sent: number[] = [];
    const sender = new LatestMoveSender<number>(async (_id, v) => {
      sent.push(v);
      if (v === 1) throw new Error("no answer");
    });
    sender.request(0, 1);
    sender.request(1, 2);
    await new Promise((r) => setTimeout(r, 0));
    expect(sent).toEqual([1, 2]);
    sender.request(0, 3);
    sender.request(1, 4);
    sender.clear();
    await new Promise((r) => setTimeout(r, 0));
    expect(sent).toEqual([1, 2, 3]);
  });

  it("keeps targets inside each servo's safe range", () => {
    expect(clampToSafe(3, 250)).toBe(130);
    expect(clampToSafe(3, 0)).toBe(40);
    expect(clampToSafe(2, 200.4)).toBe(200);
  });

  it("refuses a typed target outside the safe range instead of clamping it (docs/protocol.md §5 ranges)", () => {
    // Servo 12: lower 1, upper 198.
    expect(checkTypedTarget(12, "300")).toEqual({
      problem:
        "Servo 12: 300 is outside its safe range 1–198. Nothing was sent; the servo stays where it is.",
    });
    expect(checkTypedTarget(12, "0")).toMatchObject({
      problem: expect.stringContaining("outside its safe range 1–198"),
    });
    expect(checkTypedTarget(12, "198")).toEqual({ position: 198 });
    expect(checkTypedTarget(12, " 1 ")).toEqual({ position: 1 });
    expect(checkTypedTarget(3, "12.5")).toEqual({
      problem: 'Servo 3: "12.5" is not a whole number; use 40 to 130. Nothing was sent.',
    });
    expect(checkTypedTarget(3, "")).toEqual({
      problem: "Servo 3: enter a position from 40 to 130. Nothing was sent.",
    });
  });
});
