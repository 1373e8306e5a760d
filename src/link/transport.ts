/**
 * A byte pipe to the robot. It knows nothing of RBC packets: `device/` frames and parses; implementations
 * (Web Serial, Node serialport, in-memory) only move bytes and report their state.
 */

export type TransportStatus = "closed" | "opening" | "open" | "closing" | "lost";

/**
 * Why a link failed or was lost, as a code the outcome catalogue words (`linkReasonText` in src/i18n):
 * opening an open port; a Web Serial port open elsewhere (perhaps another tab), or not opened for another reason
 * (in use, or the adapter still starting), or opened without a writable stream; a Node port busy or not
 * permitted, failing to open, or closed while opening; writing to a port that is not open, or to a lost link;
 * a failed write; and the losses: the USB cable unplugged (Web Serial's disconnect event), the read loop
 * failing, the serial device unplugged or the port closed unexpectedly (Node), or a port error (`detail`).
 */
export type LinkReason =
  | "already-open"
  | "in-another-tab"
  | "in-use-or-starting"
  | "no-writable"
  | "busy-or-denied"
  | "open-error"
  | "open-cancelled"
  | "not-open"
  | "lost"
  | "write-failed"
  | "write-error"
  | "usb-unplugged"
  | "connection-lost"
  | "device-unplugged"
  | "closed-unexpectedly"
  | "port-error";

/** What a link failure was: its reason, and the port's `path` and the system's `detail` where they are known. */
export interface LinkFacts {
  readonly reason?: LinkReason;
  readonly path?: string;
  readonly detail?: string;
}

/** The technical line of a link failure: `link: port-busy (busy-or-denied, /dev/ttyUSB0: Resource busy)`. */
export function linkLine(code: string, facts: LinkFacts): string {
  const where = facts.path === undefined ? "" : `, ${facts.path}`;
  const detail = facts.detail === undefined ? "" : `: ${facts.detail}`;
  return `link: ${code} (${facts.reason ?? "unknown"}${where}${detail})`;
}

export interface TransportStatusEvent {
  status: TransportStatus;
  /** Why the link was lost or failed to open: a technical line (`linkLine`) for logs. */
  reason?: string;
  /** Why, as facts (`cause.reason` a `LinkReason`), which the outcome catalogue words for a person. */
  cause?: LinkFacts;
  error?: unknown;
}

export interface Transport {
  readonly status: TransportStatus;
  /**
   * True when the link is known to take no wire time: a pseudo terminal (socat's pair to `rbc sim`), where a
   * reply can come sooner than its bytes would take at 115200 baud. Unset for a serial line, which always does.
   */
  readonly unpaced?: boolean;
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
  /** Why, as facts the outcome catalogue words (`errorText`); empty for an error made without them. */
  readonly facts: LinkFacts;
  constructor(
    readonly code: LinkErrorCode,
    message: string,
    options?: { cause?: unknown; facts?: LinkFacts },
  ) {
    super(message, options);
    this.facts = options?.facts ?? {};
  }
}

/** A LinkError with its facts and technical line. */
export function linkError(code: LinkErrorCode, facts: LinkFacts, cause?: unknown): LinkError {
  return new LinkError(code, linkLine(code, facts), cause === undefined ? { facts } : { cause, facts });
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
