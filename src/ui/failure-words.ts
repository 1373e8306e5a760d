/**
 * What the page loads with import() to say a failure: the device's errors and the outcome catalogue come with
 * it, so the first page, which shows no failure, does not carry them (first load: issue 19).
 */
export { chooserProblem, errorNotice } from "./error-text.ts";
export { failureNotice } from "./failure-notice.ts";
