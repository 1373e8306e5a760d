import { memoryFootprint } from "../../protocol/catalog.ts";
import { motionImage } from "../../protocol/motion-image.ts";
import { motionDurationMs, RbmError, readRbm } from "../../protocol/rbm.ts";
import { type RbmValidation, validateRbm } from "../../protocol/rbm-validate.ts";
import type { AppState } from "../app-state.ts";
import type { Store } from "../store.ts";
import type { MotionFileEntry, MotionFilesState } from "./motions-state.ts";

/** Opening .rbm files: read, parse, check and encode them (PROTOCOL.md §6.3, §7). */

/** Far above any motion file (29 samples: 2-20 KB); a bigger file is not read at all. */
export const MAX_RBM_BYTES = 1_000_000;

let nextId = 1;

/**
 * Reads one file's text as a motion. Never throws: what is wrong ends up in `errors`, in words. A file that
 * breaks the RBC's rules keeps its motion (so its scenes and chart can be shown) but gets no image, so it can
 * never be uploaded.
 */
export function inspectMotionText(fileName: string, text: string, fileBytes = text.length): MotionFileEntry {
  const entry: MotionFileEntry = { id: nextId++, fileName, fileBytes, errors: [] };
  try {
    entry.motion = readRbm(text);
    entry.errors = validateRbm(entry.motion).errors;
    if (entry.errors.length > 0) return entry;
  } catch (e) {
    entry.errors =
      e instanceof RbmError
        ? [...e.issues]
        : [{ code: "unreadable", message: `The file could not be read as a motion (${String(e)}).` }];
    return entry;
  }
  try {
    entry.image = motionImage(entry.motion);
  } catch (e) {
    entry.errors = [
      {
        code: e instanceof RbmError ? e.code : "rbm-image",
        message: e instanceof Error ? e.message : String(e),
      },
    ];
  }
  return entry;
}

async function readEntry(file: File): Promise<MotionFileEntry> {
  if (file.size > MAX_RBM_BYTES) {
    return {
      id: nextId++,
      fileName: file.name,
      fileBytes: file.size,
      errors: [
        {
          code: "too-large",
          message: `The file is ${file.size.toLocaleString("en-US")} bytes; a motion file is a few KB. It was not read.`,
        },
      ],
    };
  }
  return inspectMotionText(file.name, await file.text(), file.size);
}

function patchFiles(store: Store<AppState>, patch: Partial<MotionFilesState>): void {
  store.update((s) => ({ motionFiles: { entries: [], ...s.motionFiles, ...patch } }));
}

/** Adds the files (picker or drop) and shows the first new one. Files that are not .rbm are still tried. */
export async function openMotionFiles(store: Store<AppState>, files: readonly File[]): Promise<void> {
  if (files.length === 0) return;
  const added = await Promise.all(files.map(readEntry));
  const current = store.get().motionFiles?.entries ?? [];
  // A file opened again replaces its earlier copy.
  const names = new Set(added.map((e) => e.fileName));
  const entries = [...current.filter((e) => !names.has(e.fileName)), ...added];
  const bad = added.filter((e) => !e.motion).length;
  patchFiles(store, {
    entries,
    selected: added[0]?.id,
    dragging: false,
    notice:
      added.length === 1
        ? undefined
        : {
            tone: bad > 0 ? "warning" : "info",
            text: `Opened ${added.length} files${bad > 0 ? `; ${bad} cannot be used (see below)` : ""}.`,
          },
  });
}

export function removeMotionFile(store: Store<AppState>, id: number): void {
  const files = store.get().motionFiles;
  if (!files) return;
  const entries = files.entries.filter((e) => e.id !== id);
  patchFiles(store, {
    entries,
    selected: files.selected === id ? entries[0]?.id : files.selected,
    notice: undefined,
  });
}

export function selectMotionFile(store: Store<AppState>, id: number): void {
  patchFiles(store, { selected: id });
}

export function setDragging(store: Store<AppState>, dragging: boolean): void {
  if ((store.get().motionFiles?.dragging ?? false) !== dragging) patchFiles(store, { dragging });
}

const validations = new Map<string, RbmValidation>();

/**
 * Errors and warnings of a file, checked against the connected robot's serial number ("made for another
 * robot"). Cached per file and serial number.
 */
export function checkEntry(entry: MotionFileEntry, serialNumber: string | undefined): RbmValidation {
  if (!entry.motion) return { errors: entry.errors, warnings: [] };
  const key = `${entry.id}:${serialNumber ?? ""}`;
  let v = validations.get(key);
  if (!v) {
    const checked = validateRbm(entry.motion, serialNumber ? { connectedSerialNumber: serialNumber } : {});
    // Errors found while encoding the image are not rule errors: keep them too.
    const extra = entry.errors.filter(
      (e) => !checked.errors.some((c) => c.code === e.code && c.message === e.message),
    );
    v = { errors: [...checked.errors, ...extra], warnings: checked.warnings };
    if (validations.size > 200) validations.clear();
    validations.set(key, v);
  }
  return v;
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
