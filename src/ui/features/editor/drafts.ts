import { inEveryLanguage, type Said, said, wordOf } from "../../../i18n/said.ts";
import { RBM_MAX_TEXT_LENGTH } from "../../../protocol/rbm.ts";
import { z } from "../../../protocol/zod.ts";
import { editorMessages } from "./messages.ts";

/**
 * Drafts: every motion being edited is kept on this computer (IndexedDB), so a reload, a crash or a closed tab
 * loses nothing (issue #12 item 2).
 *
 * A draft record is small and versioned: `{ version: 1, id, name, savedAt, rbm }`, where `rbm` is the motion as
 * Motionbuilder's file text (`saveMotion`), so a draft is exactly the file it exports. Records are checked with
 * zod when read back: a record that does not match (a later version, a damaged database) is reported and
 * skipped, never trusted. Storage sits behind `DraftStorage`, so tests use a Map and the panel uses idb-keyval,
 * loaded only when the editor opens (it stays out of the first page load). Why a record is not usable is kept
 * as a message (key and facts), worded when drawn, so it follows a language switch.
 */

export const DRAFT_VERSION = 1;

export interface DraftRecord {
  version: typeof DRAFT_VERSION;
  /** The key the record is stored under. */
  id: string;
  /** The motion's name when it was saved (for the Drafts list). */
  name: string;
  /** Epoch ms of the save. */
  savedAt: number;
  /** The motion as `.rbm` text (`saveMotion`). */
  rbm: string;
}

/** Longest draft id the panel makes or accepts. */
const MAX_ID = 100;

const draftSchema = z.object({
  version: z.literal(DRAFT_VERSION),
  id: z.string().min(1).max(MAX_ID),
  name: z.string().max(200),
  savedAt: z.number().int().nonnegative(),
  rbm: z.string().min(1).max(RBM_MAX_TEXT_LENGTH),
});

/** Where drafts are kept: IndexedDB in the panel, a Map in tests. */
export interface DraftStorage {
  entries(): Promise<[key: string, value: unknown][]>;
  get(key: string): Promise<unknown>;
  set(key: string, record: DraftRecord): Promise<void>;
  delete(key: string): Promise<void>;
}

/** A storage in memory (tests, and a browser where IndexedDB cannot be opened). */
export function memoryDraftStorage(map: Map<string, unknown> = new Map()): DraftStorage {
  return {
    entries: async () => [...map.entries()],
    get: async (key) => map.get(key),
    set: async (key, record) => {
      map.set(key, record);
    },
    delete: async (key) => {
      map.delete(key);
    },
  };
}

export const DRAFT_DATABASE = "rbc-panel-drafts";
export const DRAFT_STORE = "drafts";

/** The drafts in IndexedDB (database "rbc-panel-drafts", store "drafts"); idb-keyval is loaded on first use. */
export async function idbDraftStorage(): Promise<DraftStorage> {
  const idb = await import("idb-keyval");
  const store = idb.createStore(DRAFT_DATABASE, DRAFT_STORE);
  return {
    entries: async () => (await idb.entries(store)).map(([key, value]) => [String(key), value]),
    get: (key) => idb.get(key, store),
    set: (key, record) => idb.set(key, record, store),
    delete: (key) => idb.del(key, store),
  };
}

/** A record read back, or why it cannot be used (a message, worded when drawn). */
export type DraftRead = { ok: true; record: DraftRecord } | { ok: false; key: string; problem: Said };

/** Checks one stored value; what is wrong is kept as a message. Never throws. */
export function readDraft(key: string, value: unknown): DraftRead {
  const version = (value as { version?: unknown } | null)?.version;
  if (typeof version === "number" && version !== DRAFT_VERSION) {
    const facts = { version: String(version), supported: String(DRAFT_VERSION) };
    return { ok: false, key, problem: said(editorMessages, "editor.draftProblem.newer", facts) };
  }
  const parsed = draftSchema.safeParse(value);
  if (!parsed.success) {
    const first = parsed.error.issues[0];
    const where = first && first.path.length > 0 ? ` (${first.path.join(".")})` : "";
    // The schema's own words are English: in another language the panel says what they mean.
    const shapeReason = said(editorMessages, "editor.draftProblem.shapeReason");
    const schemaWords = first?.message;
    const reason = inEveryLanguage((locale) =>
      locale === "en" && schemaWords !== undefined ? schemaWords : wordOf(shapeReason, locale),
    );
    return { ok: false, key, problem: said(editorMessages, "editor.draftProblem.shape", { where, reason }) };
  }
  if (parsed.data.id !== key) {
    const facts = { key, id: parsed.data.id };
    return { ok: false, key, problem: said(editorMessages, "editor.draftProblem.key", facts) };
  }
  return { ok: true, record: parsed.data as DraftRecord };
}

/** A draft as the Drafts list shows it. */
export interface DraftSummary {
  id: string;
  name: string;
  savedAt: number;
  /** Number of scenes (field 9 of the text), undefined if the text does not say. */
  scenes: number | undefined;
}

/** A stored value that is not a usable draft: its key and why (a message, worded when drawn). */
export interface BrokenDraft {
  key: string;
  problem: Said;
}

export interface DraftListing {
  /** The usable drafts, the most recently saved first. */
  drafts: DraftSummary[];
  broken: BrokenDraft[];
}

/** Scenes of an `.rbm` text without parsing it: field 9 (docs/protocol.md §7). */
export function sceneCountOf(rbm: string): number | undefined {
  const field = rbm.split(":", 10)[9];
  return field !== undefined && /^\d{1,4}$/.test(field) ? Number(field) : undefined;
}

export function summarize(record: DraftRecord): DraftSummary {
  return { id: record.id, name: record.name, savedAt: record.savedAt, scenes: sceneCountOf(record.rbm) };
}

/** Every draft in the storage, checked; broken records are listed apart (with why), never thrown. */
export async function listDrafts(storage: DraftStorage): Promise<DraftListing> {
  const drafts: DraftSummary[] = [];
  const broken: BrokenDraft[] = [];
  for (const [key, value] of await storage.entries()) {
    const read = readDraft(key, value);
    if (read.ok) drafts.push(summarize(read.record));
    else broken.push({ key: read.key, problem: read.problem });
  }
  drafts.sort((a, b) => b.savedAt - a.savedAt || a.id.localeCompare(b.id));
  return { drafts, broken };
}

/** One draft, checked; undefined when there is none under `id`. */
export async function loadDraft(storage: DraftStorage, id: string): Promise<DraftRead | undefined> {
  const value = await storage.get(id);
  return value === undefined ? undefined : readDraft(id, value);
}

/**
 * The motion text a stored value carries, whether or not it is a usable draft (a draft set aside because its
 * motion does not open can still be exported as it is): `rbm` of a record, or the value itself if it is text.
 */
export function storedRbmText(value: unknown): string | undefined {
  if (typeof value === "string") return value.length > 0 ? value : undefined;
  const rbm = (value as { rbm?: unknown } | null)?.rbm;
  return typeof rbm === "string" && rbm.length > 0 ? rbm : undefined;
}

/** The name a stored value gives itself, if any (for a set-aside draft's file name). */
export function storedName(value: unknown): string | undefined {
  const name = (value as { name?: unknown } | null)?.name;
  return typeof name === "string" && name.length > 0 ? name : undefined;
}

/** A new draft id: the time and 8 random hex digits ("d-lz3k9q-1a2b3c4d"). */
export function newDraftId(now: number, random: () => number = Math.random): string {
  const hex = Math.floor(random() * 0x1_0000_0000)
    .toString(16)
    .padStart(8, "0");
  return `d-${now.toString(36)}-${hex}`;
}

export function draftRecord(id: string, name: string, rbm: string, savedAt: number): DraftRecord {
  return { version: DRAFT_VERSION, id, name, savedAt, rbm };
}

/**
 * Where the one change that waits when the page goes away is written synchronously (localStorage in the panel:
 * an IndexedDB write started while a page unloads may never finish). The next start moves it into the drafts.
 */
export interface PendingDraftStore {
  write(record: DraftRecord): void;
  /** The value written last (removed), or undefined. */
  take(): unknown;
}

export const PENDING_DRAFT_KEY = "rbc-panel-draft-pending";

/** The pending change in a `Storage` (localStorage) under "rbc-panel-draft-pending". */
export function storagePendingStore(
  storage: Pick<Storage, "getItem" | "setItem" | "removeItem">,
): PendingDraftStore {
  return {
    write: (record) => storage.setItem(PENDING_DRAFT_KEY, JSON.stringify(record)),
    take: () => {
      const text = storage.getItem(PENDING_DRAFT_KEY);
      if (text === null) return undefined;
      storage.removeItem(PENDING_DRAFT_KEY);
      try {
        return JSON.parse(text) as unknown;
      } catch {
        return text;
      }
    },
  };
}

/**
 * Moves the change written when the page went away into the drafts, unless the stored draft is as new. A value
 * that is not a draft is reported (and dropped), never stored.
 */
export async function recoverPending(
  storage: DraftStorage,
  pending: PendingDraftStore,
): Promise<BrokenDraft | undefined> {
  const value = pending.take();
  if (value === undefined) return undefined;
  const id = (value as { id?: unknown } | null)?.id;
  const read = readDraft(typeof id === "string" ? id : PENDING_DRAFT_KEY, value);
  if (!read.ok) return { key: PENDING_DRAFT_KEY, problem: read.problem };
  const stored = await storage.get(read.record.id);
  const current = stored === undefined ? undefined : readDraft(read.record.id, stored);
  if (!current?.ok || current.record.savedAt < read.record.savedAt)
    await storage.set(read.record.id, read.record);
  return undefined;
}
