import { BOOTLOADER_ACTIVE } from "../protocol/bootloader.ts";
import { PacketParser } from "../protocol/packet-parser.ts";
import type { Clock } from "../shared/clock.ts";
import { Waitress } from "../shared/waitress.ts";
import type { BootloaderPromptFacts } from "./errors.ts";

/** The error and its facts live with the device's other errors (errors.ts): saying it loads no bootloader code. */
export { type BootloaderPromptFacts, RbcInBootloaderError } from "./errors.ts";

/**
 * A robot waiting in its bootloader (docs/protocol.md §11): after an interrupted update, say, the RBC sends the
 * bootloader's prompt `^` (0x5E) every few hundred milliseconds and answers no packet. Connecting to it times
 * out; this tells that apart from a robot that is off or a wrong port, so that the person is sent to the
 * firmware update's recovery instead of to the cable.
 */

/** At least this many prompts, and not one packet, make a robot waiting in its bootloader. */
export const BOOTLOADER_PROMPTS_NEEDED = 2;
/** After a connect timed out with one prompt seen: how long to wait for the next (robot time). */
export const BOOTLOADER_PROMPT_CONFIRM_MS = 1000;

/** Watches the bytes of a connect for the bootloader's prompt. `stop()` when the connect is over. */
export class BootloaderPromptWatch {
  private readonly parser = new PacketParser();
  private prompts = 0;
  private first = 0;
  private last = 0;
  private packets = 0;
  /** `confirm`'s wait for the next prompt. */
  private readonly next: Waitress<void>;

  constructor(private readonly clock: Clock) {
    this.next = new Waitress(clock);
  }

  /** Every chunk received during the connect. */
  receive(bytes: Uint8Array): void {
    for (const b of bytes) {
      if (b !== BOOTLOADER_ACTIVE) continue;
      const now = this.clock.now();
      if (this.prompts === 0) this.first = now;
      this.last = now;
      this.prompts++;
    }
    this.packets += this.parser.push(bytes).length;
    if (this.prompts >= BOOTLOADER_PROMPTS_NEEDED) this.next.resolve();
  }

  /** The facts, when the bytes so far show a robot waiting in its bootloader. */
  get found(): BootloaderPromptFacts | undefined {
    if (this.packets > 0 || this.prompts < BOOTLOADER_PROMPTS_NEEDED) return undefined;
    return { prompts: this.prompts, overMs: this.last - this.first };
  }

  /**
   * After a connect timed out: the facts if the robot waits in its bootloader. With one prompt seen so far
   * (a connect can be shorter than the prompt's period), waits up to `confirmMs` for the next.
   */
  async confirm(confirmMs = BOOTLOADER_PROMPT_CONFIRM_MS): Promise<BootloaderPromptFacts | undefined> {
    if (this.packets === 0 && this.prompts > 0 && this.prompts < BOOTLOADER_PROMPTS_NEEDED) {
      await this.next.wait(undefined, { deadline: { ms: confirmMs, value: () => undefined } }).promise;
    }
    return this.found;
  }
}
