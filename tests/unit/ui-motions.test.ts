import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { parseRbm, serializeRbm } from "../../src/protocol/rbm.ts";
import { checkEntry, entryFacts, inspectMotionText } from "../../src/ui/features/motions/files.ts";
import { issueText } from "../../src/ui/features/motions/issue-text.ts";
import { formatSeconds, motionPlotData, sceneRows } from "../../src/ui/features/motions/plot-data.ts";
import {
  afterFailedUpload,
  afterReset,
  afterUpload,
  DOWNLOAD_MOTION_NUMBERS,
  emptyBook,
  motionNumberOf,
  observeFreeMemory,
  slotsLeft,
} from "../../src/ui/features/motions/slot-book.ts";
import {
  addSample,
  formatRate,
  formatTimeLeft,
  type ProgressSample,
  uploadFigures,
} from "../../src/ui/features/motions/upload-rate.ts";

const WAVE = readFileSync(new URL("../../examples/wave.rbm", import.meta.url), "latin1");

describe("upload rate and time left", () => {
  it("has no rate before two reports with progress", () => {
    expect(uploadFigures([], 538)).toEqual({ acknowledged: 0, total: 538, percent: 0 });
    expect(uploadFigures([{ t: 0, acknowledged: 0 }], 538)).toEqual({
      acknowledged: 0,
      total: 538,
      percent: 0,
    });
  });

  it("computes bytes/s and seconds left from the report times", () => {
    const samples: ProgressSample[] = [
      { t: 1000, acknowledged: 0 },
      { t: 1100, acknowledged: 64 },
      { t: 1200, acknowledged: 128 },
    ];
    const f = uploadFigures(samples, 640);
    expect(f.percent).toBe(20);
    expect(f.bytesPerSecond).toBeCloseTo(640);
    expect(f.secondsLeft).toBeCloseTo(0.8);
  });

  it("measures over the recent window only, so a slow start does not drag the estimate", () => {
    let samples: ProgressSample[] = [{ t: 0, acknowledged: 0 }];
    // Slow for 5 s (64 bytes/s), then fast (640 bytes/s).
    for (let i = 1; i <= 5; i++) samples = addSample(samples, { t: i * 1000, acknowledged: i * 64 }, 2000);
    for (let i = 1; i <= 30; i++) {
      samples = addSample(samples, { t: 5000 + i * 100, acknowledged: 320 + i * 64 }, 2000);
    }
    const f = uploadFigures(samples, 10_000, 2000);
    expect(f.bytesPerSecond).toBeCloseTo(640);
    // The window keeps one sample at or before its start, and not much more.
    expect(samples[0]!.t).toBeLessThanOrEqual(8000 - 2000);
    expect(samples.length).toBeLessThan(25);
  });

  it("reaches 100% and 0 s left at the end", () => {
    const f = uploadFigures(
      [
        { t: 0, acknowledged: 0 },
        { t: 50, acknowledged: 538 },
      ],
      538,
    );
    expect(f.percent).toBe(100);
    expect(f.secondsLeft).toBe(0);
  });

  it("formats rate and time left for people", () => {
    expect(formatRate(5380.4)).toBe("5,380 bytes/s");
    expect(formatRate(undefined)).toBe("— bytes/s");
    expect(formatTimeLeft(undefined)).toBe("time left: estimating…");
    expect(formatTimeLeft(0.4)).toBe("less than 1 s left");
    expect(formatTimeLeft(11.2)).toBe("about 12 s left");
    expect(formatTimeLeft(200)).toBe("about 4 min left");
  });
});

describe("slot bookkeeping", () => {
  const hi = { name: "HunoDemo_Hi", fileName: "Hi.rbm", durationMs: 3500, bytes: 538 };

  it("knows nothing until the free memory shows an empty area or a reset happens", () => {
    let book = emptyBook("motion");
    expect(slotsLeft(book)).toBeUndefined();
    book = afterUpload(book, hi);
    expect(book.entries[0]?.slot).toBeUndefined();
    expect(motionNumberOf(book.entries[0]!)).toBeUndefined();
    expect(observeFreeMemory(emptyBook("motion"), 24_000, 24_576).count).toBeUndefined();
    expect(observeFreeMemory(emptyBook("motion"), 24_576, 24_576).count).toBe(0);
  });

  it("numbers uploads in order: slots 1-10 play as 12-21, 11-20 as 33-42", () => {
    let book = observeFreeMemory(emptyBook("motion"), 24_576, 24_576);
    for (let i = 0; i < 11; i++) book = afterUpload(book, { ...hi, name: `m${i + 1}` });
    expect(book.count).toBe(11);
    expect(slotsLeft(book)).toBe(9);
    expect(book.entries.map((e) => motionNumberOf(e))).toEqual([12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 33]);
  });

  it("a reset forgets the slots and starts again at slot 1, replacing what was there", () => {
    let book = observeFreeMemory(emptyBook("motion"), 24_576, 24_576);
    book = afterUpload(book, hi);
    book = afterUpload(book, { ...hi, name: "second" });
    book = afterReset(book);
    expect(book).toMatchObject({ count: 0, entries: [] });
    book = afterUpload(book, { ...hi, name: "third" });
    expect(book.entries.map((e) => [e.name, e.slot])).toEqual([["third", 1]]);
  });

  it("a failed upload keeps the count only when the robot recorded nothing", () => {
    const book = afterUpload(observeFreeMemory(emptyBook("motion"), 24_576, 24_576), hi);
    expect(afterFailedUpload(book, "nothing-recorded").count).toBe(1);
    expect(afterFailedUpload(book, "unknown").count).toBeUndefined();
    expect(afterFailedUpload(book, undefined).count).toBeUndefined();
  });

  it("offers exactly the 20 download numbers and holds at most 10 actions", () => {
    expect(DOWNLOAD_MOTION_NUMBERS).toEqual([
      12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42,
    ]);
    expect(emptyBook("action").max).toBe(10);
  });
});

describe("motion files", () => {
  it("reads wave.rbm: facts, image and footprint", () => {
    const entry = inspectMotionText("wave.rbm", WAVE);
    expect(entry.errors).toEqual([]);
    // 6 scenes of 16 servos: 108 + 86 · 6 = 624 bytes, 640 on the robot (docs/protocol.md §6).
    expect(entryFacts(entry)).toEqual({
      name: "RbcPanel_Wave",
      scenes: 6,
      servos: 16,
      durationMs: 3200,
      imageBytes: 624,
      footprint: 640,
    });
  });

  it("puts every error of a broken file into words, never throwing", () => {
    const motion = parseRbm(WAVE);
    motion.scenes[0]!.timeMs = motion.scenes[0]!.frames * 10;
    motion.scenes[1]!.servos[2]!.torque = 7;
    const entry = inspectMotionText("Edited.rbm", serializeRbm(motion));
    // Kept for the scene table and the chart, but with no image it can never be uploaded.
    expect(entry.motion?.scenes).toHaveLength(6);
    expect(entry.image).toBeUndefined();
    expect(entry.errors.map((e) => e.code)).toEqual(["rbm-frame-interval-short", "rbm-torque"]);
    expect(checkEntry(entry, undefined).errors.map((e) => e.code)).toEqual([
      "rbm-frame-interval-short",
      "rbm-torque",
    ]);
    // Said in words (the exact sentence is the outcome catalogue's).
    const said = (name: string, text: string) => {
      const issue = inspectMotionText(name, text).errors[0];
      return issue && issueText(issue, "en");
    };
    expect(said("x.rbm", "not a motion")).toMatch(/not a Motionbuilder motion file|should end with ":"/);
    expect(said("empty.rbm", "")).toBe("The motion file is empty.");
  });

  it("plots every servo from its start to its end position over each scene", () => {
    const motion = parseRbm(WAVE);
    const plot = motionPlotData(motion);
    // Scenes of 800, 400, 400, 400, 400 and 800 ms.
    expect(plot.x).toEqual([0, 800, 800, 1200, 1200, 1600, 1600, 2000, 2000, 2400, 2400, 3200]);
    expect(plot.series).toHaveLength(16);
    expect(plot.series[2]?.label).toBe("2 Left knee");
    const s0 = motion.scenes[0]!.servos[10]!;
    expect(plot.series[10]?.values.slice(0, 2)).toEqual([s0.start, s0.end]);
  });

  it("lists scenes with their frame interval", () => {
    const rows = sceneRows(parseRbm(WAVE));
    expect(rows[1]).toMatchObject({ index: 1, frames: 10, timeMs: 400, frameMs: 40, startsAtMs: 800 });
  });

  it("writes durations in seconds with one decimal, never to the millisecond (issue #11)", () => {
    expect(formatSeconds(3500)).toBe("3.5 s");
    expect(formatSeconds(365)).toBe("0.4 s");
    expect(formatSeconds(5671)).toBe("5.7 s");
    expect(formatSeconds(9960)).toBe("10 s");
    expect(formatSeconds(12_400)).toBe("12 s");
    expect(formatSeconds(40)).toBe("40 ms");
    expect(formatSeconds(0)).toBe("0 s");
  });
});
