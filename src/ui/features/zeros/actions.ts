import {
  RbcCancelledError,
  RbcDisconnectedError,
  RbcRejectedError,
  RbcVerifyError,
} from "../../../device/errors.ts";
import { ZeroBackupError, ZeroWriteFailedError } from "../../../device/zero-policy.ts";
import type { ParamArgs } from "../../../i18n/catalogue.ts";
import { errorSaid } from "../../../i18n/error-said.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { deviceOutcomeMessages } from "../../../i18n/outcomes/messages.ts";
import { serialMismatchWarning } from "../../../i18n/outcomes/zero-words.ts";
import { inEveryLanguage, type LocalText, type Said, said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { ZERO_COUNT } from "../../../protocol/zeros.ts";
import {
  createZerosBackup,
  parseZerosBackup,
  type ZerosBackup,
  zerosBackupFileName,
} from "../../../protocol/zeros-backup.ts";
import { formatFirmware } from "../../../shared/format.ts";
import { type AppState, type Notice, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice, technicalDetail } from "../../error-text.ts";
import { failureNotice } from "../../failure-notice.ts";
import { focusSoon } from "../../focus.ts";
import { formatDateTime } from "../../format.ts";
import type { Store } from "../../store.ts";
import { type BackupFileOutcome, saveBackupFile } from "./backup-file.ts";
import { refusal } from "./backup-refusal.ts";
import { idbBackupStorage, type KeptBackup, keepBackup, keptBackups } from "./backup-store.ts";
import { checkDraft, draftTable, factoryDraft, toDraft } from "./editor.ts";
import { trimChanged, trimWriteBegins, trimWriteEnded } from "./live/trim-live.ts";
import { zerosMessages } from "./messages.ts";
import type { ZerosState } from "./state.ts";
import { discardFirst, offerKeptDraft } from "./unwritten.ts";

/** What the zeros view does: read, edit, back up, write (after a backup), restore, factory zeros. */

function patchZeros(store: Store<AppState>, patch: Partial<ZerosState>): void {
  store.update((s) => ({ zeros: { ...s.zeros, ...patch } }));
}

export function setZeroText(ctx: AppContext, id: number, text: string): void {
  const draft = [...ctx.store.get().zeros.draft];
  draft[id] = text;
  patchZeros(ctx.store, { draft, confirming: false });
  // Trim live: that servo moves to the new value (clamped), and only that one.
  trimChanged(ctx, id, text);
}

/** "Write to robot…": asks once, in place, before anything is written. */
export function askToWrite(ctx: AppContext): void {
  patchZeros(ctx.store, { confirming: true });
  focusSoon("confirm-write");
}

export function cancelWrite(ctx: AppContext): void {
  patchZeros(ctx.store, { confirming: false });
}

/** "Read from robot": asks first when it would replace unwritten changes (unwritten.ts). */
export function askToRead(ctx: AppContext): void {
  discardFirst(ctx, { kind: "read" }, () => void readZerosFromRobot(ctx));
}

export async function readZerosFromRobot(ctx: AppContext): Promise<void> {
  const { session, store } = ctx;
  const { zeros: z, locale } = store.get();
  if (z.busy) return;
  // The first read of this connection: unwritten changes kept for this robot are offered back.
  const first = z.stored === undefined;
  patchZeros(store, { busy: "reading", result: undefined, confirming: false });
  try {
    const zeros = await session.run(said(zerosMessages, "zeros.runReading"), (client) => client.readZeros());
    patchZeros(store, {
      busy: undefined,
      stored: zeros,
      draft: toDraft(zeros),
      source: { kind: "robot" },
      fileNotice: undefined,
      ...(first ? offerKeptDraft(ctx, zeros) : undefined),
    });
  } catch (e) {
    patchZeros(store, {
      busy: undefined,
      result: errorNotice(said(zerosMessages, "zeros.readFailed"), e, locale),
    });
  }
}

export function useFactoryZeros(ctx: AppContext): void {
  discardFirst(ctx, { kind: "factory" }, () =>
    patchZeros(ctx.store, {
      draft: factoryDraft(),
      source: { kind: "factory" },
      confirming: false,
      result: undefined,
      fileNotice: noticeOf("info", ctx.store.get().locale, [say("zeros.factoryLoaded")]),
    }),
  );
}

/** Where a backup went: kept in this browser (or not), and its file, never more than the page knows. */
interface BackupSaved {
  kept: boolean;
  file: BackupFileOutcome;
}

/**
 * Keeps a backup in this browser and saves its file (backup-file.ts). Keeping it is tried first, so a backup
 * exists even when no file does; a failure to keep it is reported, not fatal. The list in the view is read
 * again.
 */
async function saveBackup(ctx: AppContext, backup: ZerosBackup, name: string): Promise<BackupSaved> {
  let kept = false;
  try {
    await keepBackup(await idbBackupStorage(), backup);
    kept = true;
  } catch {
    kept = false;
  }
  const file = await saveBackupFile(backup, name);
  if (kept) void loadKeptBackups(ctx);
  return { kept, file };
}

/** What the page knows of where a backup went, as one fact ("Backup file written: … It is kept …"). */
function whereSaid({ kept, file }: BackupSaved): Said {
  const fileSaid =
    file.kind === "written"
      ? say("zeros.fileWritten", { file: file.name })
      : file.kind === "offered"
        ? say("zeros.fileOffered", { file: file.name })
        : say("zeros.fileCancelled");
  return say("zeros.twoSentences", {
    first: fileSaid,
    second: kept ? say("zeros.keptInBrowser") : say("zeros.notKeptInBrowser"),
  });
}

const say = <K extends keyof typeof zerosMessages & string>(
  key: K,
  ...facts: ParamArgs<(typeof zerosMessages)[K], Said | LocalText>
): Said => said(zerosMessages, key, ...facts);

/** The backups kept in this browser, into the view's list (an unreadable database: an empty list). */
export async function loadKeptBackups(ctx: AppContext): Promise<void> {
  let kept: KeptBackup[];
  try {
    kept = await keptBackups(await idbBackupStorage());
  } catch {
    kept = [];
  }
  patchZeros(ctx.store, { kept });
}

/**
 * "Back up zeros": reads the table the robot holds now, keeps it in this browser and saves it as a file in the
 * panel's backup format, under the same name the write path uses (rbc-zeros-<serial>-<date>.json). The
 * editor's unsaved edits are kept; the "Stored" column shows what was just read.
 */
export async function backUpZeros(ctx: AppContext): Promise<void> {
  const { session, store } = ctx;
  const { zeros: before, locale } = store.get();
  if (before.busy) return;
  patchZeros(store, { busy: "backing-up", confirming: false, fileNotice: undefined });
  let zeros: number[];
  try {
    zeros = await session.run(said(zerosMessages, "zeros.runBackingUp"), (client) => client.readZeros());
  } catch (e) {
    patchZeros(store, {
      busy: undefined,
      fileNotice: failureNotice(say("zeros.backupReadFailed"), e, locale),
    });
    return;
  }
  const c = store.get().connection;
  const savedAt = new Date();
  const serialNumber = c.serialNumber ?? "unknown";
  const backup = createZerosBackup({
    serialNumber,
    firmware: c.firmware ? formatFirmware(c.firmware) : "unknown",
    zeros,
    savedAt,
  });
  let saved: BackupSaved;
  try {
    saved = await saveBackup(ctx, backup, zerosBackupFileName(serialNumber, savedAt));
  } catch (e) {
    patchZeros(store, {
      busy: undefined,
      fileNotice: errorNotice(said(zerosMessages, "zeros.notKeptInBrowser"), e, locale),
    });
    return;
  }
  const z = store.get().zeros;
  const sure = saved.kept || saved.file.kind === "written";
  patchZeros(store, {
    busy: undefined,
    stored: zeros,
    // Before the first read the editor is empty: fill it with what was read (and what was kept unwritten).
    ...(z.draft.length === ZERO_COUNT
      ? {}
      : { draft: toDraft(zeros), source: { kind: "robot" }, ...offerKeptDraft(ctx, zeros) }),
    fileNotice: noticeOf(sure ? "ok" : "warning", locale, [
      say("zeros.backupDone", { count: zeros.length }),
      whereSaid(saved),
    ]),
  });
}

/** "Restore" in the list of backups kept in this browser: into the editor; nothing is written. */
export function restoreKeptBackup(ctx: AppContext, kept: KeptBackup): void {
  discardFirst(ctx, { kind: "kept", savedAt: kept.backup.savedAt }, () => putKeptBackup(ctx, kept));
}

function putKeptBackup(ctx: AppContext, kept: KeptBackup): void {
  const { store } = ctx;
  const { backup } = kept;
  const serial = store.get().connection.serialNumber;
  const saved = inEveryLanguage((locale) => formatDateTime(new Date(backup.savedAt), locale));
  const fileNotice: Notice =
    serial !== undefined && serialMismatchWarning(backup, serial)
      ? noticeOf("warning", store.get().locale, [
          say("zeros.keptLoadedOtherRobot", {
            saved,
            backupSerial: backup.serialNumber || say("zeros.unknownRobot"),
            serial,
          }),
        ])
      : noticeOf("info", store.get().locale, [say("zeros.keptLoaded", { saved })]);
  patchZeros(store, {
    draft: toDraft(backup.zeros),
    source: { kind: "kept", savedAt: backup.savedAt },
    confirming: false,
    result: undefined,
    fileNotice,
  });
  focusSoon("zero-0");
}

export async function restoreFromFile(ctx: AppContext, file: File): Promise<void> {
  const { store } = ctx;
  const { locale } = store.get();
  const t = translator(zerosMessages, locale);
  let text: string;
  try {
    text = await file.text();
  } catch (e) {
    patchZeros(store, {
      fileNotice: errorNotice(said(zerosMessages, "zeros.fileUnreadable", { file: file.name }), e, locale),
    });
    return;
  }
  const parsed = parseZerosBackup(text);
  if (!parsed.ok) {
    patchZeros(store, { fileNotice: refusal(file, parsed, t.locale) });
    return;
  }
  const { backup } = parsed;
  const serial = store.get().connection.serialNumber;
  const saved = inEveryLanguage((l) => formatDateTime(new Date(backup.savedAt), l));
  // serialMismatchWarning decides (the CLI warns with its sentence); the panel says it in its language.
  const fileNotice: Notice =
    serial !== undefined && serialMismatchWarning(backup, serial)
      ? noticeOf("warning", locale, [
          say("zeros.loadedOtherRobot", {
            file: file.name,
            saved,
            backupSerial: backup.serialNumber || say("zeros.unknownRobot"),
            serial,
          }),
        ])
      : noticeOf("info", locale, [say("zeros.loaded", { file: file.name, saved })]);
  discardFirst(ctx, { kind: "file", file: file.name }, () =>
    patchZeros(store, {
      draft: toDraft(backup.zeros),
      source: { kind: "backup", file: file.name },
      confirming: false,
      result: undefined,
      fileNotice,
    }),
  );
}

/** Why the backup step ended the write (the Save dialog closed): nothing was written. */
class BackupDialogClosed extends Error {
  constructor(readonly saved: BackupSaved) {
    super("The Save dialog for the backup file was closed: nothing was written.");
  }
}

function failureSentence(e: unknown, saved: BackupSaved, locale: Locale): Notice {
  const backup = whereSaid(saved);
  const detail = technicalDetail(e);
  if (e instanceof RbcVerifyError) {
    const wrong = e.expected
      .map((v, id) => (e.readBack[id] === v ? undefined : id))
      .filter((id) => id !== undefined);
    return noticeOf(
      "danger",
      locale,
      [
        say("zeros.verifyFailed", {
          read: ZERO_COUNT - wrong.length,
          total: ZERO_COUNT,
          servos: wrong.join(", "),
          backup,
        }),
      ],
      detail,
    );
  }
  if (e instanceof RbcDisconnectedError) {
    return noticeOf("danger", locale, [say("zeros.writeDisconnected", { backup })], detail);
  }
  if (e instanceof RbcCancelledError) {
    return noticeOf("danger", locale, [say("zeros.writeCancelled", { backup })], detail);
  }
  if (e instanceof RbcRejectedError) {
    return noticeOf("danger", locale, [errorSaid(e), backup], detail);
  }
  return noticeOf("danger", locale, [say("zeros.writeFailed"), errorSaid(e), backup], detail);
}

/**
 * Backup first (the robot's current zeros, read fresh, kept in this browser and saved as a file), then write,
 * read back and verify. Closing the backup's Save dialog writes nothing.
 */
export async function writeZerosToRobot(ctx: AppContext): Promise<void> {
  const { session, store } = ctx;
  const state = store.get();
  if (state.zeros.busy) return;
  const locale: Locale = state.locale;
  const table = draftTable(checkDraft(state.zeros.draft, locale));
  if (!table) {
    patchZeros(store, {
      confirming: false,
      result: noticeOf("danger", locale, [say("zeros.invalidValues")]),
    });
    return;
  }
  // Trim live on: Write leaves direct mode (the servos hold the trimmed pose) and ends it (trim-live.ts).
  const trimming = trimWriteBegins(ctx);
  const trimEnded = (): Said[] => (trimming ? [trimWriteEnded(ctx)] : []);
  patchZeros(store, { busy: "writing", confirming: false, result: undefined });
  let saved: BackupSaved | undefined;
  const c = store.get().connection;
  let readBack: number[];
  try {
    // The device's zero-write policy: check, read the current zeros, save them (here: kept in this browser and
    // saved as a file), then write, read back and verify. The robot's zeros are never changed before the
    // backup exists.
    const outcome = await session.run(said(zerosMessages, "zeros.runWriting"), (client) =>
      client.writeZerosWithBackup(table, {
        robot: {
          serialNumber: c.serialNumber,
          firmware: c.firmware ? formatFirmware(c.firmware) : undefined,
        },
        saveBackup: async (backup, name) => {
          const where = await saveBackup(ctx, backup, name);
          if (where.file.kind === "cancelled") throw new BackupDialogClosed(where);
          saved = where;
          return where.file.name;
        },
      }),
    );
    if (!outcome.changed) {
      patchZeros(store, {
        busy: undefined,
        stored: outcome.current,
        draft: toDraft(outcome.current),
        source: { kind: "robot" },
        result: noticeOf("ok", locale, [say("zeros.alreadyHeld"), ...trimEnded()]),
      });
      return;
    }
    readBack = outcome.readBack;
  } catch (e) {
    const cause: unknown =
      e instanceof ZeroWriteFailedError ? e.reason : e instanceof ZeroBackupError ? e.cause : e;
    const result =
      cause instanceof BackupDialogClosed
        ? noticeOf("warning", locale, [
            say("zeros.writeCancelledAtSave"),
            cause.saved.kept ? say("zeros.keptInBrowser") : say("zeros.notKeptInBrowser"),
          ])
        : saved
          ? failureSentence(cause, saved, locale)
          : failureNotice(said(deviceOutcomeMessages, "outcome.zerosNotRead"), cause, locale);
    const ended = trimEnded();
    patchZeros(store, {
      busy: undefined,
      result:
        ended.length > 0 && result.said
          ? noticeOf(result.tone, locale, [...result.said, ...ended], result.detail)
          : result,
    });
    return;
  }
  const verified = readBack.filter((v, id) => v === table[id]).length;
  patchZeros(store, {
    busy: undefined,
    stored: readBack,
    draft: toDraft(readBack),
    source: { kind: "robot" },
    fileNotice: undefined,
    result: noticeOf("verified", locale, [
      say("zeros.written", { read: verified, total: ZERO_COUNT }),
      ...(saved ? [whereSaid(saved)] : []),
      ...trimEnded(),
    ]),
  });
}
