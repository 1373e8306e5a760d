import { readFileSync } from "node:fs";
import { join, relative } from "node:path";
import type { MessageText } from "../../src/i18n/index.ts";
import { isCatalogue } from "./catalogue-shape.ts";
import { tsFiles } from "./source-files.ts";

/** The source folder whose catalogues are read. */
export const SRC = join(import.meta.dirname, "../../src");

/** One entry of one catalogue, its plural forms one after the other ("one | other"). */
export interface CatalogueEntry {
  /** The file, relative to src/ ("cli/messages.ts"). */
  readonly file: string;
  readonly key: string;
  readonly en: string;
  readonly ko: string;
}

/** A text, its plural forms one after the other. */
const textOf = (text: MessageText) => (typeof text === "string" ? text : `${text.one} | ${text.other}`);

/**
 * Every entry of every catalogue (`defineMessages`) of the command line (src/cli), the panel (src/ui) and the
 * shared words (src/i18n), read by importing the modules that define them.
 */
export async function catalogueEntries(): Promise<CatalogueEntry[]> {
  const files = tsFiles(SRC).filter(
    (path) =>
      /^(i18n|ui|cli)\//.test(relative(SRC, path)) && readFileSync(path, "utf8").includes("defineMessages("),
  );
  const entries: CatalogueEntry[] = [];
  for (const path of files) {
    const module = (await import(path)) as Record<string, unknown>;
    for (const value of Object.values(module)) {
      if (!isCatalogue(value)) continue;
      for (const [key, m] of Object.entries(value)) {
        entries.push({ file: relative(SRC, path), key, en: textOf(m.en), ko: textOf(m.ko) });
      }
    }
  }
  return entries;
}
