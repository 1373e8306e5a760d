/**
 * The IR remote's key map (docs/protocol.md §3.1; issue 23 item 3): codes from the spec, literal, and what each key
 * plays from what the robot reported (firmware 9.99 = the official "user" build, free memory, the slot book).
 */
import { describe, expect, it } from "vitest";
import { keyPlays, REMOTE_KEYS, remoteKeyOf } from "../../src/ui/features/sensors/remote/key-map.ts";

const key = (code: number) => {
  const k = remoteKeyOf(code);
  if (!k) throw new Error(`no key ${code}`);
  return k;
};

describe("the remote's key map", () => {
  it("has the codes of §3.1: built-ins 1-11, keys 1-9,0 = 12-21, * keys = 33-42, # + A = 0x2B, # + C = 0x31", () => {
    expect(REMOTE_KEYS.map((k) => k.code)).toEqual([
      1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 33, 34, 35, 36, 37, 38, 39,
      40, 41, 42, 0x2b, 0x31,
    ]);
    expect(
      REMOTE_KEYS.filter((k) => k.group === "number")
        .map((k) => k.face)
        .join(""),
    ).toBe("1234567890");
    expect(key(21)).toMatchObject({ group: "number", face: "0", slot: 10 });
    expect(key(33)).toMatchObject({ group: "star", face: "1", slot: 11 });
    expect(key(42)).toMatchObject({ group: "star", face: "0", slot: 20 });
    expect(key(43)).toMatchObject({ group: "hash", face: "A", hazard: "charging" });
    expect(key(49)).toMatchObject({ group: "hash", face: "C", hazard: "zero-pose" });
    expect(key(20)).toMatchObject({ face: "9", hazard: "endless-walk" });
    expect(remoteKeyOf(22)).toBeUndefined();
  });

  it("on firmware 9.99 (the official user build): keys 1-8 and * play nothing, 0 the demo in flash, 9 the endless walk", () => {
    const user = { firmware: { major: 9, minor: 99 }, freeMotion: 24_576 };
    expect(keyPlays(key(12), user)).toEqual({ kind: "user-nothing" });
    expect(keyPlays(key(40), user)).toEqual({ kind: "user-nothing" });
    expect(keyPlays(key(21), user)).toEqual({ kind: "user-flash-demo" });
    expect(keyPlays(key(20), user)).toEqual({ kind: "user-endless-walk" });
    expect(keyPlays(key(4), user)).toEqual({ kind: "builtin", code: 4 });
    expect(keyPlays(key(43), user)).toEqual({ kind: "hazard", hazard: "charging" });
  });

  it("on other firmware: a download the panel uploaded by name, empty slots, and slots it cannot know", () => {
    const fw = { major: 2, minor: 23 };
    expect(keyPlays(key(12), { firmware: fw, freeMotion: 24_576 })).toEqual({ kind: "empty", slot: 1 });
    expect(keyPlays(key(12), { firmware: fw, freeMotion: 20_000 })).toEqual({
      kind: "download-unknown",
      slot: 1,
    });
    const names = new Map([[1, "RbcPanel_Wave"]]);
    // One upload after a reset: slot 1 is the wave, slot 2 is empty (the count is newer than the free memory).
    const facts = { firmware: fw, freeMotion: 24_576, downloads: 1, names };
    expect(keyPlays(key(12), facts)).toEqual({ kind: "download", slot: 1, name: "RbcPanel_Wave" });
    expect(keyPlays(key(13), facts)).toEqual({ kind: "empty", slot: 2 });
    expect(keyPlays(key(33), { firmware: fw, downloads: 12 })).toEqual({
      kind: "download-unknown",
      slot: 11,
    });
    expect(keyPlays(key(20), { firmware: fw })).toEqual({ kind: "download-unknown", slot: 9 });
  });
});
