/**
 * Saves a file the panel made: through the browser's Save dialog where there is one (the File System Access
 * API, `showSaveFilePicker`: Chrome and Edge on a computer), so the page writes the file itself and knows the
 * name it went under; else as a download, which is only offered: the browser may ask where, rename it ("… (1)")
 * or be told no, and the page is never told. The zero backups save through it too (features/zeros/backup-file.ts).
 */

export type SavedFile =
  | { kind: "written"; name: string }
  | { kind: "offered"; name: string }
  /** The person closed the Save dialog: no file. */
  | { kind: "cancelled" };

export interface SaveFileOptions {
  /** What the Save dialog calls the file type ("Motionbuilder motion"). */
  description: string;
  mime: string;
  extension: string;
}

interface WritableFile {
  write(data: Blob): Promise<void>;
  close(): Promise<void>;
}

interface SaveFilePickerWindow {
  showSaveFilePicker?: (options: {
    suggestedName: string;
    types: { description: string; accept: Record<string, string[]> }[];
  }) => Promise<{ name: string; createWritable(): Promise<WritableFile> }>;
}

function isAbort(e: unknown): boolean {
  return e instanceof DOMException && e.name === "AbortError";
}

/** Offers `blob` as a download named `name` (the browser decides where it goes; the page is never told). */
export function offerDownload(name: string, blob: Blob): void {
  const url = URL.createObjectURL(blob);
  const a = document.createElement("a");
  a.href = url;
  a.download = name;
  a.hidden = true;
  document.body.append(a);
  a.click();
  a.remove();
  // Give the browser time to start the download before the URL goes away.
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}

/**
 * Saves `data` (bytes exactly as given, or text as UTF-8) under `suggestedName`. A Save dialog that cannot open
 * (no user gesture any more, a policy) falls back to the download; a write that fails after the dialog throws.
 */
export async function saveFile(
  data: Uint8Array | string,
  suggestedName: string,
  options: SaveFileOptions,
): Promise<SavedFile> {
  const blob = new Blob([typeof data === "string" ? data : new Uint8Array(data)], { type: options.mime });
  const picker = (globalThis as SaveFilePickerWindow).showSaveFilePicker;
  if (picker) {
    let handle: Awaited<ReturnType<NonNullable<SaveFilePickerWindow["showSaveFilePicker"]>>> | undefined;
    try {
      handle = await picker({
        suggestedName,
        types: [{ description: options.description, accept: { [options.mime]: [options.extension] } }],
      });
    } catch (e) {
      if (isAbort(e)) return { kind: "cancelled" };
      handle = undefined;
    }
    if (handle) {
      const writable = await handle.createWritable();
      await writable.write(blob);
      await writable.close();
      return { kind: "written", name: handle.name };
    }
  }
  offerDownload(suggestedName, blob);
  return { kind: "offered", name: suggestedName };
}
