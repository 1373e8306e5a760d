import { readFileSync } from "node:fs";
import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import { said, wordOf } from "../../src/i18n/said.ts";
import { translator } from "../../src/i18n/translate.ts";
import {
  addScene,
  type Motion,
  MotionError,
  mirrorPose,
  newMotion,
  openMotion,
  retime,
  saveMotion,
  setMotionName,
  setPosition,
  setTiming,
} from "../../src/motion/index.ts";
import { noticeText } from "../../src/ui/app-state.ts";
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
import { editorMessages } from "../../src/ui/features/editor/messages.ts";
import { playFailureText, playQuestion, playResultNotice } from "../../src/ui/features/editor/play-model.ts";
import { refusalOf, refusalText, TypedValueError } from "../../src/ui/features/editor/refusal-text.ts";
import { formatSavedAt } from "../../src/ui/features/editor/saved-at.ts";
import { isTextEntry, shortcutOf } from "../../src/ui/features/editor/shortcuts.ts";
import {
  applyEdit,
  EDITOR_TABS,
  type EditorState,
  initialEditor,
  isDetached,
  redoEdit,
  selectScene,
  setDetached,
  startDocument,
  undoEdit,
} from "../../src/ui/features/editor/state.ts";
import {
  holdNotice,
  limbsText,
  limpNotice,
  readNotice,
} from "../../src/ui/features/editor/teach-in-model.ts";
import { tabAfterKey } from "../../src/ui/tabs-keyboard.ts";
import { motionRefusal as refused } from "../support/motion-refusal.ts";

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
      expect(wordOf(later.problem, "en")).toBe(
        "It was saved by a newer panel (draft format 2); this panel reads format 1.",
      );
    const noText = readDraft("d-1", { ...good, rbm: undefined });
    expect(noText.ok).toBe(false);
    if (!noText.ok)
      expect(wordOf(noText.problem, "en")).toMatch(/^It is not a draft this panel wrote \(rbm\)/);
    const negative = readDraft("d-1", { ...good, savedAt: -3 });
    expect(negative.ok).toBe(false);
    const moved = readDraft("d-2", good);
    expect(moved.ok).toBe(false);
    if (!moved.ok) {
      expect(moved.key).toBe("d-2");
      expect(wordOf(moved.problem, "en")).toBe('It is stored under "d-2" but names itself "d-1".');
    }
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
    const newest = latest.broken.find((b) => b.key === "newest");
    expect(newest && wordOf(newest.problem, "en")).toMatch(/^Its motion cannot be read: /);
    expect(await findLatestDraft(memoryDraftStorage())).toEqual({ drafts: [], broken: [] });
    const gone = await readDraftDocument(storage, "gone");
    expect("problem" in gone && wordOf(gone.problem, "en")).toBe(
      "It is no longer stored (deleted in another tab?).",
    );
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
    expect(broken && wordOf(broken.problem, "en")).toMatch(/^It is not a draft this panel wrote/);
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

/** An undo step's name, as the Editor makes them: a message of its catalogue. */
const step = (scene: string) => said(editorMessages, "editor.label.addScene", { scene });

describe("editor state", () => {
  const started = (doc: Motion = newMotion()): EditorState => startDocument(initialEditor(), doc, "d-1");
  const three = () => addScene(addScene(newMotion()));

  it("applies an edit as one undo step, with its label", () => {
    const s = started();
    const label = said(editorMessages, "editor.label.setEnd", { joint: "Left knee", scene: "0" });
    const out = applyEdit(s, (d) => setPosition(d, 0, 2, 150), label, { field: "end:2" });
    expect(out.changed).toBe(true);
    expect(out.state.history?.present.scenes[0]?.servos[2]?.end).toBe(150);
    expect(out.state.history?.label).toBe(label);
    expect(out.state.history?.undoCount).toBe(1);
  });

  it("puts a refused edit next to its field as the core's code and facts, and changes nothing; a good edit clears it", () => {
    const s = started();
    const out = applyEdit(s, (d) => setPosition(d, 0, 2, 300), step("0"), {
      field: "end:2",
      text: "300",
    });
    expect(out.changed).toBe(false);
    expect(out.error).toBeInstanceOf(MotionError);
    expect(out.state.history).toBe(s.history);
    expect(out.state.problems["end:2"]).toEqual({
      text: "300",
      why: {
        code: "motion-value",
        facts: { rule: "whole", subject: { field: "end", scene: 0, servo: 2 }, value: 300, min: 0, max: 254 },
      },
    });
    const fixed = applyEdit(out.state, (d) => setPosition(d, 0, 2, 200), step("0"), {
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
        step("x"),
        { field: "f" },
      ),
    ).toThrow(TypeError);
  });

  it("merges a slider drag into one undo step, and a new drag is a step of its own", () => {
    let s = started();
    for (const v of [130, 140, 150]) {
      s = applyEdit(s, (d) => setPosition(d, 0, 2, v), step("0"), {
        field: "end:2",
        mergeKey: "slide:0:2:0",
      }).state;
    }
    expect(s.history?.undoCount).toBe(1);
    s = applyEdit(s, (d) => setPosition(d, 0, 2, 160), step("0"), {
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
    s = applyEdit(s, (d) => addScene(d, 3), step("3"), {
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
    s = applyEdit(s, (d) => setPosition(d, 1, 2, 10), step("1"), { field: "end:2" }).state;
    s = applyEdit(s, (d) => setPosition(d, 1, 2, 999), step("1"), { field: "end:2", text: "999" }).state;
    expect(Object.keys(s.problems)).toEqual(["end:2"]);
    expect(undoEdit(s).state.problems).toEqual({});
    s = applyEdit(s, (d) => setPosition(d, 1, 2, 999), step("1"), { field: "end:2", text: "999" }).state;
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
    const moved = applyEdit(s, (d) => addScene(d, 0), step("0"), { field: "structure", structural: true });
    expect(moved.state.detached).toEqual([]);
  });

  it("starts a document with a fresh history on its first scene", () => {
    const s = startDocument(
      { ...started(three()), scene: 2, problems: { x: { text: "", why: step("2") } } },
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

describe("the tab list's keys", () => {
  it("lists the tabs in order: Pose, Scene, Tools, Teach-in, Play, Check", () => {
    expect(EDITOR_TABS.map((t) => t.id)).toEqual(["pose", "scene", "tools", "teach", "play", "check"]);
    const en = translator(editorMessages, "en");
    const ko = translator(editorMessages, "ko");
    expect(EDITOR_TABS.map((t) => en(t.key))).toEqual([
      "Pose",
      "Scene",
      "Tools",
      "Teach-in",
      "Play",
      "Check",
    ]);
    expect(EDITOR_TABS.map((t) => ko(t.key))).toEqual(["자세", "장면", "도구", "티칭", "재생", "검사"]);
  });

  it("moves to the next and previous tab with the arrows, wrapping at either end", () => {
    expect(tabAfterKey(EDITOR_TABS, "pose", "ArrowRight")).toBe("scene");
    expect(tabAfterKey(EDITOR_TABS, "teach", "ArrowRight")).toBe("play");
    expect(tabAfterKey(EDITOR_TABS, "check", "ArrowRight")).toBe("pose");
    expect(tabAfterKey(EDITOR_TABS, "scene", "ArrowLeft")).toBe("pose");
    expect(tabAfterKey(EDITOR_TABS, "pose", "ArrowLeft")).toBe("check");
  });

  it("goes to the first tab with Home and the last with End", () => {
    expect(tabAfterKey(EDITOR_TABS, "play", "Home")).toBe("pose");
    expect(tabAfterKey(EDITOR_TABS, "pose", "Home")).toBe("pose");
    expect(tabAfterKey(EDITOR_TABS, "scene", "End")).toBe("check");
    expect(tabAfterKey(EDITOR_TABS, "check", "End")).toBe("check");
  });

  it("leaves every other key alone (the page keeps it: Tab, Enter, up and down, letters)", () => {
    for (const key of ["ArrowUp", "ArrowDown", "Enter", " ", "Tab", "Escape", "a", "PageDown"]) {
      expect(tabAfterKey(EDITOR_TABS, "tools", key)).toBeUndefined();
    }
  });
});

describe("the editor in Korean", () => {
  const words = (e: MotionError) => ({
    en: refusalText(refusalOf(e), "en"),
    ko: refusalText(refusalOf(e), "ko"),
  });

  it("says a refused value from the core's code and facts, in English as in Korean", () => {
    const value = refused(() => setPosition(newMotion(), 0, 2, 300));
    expect(value.message).toMatch(/^motion-value \(rule whole, /);
    expect(words(value)).toEqual({
      en: "The end position of Left knee (servo 2) must be a whole number from 0 to 254, not 300.",
      ko: "왼쪽 무릎(서보 2)의 끝 위치에는 0에서 254 사이의 정수만 쓸 수 있어요. 입력한 값: 300.",
    });
    expect(words(refused(() => setMotionName(newMotion(), "인사")))).toEqual({
      en: "The motion name can use only plain letters, digits, spaces and punctuation (ASCII), as Motionbuilder does.",
      ko: "모션 이름에는 영문 글자, 숫자, 공백, 문장 부호(ASCII)만 쓸 수 있어요. Motionbuilder와 같아요.",
    });
    expect(words(refused(() => setMotionName(newMotion(), "a:b"))).ko).toBe(
      '모션 이름에는 ":"을 쓸 수 없어요. 모션 파일에서 칸을 나누는 기호예요.',
    );
  });

  it("says frames too close or too far apart with the numbers that would fix them", () => {
    const close = refused(() => setTiming(newMotion(), 0, { frames: 10, timeMs: 100 }));
    expect(words(close)).toEqual({
      en: "10 frames in 100 ms are 10.0 ms apart; the RBC needs at least 20 ms, so use at most 5 frames or at least 200 ms.",
      ko: "프레임 10개를 100ms에 재생하면 프레임 사이가 10.0ms예요. RBC는 20ms 이상이 필요해요. 프레임을 5개 이하로 하거나 시간을 200ms 이상으로 해 주세요.",
    });
    const far = refused(() => setTiming(newMotion(), 0, { frames: 1, timeMs: 10_000 }));
    expect(words(far).ko).toBe(
      "프레임 1개를 10,000ms에 재생하면 프레임 사이가 10,000.0ms예요. RBC는 4,550ms까지만 허용해요. 프레임을 3개 이상으로 해 주세요.",
    );
  });

  it("says a retime or a mirror the core refuses, naming the scene and the servos", () => {
    const fast = refused(() => retime(newMotion(), 0.001));
    expect(words(fast).ko).toBe(
      "그러면 장면 0의 시간이 1ms가 돼요. 장면은 적어도 20ms(프레임 1개)는 걸리므로 모션을 그만큼 빠르게 할 수 없어요.",
    );
    const doc = setPosition(newMotion(), 0, 10, 254);
    const mirror = refused(() => mirrorPose(doc, 0, { mode: "left-to-right" }));
    expect(mirror.facts.positions?.length).toBeGreaterThan(0);
    expect(words(mirror).ko).toMatch(
      /^장면 0은\(는\) 좌우 대칭할 수 없어요\. 서보 13 → -?\d+: 위치 0-254를 벗어나요\.$/,
    );
  });

  it("keeps what the editor itself refused as its message, and says a refusal without facts by its code", () => {
    const typed = new TypedValueError(
      "motion-value",
      said(editorMessages, "editor.refusal.factor", { text: "빠르게" }),
    );
    expect(typed.message).toBe(
      'A time factor is a number above 0 (2 = half as fast, 0.5 = twice as fast); "빠르게" is not.',
    );
    expect(words(typed).ko).toBe(
      '시간 배수는 0보다 큰 수여야 해요 (2 = 절반 속도, 0.5 = 두 배 속도). 입력한 값: "빠르게".',
    );
    expect(words(new MotionError("motion-last-scene", "A motion needs at least one scene…")).ko).toBe(
      "모션에는 장면이 하나 이상 있어야 해서 하나뿐인 장면은 지울 수 없어요.",
    );
    expect(words(new MotionError("motion-mirror", "no")).en).toBe("This scene cannot be mirrored.");
  });

  it("keeps a refusal beside its field as data: the same state reads in English, then in Korean", () => {
    const s = startDocument(initialEditor(), newMotion(), "d-1");
    const out = applyEdit(s, (d) => setPosition(d, 0, 3, 300), step("0"), { field: "end:3", text: "300" });
    const problem = out.state.problems["end:3"];
    expect(problem?.text).toBe("300");
    expect(problem && refusalText(problem.why, "en")).toBe(
      "The end position of Left ankle pitch (servo 3) must be a whole number from 0 to 254, not 300.",
    );
    expect(problem && refusalText(problem.why, "ko")).toBe(
      "왼쪽 발목 앞뒤(서보 3)의 끝 위치에는 0에서 254 사이의 정수만 쓸 수 있어요. 입력한 값: 300.",
    );
  });

  it("writes a draft's time with a Korean date on another day, and a broken draft's reason in Korean", () => {
    const now = new Date(2026, 10, 21, 15, 30).getTime();
    expect(formatSavedAt(new Date(2026, 10, 21, 9, 5).getTime(), now, "ko")).toBe("09:05");
    expect(formatSavedAt(new Date(2026, 10, 20, 23, 59).getTime(), now, "ko")).toBe("11월 20일 23:59");
    const later = readDraft("d-1", { ...record("d-1", 5), version: 2 });
    expect(later.ok ? "" : wordOf(later.problem, "ko")).toBe(
      "더 새로운 패널이 저장했어요 (임시 저장본 형식 2). 이 패널은 형식 1만 읽을 수 있어요.",
    );
    const noText = readDraft("d-1", { ...record("d-1", 5), rbm: undefined });
    expect(noText.ok ? "" : wordOf(noText.problem, "ko")).toBe(
      "이 패널이 저장한 임시 저장본이 아니에요 (rbm): 저장된 값의 형식이 맞지 않아요.",
    );
  });

  it("says what teach-in's servos confirmed in Korean", () => {
    expect(limbsText(["left-arm", "right-leg"], "ko")).toBe("오른쪽 다리, 왼쪽 팔");
    expect(limbsText(["left-arm", "right-leg", "left-leg", "right-arm"], "ko")).toBe("모든 서보");
    expect(limpNotice([10, 11, 12], [13], false, "ko").text).toBe(
      "서보 10–12의 힘이 빠졌어요 (확인함). 손으로 자세를 잡아 주세요. 서보 13에서 응답이 없어서 아직 힘이 들어가 있을 수 있어요. 케이블을 확인해 주세요.",
    );
    const reading = { pose: new Map([[0, 120]]), converted: [0], notInMotion: [] };
    expect(readNotice(2, reading, [], true, "ko").text).toBe(
      "서보 0의 위치를 장면 2의 끝 자세로 읽어 넣었어요 (실행 취소 한 번). 서보 0의 경우 로봇의 영점이 모션의 영점과 달라요. 그 위치를 모션의 영점에 맞게 바꿔서, 재생하면 읽은 자리로 가요.",
    );
    expect(holdNotice([{ id: 4, read: 30, held: 41 }], [], false, "ko").text).toBe(
      "서보 4을(를) 자세를 잡은 자리에 고정했어요 (토크 켜짐, 확인함). 서보 4은(는) 안전 범위 밖인 30에 있어서 41에 고정했어요.",
    );
  });

  it("keeps teach-in's and play's notices as messages: made in English, they read in Korean after a switch", () => {
    const limp = limpNotice([10, 11, 12], [13], false, "en");
    expect(limp.text).toBe(
      "Servos 10–12 are limp (confirmed): pose them by hand. Servo 13 did not answer and may still hold; check its cable.",
    );
    expect(noticeText(limp, "ko")).toBe(
      "서보 10–12의 힘이 빠졌어요 (확인함). 손으로 자세를 잡아 주세요. 서보 13에서 응답이 없어서 아직 힘이 들어가 있을 수 있어요. 케이블을 확인해 주세요.",
    );
    const hold = holdNotice([{ id: 4, read: 30, held: 41 }], [], false, "en");
    expect(noticeText(hold, "ko")).toBe(
      "서보 4을(를) 자세를 잡은 자리에 고정했어요 (토크 켜짐, 확인함). 서보 4은(는) 안전 범위 밖인 30에 있어서 41에 고정했어요.",
    );
    const played = playResultNotice({ outcome: "finished", framesSent: 42, durationMs: 1500 }, 1, 1, "en");
    expect(played.text).toBe("Played scene 1 (42 frames, 1.5 s); the servos hold the last frame.");
    expect(noticeText(played, "ko")).toBe(
      "장면 1을(를) 재생했어요 (프레임 42개, 1.5초). 서보는 마지막 프레임 자세를 유지해요.",
    );
    const stopped = playResultNotice(
      { outcome: "stopped", framesSent: 5, durationMs: 0, lastFrame: { scene: -1, frame: 3 } },
      0,
      2,
      "ko",
    );
    expect(noticeText(stopped, "en")).toBe(
      "Stopped at the move to the first pose (step 3); the servos hold that pose.",
    );
  });

  it("asks before tethered play and says what the robot confirmed, in Korean", () => {
    expect(playQuestion(1, 3, 2500, "ko")).toBe(
      "로봇이 장면 1–3을(를) 따라 움직여요 (2.5초). 로봇을 잡거나 혼자 설 수 있는지 확인해 주세요.",
    );
    expect(playResultNotice({ outcome: "finished", framesSent: 42, durationMs: 1500 }, 1, 1, "ko").text).toBe(
      "장면 1을(를) 재생했어요 (프레임 42개, 1.5초). 서보는 마지막 프레임 자세를 유지해요.",
    );
    expect(
      playResultNotice(
        { outcome: "stopped", framesSent: 5, durationMs: 0, lastFrame: { scene: -1, frame: 3 } },
        0,
        2,
        "ko",
      ).text,
    ).toBe("첫 자세로 가는 동작(3단계)에서 멈췄어요. 서보는 그 자세를 유지해요.");
    expect(playFailureText("unknown", { scene: 2, frame: 4 }, true, "ko")).toBe(
      "장면 2, 프레임 4 다음에 로봇에서 재생하지 못했어요. 로봇이 마지막 프레임을 받았는지 알 수 없어요. 로봇을 잡아 주세요.",
    );
  });
});
