import { BYTE_TIME_MS } from "../sim/mock-serial-options.ts";
import { applyFault, type FaultKind, SPLIT_GAP_MS } from "./sim-faults.ts";
import { TimedQueue } from "./timed-queue.ts";

/**
 * The wire between a serial device and the simulated RBC in `rbc sim`: the timing and faults that
 * MockSerialPort models in-process, applied to bytes that really cross a serial device.
 *
 * - `baudPacing`: each byte takes 86.8 µs (115200 baud, 8N1) in each direction, serialized: requests reach
 *   the simulator, and replies leave it, no faster than the real wire would carry them.
 * - `latencyMs`: added to every reply, like a USB adapter holding bytes (16 ms is an FTDI default).
 * - `fault`: applied to every `faultEvery`-th reply (see sim-faults.ts). Later replies never overtake a
 *   delayed one.
 */
export interface SimLinkOptions {
  baudPacing: boolean;
  latencyMs: number;
  fault: FaultKind | undefined;
  faultEvery: number;
  faultDelayMs: number;
}

export class SimLink {
  private readonly rx = new TimedQueue();
  private readonly tx = new TimedQueue();
  private rxFree = 0;
  private txFree = 0;
  private lastDelivery = 0;
  private replies = 0;

  constructor(
    private readonly options: SimLinkOptions,
    /** Hands request bytes to the simulator (after wire time). */
    private readonly toRobot: (bytes: Uint8Array) => void,
    /** Writes reply bytes to the serial device. */
    private readonly toDevice: (bytes: Uint8Array) => void,
    /** Told about every reply as it is scheduled, with what a fault did to it. */
    private readonly onReply: (reply: Uint8Array, note: string | undefined) => void,
    private readonly now: () => number = () => performance.now(),
  ) {}

  /** Bytes read from the serial device (the PC's request). */
  fromDevice(bytes: Uint8Array): void {
    if (!this.options.baudPacing) {
      this.rx.push(0, () => this.toRobot(bytes));
      return;
    }
    this.rxFree = Math.max(this.now(), this.rxFree) + bytes.length * BYTE_TIME_MS;
    this.rx.push(this.rxFree, () => this.toRobot(bytes));
  }

  /** One transmission of the simulator (a reply, an event, a download `40`, a servo answer). */
  fromRobot(reply: Uint8Array): void {
    this.replies++;
    const { fault, faultEvery, faultDelayMs, baudPacing, latencyMs } = this.options;
    const faulted =
      fault && this.replies % faultEvery === 0
        ? applyFault(fault, reply, faultDelayMs)
        : { chunks: [reply], delayMs: 0, note: undefined };
    this.onReply(reply, faulted.note);
    if (faulted.chunks.length === 0) return;
    const bytes = faulted.chunks.reduce((n, c) => n + c.length, 0);
    const now = this.now();
    this.txFree = Math.max(now, this.txFree) + (baudPacing ? bytes * BYTE_TIME_MS : 0);
    let at = Math.max(this.txFree + latencyMs + faulted.delayMs, this.lastDelivery);
    for (const [i, chunk] of faulted.chunks.entries()) {
      if (i > 0) at += SPLIT_GAP_MS;
      this.tx.push(at, () => this.toDevice(chunk));
    }
    this.lastDelivery = at;
  }

  /** Forgets whatever is still scheduled. */
  stop(): void {
    this.rx.clear();
    this.tx.clear();
  }
}
