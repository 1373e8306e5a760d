/**
 * How a failed command is told: one line on stderr in the person's language (with the English technical
 * detail after `--log`), the same failure as JSON on stdout with `--json`, and its exit code. Used by main and
 * by each port of a command given several ports (multi-port.ts).
 */

import { RbcUploadError } from "../device/errors.ts";
import { technicalDetail } from "../device/technical-detail.ts";
import type { Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import type { CommandDef } from "./command.ts";
import { CliError, EXIT, errorCode, errorLine, UsageError } from "./errors.ts";
import { cliMessages } from "./messages.ts";
import type { Output } from "./output.ts";

/** How a failure is told to a person: in their language, with the English technical detail after `--log`. */
export interface Telling {
  locale: Locale;
  log: boolean;
}

/**
 * The failure's line for a person, on stderr. In English it is the line `--json` carries too; in another
 * language it is said in that language, and `--log` adds the English technical detail on the next line.
 */
function tellFailure(out: Output, e: unknown, telling: Telling): void {
  const { locale, log } = telling;
  out.note(`rbc: ${errorLine(e, locale, { detailShown: log })}`);
  if (locale !== "en" && log) {
    out.note(`rbc: ${translator(cliMessages, locale)("cli.error.detail", { detail: technicalDetail(e) })}`);
  }
}

export function reportFailure(
  out: Output,
  e: unknown,
  command: CommandDef | undefined,
  telling: Telling,
): number {
  const t = translator(cliMessages, telling.locale);
  if (e instanceof UsageError) {
    const which = e.command ?? command?.name;
    tellFailure(out, e, telling);
    out.note(t("cli.usage.seeHelp", { help: `rbc ${which ? `${which} ` : ""}--help` }));
    out.result({ ok: false, error: { code: errorCode(e), message: errorLine(e) } });
    return EXIT.usage;
  }
  tellFailure(out, e, telling);
  const details =
    e instanceof RbcUploadError
      ? { acknowledged: e.acknowledged, total: e.total, outcome: e.outcome }
      : e instanceof CliError
        ? e.details
        : {};
  out.result({ ok: false, error: { code: errorCode(e), message: errorLine(e), ...details } });
  return e instanceof CliError ? e.exitCode : EXIT.failed;
}
