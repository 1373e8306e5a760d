import { errorText } from "./outcomes/error-text.ts";
import { isSaid, type Said, saidBy, wordOf } from "./said.ts";

/**
 * A failure as a message, for the panel's notices and `rbc`'s one line alike: an error that carries its own
 * words (`said`, as `rbc`'s CliError does) says them; any other is worded by the outcome catalogue
 * (`errorText`: in English the error's own message, in Korean the sentence from its code and facts).
 */
export interface ErrorSaidOptions {
  /**
   * Where a Korean sentence that does not say enough points for the technical detail: the panel's default (its
   * "technical detail" disclosure), or the command line's own (`--log`).
   */
  readonly detailHint?: Said;
}

/** `e` as a message in every language, worded when drawn. */
export function errorSaid(e: unknown, options: ErrorSaidOptions = {}): Said {
  const own = typeof e === "object" && e !== null && "said" in e ? e.said : undefined;
  if (isSaid(own)) return own;
  const { detailHint } = options;
  return saidBy((locale) =>
    errorText(e, locale, detailHint ? { detailHint: wordOf(detailHint, locale) } : {}),
  );
}
