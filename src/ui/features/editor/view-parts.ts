import { html, nothing, type TemplateResult } from "lit-html";
import type { Locale } from "../../../i18n/locale.ts";
import type { EditorTranslator } from "./messages.ts";
import { refusalText } from "./refusal-text.ts";
import type { FieldProblem } from "./state.ts";

/** Small pieces the editor's views share. */

/**
 * Why an edit was refused, under its control (its id goes into the control's aria-describedby), worded now in
 * `locale`: a refusal made before a language switch reads in the new language.
 */
export function problemText(
  id: string,
  problem: FieldProblem | undefined,
  locale: Locale,
): TemplateResult | typeof nothing {
  if (!problem) return nothing;
  return html`<p id=${id} class="text-danger small field-problem" data-testid="field-problem">${refusalText(problem.why, locale)}</p>`;
}

/** The torque values 0-4 as the scene's torque choice names them: "0 (strong)" … "4 (weak)". */
export function torqueWords(t: EditorTranslator): readonly string[] {
  return [t("editor.torque.strong"), "1", "2", "3", t("editor.torque.weak")];
}
export const TORQUE_VALUES: readonly number[] = [0, 1, 2, 3, 4];
export const PORT_VALUES: readonly number[] = [0, 1, 2, 3];

/** The number typed into a number field, from its event. */
export function inputValue(e: Event): string {
  return (e.target as HTMLInputElement | HTMLSelectElement).value;
}
