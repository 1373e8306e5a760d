import { html, nothing, type TemplateResult } from "lit-html";
import { translator } from "../../../../i18n/translate.ts";
import { ACTION_AREA_BYTES, MOTION_AREA_BYTES } from "../../../../protocol/catalog.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { type MotionsTranslator, motionsMessages } from "../messages.ts";
import type { SlotBook } from "../slot-book.ts";
import { motionsOf } from "../state.ts";
import { setResetFirst } from "../upload-actions.ts";

/**
 * The robot's memory as what is used: an empty bar when nothing is stored, filling up as files are uploaded
 * (a bar of the free bytes looked full on an empty robot). Figures from the robot's own free-memory reply.
 */

function countText(t: MotionsTranslator, book: SlotBook, area: "motion" | "action"): string {
  const { count, max } = book;
  if (area === "motion") {
    return count === undefined
      ? t("motions.memory.motionsUnknown", { max })
      : t("motions.memory.motionsStored", { stored: count, max });
  }
  return count === undefined
    ? t("motions.memory.actionsUnknown", { max })
    : t("motions.memory.actionsStored", { stored: count, max });
}

/** "640 of 24,576 bytes used", or "not read yet". */
function usedText(t: MotionsTranslator, used: number | undefined, size: number): string {
  return used === undefined ? t("motions.memory.notRead") : t("motions.memory.used", { used, size });
}

export function usedMemoryRow(
  t: MotionsTranslator,
  id: string,
  label: string,
  free: number | undefined,
  size: number,
  note: string,
): TemplateResult {
  const used = free === undefined ? undefined : Math.max(0, size - free);
  return html`
    <div class="used-row">
      <label for=${id}>${label}</label>
      <meter
        id=${id}
        min="0"
        max=${size}
        value=${used ?? 0}
        low=${size * 0.75}
        high=${size * 0.9}
        optimum="0"
        aria-valuetext=${usedText(t, used, size)}
      ></meter>
      <strong class="num used-figures" data-testid=${`${id}-used`}>${usedText(t, used, size)}</strong>
      <span class="muted small used-note">
        ${
          free === undefined
            ? nothing
            : html`<span class="num" data-testid=${`${id}-text`}>${t("motions.memory.free", { free, size })}</span> ·`
        }
        <span data-testid=${`${id}-count`}>${note}</span>
      </span>
    </div>
  `;
}

/**
 * The Files tab's strip above the files: the motion memory in one line and the reset option, the two things
 * an upload from a file card depends on. The whole memory is on the Memory tab.
 */
export function motionMemoryStrip(ctx: ViewContext): TemplateResult {
  const d = ctx.state.device;
  const m = motionsOf(ctx.state);
  const t = translator(motionsMessages, ctx.state.locale);
  const free = d.freeMotion;
  const size = MOTION_AREA_BYTES;
  const used = free === undefined ? undefined : Math.max(0, size - free);
  return html`
    <div class="memory-strip" data-testid="memory-card">
      <div class="strip-row">
        <label for="mem-motion">${t("motions.memory.motionLabel")}</label>
        <meter
          id="mem-motion"
          min="0"
          max=${MOTION_AREA_BYTES}
          value=${used ?? 0}
          low=${MOTION_AREA_BYTES * 0.75}
          high=${MOTION_AREA_BYTES * 0.9}
          optimum="0"
          aria-valuetext=${usedText(t, used, size)}
        ></meter>
        <span class="small">
          ${
            used === undefined || free === undefined
              ? t("motions.memory.notRead")
              : html`<strong class="num" data-testid="mem-motion-used">${t("motions.memory.usedOnly", { used })}</strong>,
                  <span class="num" data-testid="mem-motion-text">${t("motions.memory.free", { free, size })}</span>`
          }
        </span>
      </div>
      <label class="check small">
        <input
          type="checkbox"
          data-testid="reset-first"
          .checked=${m.resetMotionFirst}
          ?disabled=${m.upload !== undefined}
          @change=${(e: Event) => setResetFirst(ctx, "motion", (e.target as HTMLInputElement).checked)}
        />
        ${t("motions.memory.resetMotion")}
      </label>
    </div>
  `;
}

export function memoryCard(ctx: ViewContext): TemplateResult {
  const d = ctx.state.device;
  const m = motionsOf(ctx.state);
  const t = translator(motionsMessages, ctx.state.locale);
  return html`
    <section class="card memory-card" aria-labelledby="memory-title" data-testid="memory-card">
      <h2 id="memory-title" class="card-title">${t("motions.memory.title")}</h2>
      <div class="used-rows">
        ${usedMemoryRow(t, "mem-motion", t("motions.memory.motions"), d.freeMotion, MOTION_AREA_BYTES, countText(t, m.motionBook, "motion"))}
        ${usedMemoryRow(t, "mem-action", t("motions.memory.actions"), d.freeAction, ACTION_AREA_BYTES, countText(t, m.actionBook, "action"))}
      </div>
    </section>
  `;
}
