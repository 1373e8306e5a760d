import type { LinkKind } from "../device/round-trip.ts";
import type { Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import { uiMessages } from "./messages.ts";

/** Web Serial in the panel: feature detection, the chooser's filters, and names for ports. */

/**
 * The Bluetooth Serial Port Profile's service class (RFCOMM). Chrome 117+ lists a paired Bluetooth module's
 * serial port in the chooser when a filter names it, and reports it in `getInfo().bluetoothServiceClassId`.
 */
export const SERIAL_PORT_PROFILE = "00001101-0000-1000-8000-00805f9b34fb";

/** `SerialPortInfo` with the Bluetooth field of Chrome 117+ (`@types/w3c-web-serial` 1.0.8 lacks it). */
export interface PortInfo extends SerialPortInfo {
  bluetoothServiceClassId?: number | string;
}

/** A chooser filter: USB ids, or (Chrome 117+) a Bluetooth service class. */
export type PortFilter = SerialPortFilter & { bluetoothServiceClassId?: number | string };

/** The chooser's options with the Bluetooth fields of Chrome 117+. */
export interface PortRequestOptions {
  filters?: PortFilter[];
  allowedBluetoothServiceClassIds?: (number | string)[];
}

/** `navigator.serial` as the panel calls it: `requestPort` takes the Bluetooth fields too. */
type BluetoothAwareSerial = Omit<Serial, "requestPort"> & {
  requestPort(options?: PortRequestOptions): Promise<SerialPort>;
};

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

/** The Bluetooth filter the chooser gets beside the USB ones: a paired RBC Bluetooth module (SPP). */
export const BLUETOOTH_FILTER: PortFilter = { bluetoothServiceClassId: SERIAL_PORT_PROFILE };

/**
 * The chooser's options: the USB adapters and paired Bluetooth modules (Serial Port Profile), or with
 * `showAll` every serial port (Chrome lists SPP ports then as well).
 */
export function chooserOptions(showAll: boolean): PortRequestOptions {
  return showAll
    ? { allowedBluetoothServiceClassIds: [SERIAL_PORT_PROFILE] }
    : {
        filters: [...PORT_FILTERS, BLUETOOTH_FILTER],
        allowedBluetoothServiceClassIds: [SERIAL_PORT_PROFILE],
      };
}

/** What carries a port's bytes, from what the browser says of it (it picks the client's first timeouts). */
export function linkKindOf(info: PortInfo): LinkKind {
  if (info.bluetoothServiceClassId !== undefined) return "bluetooth";
  return info.usbVendorId === undefined ? "unknown" : "wired";
}

/**
 * "FTDI USB serial adapter (0403:6001)", "Bluetooth serial port", or a description of a port without ids, in
 * the panel's language (English when not given).
 */
export function describePort(info: PortInfo, locale: Locale = "en"): string {
  const t = translator(uiMessages, locale);
  if (info.bluetoothServiceClassId !== undefined) return t("port.bluetooth");
  if (info.usbVendorId === undefined) return t("port.builtIn");
  const vendor = USB_SERIAL_VENDORS.find((v) => v.usbVendorId === info.usbVendorId)?.name;
  const ids = `${hex4(info.usbVendorId)}:${info.usbProductId === undefined ? "????" : hex4(info.usbProductId)}`;
  return vendor ? t("port.usbAdapter", { vendor, ids }) : t("port.usbDevice", { ids });
}

/**
 * Opens the browser's port chooser. Must be called straight from a click (user activation). A browser before
 * Chrome 117 does not know the Bluetooth filter: to it the filter is empty, and it refuses the options with a
 * TypeError before showing anything; the chooser is then opened again with the USB filters alone (still within
 * the click's activation, which lasts seconds).
 */
export function choosePort(serial: Serial, showAll: boolean): Promise<SerialPort> {
  const chooser = serial as BluetoothAwareSerial;
  const options = chooserOptions(showAll);
  let first: Promise<SerialPort>;
  try {
    first = chooser.requestPort(options);
  } catch (e) {
    first = Promise.reject(e);
  }
  if (showAll) return first;
  return first.catch((e: unknown) => {
    if (!(e instanceof TypeError)) throw e;
    return chooser.requestPort({ filters: PORT_FILTERS });
  });
}

/** Ports this site was granted earlier, with their descriptions in English (views name them with `describePort`). */
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
