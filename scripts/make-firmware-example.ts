/**
 * The project's example firmware file for the demo robot, examples/firmware/demo-2.50.hex: 16 KiB of filler
 * (a fixed pseudo-random pattern) that declares firmware 2.50 with the `RBCFW 2.50` marker the simulated
 * bootloader reads (docs/firmware-update.md). It is not a firmware: a real RBC would not run it. It is there so
 * that `rbc flash examples/firmware/demo-2.50.hex --demo` and the panel's demo robot can show an update.
 *
 * `npx tsx scripts/make-firmware-example.ts` (re)writes it; tests/unit/cli-flash.test.ts checks that the
 * committed file is exactly what `demoFirmwareExample()` produces.
 */
import { writeFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { demoFirmwareHex } from "../src/sim/sim-bootloader.ts";

export const DEMO_FIRMWARE_FILE = "examples/firmware/demo-2.50.hex";
export const DEMO_FIRMWARE_VERSION = { major: 2, minor: 50 } as const;
export const DEMO_FIRMWARE_BYTES = 16 * 1024;

/** The text of examples/firmware/demo-2.50.hex (CR LF line ends, 16-byte records). */
export function demoFirmwareExample(): string {
  return demoFirmwareHex(DEMO_FIRMWARE_VERSION, DEMO_FIRMWARE_BYTES);
}

if (process.argv[1] !== undefined && fileURLToPath(import.meta.url) === process.argv[1]) {
  const text = demoFirmwareExample();
  writeFileSync(new URL(`../${DEMO_FIRMWARE_FILE}`, import.meta.url), text, "latin1");
  console.log(`${DEMO_FIRMWARE_FILE}: ${text.length} characters`);
}
