import { html, type TemplateResult } from "lit-html";

/**
 * A motion, scene or file name with line-break opportunities (`<wbr>`) only where a word ends: after an
 * underscore or a hyphen followed by a letter, and between a lower-case letter and a capital
 * ("RbcPanel_LongWalk" → "Rbc·Panel_·Long·Walk"). With `.name-text` (base.css: `word-break: keep-all`, and
 * `overflow-wrap: break-word` only for a single word wider than its whole line) a name never breaks mid-word,
 * and "Scene_1" stays whole.
 */
export function nameWithBreaks(name: string): TemplateResult {
  const parts = name.split(/(?<=[_-])(?=\p{L})|(?<=\p{Ll})(?=\p{Lu})/u);
  return html`${parts.map((part, i) => (i === 0 ? part : html`<wbr />${part}`))}`;
}
