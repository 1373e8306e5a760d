/**
 * A byte pipe to the robot. It knows nothing of RBC packets: `device/` frames and parses; implementations
 * (Web Serial, Node serialport, in-memory) only move bytes and report their state.
 */

export type TransportStatus = "closed" | "opening" | "open" | "closing" | "lost";

export interface TransportStatusEvent {
  status: TransportStatus;
  /** Why the link was lost or failed to open, for a person. */
  reason?: string;
  error?: unknown;
}

export interface Transport {
  readonly status: TransportStatus;
  /** Opens the link at 115200 8N1. Rejects with a LinkError if it cannot. */
  open(): Promise<void>;
  /** Sends bytes; resolves when they were handed to the port. Rejects with a LinkError if the link is down. */
  write(bytes: Uint8Array): Promise<void>;
  /** Subscribes to received bytes, in arrival order and chunking. Returns the unsubscribe function. */
  onData(listener: (bytes: Uint8Array) => void): () => void;
  /** Subscribes to status changes. Returns the unsubscribe function. */
  onStatus(listener: (event: TransportStatusEvent) => void): () => void;
  /** Closes the link and releases the port. Safe to call at any time, any number of times. */
  close(): Promise<void>;
}

/** The serial settings of the RBC link (docs/protocol.md §1). */
export const RBC_SERIAL_OPTIONS = {
  baudRate: 115200,
  dataBits: 8,
  stopBits: 1,
  parity: "none",
  flowControl: "none",
  bufferSize: 4096,
} as const satisfies SerialOptions;

export type LinkErrorCode = "open-failed" | "port-busy" | "not-open" | "disconnected" | "write-failed";

export class LinkError extends Error {
  override name = "LinkError";
  constructor(
    readonly code: LinkErrorCode,
    message: string,
    options?: { cause?: unknown },
  ) {
    super(message, options);
  }
}

/**
 * What every Transport shares: its status and the two listener sets. Implementations call `deliver` with
 * received bytes and `setStatus` on every change.
 */
export abstract class TransportBase {
  protected _status: TransportStatus = "closed";
  private readonly dataListeners = new Set<(bytes: Uint8Array) => void>();
  private readonly statusListeners = new Set<(event: TransportStatusEvent) => void>();

  get status(): TransportStatus {
    return this._status;
  }

  onData(listener: (bytes: Uint8Array) => void): () => void {
    this.dataListeners.add(listener);
    return () => this.dataListeners.delete(listener);
  }

  onStatus(listener: (event: TransportStatusEvent) => void): () => void {
    this.statusListeners.add(listener);
    return () => this.statusListeners.delete(listener);
  }

  protected deliver(bytes: Uint8Array): void {
    for (const l of this.dataListeners) l(bytes);
  }

  protected setStatus(event: TransportStatusEvent): void {
    this._status = event.status;
    for (const l of this.statusListeners) l(event);
  }
}
