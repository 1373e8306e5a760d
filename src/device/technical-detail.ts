import { LinkError } from "../link/transport.ts";
import { RbcError } from "./errors.ts";

/**
 * "RbcTimeoutError (timeout): no reply to 0x16 within 300 ms", with its causes: the technical detail, in
 * English, for logs, `--log` and the panel's "Technical detail". What a person reads is worded from the error's
 * code and facts by the outcome catalogue (src/i18n/outcomes/error-text.ts).
 */
export function technicalDetail(e: unknown): string {
  if (e instanceof RbcError || e instanceof LinkError) {
    const cause = e.cause === undefined ? "" : ` — caused by ${technicalDetail(e.cause)}`;
    return `${e.name} (${e.code}): ${e.message}${cause}`;
  }
  if (e instanceof Error) return `${e.name}: ${e.message}`;
  return String(e);
}
