import { readFileSync } from "node:fs";
import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import {
  addScene,
  type Motion,
  MotionError,
  newMotion,
  openMotion,
  saveMotion,
  setPosition,
} from "../../src/motion/index.ts";
import { Autosaver } from "../../src/ui/features/editor/autosave.ts";
import { findLatestDraft, readDraftDocument } from "../../src/ui/features/editor/draft-actions.ts";
import {
  DRAFT_VERSION,
  type DraftRecord,
  draftRecord,
  listDrafts,
  memoryDraftStorage,
  newDraftId,
  PENDING_DRAFT_KEY,
  readDraft,
  recoverPending,
  sceneCountOf,
  storagePendingStore,
} from "../../src/ui/features/editor/drafts.ts";
import { motionFileName } from "../../src/ui/features/editor/file-name.ts";
import { formatSavedAt } from "../../src/ui/features/editor/saved-at.ts";
import { isTextEntry, shortcutOf } from "../../src/ui/features/editor/shortcuts.ts";
import {
  applyEdit,
  type EditorState,
  initialEditor,
  isDetached,
  redoEdit,
  selectScene,
  setDetached,
  startDocument,
  undoEdit,
} from "../../src/ui/features/editor/state.ts";

const WAVE = readFileSync(new URL("../../examples/wave.rbm", import.meta.url), "latin1");

const record = (id: string, savedAt: number, rbm = WAVE, name = "RbcPanel_Wave"): DraftRecord =>
  draftRecord(id, name, rbm, savedAt);

describe("draft records", () => {
  it("are small and versioned: the motion's own .rbm text, its name, id and time", () => {
    const r = record("d-1", 1_700_000_000_000);
    expect(r).toEqual({
      version: 1,
      id: "d-1",
      name: "RbcPanel_Wave",
      savedAt: 1_700_000_000_000,
      rbm: WAVE,
    });
    expect(Object.keys(r).sort()).toEqual(["id", "name", "rbm", "savedAt", "version"]);
    expect(readDraft("d-1", r)).toEqual({ ok: true, record: r });
  });

  it("read back from storage are checked: another version, a wrong shape or key is reported, not used", () => {
    const good = record("d-1", 5);
    const later = readDraft("d-1", { ...good, version: 2 });
    expect(later.ok).toBe(false);
    if (!later.ok)
      expect(later.problem).toBe(
        "It was saved by a newer panel (draft format 2); this panel reads format 1.",
      );
    const noText = readDraft("d-1", { ...good, rbm: undefined });
    expect(noText.ok).toBe(false);
    if (!noText.ok) expect(noText.problem).toMatch(/^It is not a draft this panel wrote \(rbm\)/);
    const negative = readDraft("d-1", { ...good, savedAt: -3 });
    expect(negative.ok).toBe(false);
    const moved = readDraft("d-2", good);
    expect(moved).toEqual({
      ok: false,
      key: "d-2",
      problem: 'It is stored under "d-2" but names itself "d-1".',
    });
    for (const junk of [null, undefined, 42, "text", [], { version: DRAFT_VERSION }]) {
      expect(readDraft("k", junk).ok).toBe(false);
    }
  });

  it("are listed newest first, broken ones apart, with the scene count from the text", async () => {
    const map = new Map<string, unknown>([
      ["a", record("a", 100)],
      ["b", record("b", 300, saveMotion(newMotion({ name: "Fresh" })), "Fresh")],
      ["c", { version: 1, id: "c" }],
      ["d", record("d", 200)],
    ]);
    const { drafts, broken } = await listDrafts(memoryDraftStorage(map));
    expect(drafts.map((d) => [d.id, d.name, d.scenes, d.savedAt])).toEqual([
      ["b", "Fresh", 1, 300],
      ["d", "RbcPanel_Wave", 6, 200],
      ["a", "RbcPanel_Wave", 6, 100],
    ]);
    expect(broken.map((b) => b.key)).toEqual(["c"]);
    expect(sceneCountOf(WAVE)).toBe(6);
    expect(sceneCountOf("not a motion")).toBeUndefined();
  });

  it("restore the newest draft that opens; a newer one whose motion is damaged is reported and skipped", async () => {
    const damaged = WAVE.replace(":RbcPanel_Wave:", ":RbcPanel_Wav:");
    const storage = memoryDraftStorage(
      new Map<string, unknown>([
        ["old", record("old", 100)],
        ["newest", record("newest", 300, damaged)],
        ["other", { hello: "world" }],
      ]),
    );
    const latest = await findLatestDraft(storage);
    expect(latest.restored?.record.id).toBe("old");
    expect(saveMotion(latest.restored!.doc)).toBe(WAVE);
    expect(latest.drafts.map((d) => d.id)).toEqual(["old"]);
    expect(latest.broken.map((b) => b.key).sort()).toEqual(["newest", "other"]);
    expect(latest.broken.find((b) => b.key === "newest")?.problem).toMatch(/^Its motion cannot be read: /);
    expect(await findLatestDraft(memoryDraftStorage())).toEqual({ drafts: [], broken: [] });
    expect(await readDraftDocument(storage, "gone")).toEqual({
      problem: "It is no longer stored (deleted in another tab?).",
    });
  });

  it("get ids from the time and a random number", () => {
    expect(newDraftId(0, () => 0)).toBe("d-0-00000000");
    expect(newDraftId(1_700_000_000_000, () => 0.5)).toBe("d-loyw3v28-80000000");
    expect(newDraftId(1, () => 0.999999999)).toMatch(/^d-1-[0-9a-f]{8}$/);
  });
});

describe("autosave", () => {
  beforeEach(() => {
    vi.useFakeTimers();
  });
  afterEach(() => {
    vi.useRealTimers();
  });

  it("saves once, 300 ms after the last of a run of changes, the latest document", async () => {
    const saved: DraftRecord[] = [];
    const made: number[] = [];
    const saver = new Autosaver(async (r) => {
      saved.push(r);
    });
    for (let i = 0; i < 5; i++) {
      saver.schedule(() => {
        made.push(i);
        return record("d", i);
      });
      await vi.advanceTimersByTimeAsync(100);
    }
    expect(saved).toEqual([]);
    expect(saver.pending).toBe(true);
    await vi.advanceTimersByTimeAsync(199);
    expect(saved).toEqual([]);
    await vi.advanceTimersByTimeAsync(1);
    expect(saved.map((r) => r.savedAt)).toEqual([4]);
    expect(made).toEqual([4]);
    expect(saver.pending).toBe(false);
  });

  it("saves at once on flush (the page is hidden), and not again when the timer would have fired", async () => {
    const saved: number[] = [];
    const saver = new Autosaver(async (r) => {
      saved.push(r.savedAt);
    });
    saver.schedule(() => record("d", 1));
    await saver.flush();
    expect(saved).toEqual([1]);
    await vi.advanceTimersByTimeAsync(1000);
    expect(saved).toEqual([1]);
    await saver.flush();
    expect(saved).toEqual([1]);
  });

  it("forgets a cancelled change, and reports a failed save without stopping later ones", async () => {
    const saved: number[] = [];
    const errors: string[] = [];
    const done: number[] = [];
    const saver = new Autosaver(
      async (r) => {
        if (r.savedAt === 2) throw new Error("quota exceeded");
        saved.push(r.savedAt);
      },
      { onSaved: (r) => done.push(r.savedAt), onError: (e) => errors.push(String(e)) },
    );
    saver.schedule(() => record("d", 1));
    saver.cancel();
    await vi.advanceTimersByTimeAsync(1000);
    expect(saved).toEqual([]);
    saver.schedule(() => record("d", 2));
    await vi.advanceTimersByTimeAsync(300);
    expect(errors).toEqual(["Error: quota exceeded"]);
    saver.schedule(() => record("d", 3));
    await vi.advanceTimersByTimeAsync(300);
    expect(saved).toEqual([3]);
    expect(done).toEqual([3]);
  });

  it("writes the waiting change synchronously when the page goes away, then saves it as usual", async () => {
    const saved: number[] = [];
    const written: number[] = [];
    const saver = new Autosaver(async (r) => {
      saved.push(r.savedAt);
    });
    void saver.flushNow((r) => written.push(r.savedAt));
    expect(written).toEqual([]);
    saver.schedule(() => record("d", 7));
    const done = saver.flushNow((r) => written.push(r.savedAt));
    expect(written).toEqual([7]);
    await done;
    expect(saved).toEqual([7]);
    await vi.advanceTimersByTimeAsync(1000);
    expect(saved).toEqual([7]);
  });

  it("stores saves in order, even when an earlier one is slow", async () => {
    const stored: number[] = [];
    const saver = new Autosaver(
      (r) =>
        new Promise<void>((resolve) =>
          setTimeout(
            () => {
              stored.push(r.savedAt);
              resolve();
            },
            r.savedAt === 1 ? 500 : 10,
          ),
        ),
    );
    saver.schedule(() => record("d", 1));
    void saver.flush();
    saver.schedule(() => record("d", 2));
    void saver.flush();
    await vi.advanceTimersByTimeAsync(600);
    expect(stored).toEqual([1, 2]);
  });
});

describe("a change written as the page went away", () => {
  const local = () => {
    const items = new Map<string, string>();
    return {
      items,
      store: storagePendingStore({
        getItem: (k) => items.get(k) ?? null,
        setItem: (k, v) => void items.set(k, v),
        removeItem: (k) => void items.delete(k),
      }),
    };
  };

  it("is moved into the drafts at the next start when it is newer than the stored draft", async () => {
    const { items, store } = local();
    const storage = memoryDraftStorage(new Map([["d", record("d", 100)]]));
    store.write(record("d", 200, saveMotion(newMotion({ name: "Later" })), "Later"));
    expect([...items.keys()]).toEqual([PENDING_DRAFT_KEY]);
    expect(await recoverPending(storage, store)).toBeUndefined();
    expect(items.size).toBe(0);
    expect(((await storage.get("d")) as DraftRecord).name).toBe("Later");
    expect(await recoverPending(storage, store)).toBeUndefined();
  });

  it("never replaces a newer stored draft, and a damaged one is reported, not stored", async () => {
    const { items, store } = local();
    const storage = memoryDraftStorage(new Map([["d", record("d", 300)]]));
    store.write(record("d", 200, saveMotion(newMotion({ name: "Older" })), "Older"));
    await recoverPending(storage, store);
    expect(((await storage.get("d")) as DraftRecord).savedAt).toBe(300);
    items.set(PENDING_DRAFT_KEY, "{not json");
    const broken = await recoverPending(storage, store);
    expect(broken?.key).toBe(PENDING_DRAFT_KEY);
    expect(broken?.problem).toMatch(/^It is not a draft this panel wrote/);
    expect((await storage.entries()).map(([k]) => k)).toEqual(["d"]);
  });
});

describe("file names and times", () => {
  it("turn a motion's name into a file name people and file systems accept", () => {
    expect(motionFileName("RbcPanel_Wave")).toBe("RbcPanel_Wave.rbm");
    expect(motionFileName("Wave hello!")).toBe("Wave-hello.rbm");
    expect(motionFileName("  a/b\\c..d  ")).toBe("a-b-c-d.rbm");
    expect(motionFileName("...")).toBe("motion.rbm");
    expect(motionFileName("x".repeat(99))).toBe(`${"x".repeat(60)}.rbm`);
  });

  it("write a draft's time as HH:MM today, with the date otherwise", () => {
    const now = new Date(2026, 10, 21, 15, 30).getTime();
    expect(formatSavedAt(new Date(2026, 10, 21, 9, 5).getTime(), now)).toBe("09:05");
    expect(formatSavedAt(new Date(2026, 10, 20, 23, 59).getTime(), now)).toBe("20 Nov 23:59");
  });
});

describe("keyboard shortcuts", () => {
  const key = (
    k: string,
    mods: Partial<{ ctrl: boolean; meta: boolean; shift: boolean; alt: boolean }> = {},
  ) => ({
    key: k,
    ctrlKey: mods.ctrl ?? false,
    metaKey: mods.meta ?? false,
    shiftKey: mods.shift ?? false,
    altKey: mods.alt ?? false,
  });

  it("Ctrl+Z undoes, Ctrl+Shift+Z and Ctrl+Y redo (Cmd on a Mac); nothing else is taken", () => {
    expect(shortcutOf(key("z", { ctrl: true }))).toBe("undo");
    expect(shortcutOf(key("Z", { ctrl: true, shift: true }))).toBe("redo");
    expect(shortcutOf(key("y", { ctrl: true }))).toBe("redo");
    expect(shortcutOf(key("z", { meta: true }))).toBe("undo");
    expect(shortcutOf(key("z"))).toBeUndefined();
    expect(shortcutOf(key("z", { ctrl: true, alt: true }))).toBeUndefined();
    expect(shortcutOf(key("Y", { ctrl: true, shift: true }))).toBeUndefined();
    expect(shortcutOf(key("x", { ctrl: true }))).toBeUndefined();
  });

  it("leave the keys to text fields (their own undo), not to sliders, checkboxes or buttons", () => {
    expect(isTextEntry({ tagName: "INPUT", type: "number" })).toBe(true);
    expect(isTextEntry({ tagName: "INPUT", type: "text" })).toBe(true);
    expect(isTextEntry({ tagName: "INPUT" })).toBe(true);
    expect(isTextEntry({ tagName: "TEXTAREA" })).toBe(true);
    expect(isTextEntry({ tagName: "DIV", isContentEditable: true })).toBe(true);
    expect(isTextEntry({ tagName: "INPUT", type: "range" })).toBe(false);
    expect(isTextEntry({ tagName: "INPUT", type: "checkbox" })).toBe(false);
    expect(isTextEntry({ tagName: "BUTTON" })).toBe(false);
    expect(isTextEntry({ tagName: "SELECT" })).toBe(false);
    expect(isTextEntry(null)).toBe(false);
  });
});

describe("editor state", () => {
  const started = (doc: Motion = newMotion()): EditorState => startDocument(initialEditor(), doc, "d-1");
  const three = () => addScene(addScene(newMotion()));

  it("applies an edit as one undo step, with its label", () => {
    const s = started();
    const out = applyEdit(s, (d) => setPosition(d, 0, 2, 150), "set Right knee", { field: "end:2" });
    expect(out.changed).toBe(true);
    expect(out.state.history?.present.scenes[0]?.servos[2]?.end).toBe(150);
    expect(out.state.history?.label).toBe("set Right knee");
    expect(out.state.history?.undoCount).toBe(1);
  });

  it("puts a refused edit's message next to its field and changes nothing; a good edit clears it", () => {
    const s = started();
    const out = applyEdit(s, (d) => setPosition(d, 0, 2, 300), "set Right knee", {
      field: "end:2",
      text: "300",
    });
    expect(out.changed).toBe(false);
    expect(out.error).toBeInstanceOf(MotionError);
    expect(out.state.history).toBe(s.history);
    expect(out.state.problems["end:2"]).toEqual({
      text: "300",
      message: "Scene 0: the end position of servo 2 must be a whole number from 0 to 254, not 300.",
    });
    const fixed = applyEdit(out.state, (d) => setPosition(d, 0, 2, 200), "set Right knee", {
      field: "end:2",
    });
    expect(fixed.state.problems).toEqual({});
    expect(fixed.changed).toBe(true);
  });

  it("throws what is not a refusal (a bug must not look like a refused value)", () => {
    expect(() =>
      applyEdit(
        started(),
        () => {
          throw new TypeError("oops");
        },
        "x",
        { field: "f" },
      ),
    ).toThrow(TypeError);
  });

  it("merges a slider drag into one undo step, and a new drag is a step of its own", () => {
    let s = started();
    for (const v of [130, 140, 150]) {
      s = applyEdit(s, (d) => setPosition(d, 0, 2, v), "slide", {
        field: "end:2",
        mergeKey: "slide:0:2:0",
      }).state;
    }
    expect(s.history?.undoCount).toBe(1);
    s = applyEdit(s, (d) => setPosition(d, 0, 2, 160), "slide", {
      field: "end:2",
      mergeKey: "slide:0:2:1",
    }).state;
    expect(s.history?.undoCount).toBe(2);
    s = undoEdit(s).state;
    expect(s.history?.present.scenes[0]?.servos[2]?.end).toBe(150);
    s = undoEdit(s).state;
    expect(s.history?.present.scenes[0]?.servos[2]?.end).toBe(199);
  });

  it("keeps the selection inside the motion through structural edits, undo and redo", () => {
    let s = started(three());
    s = selectScene(s, 2);
    expect(s.scene).toBe(2);
    s = applyEdit(s, (d) => addScene(d, 3), "add scene 3", {
      field: "structure",
      structural: true,
      select: () => 3,
    }).state;
    expect(s.scene).toBe(3);
    s = undoEdit(s).state;
    expect(s.scene).toBe(2);
    s = redoEdit(s).state;
    expect(s.scene).toBe(2);
    expect(selectScene(s, 99).scene).toBe(3);
    expect(undoEdit(started()).changed).toBe(false);
    expect(redoEdit(started()).changed).toBe(false);
  });

  it("clears the problems shown when the document moves (undo, another scene)", () => {
    let s = started(three());
    s = applyEdit(s, (d) => setPosition(d, 1, 2, 10), "x", { field: "end:2" }).state;
    s = applyEdit(s, (d) => setPosition(d, 1, 2, 999), "x", { field: "end:2", text: "999" }).state;
    expect(Object.keys(s.problems)).toEqual(["end:2"]);
    expect(undoEdit(s).state.problems).toEqual({});
    s = applyEdit(s, (d) => setPosition(d, 1, 2, 999), "x", { field: "end:2", text: "999" }).state;
    expect(selectScene(s, 2).problems).toEqual({});
  });

  it("detaches a boundary: edits on either side of it then leave the other side alone", () => {
    let s = started(three());
    expect(isDetached(s, 1, "start")).toBe(false);
    s = setDetached(s, 2, true);
    expect(isDetached(s, 1, "end")).toBe(true);
    expect(isDetached(s, 2, "start")).toBe(true);
    expect(isDetached(s, 1, "start")).toBe(false);
    expect(setDetached(s, 2, true)).toBe(s);
    expect(setDetached(s, 2, false).detached).toEqual([]);
    // Structural edits reset the options (the boundaries move with the scenes).
    const moved = applyEdit(s, (d) => addScene(d, 0), "add", { field: "structure", structural: true });
    expect(moved.state.detached).toEqual([]);
  });

  it("starts a document with a fresh history on its first scene", () => {
    const s = startDocument(
      { ...started(three()), scene: 2, problems: { x: { text: "", message: "m" } } },
      openMotion(WAVE),
      undefined,
    );
    expect(s.scene).toBe(0);
    expect(s.draftId).toBeUndefined();
    expect(s.problems).toEqual({});
    expect(s.history?.undoCount).toBe(0);
    expect(saveMotion(s.history!.present)).toBe(WAVE);
  });
});
