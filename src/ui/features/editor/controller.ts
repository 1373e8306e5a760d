import { said } from "../../../i18n/said.ts";
import { type Motion, motionIssues } from "../../../motion/index.ts";
import type { RbmValidation } from "../../../protocol/rbm-validate.ts";
import type { AppContext } from "../../context.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { Autosaver } from "./autosave.ts";
import {
  type DraftRecord,
  type DraftStorage,
  type DraftSummary,
  idbDraftStorage,
  memoryDraftStorage,
  type PendingDraftStore,
  storagePendingStore,
  summarize,
} from "./drafts.ts";
import { editorMessages } from "./messages.ts";
import { patchEditor } from "./state.ts";

/**
 * The editor's controller, one per page (the motion being made outlives connections): the draft storage and
 * its autosaver, the page listeners (autosave when the page is hidden or left, Ctrl+Z / Ctrl+Y), the checks of
 * the documents shown (cached by document: documents are values), and the number of the slider drag under way.
 */
export class EditorController implements Controller {
  /**
   * The drafts' storage: IndexedDB, or memory when it cannot be opened (`storageProblem` is the browser's
   * reason, a technical message the panel quotes).
   */
  readonly storage: Promise<DraftStorage>;
  storageProblem: string | undefined;
  readonly autosaver: Autosaver;
  /** Where a change waiting when the page goes away is written synchronously. */
  readonly pending: PendingDraftStore;
  /** Bumped when a slider drag ends, so that the next drag is an undo step of its own. */
  drag = 0;
  /** The page listeners are in place. */
  listening = false;
  private readonly checks = new WeakMap<Motion, RbmValidation>();
  private readonly removers: (() => void)[] = [];

  constructor(
    storage: Promise<DraftStorage>,
    pending: PendingDraftStore,
    handlers: { onSaved(record: DraftRecord): void; onError(error: unknown): void },
  ) {
    this.pending = pending;
    this.storage = storage.catch((e: unknown) => {
      this.storageProblem = e instanceof Error ? e.message : String(e);
      return memoryDraftStorage();
    });
    this.autosaver = new Autosaver(async (record) => (await this.storage).set(record.id, record), handlers);
  }

  /** The validator's errors and warnings for `doc` (computed once per document). */
  issuesOf(doc: Motion): RbmValidation {
    let v = this.checks.get(doc);
    if (!v) {
      v = motionIssues(doc);
      this.checks.set(doc, v);
    }
    return v;
  }

  /** Adds a listener that is removed when the page scope ends. */
  listen(target: EventTarget, type: string, handler: (e: Event) => void): void {
    target.addEventListener(type, handler);
    this.removers.push(() => target.removeEventListener(type, handler));
  }

  dispose(): void {
    void this.autosaver.flush();
    for (const remove of this.removers.splice(0)) remove();
  }
}

/** localStorage for the change waiting when the page goes away; memory (no rescue) where it is unavailable. */
function pagePendingStore(): PendingDraftStore {
  try {
    if (typeof localStorage !== "undefined") return storagePendingStore(localStorage);
  } catch {
    // Storage disabled: fall through.
  }
  let last: unknown;
  return {
    write: (record) => {
      last = record;
    },
    take: () => {
      const value = last;
      last = undefined;
      return value;
    },
  };
}

/** The Drafts list with `summary` in place of its earlier entry, the newest first. */
export function withSummary(
  list: readonly DraftSummary[] | undefined,
  summary: DraftSummary,
): DraftSummary[] | undefined {
  if (list === undefined) return undefined;
  return [summary, ...list.filter((d) => d.id !== summary.id)].sort((a, b) => b.savedAt - a.savedAt);
}

export const EDITOR = controllerKey(
  "editor",
  (ctx: AppContext) =>
    new EditorController(idbDraftStorage(), pagePendingStore(), {
      onSaved: (record) =>
        patchEditor(ctx.store, (s) => ({
          savedAt: s.draftId === record.id ? record.savedAt : s.savedAt,
          saveProblem: undefined,
          drafts: withSummary(s.drafts, summarize(record)),
        })),
      onError: (e) =>
        patchEditor(ctx.store, {
          // The browser's own sentence (the status line has no technical detail to point to).
          saveProblem: said(editorMessages, "editor.draftSaveFailed", {
            error: e instanceof Error ? e.message : String(e),
          }),
        }),
    }),
);

/** The editor's controller of this page. */
export function editorController(ctx: AppContext): EditorController {
  return ctx.session.pageScope.get(EDITOR);
}
