import { html, type TemplateResult } from "lit-html";
import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { shellMessages } from "./messages.ts";

/** One memory area of the robot: a meter of the free bytes, the figures, and a note under them. */
export function memoryRow(
  locale: Locale,
  id: string,
  label: string,
  free: number | undefined,
  size: number,
  note: string,
  noteTestId?: string,
): TemplateResult {
  const t = translator(shellMessages, locale);
  return html`
    <div class="memory-row">
      <label for=${id}>${label}</label>
      <meter id=${id} min="0" max=${size} value=${free ?? 0} low=${size * 0.1} optimum=${size}></meter>
      <span class="num" data-testid=${`${id}-text`}>
        ${free === undefined ? "—" : t("shell.bytesFree", { free, size })}
      </span>
      <span class="muted small" data-testid=${noteTestId ?? `${id}-note`}>${note}</span>
    </div>
  `;
}
