import type { Finding, ServoReading } from "./types.ts";

/**
 * [decision] A load byte at or above this, read while the robot rests, is "high": a free servo at rest reads
 * about 0, and the load byte is the servo's only health figure (docs/protocol.md §5); the wCK manual gives no
 * unit, so the threshold is the project's.
 */
export const HIGH_LOAD_AT_REST = 100;

/**
 * What a scan's readings mean, as data: a replacement servo (id 0 garbled, expected ids silent), a missing
 * servo, two servos at one id, a high load at rest, or a bus where nothing answers.
 */
export function scanFindings(readings: readonly ServoReading[], expected: readonly number[]): Finding[] {
  const byId = new Map(readings.map((r) => [r.id, r]));
  const silentExpected = expected.filter((id) => byId.get(id)?.status === "silent");
  const findings: Finding[] = [];
  if (readings.length > 0 && readings.every((r) => r.status === "silent")) {
    return [{ code: "bus-silent", ids: readings.map((r) => r.id) }];
  }
  const zeroGarbled = byId.get(0)?.status === "garbled";
  const replaced = zeroGarbled ? silentExpected.filter((id) => id !== 0) : [];
  if (replaced.length > 0) findings.push({ code: "servo-replacement", ids: [0, ...replaced] });
  for (const r of readings) {
    if (r.status === "garbled" && !(r.id === 0 && replaced.length > 0)) {
      findings.push({ code: "servo-duplicate", ids: [r.id] });
    }
  }
  for (const id of silentExpected) {
    if (!replaced.includes(id)) findings.push({ code: "servo-missing", ids: [id] });
  }
  for (const r of readings) {
    if (r.status === "answered" && r.load >= HIGH_LOAD_AT_REST) {
      findings.push({ code: "servo-high-load", ids: [r.id], load: r.load });
    }
  }
  return findings;
}
