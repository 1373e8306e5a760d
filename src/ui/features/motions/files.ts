import type { Locale } from "../../../i18n/locale.ts";
import { said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { memoryFootprint } from "../../../protocol/catalog.ts";
import { motionImage } from "../../../protocol/motion-image.ts";
import { motionDurationMs, RbmError, readRbm } from "../../../protocol/rbm.ts";
import { type RbmValidation, validateRbm } from "../../../protocol/rbm-validate.ts";
import { type AppState, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import type { Store } from "../../store.ts";
import { FILE_CHECKS } from "./controllers.ts";
import { motionsMessages } from "./messages.ts";
import { type MotionFileEntry, motionFilesOf, patchMotionFiles } from "./state.ts";

/** Opening .rbm files: read, parse, check and encode them (docs/protocol.md §6.3, §7). */

/** Far above any motion file (29 samples: 2-20 KB); a bigger file is not read at all. */
export const MAX_RBM_BYTES = 1_000_000;

/** A file to open: from the picker, a drop, or one of the project's examples. */
export interface MotionText {
  fileName: string;
  text: string;
  /** Size of the file (the text's length when not given). */
  fileBytes?: number;
  /** The file's bytes as read (the text's UTF-8 when not given). */
  bytes?: Uint8Array;
}

/** Issue codes the panel words itself (in the panel's language); the validator's are English sentences. */
export const PANEL_ISSUE_CODES: readonly string[] = ["unreadable", "too-large"];

/**
 * Reads one file's text as a motion. Never throws: what is wrong ends up in `errors`, in words. A file that
 * breaks the RBC's rules keeps its motion (so its scenes and chart can be shown) but gets no image, so it can
 * never be uploaded.
 */
export function inspectMotionText(
  fileName: string,
  text: string,
  fileBytes = text.length,
  id = 0,
  locale: Locale = "en",
): MotionFileEntry {
  const entry: MotionFileEntry = { id, fileName, fileBytes, errors: [] };
  try {
    entry.motion = readRbm(text);
    entry.errors = validateRbm(entry.motion).errors;
    if (entry.errors.length > 0) return entry;
  } catch (e) {
    entry.errors =
      e instanceof RbmError
        ? [...e.issues]
        : [
            {
              code: "unreadable",
              message: translator(motionsMessages, locale)("motions.files.unreadable", { reason: String(e) }),
            },
          ];
    return entry;
  }
  try {
    entry.image = motionImage(entry.motion);
  } catch (e) {
    entry.errors =
      e instanceof RbmError
        ? [...e.issues]
        : [{ code: "rbm-image", message: e instanceof Error ? e.message : String(e) }];
  }
  return entry;
}

/** A picked or dropped file as text, or the reason it is not read. */
async function readFile(file: File, locale: Locale): Promise<MotionText | MotionFileEntry> {
  if (file.size > MAX_RBM_BYTES) {
    return {
      id: 0,
      fileName: file.name,
      fileBytes: file.size,
      errors: [
        {
          code: "too-large",
          message: translator(motionsMessages, locale)("motions.files.tooLarge", { size: file.size }),
        },
      ],
    };
  }
  const bytes = new Uint8Array(await file.arrayBuffer());
  return { fileName: file.name, text: new TextDecoder().decode(bytes), fileBytes: file.size, bytes };
}

/**
 * Adds motions to the open files and shows the first new one; a file opened again replaces its earlier copy.
 * Picked files, dropped files and examples all come through here.
 */
export function addMotionTexts(
  store: Store<AppState>,
  opened: readonly (MotionText | MotionFileEntry)[],
): void {
  if (opened.length === 0) return;
  const { locale } = store.get();
  const files = motionFilesOf(store.get());
  const added = opened.map((o, i) => {
    const id = files.nextId + i;
    return "text" in o
      ? {
          ...inspectMotionText(o.fileName, o.text, o.fileBytes ?? o.text.length, id, locale),
          bytes: o.bytes ?? new TextEncoder().encode(o.text),
        }
      : { ...o, id };
  });
  const names = new Set(added.map((e) => e.fileName));
  const current = motionFilesOf(store.get());
  const entries = [...current.entries.filter((e) => !names.has(e.fileName)), ...added];
  const bad = added.filter((e) => !e.motion).length;
  patchMotionFiles(store, {
    entries,
    nextId: Math.max(current.nextId, files.nextId + added.length),
    selected: added[0]?.id,
    dragging: false,
    notice:
      added.length === 1
        ? undefined
        : noticeOf(bad > 0 ? "warning" : "info", locale, [
            bad > 0
              ? said(motionsMessages, "motions.files.openedBad", { files: added.length, bad })
              : said(motionsMessages, "motions.files.opened", { files: added.length }),
          ]),
  });
}

/** Adds the files (picker or drop) and shows the first new one. Files that are not .rbm are still tried. */
export async function openMotionFiles(ctx: AppContext, files: readonly File[]): Promise<void> {
  if (files.length === 0) return;
  const { locale } = ctx.store.get();
  addMotionTexts(ctx.store, await Promise.all(files.map((file) => readFile(file, locale))));
}

export function removeMotionFile(ctx: AppContext, id: number): void {
  const files = ctx.store.get().motionFiles;
  if (!files) return;
  const entries = files.entries.filter((e) => e.id !== id);
  patchMotionFiles(ctx.store, {
    entries,
    selected: files.selected === id ? entries[0]?.id : files.selected,
    notice: undefined,
  });
}

export function setDragging(ctx: AppContext, dragging: boolean): void {
  if ((ctx.store.get().motionFiles?.dragging ?? false) !== dragging)
    patchMotionFiles(ctx.store, { dragging });
}

/**
 * Errors and warnings of a file, checked against the connected robot's serial number ("made for another
 * robot"). Pure; `checkedEntry` caches it.
 */
export function checkEntry(entry: MotionFileEntry, serialNumber: string | undefined): RbmValidation {
  if (!entry.motion) return { errors: entry.errors, warnings: [] };
  const checked = validateRbm(entry.motion, serialNumber ? { connectedSerialNumber: serialNumber } : {});
  // Errors found while encoding the image are not rule errors: keep them too.
  const extra = entry.errors.filter(
    (e) => !checked.errors.some((c) => c.code === e.code && c.message === e.message),
  );
  return { errors: [...checked.errors, ...extra], warnings: checked.warnings };
}

/** `checkEntry` against the connected robot, cached for the page (files and robots change rarely). */
export function checkedEntry(ctx: AppContext, entry: MotionFileEntry): RbmValidation {
  const serialNumber = ctx.store.get().connection.serialNumber;
  return ctx.session.pageScope
    .get(FILE_CHECKS)
    .get(entry.id, serialNumber, () => checkEntry(entry, serialNumber));
}

export interface EntryFacts {
  name: string;
  scenes: number;
  servos: number;
  durationMs: number;
  imageBytes: number;
  footprint: number;
}

export function entryFacts(entry: MotionFileEntry): EntryFacts | undefined {
  const { motion, image } = entry;
  if (!motion) return undefined;
  const imageBytes = image?.length ?? 0;
  return {
    name: motion.name,
    scenes: motion.scenes.length,
    servos: motion.servos.length,
    durationMs: motionDurationMs(motion),
    imageBytes,
    footprint: imageBytes > 0 ? memoryFootprint(imageBytes) : 0,
  };
}
