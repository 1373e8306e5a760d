import { describe, expect, it } from "vitest";
import { wordOf } from "../../src/i18n/said.ts";
import { parseRbm, RbmError, readRbm, validateRbm } from "../../src/protocol/rbm.ts";
import { Autosaver, UnopenableDraftError } from "../../src/ui/features/editor/autosave.ts";
import { findLatestDraft } from "../../src/ui/features/editor/draft-actions.ts";
import {
  type DeadlineTimers,
  DraftTimeoutError,
  withDeadline,
} from "../../src/ui/features/editor/draft-deadline.ts";
import {
  type DraftRecord,
  draftRecord,
  memoryDraftStorage,
  storedName,
  storedRbmText,
} from "../../src/ui/features/editor/drafts.ts";
import { issueText } from "../../src/ui/features/motions/issue-text.ts";

/**
 * Issue 20 item 9: a motion with zero scenes (docs/protocol.md §7: S = 0 is an error) is refused where it is
 * read, never opened as a draft, never autosaved, and the Editor opens whatever the drafts hold.
 */

/** One servo, zero scenes: 13 header fields + 6 servo fields, field 9 (S) = 0. */
const ZERO_SCENES =
  "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:5:Empty:0:1:0:2:1:4:00:020:030:000:0:125:";
/** The same motion with one scene of 10 frames in 500 ms. */
const ONE_SCENE =
  "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:5:Empty:0:1:1:2:1:4:00:020:030:000:0:125:000:07:Scene_0:10:500:0:00:125:125:2:0:";

describe("an .rbm file with S = 0 (docs/protocol.md §7)", () => {
  it("is read (so it can be shown) but is a validation error with a code and its facts", () => {
    const motion = readRbm(ZERO_SCENES);
    expect(motion.sceneCount).toBe(0);
    expect(motion.scenes).toEqual([]);
    const { errors } = validateRbm(motion);
    expect(errors).toEqual([
      {
        code: "rbm-no-scenes",
        message: "rbm-no-scenes (scenes 0, min 1)",
        values: { scenes: 0, min: 1 },
      },
    ]);
  });

  it("the same motion with one scene has no error (the check above can fail)", () => {
    expect(validateRbm(readRbm(ONE_SCENE)).errors).toEqual([]);
  });

  it("is refused by parseRbm with RbmError rbm-no-scenes", () => {
    expect(() => parseRbm(ZERO_SCENES)).toThrow(RbmError);
    try {
      parseRbm(ZERO_SCENES);
    } catch (e) {
      expect((e as RbmError).code).toBe("rbm-no-scenes");
    }
  });

  it("is worded in Korean from its facts", () => {
    const [issue] = validateRbm(readRbm(ZERO_SCENES)).errors;
    expect(issueText(issue!, "ko")).toBe("모션에 장면이 없어요. 모션에는 장면이 1개 이상 있어야 해요.");
    expect(issueText(issue!, "en")).toBe("The motion has no scenes; a motion needs at least one.");
  });
});

describe("the draft store with a zero-scene draft", () => {
  const stored = (id: string, savedAt: number, rbm: string): DraftRecord =>
    draftRecord(id, `Motion ${id}`, rbm, savedAt);

  it("the newest draft, with no scenes, is set aside with a sentence; the older one opens", async () => {
    const storage = memoryDraftStorage(
      new Map<string, unknown>([
        ["older", stored("older", 100, ONE_SCENE)],
        ["newest", stored("newest", 300, ZERO_SCENES)],
      ]),
    );
    const latest = await findLatestDraft(storage);
    expect(latest.restored?.record.id).toBe("older");
    expect(latest.setAside?.key).toBe("newest");
    expect(latest.setAside?.name).toBe("Motion newest");
    const problem = latest.setAside?.problem;
    expect(problem && wordOf(problem, "en")).toBe(
      "Its motion cannot be read: The motion has no scenes; a motion needs at least one.",
    );
    expect(latest.drafts.map((d) => d.id)).toEqual(["older"]);
    expect(latest.broken.map((b) => b.key)).toEqual(["newest"]);
    // Set aside, not deleted: its text can still be exported exactly as it was stored.
    const value = await storage.get("newest");
    expect(storedRbmText(value)).toBe(ZERO_SCENES);
    expect(storedName(value)).toBe("Motion newest");
  });

  it("with only the broken draft: nothing to restore, the draft set aside, in Korean too", async () => {
    const storage = memoryDraftStorage(new Map<string, unknown>([["only", stored("only", 5, ZERO_SCENES)]]));
    const latest = await findLatestDraft(storage);
    expect(latest.restored).toBeUndefined();
    expect(latest.setAside?.key).toBe("only");
    const problem = latest.setAside?.problem;
    expect(problem && wordOf(problem, "ko")).toBe(
      "저장된 모션을 읽을 수 없어요: 모션 파일 형식이 맞지 않아요.",
    );
  });

  it("the text of a stored value that is not a record: the value itself, or nothing", () => {
    expect(storedRbmText(ZERO_SCENES)).toBe(ZERO_SCENES);
    expect(storedRbmText({ hello: "world" })).toBeUndefined();
    expect(storedRbmText(null)).toBeUndefined();
    expect(storedName(42)).toBeUndefined();
  });
});

describe("autosave refuses a motion with no scenes", () => {
  it("the record is never stored, and the refusal is reported with its code", async () => {
    const saved: DraftRecord[] = [];
    const errors: unknown[] = [];
    const saver = new Autosaver(
      async (r) => {
        saved.push(r);
      },
      { onError: (e) => errors.push(e) },
    );
    saver.schedule(() => draftRecord("d", "Empty", ZERO_SCENES, 1));
    await saver.flush();
    saver.schedule(() => draftRecord("d", "Empty", ONE_SCENE, 2));
    await saver.flush();
    expect(saved.map((r) => r.savedAt)).toEqual([2]);
    expect(errors).toHaveLength(1);
    expect(errors[0]).toBeInstanceOf(UnopenableDraftError);
    expect((errors[0] as UnopenableDraftError).code).toBe("rbm-no-scenes");
  });

  it("nor written synchronously when the page goes away", async () => {
    const written: DraftRecord[] = [];
    const errors: unknown[] = [];
    const saver = new Autosaver(async () => {}, { onError: (e) => errors.push(e) });
    saver.schedule(() => draftRecord("d", "Empty", ZERO_SCENES, 1));
    await saver.flushNow((r) => written.push(r));
    expect(written).toEqual([]);
    expect(errors[0]).toBeInstanceOf(UnopenableDraftError);
  });
});

/** Timers a test fires by hand. */
function manualTimers() {
  const pending = new Map<number, { callback: () => void; ms: number }>();
  let next = 1;
  const timers: DeadlineTimers = {
    set: (callback, ms) => {
      pending.set(next, { callback, ms });
      return next++;
    },
    clear: (handle) => pending.delete(handle as number),
  };
  const fire = () => {
    for (const [id, t] of [...pending]) {
      pending.delete(id);
      t.callback();
    }
  };
  return { timers, pending, fire };
}

describe("opening the drafts has a deadline", () => {
  it("a read that never ends is abandoned with DraftTimeoutError when the deadline passes", async () => {
    const { timers, pending, fire } = manualTimers();
    const never = new Promise<string>(() => {});
    const result = withDeadline(never, 5000, timers);
    expect([...pending.values()].map((t) => t.ms)).toEqual([5000]);
    fire();
    await expect(result).rejects.toBeInstanceOf(DraftTimeoutError);
    await expect(result).rejects.toMatchObject({ code: "draft-timeout", ms: 5000 });
  });

  it("a read that ends in time gives its value and clears the timer", async () => {
    const { timers, pending } = manualTimers();
    await expect(withDeadline(Promise.resolve("drafts"), 5000, timers)).resolves.toBe("drafts");
    expect(pending.size).toBe(0);
  });

  it("a read that fails passes its own error on", async () => {
    const { timers } = manualTimers();
    const failure = new Error("IndexedDB is broken");
    await expect(withDeadline(Promise.reject(failure), 5000, timers)).rejects.toBe(failure);
  });
});
