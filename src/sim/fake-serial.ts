import type { MockSerialPort } from "./mock-serial-port.ts";

/**
 * A `navigator.serial` look-alike backed by MockSerialPort instances, for e2e tests and the demo robot.
 * requestPort() "shows the chooser": it grants the first known port that matches the filters (or any port
 * without filters), unless the user is set to cancel (or the chooser to hang). Connect and disconnect events of the ports are
 * re-dispatched here, as Chrome bubbles them from the port to `navigator.serial`.
 */
export class FakeSerial extends EventTarget implements Serial {
  onconnect: ((this: Serial, ev: Event) => void) | null = null;
  ondisconnect: ((this: Serial, ev: Event) => void) | null = null;
  /** When true, every requestPort() rejects as if the user closed the chooser. */
  userCancels = false;
  /**
   * When true, requestPort() never settles by itself (a chooser that hangs), until `answerHeldRequests()`:
   * the page must offer a way back.
   */
  chooserHangs = false;
  private readonly held: Array<() => void> = [];
  private readonly ports: MockSerialPort[] = [];
  private readonly granted = new Set<MockSerialPort>();
  private nextError: DOMException | undefined;
  /** requestPort() calls, with their options, for assertions. */
  readonly requests: (SerialPortRequestOptions | undefined)[] = [];

  constructor(ports: readonly MockSerialPort[] = [], options: { granted?: boolean } = {}) {
    super();
    for (const port of ports) this.addPort(port, options);
  }

  /** Makes a port known (as if plugged in); `granted` lists it in getPorts() without a chooser. */
  addPort(port: MockSerialPort, options: { granted?: boolean } = {}): void {
    if (this.ports.includes(port)) return;
    this.ports.push(port);
    if (options.granted) this.granted.add(port);
    port.addEventListener("connect", this.forward);
    port.addEventListener("disconnect", this.forward);
  }

  /** The next requestPort() rejects with `error` (default: the user cancelled the chooser). */
  rejectNextRequest(error: DOMException = notFound()): void {
    this.nextError = error;
  }

  /** Lets every requestPort() held by `chooserHangs` answer now (as the chooser would have). */
  answerHeldRequests(): number {
    const held = this.held.splice(0);
    for (const answer of held) answer();
    return held.length;
  }

  async requestPort(options?: SerialPortRequestOptions): Promise<SerialPort> {
    this.requests.push(options);
    if (this.chooserHangs) await new Promise<void>((resolve) => this.held.push(resolve));
    const error = this.nextError;
    this.nextError = undefined;
    if (error) throw error;
    if (this.userCancels) throw notFound();
    const filters = options?.filters ?? [];
    const port = this.ports.find(
      (p) =>
        p.connected &&
        (filters.length === 0 ||
          filters.some((f) => {
            const info = p.getInfo();
            return (
              (f.usbVendorId === undefined || f.usbVendorId === info.usbVendorId) &&
              (f.usbProductId === undefined || f.usbProductId === info.usbProductId)
            );
          })),
    );
    if (!port) throw notFound();
    port.forgotten = false;
    this.granted.add(port);
    return port;
  }

  /** Ports granted earlier and not forgotten. */
  async getPorts(): Promise<SerialPort[]> {
    return this.ports.filter((p) => this.granted.has(p) && !p.forgotten);
  }

  override dispatchEvent(event: Event): boolean {
    const result = super.dispatchEvent(event);
    if (event.type === "connect") this.onconnect?.call(this, event);
    if (event.type === "disconnect") this.ondisconnect?.call(this, event);
    return result;
  }

  private readonly forward = (event: Event): void => {
    this.dispatchEvent(new Event(event.type, { bubbles: true }));
  };
}

/** What Chrome rejects requestPort() with when the user cancels or no port matches. */
function notFound(): DOMException {
  return new DOMException("No port selected by the user.", "NotFoundError");
}
