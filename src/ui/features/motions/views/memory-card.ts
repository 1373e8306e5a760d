import { html, nothing, type TemplateResult } from "lit-html";
import { ACTION_AREA_BYTES, MOTION_AREA_BYTES } from "../../../../protocol/catalog.ts";
import { formatCount } from "../../../format.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import type { SlotBook } from "../slot-book.ts";
import { motionsOf } from "../state.ts";
import { setResetFirst } from "../upload-actions.ts";

/**
 * The robot's memory as what is used: an empty bar when nothing is stored, filling up as files are uploaded
 * (a bar of the free bytes looked full on an empty robot). Figures from the robot's own free-memory reply.
 */

function countText(book: SlotBook, what: string): string {
  return book.count === undefined
    ? `at most ${book.max} ${what}s (how many it holds now is not known)`
    : `${book.count} of ${book.max} ${what}s stored since the last reset or power-up`;
}

export function usedMemoryRow(
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
        aria-valuetext=${used === undefined ? "not read yet" : `${formatCount(used)} of ${formatCount(size)} bytes used`}
      ></meter>
      <strong class="num used-figures" data-testid=${`${id}-used`}>
        ${used === undefined ? "not read yet" : `${formatCount(used)} of ${formatCount(size)} bytes used`}
      </strong>
      <span class="muted small used-note">
        ${
          free === undefined
            ? nothing
            : html`<span class="num" data-testid=${`${id}-text`}>${formatCount(free)} of ${formatCount(size)} bytes free</span> ·`
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
  const free = d.freeMotion;
  const used = free === undefined ? undefined : Math.max(0, MOTION_AREA_BYTES - free);
  return html`
    <div class="memory-strip" data-testid="memory-card">
      <div class="strip-row">
        <label for="mem-motion">Motion memory</label>
        <meter
          id="mem-motion"
          min="0"
          max=${MOTION_AREA_BYTES}
          value=${used ?? 0}
          low=${MOTION_AREA_BYTES * 0.75}
          high=${MOTION_AREA_BYTES * 0.9}
          optimum="0"
          aria-valuetext=${used === undefined ? "not read yet" : `${formatCount(used)} of ${formatCount(MOTION_AREA_BYTES)} bytes used`}
        ></meter>
        <span class="small">
          ${
            used === undefined || free === undefined
              ? "not read yet"
              : html`<strong class="num" data-testid="mem-motion-used">${formatCount(used)} bytes used</strong>,
                  <span class="num" data-testid="mem-motion-text">${formatCount(free)} of ${formatCount(MOTION_AREA_BYTES)} bytes free</span>`
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
        Reset motion memory first (forgets earlier downloads; the upload becomes motion 12)
      </label>
    </div>
  `;
}

export function memoryCard(ctx: ViewContext): TemplateResult {
  const d = ctx.state.device;
  const m = motionsOf(ctx.state);
  return html`
    <section class="card memory-card" aria-labelledby="memory-title" data-testid="memory-card">
      <h2 id="memory-title" class="card-title">Robot memory</h2>
      <div class="used-rows">
        ${usedMemoryRow("mem-motion", "Motions", d.freeMotion, MOTION_AREA_BYTES, countText(m.motionBook, "motion"))}
        ${usedMemoryRow("mem-action", "Actions", d.freeAction, ACTION_AREA_BYTES, countText(m.actionBook, "action"))}
      </div>
    </section>
  `;
}
