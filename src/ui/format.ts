/** How the panel writes numbers, versions and times for people. Pure functions. */

/** 24576 → "24,576". */
export function formatCount(n: number): string {
  return n.toLocaleString("en-US");
}

/** A signed difference: +3, −2 (true minus sign), or "" for none. */
export function formatDelta(delta: number): string {
  if (delta === 0) return "";
  return delta > 0 ? `+${delta}` : `\u2212${Math.abs(delta)}`;
}

/** A wall-clock time with milliseconds, "14:02:11.045", from epoch ms. */
export function formatClockTime(epochMs: number): string {
  const d = new Date(epochMs);
  const two = (n: number) => String(n).padStart(2, "0");
  return `${two(d.getHours())}:${two(d.getMinutes())}:${two(d.getSeconds())}.${String(d.getMilliseconds()).padStart(3, "0")}`;
}

/** "0x17" style for a byte. */
export function formatByteHex(n: number): string {
  return `0x${n.toString(16).toUpperCase().padStart(2, "0")}`;
}
