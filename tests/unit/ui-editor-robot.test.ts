/**
 * The Editor's "Upload to robot" and "Run on robot" (issue 23 item 1): the pure part (robot-model.ts: the
 * remote key of a Run number, docs/protocol.md §3.1; whether the robot holds the document on screen or an
 * earlier version), and the upload itself through the Motions upload path on the demo robot, on a virtual clock.
 */
import { afterEach, beforeAll, describe, expect, it } from "vitest";
import type { DirectUse } from "../../src/device/index.ts";
import { translator } from "../../src/i18n/translate.ts";
import { type Motion, motionIssues, newMotion, setPosition } from "../../src/motion/index.ts";
import { initialState } from "../../src/ui/app-state.ts";
import { liveOf, type RobotCopy } from "../../src/ui/features/editor/live-state.ts";
import { editorMessages } from "../../src/ui/features/editor/messages.ts";
import {
  motionPlaying,
  requestEditorUpload,
  robotRefusal,
  startEditorUpload,
  stopEndsIt,
} from "../../src/ui/features/editor/robot-actions.ts";
import {
  copyInBook,
  editorUploadTarget,
  isEditorTarget,
  remoteKeyText,
  robotCopyStatus,
  sameDocument,
} from "../../src/ui/features/editor/robot-model.ts";
import { showMemory } from "../../src/ui/features/motions/memory.ts";
import {
  afterReset,
  afterUpload,
  type BookEntry,
  emptyBook,
  type SlotBook,
} from "../../src/ui/features/motions/slot-book.ts";
import { motionsOf } from "../../src/ui/features/motions/state.ts";
import { uploadPayload } from "../../src/ui/features/motions/upload-actions.ts";
import { demoContext } from "../support/demo-context.ts";

const en = translator(editorMessages, "en");
const ko = translator(editorMessages, "ko");

describe("the remote key of a Run number (docs/protocol.md §3.1)", () => {
  it("number keys 1-9, 0 for 12-21; * then a key for 33-42", () => {
    expect(remoteKeyText(12, en)).toBe("remote key 1");
    expect(remoteKeyText(20, en)).toBe("remote key 9");
    expect(remoteKeyText(21, en)).toBe("remote key 0");
    expect(remoteKeyText(33, en)).toBe("remote * then 1");
    expect(remoteKeyText(42, en)).toBe("remote * then 0");
    expect(remoteKeyText(12, ko)).toBe("리모컨 1번 키");
    expect(remoteKeyText(33, ko)).toBe("리모컨 * 다음 1번 키");
  });

  it("no key for a built-in motion or a number outside the download slots", () => {
    expect(remoteKeyText(7, en)).toBeUndefined();
    expect(remoteKeyText(22, en)).toBeUndefined();
    expect(remoteKeyText(43, en)).toBeUndefined();
  });
});

/** A book after a reset and one upload of `name` (slot 1), as the Motions upload path records it. */
function bookWith(name: string, bytes = 280): { book: SlotBook; entry: BookEntry } {
  const book = afterUpload(afterReset(emptyBook("motion")), { name, fileName: `${name}.rbm`, bytes });
  return { book, entry: book.entries.at(-1)! };
}

describe("what the robot holds of the Editor's motion", () => {
  const doc = newMotion();
  const edited = setPosition(doc, 0, 0, 100);

  it("the upload target carries the document itself, under the file name Save gives it", () => {
    const target = editorUploadTarget(doc);
    expect(isEditorTarget(target)).toBe(true);
    expect(target).toMatchObject({ area: "motion", place: "editor", fileName: "NewMotion.rbm" });
    expect(isEditorTarget(target) && target.motion).toBe(doc);
    expect(isEditorTarget({ area: "motion", entryId: 3 })).toBe(false);
  });

  it("the same document: the same value, or one that saves as the same file (an edit undone by hand)", () => {
    expect(sameDocument(doc, doc)).toBe(true);
    expect(sameDocument(doc, edited)).toBe(false);
    const back = setPosition(edited, 0, 0, doc.scenes[0]!.servos[0]!.end);
    expect(back).not.toBe(doc);
    expect(sameDocument(doc, back)).toBe(true);
  });

  it("same, earlier, or none once the slot book no longer holds the slot", () => {
    const { book, entry } = bookWith("NewMotion");
    const copy: RobotCopy = { doc, entry };
    expect(robotCopyStatus(copy, book, doc)).toEqual({ kind: "same", number: 12, entry });
    expect(robotCopyStatus(copy, book, edited)).toEqual({ kind: "earlier", number: 12, entry });
    expect(robotCopyStatus(undefined, book, doc)).toEqual({ kind: "none" });
    // A memory reset forgets every slot; another file uploaded after it takes slot 1.
    expect(robotCopyStatus(copy, afterReset(book), doc)).toEqual({ kind: "none" });
    const other = afterUpload(afterReset(book), { name: "Wave", fileName: "Wave.rbm", bytes: 280 });
    expect(copyInBook(entry, other)).toBe(false);
    expect(robotCopyStatus(copy, other, doc)).toEqual({ kind: "none" });
  });

  it("no number when the slot is not known (the robot held downloads the panel did not see arrive)", () => {
    const book = afterUpload(emptyBook("motion"), {
      name: "NewMotion",
      fileName: "NewMotion.rbm",
      bytes: 280,
    });
    const entry = book.entries[0]!;
    expect(entry.slot).toBeUndefined();
    expect(robotCopyStatus({ doc, entry }, book, doc)).toEqual({ kind: "same", number: undefined, entry });
  });
});

describe("why the Editor's robot buttons refuse", () => {
  const base = initialState({ serialSupported: false, secureContext: true, route: "editor" });
  const connected = { ...base.connection, phase: "connected" as const, mode: "packet" as const };

  it("not connected, a motion started here or found playing, direct mode; nothing when idle", () => {
    expect(robotRefusal(base)).toBe("Connect a robot first.");
    expect(robotRefusal({ ...base, connection: connected })).toBeUndefined();
    expect(motionPlaying({ ...base, connection: connected })).toBe(false);
    // The device's activity, as the store keeps it: a motion started elsewhere, found by the busy probe.
    const activity = {
      doing: { kind: "busy" as const, since: 0, evidence: "probe" as const },
      halt: undefined,
      limp: false,
    };
    const busy = { ...base, connection: { ...connected, activity } };
    expect(robotRefusal(busy)).toBe(
      "A motion is playing: the robot ignores everything but Basic posture (7) until it ends.",
    );
    expect(motionPlaying(busy)).toBe(true);
    // Direct mode with no activity telling what holds it (not expected): the generic sentence, with Stop.
    const direct = { ...base, connection: { ...connected, mode: "direct" as const } };
    expect(robotRefusal(direct)).toBe("The robot is in direct mode: press Stop to leave it.");
    expect(motionPlaying(direct)).toBe(false);
    expect(stopEndsIt(direct)).toBe(true);
  });

  it("names what holds the robot in direct mode, from the device's activity, and whether Stop ends it (issue 33 item 4)", () => {
    const held = (use: DirectUse) => ({
      ...base,
      connection: {
        ...connected,
        mode: "direct" as const,
        activity: {
          doing: { kind: "direct" as const, use, since: 0 },
          halt: undefined,
          limp: use === "limp",
        },
      },
    });
    expect(robotRefusal(held("tethered-play"))).toBe(
      "Tethered play (Play on robot) keeps the robot in direct mode: press Stop to end it. The servos keep their pose.",
    );
    expect(robotRefusal({ ...held("tethered-play"), locale: "ko" })).toBe(
      "로봇에서 재생 때문에 로봇이 직접 모드에 있어요. 끝내려면 정지를 눌러 주세요. 서보는 자세를 그대로 유지해요.",
    );
    expect(robotRefusal(held("teach-in"))).toBe(
      "Teach-in keeps the robot in direct mode: press End teach-in on the Teach-in tab to end it.",
    );
    expect(robotRefusal(held("servo-control"))).toBe(
      "Servo control keeps the robot in direct mode: press Stop, or Leave servo control in the Servos view, to end it. The servos keep their pose.",
    );
    expect(robotRefusal(held("limp"))).toBe(
      "Limp left the robot in direct mode with its servos limp: press Stop to leave direct mode (the servos stay limp).",
    );
    // Stop beside the sentence where the sentence says Stop; teach-in ends by its own button (it holds first).
    expect(
      ["tethered-play", "servo-control", "limp", "teach-in"].map((u) => stopEndsIt(held(u as DirectUse))),
    ).toEqual([true, true, true, false]);
    expect(stopEndsIt({ ...base, connection: connected })).toBe(false);
  });
});

describe("the Editor's upload on the demo robot", () => {
  let close: (() => Promise<void>) | undefined;
  beforeAll(() => {
    // focusSoon() asks for animation frames; there are none in Node.
    globalThis.requestAnimationFrame ??= () => 0;
  });
  afterEach(async () => {
    await close?.();
    close = undefined;
  });

  it("stores the document on screen in slot 1 (Run 12) and remembers that document", async () => {
    const demo = await demoContext();
    close = demo.close;
    const { ctx, sim, run } = demo;
    await run(showMemory(ctx));
    const doc = setPosition(newMotion(), 0, 0, 100);
    await run(startEditorUpload(ctx, editorUploadTarget(doc)));
    // One scene of 16 servos: 12 + 6·16 + 86 = 194 bytes (docs/protocol.md §6.3), in slot 1.
    expect(sim.motions.map((m) => [m.slot, m.size])).toEqual([[1, 194]]);
    const copy = liveOf(ctx.store.get()).robotCopy;
    expect(copy?.doc).toBe(doc);
    expect(copy?.entry).toMatchObject({ slot: 1, name: "NewMotion", fileName: "NewMotion.rbm", bytes: 194 });
    expect(robotCopyStatus(copy, motionsOf(ctx.store.get()).motionBook, doc)).toMatchObject({
      kind: "same",
      number: 12,
    });
    expect(motionsOf(ctx.store.get()).uploadResult?.text).toContain(
      "Stored as motion 12 (key 1): Run takes this number.",
    );
  });

  it("refuses a document with errors before any byte, and changes nothing", async () => {
    const demo = await demoContext();
    close = demo.close;
    const { ctx, sim, packetLog } = demo;
    // The motion index (field 7) is one byte of the motion image (docs/protocol.md §6.3).
    const bad: Motion = { ...newMotion(), motionIndex: 300 };
    expect(motionIssues(bad).errors.length).toBe(1);
    const payload = uploadPayload(ctx, editorUploadTarget(bad));
    expect(payload).toEqual({
      refused: "Cannot upload: the file has 1 error (listed below). Nothing is sent.",
    });
    const before = packetLog.size;
    const state = ctx.store.get();
    requestEditorUpload(ctx, bad);
    await startEditorUpload(ctx, editorUploadTarget(bad));
    expect(ctx.store.get()).toBe(state);
    expect(packetLog.size).toBe(before);
    expect(sim.motions).toEqual([]);
  });
});
