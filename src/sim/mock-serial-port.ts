import { type Clock, realClock } from "../shared/clock.ts";
import { seededRandom } from "../shared/random.ts";
import {
  applySerialOptions,
  BYTE_TIME_MS,
  type MockSerialPortOptions,
  type MockSerialPortStats,
  type OpenedOptions,
  type PortInfo,
  RBC_BAUD_RATE,
} from "./mock-serial-options.ts";
import { PortFaults } from "./port-faults.ts";
import { SimTimers } from "./sim-timers.ts";
import type { SimulatedRbc } from "./simulated-rbc.ts";

const DEVICE_LOST = "The device has been lost.";

/**
 * A Web Serial `SerialPort` look-alike wired to a SimulatedRbc, so that the real link and device code can run
 * against the simulator in unit tests, e2e tests and the demo. It mirrors Chrome's behaviour where it matters
 * to a client: open options and their errors, lazily created WHATWG streams, close() refusing locked streams,
 * the "device lost" error and disconnect event on a cable pull. Link timing (115200 baud pacing, adapter
 * latency, a Bluetooth link's jitter and bursts: `bluetoothLinkOptions`) follows the injected clock, and
 * faults can be injected (`faults`).
 */

/**
 * What the mock port needs of the robot behind it: bytes in, and a way to hear what it sends. A SimulatedRbc,
 * or something in front of one (the bootloader of docs/protocol.md §11, `BootloaderRbc`).
 */
export interface SimEndpoint {
  receive(bytes: Uint8Array): void;
  onTransmit(listener: (bytes: Uint8Array) => void): () => void;
}

export class MockSerialPort<S extends SimEndpoint = SimulatedRbc> extends EventTarget implements SerialPort {
  onconnect: ((this: SerialPort, ev: Event) => void) | null = null;
  ondisconnect: ((this: SerialPort, ev: Event) => void) | null = null;
  readonly faults = new PortFaults();
  readonly stats: MockSerialPortStats = {
    bytesFromPc: 0,
    bytesToPc: 0,
    baudMismatchBytes: 0,
    bytesLost: 0,
    opens: 0,
    closes: 0,
  };
  /** Every chunk the PC wrote, in order (copies); empty when the `record` option is off. */
  readonly written: Uint8Array[] = [];
  /** Every chunk handed to the PC's readable, in order; empty when the `record` option is off. */
  readonly delivered: Uint8Array[] = [];
  private readonly record: boolean;
  /** The options of the last successful open(), defaults filled in (kept after close). */
  openOptions: OpenedOptions | undefined;
  /** Set by forget(); FakeSerial no longer lists the port. */
  forgotten = false;

  private readonly clock: Clock;
  private readonly timers: SimTimers;
  /** Bytes on their way to the robot: they still arrive after close() (the OS flushes them). */
  private readonly wireToRobot: SimTimers;
  private readonly pacing: boolean;
  private readonly latencyMs: number;
  private readonly jitterMs: number;
  private readonly burstMs: number;
  private readonly random: () => number;
  private readonly info: PortInfo;
  /** The burst being gathered for delivery at `at` (burst delivery only). */
  private burst: { at: number; chunks: Uint8Array[] } | undefined;
  private opened = false;
  private plugged = true;
  private readableStream: ReadableStream<Uint8Array> | null = null;
  private readController: ReadableStreamDefaultController<Uint8Array> | undefined;
  private writableStream: WritableStream<Uint8Array> | null = null;
  private writeController: WritableStreamDefaultController | undefined;
  /** Bytes that arrived while no readable existed (handed over when one is created). */
  private pendingRx: Uint8Array[] = [];
  private txBusyUntil = 0;
  private rxBusyUntil = 0;
  private lastDeliveryAt = 0;
  private signals: SerialOutputSignals = { dataTerminalReady: true, requestToSend: true, break: false };
  private readonly detach: () => void;

  constructor(
    readonly sim: S,
    options: MockSerialPortOptions = {},
  ) {
    super();
    this.clock = options.clock ?? realClock;
    this.timers = new SimTimers(this.clock);
    this.wireToRobot = new SimTimers(this.clock);
    this.pacing = options.baudPacing ?? false;
    this.latencyMs = options.latencyMs ?? 0;
    this.jitterMs = options.jitterMs ?? 0;
    this.burstMs = options.burstMs ?? 0;
    if (!(this.latencyMs >= 0 && this.jitterMs >= 0 && this.burstMs >= 0)) {
      throw new RangeError("sim: latencyMs, jitterMs or burstMs below 0");
    }
    this.random = seededRandom(options.seed ?? 1);
    this.info = { ...(options.info ?? { usbVendorId: 0x0403, usbProductId: 0x6001 }) };
    this.record = options.record ?? true;
    this.detach = sim.onTransmit((bytes) => this.fromRobot(bytes));
  }

  get connected(): boolean {
    return this.plugged;
  }

  get isOpen(): boolean {
    return this.opened;
  }

  get readable(): ReadableStream<Uint8Array> | null {
    if (this.readableStream) return this.readableStream;
    if (!this.opened) return null;
    this.readableStream = new ReadableStream<Uint8Array>({
      start: (controller) => {
        this.readController = controller;
        for (const chunk of this.pendingRx) controller.enqueue(chunk);
        this.pendingRx = [];
      },
      cancel: () => this.dropReadable(),
    });
    return this.readableStream;
  }

  get writable(): WritableStream<Uint8Array> | null {
    if (this.writableStream) return this.writableStream;
    if (!this.opened) return null;
    this.writableStream = new WritableStream<Uint8Array>(
      {
        start: (controller) => {
          this.writeController = controller;
        },
        write: (chunk) => this.fromPc(chunk),
        close: () => this.dropWritable(),
        abort: () => this.dropWritable(),
      },
      { highWaterMark: 1 },
    );
    return this.writableStream;
  }

  getInfo(): PortInfo {
    return { ...this.info };
  }

  async open(options: SerialOptions): Promise<void> {
    if (this.opened) throw new DOMException("The port is already open.", "InvalidStateError");
    const filled = applySerialOptions(options);
    if (!this.plugged) throw new DOMException("Failed to open serial port.", "NetworkError");
    this.openOptions = filled;
    this.opened = true;
    this.stats.opens++;
    this.pendingRx = [];
    this.txBusyUntil = this.rxBusyUntil = this.lastDeliveryAt = this.clock.now();
  }

  /** Like Chrome: rejects with a TypeError while a stream is locked, InvalidStateError if not open. */
  async close(): Promise<void> {
    if (!this.opened) throw new DOMException("The port is already closed.", "InvalidStateError");
    if (this.readableStream?.locked || this.writableStream?.locked) {
      throw new TypeError("Failed to execute 'close' on 'SerialPort': Cannot cancel a locked stream");
    }
    const readable = this.readableStream;
    const writable = this.writableStream;
    await Promise.all([
      readable?.cancel(),
      writable?.abort(new DOMException("The port is closed.", "InvalidStateError")),
    ]);
    this.shutDown();
    this.stats.closes++;
  }

  async forget(): Promise<void> {
    if (this.opened) {
      this.failStreams();
      this.shutDown();
    }
    this.forgotten = true;
  }

  async getSignals(): Promise<SerialInputSignals> {
    if (!this.opened) throw new DOMException("The port is closed.", "InvalidStateError");
    return { dataCarrierDetect: false, clearToSend: true, ringIndicator: false, dataSetReady: true };
  }

  async setSignals(signals: SerialOutputSignals): Promise<void> {
    if (!this.opened) throw new DOMException("The port is closed.", "InvalidStateError");
    this.signals = { ...this.signals, ...signals };
  }

  /** The output signals last set (DTR/RTS/break), for tests. */
  get outputSignals(): SerialOutputSignals {
    return { ...this.signals };
  }

  /** A cable pull: streams error with NetworkError, the port closes, "disconnect" fires. */
  unplug(): void {
    if (!this.plugged) return;
    this.plugged = false;
    if (this.opened) {
      this.failStreams();
      this.shutDown();
    }
    this.fire("disconnect");
  }

  /** The cable is back: the port can be opened again, "connect" fires. */
  replug(): void {
    if (this.plugged) return;
    this.plugged = true;
    this.fire("connect");
  }

  /** Stops listening to the simulator (the port is unusable afterwards). */
  dispose(): void {
    this.detach();
    this.timers.cancelAll();
    this.wireToRobot.cancelAll();
  }

  override dispatchEvent(event: Event): boolean {
    const result = super.dispatchEvent(event);
    if (event.type === "connect") this.onconnect?.call(this, event);
    if (event.type === "disconnect") this.ondisconnect?.call(this, event);
    return result;
  }

  // ---- PC → RBC ----

  private fromPc(chunk: Uint8Array): void {
    if (!this.opened) throw new DOMException(DEVICE_LOST, "NetworkError");
    let bytes = chunk.slice();
    const limit = this.faults.disconnectAtPcBytes;
    const cut = limit !== undefined && this.stats.bytesFromPc + bytes.length >= limit;
    if (cut) bytes = bytes.slice(0, Math.max(0, limit - this.stats.bytesFromPc));
    this.stats.bytesFromPc += bytes.length;
    if (this.record) this.written.push(bytes);
    this.toRobot(bytes);
    if (cut) {
      this.faults.disconnectAtPcBytes = undefined;
      this.unplug();
      throw new DOMException(DEVICE_LOST, "NetworkError");
    }
  }

  private toRobot(bytes: Uint8Array): void {
    if (bytes.length === 0) return;
    if (this.openOptions?.baudRate !== RBC_BAUD_RATE) {
      this.stats.baudMismatchBytes += bytes.length;
      return;
    }
    if (!this.pacing) {
      this.sim.receive(bytes);
      return;
    }
    const now = this.clock.now();
    this.txBusyUntil = Math.max(now, this.txBusyUntil) + bytes.length * BYTE_TIME_MS;
    // Bytes on the wire still arrive after close() (the OS flushes them), but not after a cable pull.
    this.wireToRobot.after(this.txBusyUntil - now, () => {
      if (this.plugged) this.sim.receive(bytes);
    });
  }

  // ---- RBC → PC ----

  private fromRobot(bytes: Uint8Array): void {
    if (!this.opened || this.openOptions?.baudRate !== RBC_BAUD_RATE) {
      this.stats.bytesLost += bytes.length;
      return;
    }
    const reply = this.faults.apply(bytes);
    if (!reply) return;
    const total = reply.chunks.reduce((n, c) => n + c.length, 0);
    if (total === 0) return;
    const now = this.clock.now();
    let at = now;
    if (this.pacing) {
      this.rxBusyUntil = Math.max(now, this.rxBusyUntil) + total * BYTE_TIME_MS;
      at = this.rxBusyUntil;
    }
    at = Math.max(at + this.linkDelayMs() + reply.delayMs, this.lastDeliveryAt);
    if (this.burstMs > 0) at = Math.ceil(at / this.burstMs) * this.burstMs;
    this.lastDeliveryAt = at;
    if (this.burstMs > 0 && at > now) this.addToBurst(at, reply.chunks);
    else {
      const deliver = () => {
        for (const chunk of reply.chunks) this.toPc(chunk);
      };
      if (at <= now) deliver();
      else this.timers.after(at - now, deliver);
    }
    for (const extra of reply.after) this.deliverAt(at + extra.afterMs, extra.bytes);
  }

  /** This transmission's latency: `latencyMs`, varied by up to `jitterMs` either way (seeded), at least 0. */
  private linkDelayMs(): number {
    if (this.jitterMs === 0) return this.latencyMs;
    return Math.max(0, this.latencyMs + (this.random() * 2 - 1) * this.jitterMs);
  }

  /**
   * Burst delivery: what is due at `at` joins the burst gathered for that moment and is handed over with it in
   * one read. Deliveries never go back in time (`lastDeliveryAt`), so only the latest burst can be joined.
   */
  private addToBurst(at: number, chunks: Uint8Array[]): void {
    if (this.burst?.at === at) {
      this.burst.chunks.push(...chunks);
      return;
    }
    const burst = { at, chunks: [...chunks] };
    this.burst = burst;
    this.timers.after(at - this.clock.now(), () => {
      if (this.burst === burst) this.burst = undefined;
      const total = burst.chunks.reduce((n, c) => n + c.length, 0);
      const whole = new Uint8Array(total);
      let offset = 0;
      for (const chunk of burst.chunks) {
        whole.set(chunk, offset);
        offset += chunk.length;
      }
      if (total > 0) this.toPc(whole);
    });
  }

  /**
   * `bytes` reach the PC `afterMs` from now as if the robot had sent them unasked (a stray acknowledgement,
   * noise): no fault applies to them, and replies already on their way are not held back.
   */
  injectToPc(bytes: ArrayLike<number>, afterMs = 0): void {
    if (!(afterMs >= 0)) throw new RangeError(`sim: afterMs ${afterMs} below 0`);
    this.deliverAt(this.clock.now() + afterMs, Uint8Array.from(bytes));
  }

  private deliverAt(at: number, bytes: Uint8Array): void {
    if (bytes.length === 0) return;
    const now = this.clock.now();
    if (at <= now) this.toPc(bytes);
    else this.timers.after(at - now, () => this.toPc(bytes));
  }

  private toPc(chunk: Uint8Array): void {
    if (!this.opened) {
      this.stats.bytesLost += chunk.length;
      return;
    }
    this.stats.bytesToPc += chunk.length;
    if (this.record) this.delivered.push(chunk);
    if (this.readController) this.readController.enqueue(chunk);
    else this.pendingRx.push(chunk);
  }

  // ---- lifecycle helpers ----

  private dropReadable(): void {
    this.readableStream = null;
    this.readController = undefined;
  }

  private dropWritable(): void {
    this.writableStream = null;
    this.writeController = undefined;
  }

  private failStreams(): void {
    const error = new DOMException(DEVICE_LOST, "NetworkError");
    this.readController?.error(error);
    this.writeController?.error(error);
    this.dropReadable();
    this.dropWritable();
  }

  private shutDown(): void {
    this.opened = false;
    this.burst = undefined;
    this.dropReadable();
    this.dropWritable();
    this.pendingRx = [];
    this.timers.cancelAll();
  }

  private fire(type: "connect" | "disconnect"): void {
    this.dispatchEvent(new Event(type, { bubbles: true }));
  }
}
