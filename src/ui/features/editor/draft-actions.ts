import { errorSaid } from "../../../i18n/error-said.ts";
import { lowerErrorText } from "../../../i18n/outcomes/lower-error-text.ts";
import { inEveryLanguage, type Said, said, wordOf } from "../../../i18n/said.ts";
import { type Motion, newMotion, openMotion, saveMotion } from "../../../motion/index.ts";
import { noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { technicalDetail } from "../../error-text.ts";
import { editorController } from "./controller.ts";
import { DRAFT_OPEN_TIMEOUT_MS, DraftTimeoutError, withDeadline } from "./draft-deadline.ts";
import {
  type BrokenDraft,
  type DraftRecord,
  type DraftStorage,
  type DraftSummary,
  draftRecord,
  listDrafts,
  loadDraft,
  newDraftId,
  recoverPending,
} from "./drafts.ts";
import { liveOf } from "./live-state.ts";
import { editorMessages } from "./messages.ts";
import { formatSavedAt } from "./saved-at.ts";
import { docOf, editorOf, patchEditor, startDocument } from "./state.ts";

/** Drafts: autosave, the draft restored when the editor opens, and the Drafts list (open, rename, export, delete). */

/** The error in English words: the outcome catalogue's for the lower layers' errors (a file the parser refused). */
function message(e: unknown): string {
  return lowerErrorText(e, "en") ?? (e instanceof Error ? e.message : String(e));
}

function randomUnit(): number {
  const buf = new Uint32Array(1);
  crypto.getRandomValues(buf);
  return buf[0]! / 0x1_0000_0000;
}

/** The zero table of the connected robot if it has been read (Zeros view, or teach-in), for a new motion. */
export function robotZeros(ctx: AppContext): readonly number[] | undefined {
  const state = ctx.store.get();
  if (state.connection.phase !== "connected") return undefined;
  const zeros = state.zeros.stored ?? liveOf(state).teach.robotZeros;
  return zeros && zeros.length === 16 ? zeros : undefined;
}

/** Saves the document as its draft ~300 ms after the last change (a draft id is given on the first save). */
export function scheduleAutosave(ctx: AppContext): void {
  const s = editorOf(ctx.store.get());
  const doc = docOf(s);
  if (!doc) return;
  let id = s.draftId;
  if (id === undefined) {
    id = newDraftId(Date.now(), randomUnit);
    patchEditor(ctx.store, { draftId: id });
  }
  const draftId = id;
  editorController(ctx).autosaver.schedule(() => draftRecord(draftId, doc.name, saveMotion(doc), Date.now()));
}

/** Saves a waiting change at once (before another document replaces this one, or the page goes away). */
export function flushAutosave(ctx: AppContext): Promise<void> {
  return editorController(ctx).autosaver.flush();
}

/**
 * "Its motion cannot be read: …" as a message: in English the parser's refusal in the catalogue's words; in
 * another language the panel says what it means, the sentence apart (the technical detail).
 */
export function unreadableProblem(e: unknown): Said {
  const parser = message(e);
  const meaning = said(editorMessages, "editor.draftProblem.unreadableReason");
  const reason = inEveryLanguage((l) => (l === "en" ? parser : wordOf(meaning, l)));
  return said(editorMessages, "editor.draftProblem.unreadable", { reason });
}

/** A stored draft as a document, or why it cannot be opened (a message, worded when drawn). */
export async function readDraftDocument(
  storage: DraftStorage,
  id: string,
): Promise<{ record: DraftRecord; doc: Motion } | { problem: Said }> {
  const read = await loadDraft(storage, id);
  if (read === undefined) return { problem: said(editorMessages, "editor.draftProblem.missing") };
  if (!read.ok) return { problem: read.problem };
  try {
    return { record: read.record, doc: openMotion(read.record.rbm) };
  } catch (e) {
    return { problem: unreadableProblem(e) };
  }
}

export interface LatestDraft {
  /** The newest draft that opens, if any. */
  restored?: { record: DraftRecord; doc: Motion };
  /** The newest draft, set aside because its motion does not open (it was newer than `restored`). */
  setAside?: { key: string; name: string; problem: Said };
  /** The drafts that can be listed. */
  drafts: DraftSummary[];
  /** Records that cannot be used, with why (a newer draft whose motion does not open is one). */
  broken: BrokenDraft[];
}

/** The newest draft whose motion opens; newer ones that do not are reported (with why) and skipped. */
export async function findLatestDraft(storage: DraftStorage): Promise<LatestDraft> {
  const listing = await listDrafts(storage);
  const broken = [...listing.broken];
  let restored: LatestDraft["restored"];
  let setAside: LatestDraft["setAside"];
  for (const draft of listing.drafts) {
    const read = await readDraftDocument(storage, draft.id);
    if ("doc" in read) {
      restored = read;
      break;
    }
    setAside ??= { key: draft.id, name: draft.name, problem: read.problem };
    broken.push({ key: draft.id, problem: read.problem });
  }
  const drafts = listing.drafts.filter((d) => !broken.some((b) => b.key === d.id));
  return { ...(restored ? { restored } : {}), ...(setAside ? { setAside } : {}), drafts, broken };
}

function brokenNotice(broken: readonly BrokenDraft[]): Said | undefined {
  if (broken.length === 0) return undefined;
  return said(editorMessages, "editor.drafts.skippedNotice", { count: broken.length });
}

/** The drafts as the Editor opens: recovered, listed, the newest that opens found. */
async function readDraftsAtStart(ctx: AppContext): Promise<LatestDraft> {
  const controller = editorController(ctx);
  const storage = await controller.storage;
  const lost = await recoverPending(storage, controller.pending);
  const latest = await findLatestDraft(storage);
  return lost ? { ...latest, broken: [...latest.broken, lost] } : latest;
}

/**
 * Opens the editor: reopens the last saved draft that can be read ("Draft restored: NAME, saved HH:MM"), or
 * starts from the template. Runs once per page; broken records are listed, never opened. A newest draft whose
 * motion does not open is set aside with a sentence (it can be exported from the Drafts list), and reading the
 * drafts has a deadline (`DRAFT_OPEN_TIMEOUT_MS`): the Editor never stays on "Opening the last draft…".
 */
export async function startEditor(ctx: AppContext, deadlineMs = DRAFT_OPEN_TIMEOUT_MS): Promise<void> {
  const first = editorOf(ctx.store.get());
  if (first.history || first.starting) return;
  patchEditor(ctx.store, { starting: true });
  let latest: LatestDraft = { drafts: [], broken: [] };
  let listProblem: ListProblem | undefined;
  try {
    latest = await withDeadline(readDraftsAtStart(ctx), deadlineMs);
  } catch (e) {
    listProblem =
      e instanceof DraftTimeoutError
        ? {
            said: said(editorMessages, "editor.drafts.openTimedOut", {
              seconds: String(Math.round(e.ms / 1000)),
            }),
          }
        : {
            said: said(editorMessages, "editor.drafts.readFailed", { error: errorSaid(e) }),
            detail: technicalDetail(e),
          };
  }
  try {
    finishStart(ctx, latest, listProblem);
  } catch (e) {
    // A restored draft the editor cannot show: set it aside and open the template instead.
    const aside = latest.restored;
    const problem = unreadableProblem(e);
    const setAside = aside ? { key: aside.record.id, name: aside.record.name, problem } : latest.setAside;
    const broken = aside ? [...latest.broken, { key: aside.record.id, problem }] : latest.broken;
    const drafts = aside ? latest.drafts.filter((d) => d.id !== aside.record.id) : latest.drafts;
    finishStart(ctx, { drafts, broken, ...(setAside ? { setAside } : {}) }, listProblem);
  }
}

/** Why the drafts could not be listed, with the error's technical detail when there was one. */
interface ListProblem {
  said: Said;
  detail?: string;
}

function finishStart(ctx: AppContext, latest: LatestDraft, listProblem: ListProblem | undefined): void {
  const { locale } = ctx.store.get();
  const controller = editorController(ctx);
  const { restored, drafts, broken, setAside } = latest;
  const storageProblem =
    controller.storageProblem === undefined
      ? undefined
      : said(editorMessages, "editor.drafts.storageProblem", { error: controller.storageProblem });
  const problem = listProblem?.said ?? storageProblem ?? brokenNotice(broken);
  patchEditor(ctx.store, (s) => {
    if (s.history) return { starting: false };
    const common = {
      starting: false,
      drafts,
      brokenDrafts: broken,
      draftsNotice: problem ? noticeOf("warning", locale, [problem], listProblem?.detail) : undefined,
    };
    if (!restored) {
      const started = startDocument(s, newMotion({ zeros: robotZeros(ctx) }), undefined);
      if (!setAside) return { ...started, ...common };
      const text = said(editorMessages, "editor.drafts.setAside", {
        name: setAside.name,
        problem: setAside.problem,
      });
      return { ...started, ...common, notice: noticeOf("warning", locale, [text]) };
    }
    const { record, doc } = restored;
    // Kept as messages (worded when drawn), so "Draft restored…" follows a language switch.
    const now = Date.now();
    const time = inEveryLanguage((l) => formatSavedAt(record.savedAt, now, l));
    const restoredText = said(editorMessages, "editor.drafts.restored", { name: doc.name, time });
    const asideText = setAside
      ? said(editorMessages, "editor.drafts.setAside", { name: setAside.name, problem: setAside.problem })
      : undefined;
    return {
      ...startDocument(s, doc, record.id),
      ...common,
      savedAt: record.savedAt,
      notice: asideText
        ? noticeOf("warning", locale, [restoredText, asideText])
        : noticeOf("info", locale, [restoredText]),
    };
  });
}
