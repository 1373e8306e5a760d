import type { Said } from "../../../i18n/said.ts";
import { type Notice, noticeOf, type Tone } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { technicalDetail } from "../../error-text.ts";

/**
 * The Editor's notices are kept as messages (a catalogue key and its facts, `said(editorMessages, …)`), worded
 * when drawn: a notice made before a language switch follows the switch (issue 21 item 6). Numbers, names and
 * file names are facts; a device error is kept as `errorSaid(e)` (worded by the outcome catalogue).
 */
export function editorNotice(ctx: AppContext, tone: Tone, ...sentences: readonly Said[]): Notice {
  return noticeOf(tone, ctx.store.get().locale, sentences);
}

/**
 * A failure the Editor names in `sentence` (the error a fact of it, `errorSaid(e)`), with the error's technical
 * detail one click away: in Korean an error that is not the robot's reads "자세한 내용은 기술 정보에 있어요".
 */
export function editorFailure(ctx: AppContext, sentence: Said, e: unknown): Notice {
  return { ...editorNotice(ctx, "danger", sentence), detail: technicalDetail(e) };
}
