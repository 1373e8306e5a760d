import { html, type TemplateResult } from "lit-html";
import type { RobotTranslator } from "./messages.ts";

/**
 * One memory area of the robot as a bar of what is USED: empty when nothing is stored, full when the area is
 * (a bar of the free bytes looked full on an empty robot and read as "memory full"). The figures beside it
 * say the same in words, with the free bytes under them.
 */
export function memoryUsedRow(
  t: RobotTranslator,
  id: string,
  label: string,
  free: number | undefined,
  size: number,
): TemplateResult {
  const used = free === undefined ? undefined : Math.max(0, size - free);
  return html`
    <div class="memory-row">
      <label for=${id}>${label}</label>
      <meter id=${id} min="0" max=${size} value=${used ?? 0} optimum="0" low=${size * 0.75} high=${size * 0.9}></meter>
      <span class="num" data-testid=${`${id}-text`}>
        ${used === undefined ? "—" : t("robot.bytesUsed", { used, size })}
      </span>
      <span class="muted small" data-testid=${`${id}-note`}>${freeText(t, free, size)}</span>
    </div>
  `;
}

/** "Nothing stored (24,576 bytes free)", "23,936 bytes free", or nothing before the first read. */
function freeText(t: RobotTranslator, free: number | undefined, size: number): string {
  if (free === undefined) return "";
  if (free >= size) return t("robot.nothingStored", { count: free });
  return free === 0 ? t("robot.full") : t("robot.bytesFree", { count: free });
}
