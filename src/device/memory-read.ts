import { COMMANDS, type MemoryArea } from "../protocol/commands.ts";
import { RbcNotSupportedError, RbcTimeoutError } from "./errors.ts";
import type { RbcConnection } from "./rbc-connection.ts";

/**
 * 0x0F, which some firmware never answers (the homebrew port, docs/protocol.md §3.5 [decision]): connecting and
 * `info` succeed without it (free memory "not reported"), and an upload, which needs it to check its result,
 * is refused before any byte of the file. Unanswered while 0x12 is answered at once, it is taken as not
 * supported (`RbcNotSupportedError`); with 0x12 unanswered too, the link is gone (the timeout). Must run
 * inside `exclusive`.
 */
export async function readFreeMemory(c: RbcConnection, area: MemoryArea): Promise<number> {
  try {
    return await c.request(COMMANDS.readAvailableMemory, area);
  } catch (e) {
    if (!(e instanceof RbcTimeoutError)) throw e;
    try {
      await c.request(COMMANDS.readFirmwareVersion, undefined, { retries: 0 });
    } catch {
      throw e;
    }
    throw new RbcNotSupportedError(COMMANDS.readAvailableMemory.name);
  }
}
