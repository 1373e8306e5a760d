import { saveMotion } from "../../../motion/index.ts";
import type { AppContext } from "../../context.ts";
import { saveRestampedCopy } from "../motions/index.ts";
import { saveFailedNotice } from "./document-actions.ts";
import { motionFileName } from "./file-name.ts";
import { docOf, editorOf, patchEditor } from "./state.ts";

/**
 * Editor: "Make this motion usable on this robot" saves a copy of the motion, as Save would write it, with
 * `serial` (13 digits, or zeros) in field 2 and nothing else changed. The document itself keeps its serial
 * number (a copy is made; nothing is edited).
 */
export async function restampDocument(ctx: AppContext, serial: string): Promise<void> {
  const doc = docOf(editorOf(ctx.store.get()));
  if (!doc) return;
  let text: string;
  try {
    text = saveMotion(doc);
  } catch (e) {
    patchEditor(ctx.store, { notice: saveFailedNotice(ctx, e) });
    return;
  }
  const notice = await saveRestampedCopy(text, motionFileName(doc.name), serial, ctx.store.get().locale);
  patchEditor(ctx.store, { notice });
}
