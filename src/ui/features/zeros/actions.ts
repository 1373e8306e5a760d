import {
  RbcCancelledError,
  RbcDisconnectedError,
  RbcRejectedError,
  RbcVerifyError,
} from "../../../device/errors.ts";
import { ZeroWriteFailedError } from "../../../device/zero-policy.ts";
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
import type { Store } from "../../store.ts";
import { checkDraft, draftTable, factoryDraft, toDraft } from "./editor.ts";
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
  if (store.get().zeros.busy) return;
  patchZeros(store, { busy: "reading", result: undefined, confirming: false });
  try {
    const zeros = await session.run("Reading zeros", (client) => client.readZeros());
    patchZeros(store, {
      busy: undefined,
      stored: zeros,
      draft: toDraft(zeros),
      source: "the robot",
      fileNotice: undefined,
    });
  } catch (e) {
    patchZeros(store, { busy: undefined, result: errorNotice("Reading the zeros failed.", e) });
  }
}

export function useFactoryZeros(ctx: AppContext): void {
  patchZeros(ctx.store, {
    draft: factoryDraft(),
    source: "the factory zeros",
    confirming: false,
    result: undefined,
    fileNotice: {
      tone: "info",
      text: "The factory zeros are in the editor. Nothing is written until you press Write.",
    },
  });
}

/**
 * "Back up zeros": reads the table the robot holds now and saves it in the panel's backup format, under the
 * same name the write path uses (rbc-zeros-<serial>-<date>.json). The editor's unsaved edits are kept; the
 * "Stored" column shows what was just read.
 */
export async function backUpZeros(ctx: AppContext): Promise<void> {
  const { session, store } = ctx;
  if (store.get().zeros.busy) return;
  patchZeros(store, { busy: "backing-up", confirming: false, fileNotice: undefined });
  let zeros: number[];
  try {
    zeros = await session.run("Backing up zeros", (client) => client.readZeros());
  } catch (e) {
    patchZeros(store, {
      busy: undefined,
      fileNotice: errorNotice("No backup was saved: the zeros could not be read from the robot.", e),
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
  const name = zerosBackupFileName(serialNumber, savedAt);
  downloadTextFile(name, serializeZerosBackup(backup), "application/json");
  const z = store.get().zeros;
  patchZeros(store, {
    busy: undefined,
    stored: zeros,
    // Before the first read the editor is empty: fill it with what was read.
    ...(z.draft.length === ZERO_COUNT ? {} : { draft: toDraft(zeros), source: "the robot" }),
    fileNotice: {
      tone: "ok",
      text: `Backup saved as ${name}, ${zeros.length} zeros read from the robot. To put them back later: Restore from backup.`,
    },
  });
}

export async function restoreFromFile(ctx: AppContext, file: File): Promise<void> {
  const { store } = ctx;
  let text: string;
  try {
    text = await file.text();
  } catch (e) {
    patchZeros(store, { fileNotice: errorNotice(`"${file.name}" could not be read.`, e) });
    return;
  }
  const parsed = parseZerosBackup(text);
  if (!parsed.ok) {
    patchZeros(store, {
      fileNotice: {
        tone: "danger",
        text: `"${file.name}" was not loaded. ${parsed.message}`,
        detail: parsed.problem,
      },
    });
    return;
  }
  const warning = serialMismatchWarning(parsed.backup, store.get().connection.serialNumber);
  const saved = new Date(parsed.backup.savedAt).toLocaleString();
  const fileNotice: Notice = warning
    ? { tone: "warning", text: `Loaded "${file.name}" (saved ${saved}) into the editor. ${warning}` }
    : {
        tone: "info",
        text: `Loaded "${file.name}" (saved ${saved}) into the editor. Nothing is written until you press Write.`,
      };
  patchZeros(store, {
    draft: toDraft(parsed.backup.zeros),
    source: `backup ${file.name}`,
    confirming: false,
    result: undefined,
    fileNotice,
  });
}

function failureSentence(e: unknown, backupName: string): Notice {
  const backup = `Backup saved as ${backupName}.`;
  const detail = technicalDetail(e);
  if (e instanceof RbcVerifyError) {
    const wrong = e.expected
      .map((v, id) => (e.readBack[id] === v ? undefined : id))
      .filter((id) => id !== undefined);
    return {
      tone: "danger",
      text: `Zeros were sent but did not verify: read back ${ZERO_COUNT - wrong.length}/${ZERO_COUNT} (servo ${wrong.join(", ")} differ). ${backup} Read the zeros again; restore the backup if needed.`,
      detail,
    };
  }
  if (e instanceof RbcDisconnectedError) {
    return {
      tone: "danger",
      text: `The write did not finish: the robot was disconnected. ${backup} Reconnect and read the zeros before anything else.`,
      detail,
    };
  }
  if (e instanceof RbcCancelledError) {
    return {
      tone: "danger",
      text: `The write was cancelled by Stop. ${backup} Read the zeros to see what the robot holds.`,
      detail,
    };
  }
  if (e instanceof RbcRejectedError) return { tone: "danger", text: `${e.message} ${backup}`, detail };
  return { tone: "danger", text: `Writing the zeros failed. ${errorMessage(e)} ${backup}`, detail };
}

/** Backup first (the robot's current zeros, read fresh), then write, read back and verify. */
export async function writeZerosToRobot(ctx: AppContext): Promise<void> {
  const { session, store } = ctx;
  const state = store.get();
  if (state.zeros.busy) return;
  const table = draftTable(checkDraft(state.zeros.draft));
  if (!table) {
    patchZeros(store, {
      confirming: false,
      result: {
        tone: "danger",
        text: "Nothing was written: some values are not accepted. Fix the marked fields.",
      },
    });
    return;
  }
  patchZeros(store, { busy: "writing", confirming: false, result: undefined });
  let backupName: string | undefined;
  const c = store.get().connection;
  let readBack: number[];
  try {
    // The device's zero-write policy: check, read the current zeros, save them (here: a download), then
    // write, read back and verify. The robot's zeros are never changed before the backup exists.
    const outcome = await session.run("Writing zeros", (client) =>
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
        source: "the robot",
        result: { tone: "ok", text: "The robot already holds these zeros: nothing was written." },
      });
      return;
    }
    readBack = outcome.readBack;
  } catch (e) {
    const cause: unknown = e instanceof ZeroWriteFailedError ? e.reason : e;
    const result = backupName
      ? failureSentence(cause, backupName)
      : errorNotice(
          "Nothing was written: the robot's current zeros could not be read for the backup.",
          cause,
        );
    patchZeros(store, { busy: undefined, result });
    return;
  }
  const verified = readBack.filter((v, id) => v === table[id]).length;
  patchZeros(store, {
    busy: undefined,
    stored: readBack,
    draft: toDraft(readBack),
    source: "the robot",
    fileNotice: undefined,
    result: {
      tone: "verified",
      text: `Zeros written and verified (read back ${verified}/${ZERO_COUNT}). Backup saved as ${backupName}.`,
    },
  });
}
