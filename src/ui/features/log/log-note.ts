import { html, type TemplateResult } from "lit-html";
import { formatClockTime } from "../../format.ts";
import type { LogTranslator } from "./messages.ts";
import type { LogLine } from "./packet-log.ts";

/**
 * What the Log view says beside a row's name, in the panel's language: what a run of discarded bytes was made
 * of, and that only the first bytes are shown. The device's own note ("chunk 3 (255 bytes)") stays in English,
 * marked as such. The exported log keeps `LogLine.note`, in English (a packet trace, like the CLI's).
 */
export function rowNote(line: LogLine, t: LogTranslator): (string | TemplateResult)[] | undefined {
  const shown = line.kept < line.byteCount ? t("log.firstShown", { count: line.kept }) : undefined;
  const tally = line.tally;
  if (line.kind === "discard" && tally) {
    const parts: string[] = [];
    if (tally.badChecksum > 0) parts.push(t("log.badChecksum", { count: tally.badChecksum }));
    if (tally.oversize > 0) parts.push(t("log.oversize", { count: tally.oversize }));
    // The parser reports stray bytes in pieces that mean nothing to a reader: they are only named.
    if (tally.garbageRuns > 0) parts.push(t("log.stray"));
    let note = parts.join(", ");
    if (line.lastAt > line.at) note = t("log.until", { what: note, time: formatClockTime(line.lastAt) });
    return [shown ? t("log.noteAndShown", { note, shown }) : note];
  }
  const given = line.givenNote ? html`<span lang="en">${line.givenNote}</span>` : undefined;
  if (given && shown) return t.parts("log.noteAndShown", { note: given, shown });
  if (given) return [given];
  return shown ? [shown] : undefined;
}
