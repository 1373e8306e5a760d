import { type PortInfo, SPP_SERVICE_CLASS_ID } from "./mock-serial-options.ts";
import type { MockSerialPort, SimEndpoint } from "./mock-serial-port.ts";

/** A chooser filter with the Bluetooth field Chrome 117+ takes (`@types/w3c-web-serial` 1.0.8 lacks it). */
type PortFilter = SerialPortFilter & { bluetoothServiceClassId?: number | string };
/** The chooser's options with the Bluetooth fields of Chrome 117+. */
type RequestOptions = Omit<SerialPortRequestOptions, "filters"> & {
  filters?: PortFilter[];
  allowedBluetoothServiceClassIds?: (number | string)[];
};

/** The Bluetooth base UUID's tail: a 16-bit service class id `n` stands for 0000nnnn-0000-1000-8000-00805f9b34fb. */
const BASE_UUID_TAIL = "-0000-1000-8000-00805f9b34fb";

/** A Bluetooth service class id as a lower-case UUID (a number is a 16- or 32-bit alias of the base UUID). */
function serviceUuid(id: number | string): string {
  if (typeof id === "number") return `${id.toString(16).padStart(8, "0")}${BASE_UUID_TAIL}`;
  return id.toLowerCase();
}

/**
 * A `navigator.serial` look-alike backed by MockSerialPort instances, for e2e tests and the demo robot.
 * requestPort() "shows the chooser": it grants the first known port that matches the filters (or any port
 * without filters), unless the user is set to cancel (or the chooser to hang). Connect and disconnect events of the ports are
 * re-dispatched here, as Chrome bubbles them from the port to `navigator.serial`.
 * Filters follow Chrome 117+: a USB filter names a vendor (and maybe a product), a Bluetooth filter a service
 * class (`bluetoothServiceClassId`), never both; a Bluetooth port outside the Serial Port Profile is listed
 * only when `allowedBluetoothServiceClassIds` names its class. With `bluetoothSupported` off it is an older
 * browser: the Bluetooth fields are unknown to it, so a filter with only those is empty and refused (TypeError).
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
  /** False: a browser before Chrome 117, which knows no Bluetooth fields in the chooser's options. */
  bluetoothSupported = true;
  private readonly held: Array<() => void> = [];
  private readonly ports: MockSerialPort<SimEndpoint>[] = [];
  private readonly granted = new Set<MockSerialPort<SimEndpoint>>();
  private nextError: DOMException | undefined;
  /** requestPort() calls, with their options, for assertions. */
  readonly requests: (RequestOptions | undefined)[] = [];

  constructor(ports: readonly MockSerialPort<SimEndpoint>[] = [], options: { granted?: boolean } = {}) {
    super();
    for (const port of ports) this.addPort(port, options);
  }

  /** Makes a port known (as if plugged in); `granted` lists it in getPorts() without a chooser. */
  addPort(port: MockSerialPort<SimEndpoint>, options: { granted?: boolean } = {}): void {
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

  async requestPort(options?: RequestOptions): Promise<SerialPort> {
    this.requests.push(options);
    const filters = (options?.filters ?? []).map((f) => this.known(f));
    for (const f of filters) checkFilter(f);
    const allowed = this.bluetoothSupported
      ? (options?.allowedBluetoothServiceClassIds ?? []).map(serviceUuid)
      : [];
    if (this.chooserHangs) await new Promise<void>((resolve) => this.held.push(resolve));
    const error = this.nextError;
    this.nextError = undefined;
    if (error) throw error;
    if (this.userCancels) throw notFound();
    const port = this.ports.find((p) => {
      if (!p.connected) return false;
      const info = p.getInfo();
      const service = this.bluetoothSupported ? info.bluetoothServiceClassId : undefined;
      // Bluetooth ports outside the Serial Port Profile are listed only when the page allows their class.
      if (service !== undefined) {
        const uuid = serviceUuid(service);
        if (uuid !== SPP_SERVICE_CLASS_ID && !allowed.includes(uuid)) return false;
      }
      return filters.length === 0 || filters.some((f) => matches(f, info, service));
    });
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

  /** The filter as this browser reads it: an older one drops the Bluetooth field it does not know. */
  private known(filter: PortFilter): PortFilter {
    if (this.bluetoothSupported) return filter;
    const { bluetoothServiceClassId: _unknown, ...usb } = filter;
    return usb;
  }

  private readonly forward = (event: Event): void => {
    this.dispatchEvent(new Event(event.type, { bubbles: true }));
  };
}

/** Chrome's checks of a filter (TypeError, before the chooser opens). */
function checkFilter(f: PortFilter): void {
  if (f.bluetoothServiceClassId !== undefined) {
    if (f.usbVendorId !== undefined || f.usbProductId !== undefined) {
      throw new TypeError(
        "Failed to execute 'requestPort' on 'Serial': A filter cannot specify both bluetoothServiceClassId and usbVendorId or usbProductId.",
      );
    }
    return;
  }
  if (f.usbVendorId === undefined) {
    throw new TypeError(
      f.usbProductId === undefined
        ? "Failed to execute 'requestPort' on 'Serial': A filter must provide a property to filter by."
        : "Failed to execute 'requestPort' on 'Serial': A filter containing a usbProductId must also specify a usbVendorId.",
    );
  }
}

function matches(f: PortFilter, info: PortInfo, service: number | string | undefined): boolean {
  if (f.bluetoothServiceClassId !== undefined) {
    return service !== undefined && serviceUuid(service) === serviceUuid(f.bluetoothServiceClassId);
  }
  return (
    f.usbVendorId === info.usbVendorId &&
    (f.usbProductId === undefined || f.usbProductId === info.usbProductId)
  );
}

/** What Chrome rejects requestPort() with when the user cancels or no port matches. */
function notFound(): DOMException {
  return new DOMException("No port selected by the user.", "NotFoundError");
}
