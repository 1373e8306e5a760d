import { readdirSync, readFileSync } from "node:fs";
import { join, relative } from "node:path";
import { describe, expect, it } from "vitest";
import { stopPoseMessages } from "../../src/i18n/outcomes/stop-pose-messages.ts";
import { catalogueEntries } from "../support/catalogue-entries.ts";

/**
 * Issue 33 item 6: Stop contradicted itself ("ends the motion and keeps the robot standing", then "the robot
 * holds the pose it stopped in; run Basic posture to bring it back to standing"). The firmware ends a motion at
 * the end of its current scene and holds that pose with the servos on (docs/protocol.md §3.6): the robot does
 * not fall, but it is not necessarily standing. Every catalogue of the panel, the command line and the outcome
 * catalogue is read (English and Korean), and the user-facing docs; none may say that Stop keeps the robot
 * standing. The one sentence that says what Stop leaves (`outcome.stop.holdsPose`) is checked for both languages.
 */

const ROOT = join(import.meta.dirname, "../../src");

/** English claims that Stop keeps the robot standing ("keeps the robot standing", "stands in that pose", …). */
const STANDING_EN =
  /\bkeeps (the robot |it )?standing|\bkeep (the robot |it )?standing(?! on)|\bstays standing|\bstands? in (that|the|its) pose|\bkeeps standing/i;
/** The same in Korean ("선 채로 유지해요", "계속 서 있어요", "그 자세로 서 있어요", "로봇을 세워 두려면"). */
const STANDING_KO = /선 채로|계속 서 있|그 자세로 서 있|로봇을 세워 두/;

const entries = (await catalogueEntries()).map((e) => ({ where: `${e.file} ${e.key}`, en: e.en, ko: e.ko }));

/** The user-facing docs: the README and docs/*.md. */
const DOCS = [
  join(ROOT, "../README.md"),
  ...readdirSync(join(ROOT, "../docs"))
    .filter((name) => name.endsWith(".md"))
    .map((name) => join(ROOT, "../docs", name)),
];

describe("Stop says what the firmware does: the robot holds the pose it stopped in, not necessarily standing", () => {
  it("the patterns find the old words (English and Korean) and leave the true ones alone", () => {
    for (const old of [
      "Stop (Esc) ends the motion and keeps the robot standing.",
      "End what the robot is doing; it keeps standing (Escape)",
      "The robot took Stop: it finishes the current scene and stands in that pose.",
      "end a running motion with 7; the robot keeps standing",
      "To end a motion and keep the robot standing, use `rbc stop` instead.",
    ]) {
      expect(old).toMatch(STANDING_EN);
    }
    for (const old of [
      "정지(Esc)는 모션을 끝내고 로봇을 선 채로 유지해요.",
      "로봇이 정지를 받았어요. 지금 장면까지 마치고 그 자세로 서 있어요.",
      "실행 중인 모션을 7로 끝내기 (로봇은 계속 서 있어요)",
      "모션을 끝내고 로봇을 세워 두려면 대신 `rbc stop`을 써 주세요.",
    ]) {
      expect(old).toMatch(STANDING_KO);
    }
    for (const fine of [
      "Keep it standing on a flat surface, or hold it.",
      "Basic posture cannot be interrupted: the robot finished it and stands straight.",
      "Trim on the standing robot",
    ]) {
      expect(fine).not.toMatch(STANDING_EN);
    }
    expect("평평한 곳에 세워 두거나 로봇을 잡아 주세요.").not.toMatch(STANDING_KO);
  });

  it("no catalogue entry says that Stop keeps the robot standing, in English or in Korean", () => {
    expect(entries.length).toBeGreaterThan(500);
    const standing = entries
      .filter((e) => STANDING_EN.test(e.en) || STANDING_KO.test(e.ko))
      .map((e) => `${e.where}: ${e.en} / ${e.ko}`);
    expect(standing).toEqual([]);
  });

  it("nor do the README and the docs", () => {
    const standing = DOCS.flatMap((path) =>
      readFileSync(path, "utf8")
        .split("\n")
        .filter((line) => STANDING_EN.test(line) || STANDING_KO.test(line))
        .map((line) => `${relative(join(ROOT, ".."), path)}: ${line}`),
    );
    expect(standing).toEqual([]);
  });

  it("the one sentence of what Stop leaves says 'holds the pose it stopped in' and 'not necessarily standing' in both languages", () => {
    const m = stopPoseMessages["outcome.stop.holdsPose"];
    expect(m.en).toBe(
      "The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing.",
    );
    expect(m.ko).toBe(
      "로봇은 서보에 힘이 들어간 채로 멈춘 자세를 유지해요. 넘어지지는 않지만, 꼭 서 있는 자세는 아니에요.",
    );
    // Written once: no other entry repeats it (it is reused where Stop is described).
    expect(entries.filter((e) => e.en === m.en)).toHaveLength(1);
  });
});
