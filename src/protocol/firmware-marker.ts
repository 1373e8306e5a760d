import { HEX_RECORD, type IntelHexImage } from "./intel-hex.ts";

/**
 * The version mark of this project's demo and test firmware files (docs/firmware-update.md): the ASCII text
 * `RBCFW M.mm` somewhere in the image. No way of stating a version is known for the RBC's own firmware
 * (docs/protocol.md §3.1: 0x12 is hard-coded in the firmware's code), so a real firmware file carries none; the
 * simulated bootloader reads the mark after an update to know which version to report. A file with the mark is
 * therefore one of those demo files, which a real robot cannot run: the panel and `rbc flash` flag it before
 * anything is written to a real robot (issue 21 item 5).
 */

const MARKER = /RBCFW (\d{1,3})\.(\d{2})/;

/** The version a firmware image declares with the `RBCFW M.mm` mark, or undefined. */
export function firmwareMarker(image: Uint8Array): { major: number; minor: number } | undefined {
  let text = "";
  for (const b of image) text += String.fromCharCode(b);
  const m = MARKER.exec(text);
  if (!m) return undefined;
  const major = Number(m[1]);
  return major <= 255 ? { major, minor: Number(m[2]) } : undefined;
}

/** The version a HEX file declares with the mark (its data records laid out at their addresses), if any. */
export function declaredVersion(image: IntelHexImage): { major: number; minor: number } | undefined {
  const { firstAddress, lastAddress } = image.summary;
  const bytes = new Uint8Array(lastAddress - firstAddress + 1);
  for (const record of image.records) {
    if (record.type === HEX_RECORD.data) bytes.set(record.data, record.address - firstAddress);
  }
  return firmwareMarker(bytes);
}
