/**
 * Transport over a serial device in Node, using the `serialport` package. Loaded only by the command line
 * (`src/cli/`, started by `bin/rbc.mjs`); the web app never imports it (`src/link/index.ts` does not export it).
 */
import { realpathSync } from "node:fs";
import { SerialPort } from "serialport";
import { type LinkFacts, linkError, linkLine, type Transport, TransportBase } from "./transport.ts";

export interface NodeSerialTransportOptions {
  baudRate?: number;
}

export interface SerialPortListing {
  path: string;
  manufacturer?: string;
  vendorId?: string;
  productId?: string;
}

type CloseError = (Error & { disconnected?: boolean }) | null;

/**
 * Whether `path` is (or links to) a pseudo terminal rather than a serial line: Linux's /dev/pts/N, macOS's
 * /dev/ttysNNN (socat's `pty` ends, and the links its `link=` option makes to them).
 */
export function isPseudoTerminal(path: string): boolean {
  let real = path;
  try {
    real = realpathSync(path);
  } catch {
    // A path that cannot be resolved is judged as written.
  }
  return /^\/dev\/pts\/\d+$/.test(real) || /^\/dev\/ttys\d+$/.test(real);
}

/**
 * `serialport` options for the RBC link (docs/protocol.md §1): 115200 8N1 and no flow control of either kind. With
 * `rtscts` or `xon`/`xoff` left on by an earlier program, a device would hold back or swallow bytes (0x11 and
 * 0x13 are XON/XOFF).
 */
export function rbcSerialPortOptions(path: string, baudRate = 115200) {
  return {
    path,
    baudRate,
    dataBits: 8,
    stopBits: 1,
    parity: "none",
    rtscts: false,
    xon: false,
    xoff: false,
    autoOpen: false,
  } as const;
}

export class NodeSerialTransport extends TransportBase implements Transport {
  private port: SerialPort | undefined;
  /** A pseudo terminal: bytes cross at once, with no wire time (`Transport.unpaced`); known once open. */
  unpaced = false;

  constructor(
    readonly path: string,
    private readonly options: NodeSerialTransportOptions = {},
  ) {
    super();
  }

  /** Serial ports the operating system knows of. */
  static async list(): Promise<SerialPortListing[]> {
    return (await SerialPort.list()).map((p) => ({
      path: p.path,
      manufacturer: p.manufacturer,
      vendorId: p.vendorId,
      productId: p.productId,
    }));
  }

  /** Opens at 115200 8N1, no flow control, with an exclusive lock (a second program gets "port-busy"). */
  open(): Promise<void> {
    if (this._status === "open" || this._status === "opening") {
      return Promise.reject(linkError("open-failed", { reason: "already-open" }));
    }
    this.setStatus({ status: "opening" });
    const port = new SerialPort(rbcSerialPortOptions(this.path, this.options.baudRate));
    return new Promise<void>((resolve, reject) => {
      port.open((err) => {
        if (err) {
          const busy = /lock|busy|access denied|permission/i.test(err.message);
          const code = busy ? "port-busy" : "open-failed";
          const cause: LinkFacts = {
            reason: busy ? "busy-or-denied" : "open-error",
            path: this.path,
            detail: err.message,
          };
          this.setStatus({ status: "closed", reason: linkLine(code, cause), cause, error: err });
          reject(linkError(code, cause, err));
          return;
        }
        if (this._status !== "opening") {
          // close() was called while opening: release the port again.
          port.close(() => {});
          reject(linkError("open-failed", { reason: "open-cancelled", path: this.path }));
          return;
        }
        this.port = port;
        this.unpaced = isPseudoTerminal(this.path);
        port.on("data", (chunk: Buffer) => {
          if (this.port !== port) return;
          // A copy: the chunk is a view into serialport's 64 KiB read pool, which listeners must not pin.
          const bytes = Uint8Array.from(chunk);
          this.deliver(bytes);
        });
        port.on("close", (closeErr: CloseError) => {
          if (this.port !== port || this._status !== "open") return;
          this.port = undefined;
          const cause: LinkFacts = {
            reason: closeErr?.disconnected ? "device-unplugged" : "closed-unexpectedly",
          };
          this.setStatus({ status: "lost", reason: linkLine("disconnected", cause), cause, error: closeErr });
        });
        port.on("error", (e: Error) => {
          if (this.port === port && this._status === "open") {
            const cause: LinkFacts = { reason: "port-error", detail: e.message };
            this.setStatus({ status: "lost", reason: linkLine("disconnected", cause), cause, error: e });
          }
        });
        this.setStatus({ status: "open" });
        resolve();
      });
    });
  }

  /**
   * Resolves when the operating system has accepted the bytes (as Web Serial's writer does), not when they
   * have left the wire: `drain` (tcdrain) would add a thread-pool round trip per packet, and it never returns
   * on a pseudo terminal whose other end stops reading, which would hang the unguarded handshake write.
   */
  write(bytes: Uint8Array): Promise<void> {
    const port = this.port;
    if (this._status !== "open" || !port) {
      return Promise.reject(
        this._status === "lost"
          ? linkError("disconnected", { reason: "lost" })
          : linkError("not-open", { reason: "not-open" }),
      );
    }
    return new Promise((resolve, reject) => {
      port.write(Buffer.from(bytes), (err) =>
        err
          ? reject(
              linkError("write-failed", { reason: "write-error", path: this.path, detail: err.message }, err),
            )
          : resolve(),
      );
    });
  }

  async close(): Promise<void> {
    if (this._status === "closed" || this._status === "closing") return;
    this.setStatus({ status: "closing" });
    const port = this.port;
    this.port = undefined;
    if (port?.isOpen) await new Promise<void>((resolve) => port.close(() => resolve()));
    this.setStatus({ status: "closed" });
  }
}
