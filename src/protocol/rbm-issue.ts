/**
 * A motion file's problems as data (docs/protocol.md §7): a stable code, where it is, and the facts its sentence
 * says. The sentences are the outcome catalogue's (`rbmIssueText` in src/i18n); `message` is a short technical
 * line for logs: `rbm-frames (scene 0, frames 0, min 1)`.
 */

/**
 * What an issue's sentence says, as data, so that it can be said in any language: the numbers and texts
 * (`value`, `frames`, `time`, `min`, `max`...), `kind` where one code has several sentences, and `field` naming
 * the field concerned by its name in `RbmMotion` ("start", "p", "motionIndex"; "nameLength" for a length
 * field).
 */
export type RbmIssueValues = Record<string, number | string>;

/** A problem found by `validateRbm`; `scene` is the scene's position, `servo` the servo id, when known. */
export interface RbmIssue {
  code: string;
  /** A technical line for logs; a person reads the catalogue's sentence from `code` and `values`. */
  message: string;
  scene?: number;
  servo?: number;
  /** What the sentence says (see `RbmIssueValues`). */
  values?: RbmIssueValues;
}

/** Where an issue is: the scene's position and the servo id, when known. */
export type RbmIssuePlace = { scene?: number; servo?: number };

/** The technical line of an issue: its code and its facts. */
export function rbmIssueLine(code: string, values: RbmIssueValues = {}): string {
  const facts = Object.entries(values)
    .map(([key, value]) => `${key} ${value}`)
    .join(", ");
  return facts === "" ? code : `${code} (${facts})`;
}

/** An issue with its technical line. */
export function rbmIssue(code: string, values: RbmIssueValues, where: RbmIssuePlace = {}): RbmIssue {
  return { code, message: rbmIssueLine(code, values), ...where, values };
}
