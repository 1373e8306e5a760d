import { HEX_RECORD, type IntelHexImage } from "../../../protocol/intel-hex.ts";
import { firmwareMarker } from "../../../sim/sim-bootloader.ts";

/**
 * The firmware version a file states, if any. No way of stating a version is known for the RBC's own firmware
 * (docs/protocol.md §3.1: 0x12 is hard-coded in the firmware's code), so a real firmware file states none. The
 * files this project makes for the demo robot and its tests state theirs with the ASCII mark `RBCFW M.mm`
 * (docs/firmware-update.md), which the simulated bootloader reads after an update: the same function reads it
 * here, so a file that carries the mark is one of those demo files, and is flagged before it is written to a
 * real robot (issue 21 item 5).
 */
export function declaredVersion(image: IntelHexImage): { major: number; minor: number } | undefined {
  const { firstAddress, lastAddress } = image.summary;
  const bytes = new Uint8Array(lastAddress - firstAddress + 1);
  for (const record of image.records) {
    if (record.type === HEX_RECORD.data) bytes.set(record.data, record.address - firstAddress);
  }
  return firmwareMarker(bytes);
}
