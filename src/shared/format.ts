/** Formatting shared by the panel and the command line. Pure functions. */

/** Firmware 2.23 for major 2, minor 0x17 (the minor is shown as two decimal digits). */
export function formatFirmware(firmware: { major: number; minor: number }): string {
  return `${firmware.major}.${String(firmware.minor).padStart(2, "0")}`;
}

/** "2026-11-21" in local time. */
export function formatLocalDate(date: Date): string {
  const two = (n: number) => String(n).padStart(2, "0");
  return `${date.getFullYear()}-${two(date.getMonth() + 1)}-${two(date.getDate())}`;
}
