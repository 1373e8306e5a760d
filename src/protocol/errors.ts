/**
 * Errors raised by the pure protocol layer. Every error has a stable `code` (for programs and tests), its facts
 * (the values concerned) and a short technical `message` for logs; the outcome catalogue (src/i18n/outcomes)
 * words the errors a person meets.
 */
export type ProtocolFacts = Readonly<Record<string, number | string>>;

export class ProtocolError extends Error {
  override name = "ProtocolError";
  constructor(
    readonly code: string,
    message: string,
    readonly facts: ProtocolFacts = {},
  ) {
    super(message);
  }
}

/** A value outside the range a field holds: `wck-id: id 31 not in 0-30`. */
export function outOfRange(
  code: string,
  field: string,
  value: number,
  min: number,
  max: number,
): ProtocolError {
  return new ProtocolError(code, `${code}: ${field} ${value} not in ${min}-${max}`, {
    field,
    value,
    min,
    max,
  });
}
