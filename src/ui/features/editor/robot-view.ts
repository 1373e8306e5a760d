import { html, nothing, type TemplateResult } from "lit-html";
import { builtInMotionName } from "../../../i18n/motion-names/built-in-motion-name.ts";
import { translator } from "../../../i18n/translate.ts";
import type { Motion } from "../../../motion/index.ts";
import { BASIC_POSTURE_MOTION } from "../../../protocol/catalog.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { stopAll } from "../../stop-all.ts";
import { connectionMessages } from "../connection/index.ts";
import {
  confirmMove,
  type MotionsTranslator,
  motionMemoryStrip,
  motionsMessages,
  motionsOf,
  runningPanel,
  uploadInPlace,
  uploadPayload,
} from "../motions/index.ts";
import { editorController } from "./controller.ts";
import { type EditorRunPlace, liveOf } from "./live-state.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import {
  requestEditorUpload,
  robotRefusal,
  runOnRobot,
  startEditorUpload,
  stopEndsIt,
} from "./robot-actions.ts";
import {
  type CopyStatus,
  editorUploadTarget,
  isEditorTarget,
  remoteKeyText,
  robotCopyStatus,
} from "./robot-model.ts";

/**
 * The Play tab's "Store on the robot" card (issue 23 item 1): "Upload to robot" stores the document on screen
 * in the robot's memory through the Motions view's upload (its checks, confirmation, progress and result, in
 * place), then "Run on robot" runs it by the number Run takes, with the remote key that plays it. One line says
 * how this differs from tethered play (the card above). While the robot is busy both buttons refuse, the
 * reason beside them and, while a motion plays, a Stop.
 */

/** Why the upload is refused, in the Editor's words when it is the document's errors (listed on the Check tab). */
function uploadRefusal(ctx: ViewContext, t: EditorTranslator, doc: Motion): string | undefined {
  const payload = uploadPayload(ctx, editorUploadTarget(doc));
  if (!("refused" in payload)) return undefined;
  const count = editorController(ctx).issuesOf(doc).errors.length;
  return count > 0 ? t("editor.robot.hasErrors", { count }) : payload.refused;
}

/** The refusal beside the buttons, with a Stop when a motion plays (Escape does the same). */
function busyLine(ctx: ViewContext, reason: string, showStop: boolean): TemplateResult {
  const stop = translator(connectionMessages, ctx.state.locale)("connection.stop");
  return html`<p class="muted small robot-busy" id="editor-robot-busy" data-testid="editor-robot-busy">
    <span>${reason}</span>
    ${
      showStop
        ? html`<button type="button" class="btn btn--danger" data-testid="editor-robot-stop" aria-keyshortcuts="Escape" @click=${() => void stopAll(ctx)}>
            ${stop}
          </button>`
        : nothing
    }
  </p>`;
}

/** What the robot holds of this motion, and the Run button for it. */
function copyBlock(
  ctx: ViewContext,
  t: EditorTranslator,
  status: Exclude<CopyStatus, { kind: "none" }>,
  refused: boolean,
  busy: boolean,
): TemplateResult {
  const { number } = status;
  if (number === undefined) {
    return html`<p class="small" data-testid="editor-robot-copy">${t("editor.robot.numberUnknown")}</p>`;
  }
  const key = remoteKeyText(number, t) ?? "";
  const earlier = status.kind === "earlier";
  return html`
    <p class=${earlier ? "small text-warning" : "small"} data-testid="editor-robot-copy">
      ${earlier ? t("editor.robot.earlier", { number, key }) : t("editor.robot.holds", { number, key })}
    </p>
    <div class="actions">
      <button
        type="button"
        class="btn btn--wrap"
        data-testid="editor-run"
        ?disabled=${refused}
        aria-describedby=${busy ? "editor-robot-busy" : nothing}
        @click=${() => runOnRobot(ctx, number)}
      >
        ${earlier ? t("editor.robot.runEarlier", { number, key }) : t("editor.robot.run", { number, key })}
      </button>
    </div>
  `;
}

/** After switching on the robot plays only Basic posture (7): said here, with its button (§3.1). */
function postureBlock(ctx: ViewContext, mt: MotionsTranslator, refused: boolean): TemplateResult {
  const name = builtInMotionName(BASIC_POSTURE_MOTION, mt.locale) ?? "";
  return html`<div class="notice notice--warning" data-testid="editor-posture">
    <p><strong>${mt("motions.run.postureGuidance")}</strong> ${mt("motions.run.ignoresOthers")}</p>
    <div class="actions">
      <button type="button" class="btn btn--wrap" ?disabled=${refused} @click=${() => runOnRobot(ctx, BASIC_POSTURE_MOTION, "posture")}>
        ${mt("motions.run.confirmNamed", { number: BASIC_POSTURE_MOTION, name })}
      </button>
    </div>
  </div>`;
}

/** The question, progress and result of a Run pressed at `at` (the Run tab's own parts), right under its button. */
function runInPlace(ctx: ViewContext, mt: MotionsTranslator, at: EditorRunPlace): TemplateResult {
  const s = ctx.state;
  const m = motionsOf(s);
  const live = liveOf(s);
  const from = live.runFrom;
  const here = from !== undefined && m.runFrom === from && (live.runAt ?? "card") === at;
  return html`<div class="run-in-place" data-testid=${`editor-run-place-${at}`}>
    ${here && m.confirmMove !== undefined ? confirmMove(ctx, mt, s, m.confirmMove) : nothing}
    ${here && m.run ? runningPanel(ctx, mt, m.run) : nothing}
    ${liveNotice(here ? m.runNotice : undefined, mt("motions.run.resultLabel"), mt.locale)}
  </div>`;
}

export function robotCard(ctx: ViewContext, doc: Motion): TemplateResult {
  const s = ctx.state;
  const t = translator(editorMessages, s.locale);
  const mt = translator(motionsMessages, s.locale);
  const connected = s.connection.phase === "connected";
  const m = motionsOf(s);
  const busy = connected ? robotRefusal(s) : undefined;
  const refusedUpload = uploadRefusal(ctx, t, doc);
  const status = robotCopyStatus(liveOf(s).robotCopy, m.motionBook, doc);
  const confirming = m.confirmMove !== undefined;
  // A motion this card started shows its own progress with "Stop motion"; any other gets a Stop here.
  const ownRun = m.run !== undefined && m.runFrom === liveOf(s).runFrom;
  const why = refusedUpload ?? busy;
  // The Editor's own upload shows its progress and Cancel right here: no busy sentence above it.
  const ownUpload = m.upload !== undefined && isEditorTarget(m.upload.target);
  const showBusy = busy !== undefined && !ownUpload;
  const describedBy = showBusy ? "editor-upload-why editor-robot-busy" : "editor-upload-why";
  return html`
    <section class="card editor-robot-store" aria-labelledby="robot-store-title" data-testid="editor-upload">
      <h2 id="robot-store-title" class="card-title">${t("editor.robot.title")}</h2>
      <p class="small" data-testid="editor-robot-difference">${t("editor.robot.difference")}</p>
      ${
        !connected
          ? html`<p class="muted small">${t("editor.robot.hint")}</p>`
          : html`
            ${motionMemoryStrip(ctx)}
            <div class="write-row">
              <button
                type="button"
                class="btn btn--primary"
                data-testid="editor-upload-button"
                ?disabled=${why !== undefined}
                aria-describedby=${describedBy}
                @click=${() => requestEditorUpload(ctx, doc)}
              >
                ${mt("motions.files.upload")}
              </button>
              <span id="editor-upload-why" class=${refusedUpload ? "text-danger small" : "muted small"} data-testid="editor-upload-why">
                ${
                  refusedUpload ??
                  (busy
                    ? nothing
                    : s.connection.robot?.kind === "demo"
                      ? mt("motions.files.uploadsToDemo")
                      : mt("motions.files.asksFirst"))
                }
              </span>
            </div>
            ${busy && showBusy ? busyLine(ctx, busy, stopEndsIt(s) && !ownRun) : nothing}
            ${uploadInPlace(ctx, editorUploadTarget(doc), startEditorUpload, {
              busy: busy !== undefined || confirming,
              run: (number) => runOnRobot(ctx, number, "result"),
              place: runInPlace(ctx, mt, "result"),
            })}
            ${
              // A question about another motion says "Basic posture first" itself while it is asked.
              status.kind !== "none" &&
              !s.connection.basicPostureConfirmed &&
              !(confirming && m.confirmMove !== BASIC_POSTURE_MOTION)
                ? postureBlock(ctx, mt, busy !== undefined || confirming)
                : nothing
            }
            ${runInPlace(ctx, mt, "posture")}
            ${status.kind !== "none" ? copyBlock(ctx, t, status, busy !== undefined || confirming, showBusy) : nothing}
            ${runInPlace(ctx, mt, "card")}
          `
      }
    </section>
  `;
}
