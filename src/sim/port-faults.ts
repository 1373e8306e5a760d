/**
 * Fault injection for MockSerialPort (PROTOCOL.md §9, last sentence). A "reply" is one transmission of the
 * simulated RBC (a reply packet, an event packet, a download `40`, a servo answer). Each fault applies to the
 * next `replies` replies (default 1; `Infinity` until cleared) and is then used up, except the disconnect,
 * which acts on PC→RBC traffic.
 */

export type ReplyFault =
  /** Drop byte `index` (0-based) of the reply. */
  | { kind: "drop-byte"; index: number; remaining: number }
  /** Replace byte `index` with `value`, or XOR it with `xor` (default 0x01). */
  | { kind: "corrupt-byte"; index: number; xor: number; value: number | undefined; remaining: number }
  /** Deliver the reply in chunks of `chunkSize` bytes (1 = byte by byte), each a separate read. */
  | { kind: "split"; chunkSize: number; remaining: number }
  /** Deliver the reply `ms` later than it would arrive (later replies never overtake it). */
  | { kind: "delay"; ms: number; remaining: number }
  /** The reply never arrives. */
  | { kind: "swallow"; remaining: number }
  /** `bytes` arrive just before the reply (they count as part of it for pacing). */
  | { kind: "garbage"; bytes: Uint8Array; remaining: number };

/** How one reply reaches the PC after the faults: its chunks and its extra delay. */
export interface FaultedReply {
  chunks: Uint8Array[];
  delayMs: number;
}

function count(replies: number): number {
  if (!(replies >= 1)) throw new RangeError(`A fault applies to at least 1 reply, got ${replies}.`);
  return replies;
}

export class PortFaults {
  private list: ReplyFault[] = [];
  /** Total PC→RBC bytes after which the port is unplugged (the bytes up to it reach the robot). */
  disconnectAtPcBytes: number | undefined;

  /** Drop byte `index` of each of the next `replies` replies. */
  dropByte(index: number, replies = 1): this {
    this.list.push({ kind: "drop-byte", index, remaining: count(replies) });
    return this;
  }

  /** Corrupt byte `index` of the next replies: XOR with `change.xor` (default 0x01) or set `change.value`. */
  corruptByte(index: number, change: { xor?: number; value?: number } = {}, replies = 1): this {
    this.list.push({
      kind: "corrupt-byte",
      index,
      xor: change.xor ?? 0x01,
      value: change.value,
      remaining: count(replies),
    });
    return this;
  }

  /** Split replies into chunks of `chunkSize` bytes (default: every reply until cleared). */
  splitReplies(chunkSize: number, replies = Number.POSITIVE_INFINITY): this {
    if (!(chunkSize >= 1)) throw new RangeError(`Chunk size must be at least 1, got ${chunkSize}.`);
    this.list.push({ kind: "split", chunkSize: Math.floor(chunkSize), remaining: count(replies) });
    return this;
  }

  /** Delay the next replies by `ms`. */
  delayReplies(ms: number, replies = 1): this {
    this.list.push({ kind: "delay", ms, remaining: count(replies) });
    return this;
  }

  /** The next `replies` replies never arrive. */
  swallowReplies(replies = 1): this {
    this.list.push({ kind: "swallow", remaining: count(replies) });
    return this;
  }

  /** `bytes` arrive just before the next replies. */
  garbageBeforeReply(bytes: ArrayLike<number>, replies = 1): this {
    this.list.push({ kind: "garbage", bytes: Uint8Array.from(bytes), remaining: count(replies) });
    return this;
  }

  /** Unplug the port once the PC has written `totalBytes` bytes in all (counted since the port was made). */
  disconnectAfterPcBytes(totalBytes: number): this {
    this.disconnectAtPcBytes = totalBytes;
    return this;
  }

  /** Removes every fault. */
  clear(): void {
    this.list = [];
    this.disconnectAtPcBytes = undefined;
  }

  /** The faults still pending (copies). */
  get active(): ReplyFault[] {
    return this.list.map((f) => ({ ...f }));
  }

  /** Applies the pending faults to one reply; undefined when it is swallowed. */
  apply(reply: Uint8Array): FaultedReply | undefined {
    const swallow = this.list.find((f) => f.kind === "swallow");
    if (swallow) {
      this.use(swallow);
      return undefined;
    }
    let bytes = reply.slice();
    const dropped = new Set<number>();
    let garbage: Uint8Array[] = [];
    let delayMs = 0;
    let chunkSize = Number.POSITIVE_INFINITY;
    for (const f of [...this.list]) {
      switch (f.kind) {
        case "corrupt-byte":
          if (f.index < bytes.length) bytes[f.index] = f.value ?? bytes[f.index]! ^ f.xor;
          break;
        case "drop-byte":
          dropped.add(f.index);
          break;
        case "garbage":
          garbage = [...garbage, f.bytes];
          break;
        case "delay":
          delayMs += f.ms;
          break;
        case "split":
          chunkSize = Math.min(chunkSize, f.chunkSize);
          break;
        case "swallow":
          break;
      }
      this.use(f);
    }
    if (dropped.size > 0) bytes = bytes.filter((_, i) => !dropped.has(i));
    const whole = new Uint8Array(garbage.reduce((n, g) => n + g.length, 0) + bytes.length);
    let o = 0;
    for (const g of garbage) {
      whole.set(g, o);
      o += g.length;
    }
    whole.set(bytes, o);
    const chunks: Uint8Array[] = [];
    if (!Number.isFinite(chunkSize) || chunkSize >= whole.length) chunks.push(whole);
    else for (let i = 0; i < whole.length; i += chunkSize) chunks.push(whole.slice(i, i + chunkSize));
    return { chunks, delayMs };
  }

  private use(f: ReplyFault): void {
    f.remaining--;
    if (f.remaining <= 0) this.list = this.list.filter((x) => x !== f);
  }
}
