/**
 * Errors raised by the pure protocol layer. Every error has a stable `code` (for programs and tests) and a
 * message written for a person.
 */
export class ProtocolError extends Error {
  override name = "ProtocolError";
  constructor(
    readonly code: string,
    message: string,
  ) {
    super(message);
  }
}
