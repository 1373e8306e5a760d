import { DOWNLOAD_CHUNK } from "../protocol/catalog.ts";
import { HUNO_SERVO_COUNT } from "../protocol/servo-limits.ts";
import { isAcceptedZeroTable } from "../protocol/zeros.ts";
import type { MemoryArea, StoredFile } from "./sim-downloads.ts";
import { checkServoFaults, type ServoFaults } from "./sim-servo-faults.ts";
import { ServoBus } from "./sim-servos.ts";

/**
 * What a simulated RBC keeps while its cable is out (issue 23 item 2: the demo robot keeps its memory): what a
 * real RBC holds in its EEPROM (the zero table of docs/protocol.md §4, the downloaded files of §6.1), what it
 * keeps while it stays switched on (each area's file count and next free address, which 0x0F answers from, and
 * whether Basic posture has run since power-up, §3.1), and its servos' bus ids (each wCK keeps its id in its own
 * EEPROM, §5) with the faults the bus was made with. Plain data (structured-clone friendly: the panel keeps it in
 * IndexedDB); `checkLastingMemory` refuses anything that is not such a memory, naming what is wrong.
 */

export interface SimAreaMemory {
  /** Files recorded since power-up or the last 0x1F. */
  count: number;
  /** The next free EEPROM address. */
  next: number;
  /** Every file in EEPROM, slot 1 first (the array is dense: slot k is `files[k - 1]`). */
  files: StoredFile[];
}

export interface SimServoMemory {
  /** The faults the servo bus was made with (docs/protocol.md §5, `sim-servo-faults.ts`). */
  faults: Required<ServoFaults>;
  /** The bus id of each joint's servo, joints 0-15. */
  busIds: number[];
  /** The bus ids of the extra servos a `duplicate` fault puts on the bus, in that fault's order. */
  extraBusIds: number[];
}

export interface SimLastingMemory {
  format: "rbc-sim-memory";
  version: 1;
  /** The robot this memory belongs to (13 characters). */
  serialNumber: string;
  zeros: number[];
  /** Basic posture has run since power-up (the robot stayed on while the cable was out). */
  basicPostureDone: boolean;
  motion: SimAreaMemory;
  action: SimAreaMemory;
  servos: SimServoMemory;
}

/** An area's memory, as copies (a later download must not change a memory already taken). */
export function areaMemory(area: MemoryArea): SimAreaMemory {
  return {
    count: area.count,
    next: area.next,
    files: area.files.map((f) => ({ ...f, bytes: f.bytes.slice() })),
  };
}

const isObject = (v: unknown): v is Record<string, unknown> => typeof v === "object" && v !== null;
const isInt = (v: unknown): v is number => Number.isInteger(v);

function fail(what: string): never {
  throw new RangeError(`sim memory: not a simulated robot's memory (${what}); nothing restored`);
}

function checkFile(value: unknown, slot: number, area: MemoryArea): StoredFile {
  if (!isObject(value)) fail(`${area.kind} slot ${slot} is not a file`);
  const { start, size, bytes } = value;
  if (value.slot !== slot) fail(`${area.kind} slot ${slot} says it is slot ${String(value.slot)}`);
  if (!(bytes instanceof Uint8Array)) fail(`${area.kind} slot ${slot} has no bytes`);
  if (!isInt(size) || size !== bytes.length || size < 1) fail(`${area.kind} slot ${slot} has a wrong size`);
  if (!isInt(start) || start < area.base || start % DOWNLOAD_CHUNK !== 0 || start + size > area.end) {
    fail(`${area.kind} slot ${slot} lies outside its area`);
  }
  return { slot, start, size, bytes: bytes.slice() };
}

/** Checks one area's memory against the area it would go into. */
export function checkAreaMemory(value: unknown, area: MemoryArea): SimAreaMemory {
  if (!isObject(value)) fail(`the ${area.kind} area is missing`);
  const { count, next, files } = value;
  if (!Array.isArray(files) || files.length > area.maxFiles) fail(`the ${area.kind} files are not a list`);
  if (!isInt(count) || count < 0 || count > files.length) fail(`the ${area.kind} count is wrong`);
  if (!isInt(next) || next < area.base || next > area.end + DOWNLOAD_CHUNK) {
    fail(`the ${area.kind} next free address is outside its area`);
  }
  return { count, next, files: files.map((f, i) => checkFile(f, i + 1, area)) };
}

function checkIds(value: unknown, length: number | undefined, what: string): number[] {
  if (!Array.isArray(value) || (length !== undefined && value.length !== length)) fail(`${what} are missing`);
  for (const id of value) if (!isInt(id) || id < 0 || id > 30) fail(`${what} hold ${String(id)}`);
  return [...value] as number[];
}

function checkServos(value: unknown): SimServoMemory {
  if (!isObject(value)) fail("the servos are missing");
  let faults: Required<ServoFaults>;
  try {
    faults = checkServoFaults(isObject(value.faults) ? (value.faults as ServoFaults) : undefined);
  } catch (e) {
    fail(`its servo faults: ${(e as Error).message}`);
  }
  return {
    faults,
    busIds: checkIds(value.busIds, HUNO_SERVO_COUNT, "the servo ids"),
    extraBusIds: checkIds(value.extraBusIds, faults.duplicate.length, "the extra servos' ids"),
  };
}

/**
 * `value` as a simulated robot's lasting memory for `areas` (the RBC it would be restored into), or a RangeError
 * naming what is wrong: another format or version, a zero table the RBC would refuse, files outside their
 * area, counts beyond the files, servo ids outside 0-30.
 */
export function checkLastingMemory(
  value: unknown,
  areas: { motion: MemoryArea; action: MemoryArea },
): SimLastingMemory {
  if (!isObject(value) || value.format !== "rbc-sim-memory" || value.version !== 1) {
    fail("another format or version");
  }
  const { serialNumber, zeros, basicPostureDone } = value;
  if (typeof serialNumber !== "string" || !/^[\x20-\x7e]{13}$/.test(serialNumber)) fail("no serial number");
  if (!Array.isArray(zeros) || !isAcceptedZeroTable(zeros)) fail("a zero table the robot would refuse");
  if (typeof basicPostureDone !== "boolean") fail("no power-up state");
  return {
    format: "rbc-sim-memory",
    version: 1,
    serialNumber,
    zeros: [...zeros],
    basicPostureDone,
    motion: checkAreaMemory(value.motion, areas.motion),
    action: checkAreaMemory(value.action, areas.action),
    servos: checkServos(value.servos),
  };
}

/** New servos with a memory's faults and bus ids (the servos a robot restored from `memory` had). */
export function servoBusFromMemory(memory: SimServoMemory): ServoBus {
  const bus = new ServoBus(memory.faults);
  bus.restoreBusIds({ joints: memory.busIds, extras: memory.extraBusIds });
  return bus;
}
