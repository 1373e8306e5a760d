import { type Catalogue, LOCALES, type Message } from "../../src/i18n/index.ts";

/** A catalogue entry: a text in every language the panel speaks. */
export function isMessage(value: unknown): value is Message {
  return typeof value === "object" && value !== null && LOCALES.every((l) => l in value);
}

/** A catalogue (`defineMessages`): a non-empty object whose every value is an entry. */
export function isCatalogue(value: unknown): value is Catalogue {
  return (
    typeof value === "object" &&
    value !== null &&
    Object.values(value).length > 0 &&
    Object.values(value).every(isMessage)
  );
}
