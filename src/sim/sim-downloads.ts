import {
  ACTION_AREA_BYTES,
  DOWNLOAD_CHUNK,
  MAX_ACTIONS,
  MAX_MOTIONS,
  MOTION_AREA_BYTES,
} from "../protocol/catalog.ts";

/**
 * Motion and action memory of the simulated RBC and the chunked download sequence (docs/protocol.md §6).
 */

/** A downloaded file as the simulator holds it. */
export interface StoredFile {
  /** 1-based slot: motion 1-20 (played by Run Motion 12-21, 33-42) or action 1-10. */
  slot: number;
  /** EEPROM address of the first byte. */
  start: number;
  size: number;
  bytes: Uint8Array;
}

export type AreaKind = "motion" | "action";

/**
 * One memory area. `count` and `next` are volatile (since power-up or the last 0x1F); the stored files stay
 * (EEPROM) until a later download into the same slot replaces them.
 */
export class MemoryArea {
  count = 0;
  next: number;
  /** Slot k is `files[k - 1]`; downloads fill slots 1, 2, ... so the array stays dense. */
  readonly files: StoredFile[] = [];

  constructor(
    readonly kind: AreaKind,
    readonly base: number,
    readonly capacity: number,
    readonly maxFiles: number,
    /** Error code set when a download is refused (3 motions, 4 actions). */
    readonly fullError: number,
  ) {
    this.next = base;
  }

  get end(): number {
    return this.base + this.capacity;
  }

  /** What 0x0F answers: the free bytes after the next free address. */
  get free(): number {
    return Math.max(0, this.end - this.next);
  }

  /** Whether a download of `size` bytes gets its first `40` [decision, §6.2]. */
  accepts(size: number): boolean {
    return size > 0 && this.count < this.maxFiles && this.next + size <= this.end;
  }

  /** Records a completed download; the next file starts on the following 64-byte block (quirk included). */
  record(bytes: Uint8Array): StoredFile {
    const file: StoredFile = { slot: this.count + 1, start: this.next, size: bytes.length, bytes };
    this.files[this.count] = file;
    this.count++;
    this.next = file.start + file.size + DOWNLOAD_CHUNK - (file.size % DOWNLOAD_CHUNK);
    return file;
  }

  /** 0x1F and power-up: the count goes back to zero and the next download starts at the area's start. */
  resetPointer(): void {
    this.count = 0;
    this.next = this.base;
  }

  fileInSlot(slot: number): StoredFile | undefined {
    return this.files[slot - 1];
  }

  /** Puts back a memory taken earlier (`sim-memory.ts`, which checks it first): files, count, next address. */
  restore(memory: { count: number; next: number; files: readonly StoredFile[] }): void {
    this.files.length = 0;
    this.files.push(...memory.files.map((f) => ({ ...f, bytes: f.bytes.slice() })));
    this.count = memory.count;
    this.next = memory.next;
  }
}

export function createMotionArea(): MemoryArea {
  return new MemoryArea("motion", 0, MOTION_AREA_BYTES, MAX_MOTIONS, 3);
}

export function createActionArea(): MemoryArea {
  return new MemoryArea("action", MOTION_AREA_BYTES, ACTION_AREA_BYTES, MAX_ACTIONS, 4);
}

export type ChunkResult = "more" | "chunk-ok" | "last-chunk-ok" | "bad-checksum";

/**
 * One download in progress: collects chunks of min(64, remaining) payload bytes plus one XOR checksum byte.
 */
export class DownloadSession {
  readonly payload: Uint8Array;
  /** Payload bytes accepted so far. */
  received = 0;
  private readonly chunk = new Uint8Array(DOWNLOAD_CHUNK + 1);
  private chunkLength = 0;

  constructor(
    readonly area: MemoryArea,
    readonly size: number,
  ) {
    this.payload = new Uint8Array(size);
  }

  /** Payload bytes of the chunk being received. */
  get currentChunkSize(): number {
    return Math.min(DOWNLOAD_CHUNK, this.size - this.received);
  }

  push(byte: number): ChunkResult {
    this.chunk[this.chunkLength++] = byte;
    const n = this.currentChunkSize;
    if (this.chunkLength < n + 1) return "more";
    this.chunkLength = 0;
    let x = 0;
    for (let i = 0; i < n; i++) x ^= this.chunk[i]!;
    if (x !== this.chunk[n]) return "bad-checksum";
    this.payload.set(this.chunk.subarray(0, n), this.received);
    this.received += n;
    return this.received === this.size ? "last-chunk-ok" : "chunk-ok";
  }
}
