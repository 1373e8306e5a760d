import { downloadSlotOf, MOTION_AREA_BYTES } from "../../../../protocol/catalog.ts";

/**
 * The IR remote's key map (docs/protocol.md §3.1) and what each key plays on this robot, from what the robot
 * reported: its firmware version, its free motion memory and the downloads the panel saw arrive in this
 * connection. Pure. A key sends its code; the RBC plays as if Run Motion had been sent with that number.
 *
 * - Built-in motions: codes 1-11.
 * - Number keys 1-9, 0: codes 12-21 (download slots 1-10); `*` + 1-9, 0: codes 33-42 (slots 11-20).
 * - `#` + A: 0x2B (43), battery charging when a charger is connected; `#` + C: 0x31 (49), the raw zero pose.
 *
 * What a key does depends on the firmware build: the official "user" firmware (the only official source found)
 * plays no downloads: keys 1-8 and every `*` key play nothing, 0 a demo motion kept in flash, and 9 an endless
 * obstacle-avoidance walk that no request stops, only switching the robot off. That source (and a homebrew port
 * of it) reports version 9.99 (§3.5), so a robot reporting 9.99 is taken to be that build; on any other the
 * number keys play the downloads, and key 9's hazard is still named.
 */

export type RemoteKeyGroup = "builtin" | "number" | "star" | "hash";
export type RemoteHazard = "charging" | "zero-pose" | "endless-walk";

export interface RemoteKey {
  /** The IR key code the remote sends (and the Run Motion number it stands for). */
  code: number;
  group: RemoteKeyGroup;
  /** What is printed on the key: "1"…"0" for the number keys ("*" or "#" is shown by its group). */
  face: string;
  /** The download slot it plays (1-20), for number and `*` keys. */
  slot?: number;
  /** A hazard the key carries on every build (`#` keys), or on the official "user" build (key 9). */
  hazard?: RemoteHazard;
}

const FACES = ["1", "2", "3", "4", "5", "6", "7", "8", "9", "0"];

/** Code of `#` + A and `#` + C (docs/protocol.md §3.1 "Hazards"). */
export const CHARGING_CODE = 0x2b;
export const ZERO_POSE_CODE = 0x31;
/** Key 9 (download slot 9): the endless walk on the official "user" build. */
export const ENDLESS_WALK_CODE = 20;
/** Key 0 (download slot 10): the demo motion kept in flash on the official "user" build. */
const FLASH_DEMO_CODE = 21;

export const REMOTE_KEYS: readonly RemoteKey[] = [
  ...Array.from(
    { length: 11 },
    (_, i): RemoteKey => ({ code: i + 1, group: "builtin", face: String(i + 1) }),
  ),
  ...FACES.map(
    (face, i): RemoteKey => ({
      code: 12 + i,
      group: "number",
      face,
      slot: i + 1,
      ...(12 + i === ENDLESS_WALK_CODE ? { hazard: "endless-walk" as const } : {}),
    }),
  ),
  ...FACES.map((face, i): RemoteKey => ({ code: 33 + i, group: "star", face, slot: 11 + i })),
  { code: CHARGING_CODE, group: "hash", face: "A", hazard: "charging" },
  { code: ZERO_POSE_CODE, group: "hash", face: "C", hazard: "zero-pose" },
];

/** The key that sends `code`, if it is on the map. */
export function remoteKeyOf(code: number): RemoteKey | undefined {
  return REMOTE_KEYS.find((k) => k.code === code);
}

/** What the robot reported that decides what a key plays. */
export interface RobotFacts {
  firmware?: { major: number; minor: number };
  /** Free bytes of the motion area (0x0F), when read. */
  freeMotion?: number;
  /** Downloads recorded since power-up or a reset, when the panel knows (the Motions view's slot book). */
  downloads?: number;
  /** Uploads of this connection whose slot is known: slot → motion name. */
  names?: ReadonlyMap<number, string>;
}

/** What a key plays on this robot, as far as it reported. */
export type KeyPlays =
  | { kind: "builtin"; code: number }
  | { kind: "hazard"; hazard: "charging" | "zero-pose" }
  /** A download the panel uploaded in this connection (its name). */
  | { kind: "download"; slot: number; name: string }
  /** Slot `slot` holds a download the panel did not see arrive, or none: the robot does not say which. */
  | { kind: "download-unknown"; slot: number }
  /** Nothing is recorded in that slot (the count is known, or the motion area is wholly free). */
  | { kind: "empty"; slot: number }
  /** The official "user" build: no downloads; 0 its demo motion in flash, 9 the endless walk. */
  | { kind: "user-nothing" }
  | { kind: "user-flash-demo" }
  | { kind: "user-endless-walk" };

/** The robot reports 9.99, the version the official "user" firmware source (and its homebrew port) reports. */
export function isUserFirmware(facts: RobotFacts): boolean {
  return facts.firmware?.major === 9 && facts.firmware.minor === 99;
}

export function keyPlays(key: RemoteKey, facts: RobotFacts): KeyPlays {
  if (key.group === "builtin") return { kind: "builtin", code: key.code };
  if (key.group === "hash")
    return { kind: "hazard", hazard: key.code === CHARGING_CODE ? "charging" : "zero-pose" };
  const slot = key.slot ?? downloadSlotOf(key.code) ?? 0;
  if (isUserFirmware(facts)) {
    if (key.code === ENDLESS_WALK_CODE) return { kind: "user-endless-walk" };
    if (key.code === FLASH_DEMO_CODE) return { kind: "user-flash-demo" };
    return { kind: "user-nothing" };
  }
  const name = facts.names?.get(slot);
  if (name !== undefined) return { kind: "download", slot, name };
  // The count of this connection's slot book is newer than a free-memory reading taken before its uploads.
  if (facts.downloads !== undefined) {
    return slot > facts.downloads ? { kind: "empty", slot } : { kind: "download-unknown", slot };
  }
  if (facts.freeMotion === MOTION_AREA_BYTES) return { kind: "empty", slot };
  return { kind: "download-unknown", slot };
}
