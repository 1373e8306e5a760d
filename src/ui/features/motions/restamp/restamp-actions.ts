import type { AppContext } from "../../../context.ts";
import { motionFilesOf, patchMotionFiles } from "../state.ts";
import { saveRestampedCopy } from "./restamp-save.ts";

/**
 * Motions: saves a copy of an opened file with `serial` (13 digits, or zeros) in field 2, from the file's own
 * bytes (every other byte as it was), and puts the result beside the file.
 */
export async function restampMotionFile(ctx: AppContext, entryId: number, serial: string): Promise<void> {
  const { locale } = ctx.store.get();
  const entry = motionFilesOf(ctx.store.get()).entries.find((e) => e.id === entryId);
  if (!entry?.bytes) return;
  const notice = await saveRestampedCopy(entry.bytes, entry.fileName, serial, locale);
  const entries = motionFilesOf(ctx.store.get()).entries.map((e) =>
    e.id === entryId ? { ...e, restamped: notice } : e,
  );
  patchMotionFiles(ctx.store, { entries });
}
