import { type Clock, realClock } from "../shared/clock.ts";
import {
  type LinkFacts,
  linkError,
  linkLine,
  RBC_SERIAL_OPTIONS,
  type Transport,
  TransportBase,
} from "./transport.ts";

/** The parts of a Web Serial `SerialPort` the transport uses (the real one, or `MockSerialPort`). */
export type SerialPortLike = Pick<SerialPort, "open" | "close" | "readable" | "writable" | "getInfo"> &
  Pick<EventTarget, "addEventListener" | "removeEventListener">;

export interface WebSerialTransportOptions {
  clock?: Clock;
  /** Tries to open a port that is still enumerating or briefly busy (default 4). */
  openAttempts?: number;
  /** Delay between open attempts, doubled each time (default 250 ms). */
  openRetryDelayMs?: number;
}

/** Read errors after which the port's readable is replaced and reading goes on (Web Serial spec). */
const RECOVERABLE_READ_ERRORS = new Set(["BufferOverrunError", "BreakError", "FramingError", "ParityError"]);

function errorName(e: unknown): string {
  return e instanceof Error || (typeof DOMException !== "undefined" && e instanceof DOMException)
    ? e.name
    : "";
}

/**
 * Transport over a Web Serial port. Owns the whole lifecycle: open with the RBC's settings (retrying a port
 * that is still enumerating), one long-lived read loop, one writer, the close order (cancel reader → release
 * locks → close port), and disconnect detection (the port's `disconnect` event or a fatal read error).
 */
export class WebSerialTransport extends TransportBase implements Transport {
  private reader: ReadableStreamDefaultReader<Uint8Array> | undefined;
  private writer: WritableStreamDefaultWriter<Uint8Array> | undefined;
  private readLoop: Promise<void> | undefined;
  private readonly clock: Clock;
  private readonly openAttempts: number;
  private readonly openRetryDelayMs: number;
  private readonly onDisconnect = () => this.lost({ reason: "usb-unplugged" });

  constructor(
    readonly port: SerialPortLike,
    options: WebSerialTransportOptions = {},
  ) {
    super();
    this.clock = options.clock ?? realClock;
    this.openAttempts = options.openAttempts ?? 4;
    this.openRetryDelayMs = options.openRetryDelayMs ?? 250;
  }

  async open(): Promise<void> {
    if (this._status === "open" || this._status === "opening") {
      throw linkError("open-failed", { reason: "already-open" });
    }
    this.setStatus({ status: "opening" });
    let lastError: unknown;
    for (let attempt = 1; attempt <= this.openAttempts; attempt++) {
      try {
        await this.port.open(RBC_SERIAL_OPTIONS);
        lastError = undefined;
        break;
      } catch (e) {
        lastError = e;
        // InvalidStateError: already open (by this page). Anything else may be a port still enumerating.
        if (errorName(e) === "InvalidStateError" || attempt === this.openAttempts) break;
        await new Promise<void>((r) => this.clock.setTimeout(r, this.openRetryDelayMs * 2 ** (attempt - 1)));
      }
    }
    if (lastError !== undefined) {
      const busy = errorName(lastError) === "InvalidStateError";
      const code = busy ? "port-busy" : "open-failed";
      const cause: LinkFacts = { reason: busy ? "in-another-tab" : "in-use-or-starting" };
      this.setStatus({ status: "closed", reason: linkLine(code, cause), cause, error: lastError });
      throw linkError(code, cause, lastError);
    }
    this.port.addEventListener("disconnect", this.onDisconnect);
    const writable = this.port.writable;
    if (!writable) {
      await this.close();
      throw linkError("open-failed", { reason: "no-writable" });
    }
    this.writer = writable.getWriter();
    this.setStatus({ status: "open" });
    this.readLoop = this.runReadLoop();
  }

  async write(bytes: Uint8Array): Promise<void> {
    if (this._status !== "open" || !this.writer) {
      const lost = this._status === "lost";
      throw linkError(lost ? "disconnected" : "not-open", { reason: lost ? "lost" : "not-open" });
    }
    try {
      await this.writer.write(bytes);
    } catch (e) {
      const cause: LinkFacts = { reason: "write-failed" };
      this.lost(cause, e);
      throw linkError("disconnected", cause, e);
    }
  }

  async close(): Promise<void> {
    if (this._status === "closed" || this._status === "closing") return;
    const wasLost = this._status === "lost";
    this.setStatus({ status: "closing" });
    if (!wasLost) await this.shutDown();
    else await this.cleanup;
    this.setStatus({ status: "closed" });
  }

  /** Set while a lost link is being released, so close() can wait for it. */
  private cleanup: Promise<void> | undefined;

  private async shutDown(): Promise<void> {
    this.port.removeEventListener("disconnect", this.onDisconnect);
    await this.releaseStreams();
    try {
      await this.port.close();
    } catch {
      // A lost port may refuse to close; it is gone either way.
    }
  }

  private async runReadLoop(): Promise<void> {
    while (this._status === "open" && this.port.readable) {
      const reader = this.port.readable.getReader();
      this.reader = reader;
      try {
        for (;;) {
          const { value, done } = await reader.read();
          if (done) break;
          if (value && value.length > 0) this.deliver(value);
        }
      } catch (e) {
        if (!RECOVERABLE_READ_ERRORS.has(errorName(e))) {
          this.reader = undefined;
          try {
            reader.releaseLock();
          } catch {}
          if (this._status === "open") this.lost({ reason: "connection-lost" }, e);
          return;
        }
      } finally {
        if (this.reader === reader) {
          this.reader = undefined;
          try {
            reader.releaseLock();
          } catch {}
        }
      }
    }
  }

  /** Cancel reader → wait for the loop → release the writer. */
  private async releaseStreams(): Promise<void> {
    const reader = this.reader;
    if (reader) {
      try {
        await reader.cancel();
      } catch {}
    }
    await this.readLoop?.catch(() => {});
    this.readLoop = undefined;
    const writer = this.writer;
    this.writer = undefined;
    if (writer) {
      try {
        writer.releaseLock();
      } catch {}
    }
  }

  private lost(cause: LinkFacts, error?: unknown): void {
    if (this._status !== "open") return;
    this.setStatus({ status: "lost", reason: linkLine("disconnected", cause), cause, error });
    // Free the port so that a later connect can open it again; status stays "lost" until close().
    this.cleanup = this.shutDown();
  }
}
