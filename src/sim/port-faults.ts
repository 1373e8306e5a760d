/**
 * Fault injection for MockSerialPort (docs/protocol.md §9, last sentence). A "reply" is one transmission of the
 * simulated RBC (a reply packet, an event packet, a download `40`, a servo answer). Each fault applies to the
 * next `replies` replies (default 1; `Infinity` until cleared) and is then used up, except the disconnect,
 * which acts on PC→RBC traffic. A late reply is `delay`; bytes that arrive unasked are `stray` (after a reply)
 * or `MockSerialPort.injectToPc` (at a chosen moment); a reply that arrives twice or more is `duplicate`.
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
  | { kind: "garbage"; bytes: Uint8Array; remaining: number }
  /** `bytes` arrive unasked `afterMs` after the reply (a stray download `40`, noise); later replies do not wait. */
  | { kind: "stray"; bytes: Uint8Array; afterMs: number; remaining: number }
  /** The reply arrives again `copies` times, `afterMs` apart (an echo, a firmware that repeats its replies). */
  | { kind: "duplicate"; afterMs: number; copies: number; remaining: number };

/** How one reply reaches the PC after the faults: its chunks, its extra delay and what arrives after it. */
export interface FaultedReply {
  chunks: Uint8Array[];
  delayMs: number;
  /** Bytes that arrive `afterMs` after the reply itself (strays and duplicates), in no particular order. */
  after: { bytes: Uint8Array; afterMs: number }[];
}

function count(replies: number): number {
  if (!(replies >= 1)) throw new RangeError(`sim: fault for ${replies} replies, below 1`);
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
    if (!(chunkSize >= 1)) throw new RangeError(`sim: chunk size ${chunkSize} below 1`);
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

  /**
   * `bytes` arrive unasked `afterMs` after each of the next `replies` replies (0: right behind it, as a separate read). With a
   * `40` during a download this is a stray acknowledgement at a chosen chunk boundary.
   */
  strayAfterReply(bytes: ArrayLike<number>, afterMs = 0, replies = 1): this {
    if (!(afterMs >= 0)) throw new RangeError(`sim: stray delay ${afterMs} below 0`);
    this.list.push({ kind: "stray", bytes: Uint8Array.from(bytes), afterMs, remaining: count(replies) });
    return this;
  }

  /**
   * Each of the next `replies` replies arrives again `copies` times (default once), the first copy `afterMs`
   * after the reply (0: right behind it, as a separate read) and the next ones `afterMs` apart: a duplicated reply, or
   * unsolicited repeats of it.
   */
  duplicateReplies(afterMs = 0, replies = 1, copies = 1): this {
    if (!(afterMs >= 0)) throw new RangeError(`sim: duplicate delay ${afterMs} below 0`);
    if (!(copies >= 1)) throw new RangeError(`sim: duplicate copies ${copies} below 1`);
    this.list.push({ kind: "duplicate", afterMs, copies: Math.floor(copies), remaining: count(replies) });
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
    const after: FaultedReply["after"] = [];
    const duplicates: { afterMs: number; copies: number }[] = [];
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
        case "stray":
          after.push({ bytes: f.bytes.slice(), afterMs: f.afterMs });
          break;
        case "duplicate":
          duplicates.push({ afterMs: f.afterMs, copies: f.copies });
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
    // A copy is the reply as it went out (its damage included), without the garbage that preceded it.
    for (const d of duplicates) {
      for (let i = 1; i <= d.copies; i++) after.push({ bytes: bytes.slice(), afterMs: d.afterMs * i });
    }
    return { chunks, delayMs, after };
  }

  private use(f: ReplyFault): void {
    f.remaining--;
    if (f.remaining <= 0) this.list = this.list.filter((x) => x !== f);
  }
}
