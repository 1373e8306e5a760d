/**
 * What the page loads with import() to say a failure: the device's errors and the outcome catalogue come with
 * it, so the first page, which shows no failure, does not carry them (first load: issue 19).
 */
import { RbcError, type RbcErrorCode } from "../device/errors.ts";

export { chooserProblem, errorNotice } from "./error-text.ts";
export { failureNotice } from "./failure-notice.ts";

/** The device outcome's code of a failure, if it is one (a failed connect's `in-bootloader` offers Recover). */
export function outcomeCode(e: unknown): RbcErrorCode | undefined {
  return e instanceof RbcError ? e.code : undefined;
}
