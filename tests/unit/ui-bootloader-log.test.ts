import { describe, expect, it } from "vitest";
import type { LogEntry } from "../../src/device/index.ts";
import {
  BOOTLOADER_ENTRY_NAME,
  bootloaderNote,
  duringFirmwareUpdate,
} from "../../src/ui/features/log/bootloader-bytes.ts";

// docs/protocol.md §11: XOFF 13 and XON 11 are flow control, 7E ("~") a line done: the bootloader's normal
// dialogue, which the packet parser discards (none is a header byte).
const discard = (bytes: number[]): LogEntry => ({
  time: 0,
  direction: "in",
  kind: "discard",
  name: "garbage",
  bytes: Uint8Array.from(bytes),
  note: "discarded: garbage",
});

describe("the bootloader's bytes in the packet log during a firmware update", () => {
  it("names 13 11 7E as flow control and status, not as discarded bytes", () => {
    const entry = duringFirmwareUpdate(discard([0x13, 0x11, 0x7e]));
    expect(entry.kind).toBe("raw");
    expect(entry.name).toBe(BOOTLOADER_ENTRY_NAME);
    expect(entry.note).toBe("XOFF (pause) ×1, XON (resume) ×1, ~ line done ×1");
    expect([...entry.bytes]).toEqual([0x13, 0x11, 0x7e]);
  });

  it("counts repeats, and knows every status character of §11", () => {
    expect(bootloaderNote(Uint8Array.of(0x7e, 0x7e, 0x5e, 0x3f, 0x2d, 0x25, 0x40, 0x23))).toBe(
      "~ line done ×2, ^ bootloader active ×1, ? ready ×1, - line checksum error ×1, % flash page error ×1, @ file complete ×1, # file complete with errors ×1",
    );
  });

  it("keeps a run with any other byte as discarded, and leaves packets alone", () => {
    const stray = discard([0x13, 0x41, 0x7e]);
    expect(duringFirmwareUpdate(stray)).toBe(stray);
    const packet: LogEntry = {
      time: 0,
      direction: "in",
      kind: "packet",
      name: "x",
      bytes: Uint8Array.of(0x7e),
    };
    expect(duringFirmwareUpdate(packet)).toBe(packet);
    expect(bootloaderNote(new Uint8Array(0))).toBeUndefined();
  });
});
