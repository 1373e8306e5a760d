/**
 * Transport over a serial device in Node, using the `serialport` package. Loaded only by the command line
 * (`bin/`); the web app never imports it.
 */
import { SerialPort } from "serialport";
import { LinkError, type Transport, type TransportStatus, type TransportStatusEvent } from "./transport.ts";

export interface NodeSerialTransportOptions {
  baudRate?: number;
}

export class NodeSerialTransport implements Transport {
  private _status: TransportStatus = "closed";
  private port: SerialPort | undefined;
  private readonly dataListeners = new Set<(bytes: Uint8Array) => void>();
  private readonly statusListeners = new Set<(event: TransportStatusEvent) => void>();

  constructor(
    readonly path: string,
    private readonly options: NodeSerialTransportOptions = {},
  ) {}

  /** Serial ports the operating system knows of. */
  static async list(): Promise<
    Array<{ path: string; manufacturer?: string; vendorId?: string; productId?: string }>
  > {
    return (await SerialPort.list()).map((p) => ({
      path: p.path,
      manufacturer: p.manufacturer,
      vendorId: p.vendorId,
      productId: p.productId,
    }));
  }

  get status(): TransportStatus {
    return this._status;
  }

  open(): Promise<void> {
    if (this._status === "open" || this._status === "opening") {
      return Promise.reject(new LinkError("open-failed", "The port is already open."));
    }
    this.setStatus({ status: "opening" });
    const port = new SerialPort({
      path: this.path,
      baudRate: this.options.baudRate ?? 115200,
      dataBits: 8,
      stopBits: 1,
      parity: "none",
      rtscts: false,
      autoOpen: false,
    });
    return new Promise<void>((resolve, reject) => {
      port.open((err) => {
        if (err) {
          const busy = /lock|busy|access denied|permission/i.test(err.message);
          const reason = busy
            ? `${this.path} is busy or not permitted (${err.message}). Close other programs using it; on Linux add yourself to the dialout group.`
            : `${this.path} could not be opened: ${err.message}`;
          this.setStatus({ status: "closed", reason, error: err });
          reject(new LinkError(busy ? "port-busy" : "open-failed", reason, { cause: err }));
          return;
        }
        this.port = port;
        port.on("data", (chunk: Buffer) => {
          const bytes = new Uint8Array(chunk.buffer, chunk.byteOffset, chunk.byteLength);
          for (const l of this.dataListeners) l(bytes);
        });
        port.on("close", (closeErr: (Error & { disconnected?: boolean }) | null) => {
          if (this._status === "open") {
            this.port = undefined;
            this.setStatus({
              status: "lost",
              reason: closeErr?.disconnected
                ? "The serial device was unplugged."
                : "The serial port was closed unexpectedly.",
              error: closeErr,
            });
          }
        });
        port.on("error", (e: Error) => {
          if (this._status === "open") this.setStatus({ status: "lost", reason: e.message, error: e });
        });
        this.setStatus({ status: "open" });
        resolve();
      });
    });
  }

  write(bytes: Uint8Array): Promise<void> {
    const port = this.port;
    if (this._status !== "open" || !port) {
      return Promise.reject(
        new LinkError(this._status === "lost" ? "disconnected" : "not-open", "The serial port is not open."),
      );
    }
    return new Promise((resolve, reject) => {
      port.write(Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength), (err) => {
        if (err)
          return reject(new LinkError("write-failed", `Writing to ${this.path} failed: ${err.message}`));
        port.drain((drainErr) =>
          drainErr
            ? reject(new LinkError("write-failed", `Writing to ${this.path} failed: ${drainErr.message}`))
            : resolve(),
        );
      });
    });
  }

  onData(listener: (bytes: Uint8Array) => void): () => void {
    this.dataListeners.add(listener);
    return () => this.dataListeners.delete(listener);
  }

  onStatus(listener: (event: TransportStatusEvent) => void): () => void {
    this.statusListeners.add(listener);
    return () => this.statusListeners.delete(listener);
  }

  async close(): Promise<void> {
    if (this._status === "closed" || this._status === "closing") return;
    this.setStatus({ status: "closing" });
    const port = this.port;
    this.port = undefined;
    if (port?.isOpen) await new Promise<void>((resolve) => port.close(() => resolve()));
    this.setStatus({ status: "closed" });
  }

  private setStatus(event: TransportStatusEvent): void {
    this._status = event.status;
    for (const l of this.statusListeners) l(event);
  }
}
