import { html, nothing, type TemplateResult } from "lit-html";
import { anotherRobotText, noRobotSerialText } from "../../../../i18n/outcomes/restamp/restamp-words.ts";
import { translator } from "../../../../i18n/translate.ts";
import { isRbmSerial, isZeroSerial, RBM_ZERO_SERIAL } from "../../../../motion/restamp.ts";
import type { Notice } from "../../../app-state.ts";
import { liveNotice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { restampMessages } from "./messages.ts";

/**
 * The offer of "Make this motion usable on this robot" for a motion whose serial number (field 2) is not zeros
 * and not the connected robot's (Motionbuilder refuses such a file, docs/protocol.md §7). With a robot that
 * reports its serial number: write that one, or zeros; otherwise zeros only. Nothing is shown for a motion
 * with zeros or the robot's own number, apart from the result of a copy just made.
 */
export interface RestampOfferOptions {
  /** The motion's serial number (field 2). */
  fileSerial: string;
  /** Distinguishes this offer's ids in the page (several files are listed). */
  id: string;
  /** The last copy's result. */
  notice?: Notice;
  make(serial: string): void;
}

export function restampOffer(ctx: ViewContext, o: RestampOfferOptions): TemplateResult {
  const t = translator(restampMessages, ctx.state.locale);
  const { locale } = ctx.state;
  const c = ctx.state.connection;
  const robot = c.phase === "connected" ? c.serialNumber : undefined;
  const result = liveNotice(o.notice, t("motions.restamp.result"), locale);
  if (isZeroSerial(o.fileSerial) || o.fileSerial === robot) return result;
  const usable = robot !== undefined && isRbmSerial(robot);
  const textId = `restamp-text-${o.id}`;
  return html`
    <div class="restamp-offer ${usable ? "notice notice--warning" : ""}" data-testid="restamp-offer">
      <p id=${textId}>
        ${usable ? anotherRobotText(o.fileSerial, robot, locale) : t("motions.restamp.madeFor", { serial: o.fileSerial })}
        ${c.phase === "connected" && robot === undefined ? noRobotSerialText(locale) : nothing}
        <span class="muted">${t("motions.restamp.explain")}</span>
      </p>
      <div class="row-actions">
        ${
          usable
            ? html`<button
                type="button"
                class="btn btn--primary btn--wrap"
                data-testid="restamp-robot"
                aria-describedby=${textId}
                @click=${() => o.make(robot)}
              >
                ${t("motions.restamp.makeUsable")}
              </button>`
            : nothing
        }
        <button
          type="button"
          class="btn btn--wrap"
          data-testid="restamp-zeros"
          aria-describedby=${textId}
          @click=${() => o.make(RBM_ZERO_SERIAL)}
        >
          ${t("motions.restamp.saveZeros")}
        </button>
      </div>
    </div>
    ${result}
  `;
}
