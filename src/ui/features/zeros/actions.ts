import {
  RbcCancelledError,
  RbcDisconnectedError,
  RbcRejectedError,
  RbcVerifyError,
} from "../../../device/errors.ts";
import { ZeroWriteFailedError } from "../../../device/zero-policy.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { zerosNotReadText } from "../../../i18n/outcomes/device.ts";
import { translator } from "../../../i18n/translate.ts";
import { ZERO_COUNT } from "../../../protocol/zeros.ts";
import {
  createZerosBackup,
  parseZerosBackup,
  serializeZerosBackup,
  serialMismatchWarning,
  zerosBackupFileName,
} from "../../../protocol/zeros-backup.ts";
import { formatFirmware } from "../../../shared/format.ts";
import type { AppState, Notice } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { downloadTextFile } from "../../download-file.ts";
import { errorMessage, errorNotice, technicalDetail } from "../../error-text.ts";
import { focusSoon } from "../../focus.ts";
import { formatDateTime } from "../../format.ts";
import type { Store } from "../../store.ts";
import { refusal } from "./backup-refusal.ts";
import { checkDraft, draftTable, factoryDraft, toDraft } from "./editor.ts";
import { type ZerosTranslator, zerosMessages } from "./messages.ts";
import type { ZerosState } from "./state.ts";

/** What the zeros view does: read, edit, back up, write (after a backup), restore, factory zeros. */

function patchZeros(store: Store<AppState>, patch: Partial<ZerosState>): void {
  store.update((s) => ({ zeros: { ...s.zeros, ...patch } }));
}

export function setZeroText(ctx: AppContext, id: number, text: string): void {
  const draft = [...ctx.store.get().zeros.draft];
  draft[id] = text;
  patchZeros(ctx.store, { draft, confirming: false });
}

/** "Write to robot…": asks once, in place, before anything is written. */
export function askToWrite(ctx: AppContext): void {
  patchZeros(ctx.store, { confirming: true });
  focusSoon("confirm-write");
}

export function cancelWrite(ctx: AppContext): void {
  patchZeros(ctx.store, { confirming: false });
}

export async function readZerosFromRobot(ctx: AppContext): Promise<void> {
  const { session, store } = ctx;
  const { zeros: z, locale } = store.get();
  if (z.busy) return;
  const t = translator(zerosMessages, locale);
  patchZeros(store, { busy: "reading", result: undefined, confirming: false });
  try {
    const zeros = await session.run(t("zeros.runReading"), (client) => client.readZeros());
    patchZeros(store, {
      busy: undefined,
      stored: zeros,
      draft: toDraft(zeros),
      source: { kind: "robot" },
      fileNotice: undefined,
    });
  } catch (e) {
    patchZeros(store, { busy: undefined, result: errorNotice(t("zeros.readFailed"), e, locale) });
  }
}

export function useFactoryZeros(ctx: AppContext): void {
  const t = translator(zerosMessages, ctx.store.get().locale);
  patchZeros(ctx.store, {
    draft: factoryDraft(),
    source: { kind: "factory" },
    confirming: false,
    result: undefined,
    fileNotice: { tone: "info", text: t("zeros.factoryLoaded") },
  });
}

/**
 * "Back up zeros": reads the table the robot holds now and saves it in the panel's backup format, under the
 * same name the write path uses (rbc-zeros-<serial>-<date>.json). The editor's unsaved edits are kept; the
 * "Stored" column shows what was just read.
 */
export async function backUpZeros(ctx: AppContext): Promise<void> {
  const { session, store } = ctx;
  const { zeros: before, locale } = store.get();
  if (before.busy) return;
  const t = translator(zerosMessages, locale);
  patchZeros(store, { busy: "backing-up", confirming: false, fileNotice: undefined });
  let zeros: number[];
  try {
    zeros = await session.run(t("zeros.runBackingUp"), (client) => client.readZeros());
  } catch (e) {
    patchZeros(store, { busy: undefined, fileNotice: errorNotice(t("zeros.backupReadFailed"), e, locale) });
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
  const name = zerosBackupFileName(serialNumber, savedAt);
  downloadTextFile(name, serializeZerosBackup(backup), "application/json");
  const z = store.get().zeros;
  patchZeros(store, {
    busy: undefined,
    stored: zeros,
    // Before the first read the editor is empty: fill it with what was read.
    ...(z.draft.length === ZERO_COUNT ? {} : { draft: toDraft(zeros), source: { kind: "robot" } }),
    fileNotice: { tone: "ok", text: t("zeros.backupDone", { file: name, count: zeros.length }) },
  });
}

export async function restoreFromFile(ctx: AppContext, file: File): Promise<void> {
  const { store } = ctx;
  const { locale } = store.get();
  const t = translator(zerosMessages, locale);
  let text: string;
  try {
    text = await file.text();
  } catch (e) {
    patchZeros(store, { fileNotice: errorNotice(t("zeros.fileUnreadable", { file: file.name }), e, locale) });
    return;
  }
  const parsed = parseZerosBackup(text);
  if (!parsed.ok) {
    patchZeros(store, { fileNotice: refusal(file, text, parsed, t) });
    return;
  }
  const { backup } = parsed;
  const serial = store.get().connection.serialNumber;
  const saved = formatDateTime(new Date(backup.savedAt), locale);
  // serialMismatchWarning decides (the CLI warns with its sentence); the panel says it in its language.
  const fileNotice: Notice =
    serial !== undefined && serialMismatchWarning(backup, serial)
      ? {
          tone: "warning",
          text: t("zeros.loadedOtherRobot", {
            file: file.name,
            saved,
            backupSerial: backup.serialNumber || t("zeros.unknownRobot"),
            serial,
          }),
        }
      : { tone: "info", text: t("zeros.loaded", { file: file.name, saved }) };
  patchZeros(store, {
    draft: toDraft(backup.zeros),
    source: { kind: "backup", file: file.name },
    confirming: false,
    result: undefined,
    fileNotice,
  });
}

function failureSentence(e: unknown, file: string, t: ZerosTranslator): Notice {
  const backup = t("zeros.backupSaved", { file });
  const detail = technicalDetail(e);
  if (e instanceof RbcVerifyError) {
    const wrong = e.expected
      .map((v, id) => (e.readBack[id] === v ? undefined : id))
      .filter((id) => id !== undefined);
    return {
      tone: "danger",
      text: t("zeros.verifyFailed", {
        read: ZERO_COUNT - wrong.length,
        total: ZERO_COUNT,
        servos: wrong.join(", "),
        file,
      }),
      detail,
    };
  }
  if (e instanceof RbcDisconnectedError) {
    return { tone: "danger", text: t("zeros.writeDisconnected", { file }), detail };
  }
  if (e instanceof RbcCancelledError) {
    return { tone: "danger", text: t("zeros.writeCancelled", { file }), detail };
  }
  if (e instanceof RbcRejectedError) {
    return { tone: "danger", text: `${errorMessage(e, t.locale)} ${backup}`, detail };
  }
  return {
    tone: "danger",
    text: `${t("zeros.writeFailed")} ${errorMessage(e, t.locale)} ${backup}`,
    detail,
  };
}

/** Backup first (the robot's current zeros, read fresh), then write, read back and verify. */
export async function writeZerosToRobot(ctx: AppContext): Promise<void> {
  const { session, store } = ctx;
  const state = store.get();
  if (state.zeros.busy) return;
  const locale: Locale = state.locale;
  const t = translator(zerosMessages, locale);
  const table = draftTable(checkDraft(state.zeros.draft, locale));
  if (!table) {
    patchZeros(store, { confirming: false, result: { tone: "danger", text: t("zeros.invalidValues") } });
    return;
  }
  patchZeros(store, { busy: "writing", confirming: false, result: undefined });
  let backupName: string | undefined;
  const c = store.get().connection;
  let readBack: number[];
  try {
    // The device's zero-write policy: check, read the current zeros, save them (here: a download), then
    // write, read back and verify. The robot's zeros are never changed before the backup exists.
    const outcome = await session.run(t("zeros.runWriting"), (client) =>
      client.writeZerosWithBackup(table, {
        robot: {
          serialNumber: c.serialNumber,
          firmware: c.firmware ? formatFirmware(c.firmware) : undefined,
        },
        saveBackup: (backup, name) => {
          downloadTextFile(name, serializeZerosBackup(backup), "application/json");
          backupName = name;
          return name;
        },
      }),
    );
    if (!outcome.changed) {
      patchZeros(store, {
        busy: undefined,
        stored: outcome.current,
        draft: toDraft(outcome.current),
        source: { kind: "robot" },
        result: { tone: "ok", text: t("zeros.alreadyHeld") },
      });
      return;
    }
    readBack = outcome.readBack;
  } catch (e) {
    const cause: unknown = e instanceof ZeroWriteFailedError ? e.reason : e;
    const result = backupName
      ? failureSentence(cause, backupName, t)
      : errorNotice(zerosNotReadText(locale), cause, locale);
    patchZeros(store, { busy: undefined, result });
    return;
  }
  const verified = readBack.filter((v, id) => v === table[id]).length;
  patchZeros(store, {
    busy: undefined,
    stored: readBack,
    draft: toDraft(readBack),
    source: { kind: "robot" },
    fileNotice: undefined,
    result: {
      tone: "verified",
      text: t("zeros.written", { read: verified, total: ZERO_COUNT, file: backupName ?? "" }),
    },
  });
}
