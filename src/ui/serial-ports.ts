/** Web Serial in the panel: feature detection, the chooser's filters, and names for ports. */

/** USB serial adapters the RBC is used with (by USB vendor id). */
export const USB_SERIAL_VENDORS: readonly { usbVendorId: number; name: string }[] = [
  { usbVendorId: 0x0403, name: "FTDI" },
  { usbVendorId: 0x067b, name: "Prolific" },
  { usbVendorId: 0x10c4, name: "Silicon Labs" },
  { usbVendorId: 0x1a86, name: "WCH (CH340)" },
];

export const PORT_FILTERS: SerialPortFilter[] = USB_SERIAL_VENDORS.map(({ usbVendorId }) => ({
  usbVendorId,
}));

/** `navigator.serial` when this browser has Web Serial (feature detection, not the user agent). */
export function webSerial(): Serial | undefined {
  if (typeof navigator === "undefined" || !("serial" in navigator)) return undefined;
  const serial: unknown = navigator.serial;
  return serial && typeof serial === "object" ? (serial as Serial) : undefined;
}

function hex4(n: number): string {
  return n.toString(16).toUpperCase().padStart(4, "0");
}

/** "FTDI USB serial adapter (0403:6001)", or a description of a port without USB ids. */
export function describePort(info: SerialPortInfo): string {
  if (info.usbVendorId === undefined) return "Serial port (Bluetooth or built in)";
  const vendor = USB_SERIAL_VENDORS.find((v) => v.usbVendorId === info.usbVendorId)?.name;
  const ids = `${hex4(info.usbVendorId)}:${info.usbProductId === undefined ? "????" : hex4(info.usbProductId)}`;
  return vendor ? `${vendor} USB serial adapter (${ids})` : `USB serial device (${ids})`;
}

/** Opens the browser's port chooser. Must be called straight from a click (user activation). */
export function choosePort(serial: Serial, showAll: boolean): Promise<SerialPort> {
  return serial.requestPort(showAll ? {} : { filters: PORT_FILTERS });
}

/** Ports this site was granted earlier, with their descriptions. */
export async function grantedPorts(serial: Serial): Promise<{ port: SerialPort; label: string }[]> {
  const ports = await serial.getPorts();
  return ports.map((port) => ({ port, label: describePort(port.getInfo()) }));
}

/** Revokes the site's permission for a port, where the browser supports it (Chrome 103+). */
export async function forgetPort(port: SerialPort): Promise<boolean> {
  const forget = (port as { forget?: () => Promise<void> }).forget;
  if (typeof forget !== "function") return false;
  await forget.call(port);
  return true;
}

export function domErrorName(e: unknown): string {
  return e instanceof Error || (typeof DOMException !== "undefined" && e instanceof DOMException)
    ? e.name
    : "";
}
