import type { MockSerialPort, PortFaults } from "../../src/sim/index.ts";

/**
 * Arms faults just before the simulated RBC's `n`-th transmission (1-based, counted from this call) reaches the
 * port's fault filter, so that a fault hits one chosen reply of a multi-step operation (the read-back of a zero
 * write, the ack of chunk 4, the servo's answer). Returns a function that tells how many replies were seen.
 *
 * It wraps `port.faults.apply` on this one instance; `PortFaults` itself is untouched.
 */
export function armAtReply(port: MockSerialPort, n: number, arm: (faults: PortFaults) => void): () => number {
  const faults = port.faults;
  const original = faults.apply.bind(faults);
  let seen = 0;
  faults.apply = (reply: Uint8Array) => {
    seen++;
    if (seen === n) arm(faults);
    return original(reply);
  };
  return () => seen;
}

/** Bytes that look like the start of packets but never complete one (and hold no download ack `40`). */
export const LINE_NOISE: readonly number[] = [
  0xff, 0xff, 0xaa, 0x55, 0xaa, 0x55, 0x37, 0x00, 0x13, 0xff, 0xff, 0xaa,
];
