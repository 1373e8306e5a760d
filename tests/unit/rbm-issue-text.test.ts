/**
 * The motion file checker's issues in Korean (issue #14 item 1): every code the parser, the validator and the
 * image encoder produce, driven by files built from examples/*.rbm, has a Korean sentence filled from the
 * issue's `values`; English is the catalogue's too, the sentence the protocol used to write; an issue without a
 * sentence keeps its technical line, marked as English.
 */
import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { motionImage } from "../../src/protocol/motion-image.ts";
import { RbmError, type RbmIssue, type RbmMotion, readRbm, validateRbm } from "../../src/protocol/rbm.ts";
import { issueText, issueWords } from "../../src/ui/features/motions/issue-text.ts";

const SRC = new URL("../../src/protocol/", import.meta.url);
const example = (name: string) => readFileSync(new URL(`../../examples/${name}`, import.meta.url), "latin1");
const WAVE = example("wave.rbm"); // 16 servos, 6 scenes
const ARMS = example("arms-only.rbm"); // 6 servos

/** Field positions in a file with `W` servos (docs/protocol.md §7). */
const sceneField = (W: number, scene: number, offset: number) => 13 + 6 * W + scene * (5 + 6 * W) + offset;
const servoField = (servo: number, j: number) => 13 + 6 * servo + j;
const recordField = (W: number, scene: number, record: number, j: number) =>
  sceneField(W, scene, 5 + 6 * record + j);

/** The text with some fields replaced: [index, new text]... */
function edit(text: string, ...changes: [number, string][]): string {
  const fields = text.split(":");
  for (const [i, value] of changes) fields[i] = value;
  return fields.join(":");
}

/** What the panel shows for a file: the reader's error, or the validator's errors and warnings. */
function issuesOf(text: string, connectedSerialNumber?: string): RbmIssue[] {
  try {
    const motion = readRbm(text);
    const { errors, warnings } = validateRbm(motion, connectedSerialNumber ? { connectedSerialNumber } : {});
    return [...errors, ...warnings];
  } catch (e) {
    if (e instanceof RbmError) return [...e.issues];
    throw e;
  }
}

/** The validator's issues for a motion changed in code (the editor's document, a draft). */
function issuesOfMotion(change: (m: RbmMotion) => void, text = WAVE): RbmIssue[] {
  const motion = readRbm(text);
  change(motion);
  const { errors, warnings } = validateRbm(motion);
  return [...errors, ...warnings];
}

/** The image encoder's error for a motion (the panel encodes a file that passed the checks). */
function imageIssues(change: (m: RbmMotion) => void): RbmIssue[] {
  const motion = readRbm(WAVE);
  change(motion);
  try {
    motionImage(motion);
  } catch (e) {
    if (e instanceof RbmError) return [...e.issues];
    throw e;
  }
  return [];
}

const W = 16;
const CASES: readonly RbmIssue[] = [
  // The reader.
  ...issuesOf(5 as unknown as string),
  ...issuesOf(`1:13:${"0".repeat((1 << 20) + 1)}`),
  ...issuesOf("  \n"),
  ...issuesOf("Hello, robot"),
  ...issuesOf(WAVE.trimEnd().slice(0, -1)),
  ...issuesOf("1:13:0000000000000:RBC_Panel_:x:"),
  ...issuesOf(WAVE.split(":").slice(0, -7).join(":").concat(":")),
  ...issuesOf(edit(WAVE, [recordField(W, 0, 2, 2), "x1"])),
  ...issuesOf(edit(WAVE, [sceneField(W, 3, 3), "many"])),
  ...issuesOf(edit(WAVE, [3, "RBC_Panel_and_more"])),
  ...issuesOf(edit(WAVE, [5, "100"])),
  ...issuesOf(edit(WAVE, [sceneField(W, 1, 1), "03"])),
  ...issuesOf(edit(WAVE, [1, "12"])),
  ...issuesOf(edit(WAVE, [11, "0"])),
  // The validator, on files.
  ...issuesOf(edit(WAVE, [7, "300"])),
  ...issuesOf(edit(WAVE, [servoField(3, 1), "256"])),
  ...issuesOf(edit(WAVE, [sceneField(W, 2, 4), "70000"])),
  ...issuesOf(edit(WAVE, [servoField(3, 5), "300"])),
  ...issuesOf(edit(WAVE, [recordField(W, 1, 4, 3), "255"])),
  ...issuesOf(edit(WAVE, [1, "05"], [2, "12345"])),
  ...issuesOf(edit(WAVE, [2, "1234567890123"]), "9999999999999"),
  ...issuesOf(edit(WAVE, [0, "2"], [8, "3"], [10, "5"], [12, "7"])),
  ...issuesOf(ARMS),
  ...issuesOf(edit(WAVE, [servoField(5, 0), "40"])),
  ...issuesOf(edit(WAVE, [servoField(5, 0), "04"])),
  ...issuesOf(edit(WAVE, [sceneField(W, 2, 0), "005"])),
  ...issuesOf(edit(WAVE, [sceneField(W, 0, 3), "0"])),
  ...issuesOf(edit(WAVE, [sceneField(W, 0, 4), "200"])),
  ...issuesOf(edit(WAVE, [sceneField(W, 0, 3), "1"], [sceneField(W, 0, 4), "5000"])),
  ...issuesOf(edit(WAVE, [sceneField(W, 0, 3), "150"], [sceneField(W, 0, 4), "4500"])),
  ...issuesOf(edit(WAVE, [sceneField(W, 0, 3), "10"], [sceneField(W, 0, 4), "12000"])),
  ...issuesOf(edit(WAVE, [recordField(W, 0, 7, 4), "5"], [recordField(W, 0, 8, 5), "4"])),
  ...issuesOf(edit(WAVE, [recordField(W, 0, 2, 2), "100"])),
  ...issuesOf(edit(WAVE, [recordField(W, 0, 2, 2), "100"], [recordField(W, 0, 2, 3), "110"])),
  ...issuesOf(edit(WAVE, [recordField(W, 1, 10, 2), "060"])),
  // The validator, on motions built in code.
  ...issuesOfMotion((m) => {
    m.name = "Wave:there";
    m.scenes[1]!.name = "Up:down";
    m.servoCount = 5;
    m.sceneCount = 9;
    m.scenes[4]!.servos.pop();
  }),
  ...issuesOfMotion((m) => {
    m.servos = [];
    m.servoCount = undefined;
    m.scenes = [];
    m.sceneCount = undefined;
  }),
  // 65,536 scenes (the same scene again and again): only the count matters here, not the jumps between them.
  ...issuesOfMotion((m) => {
    const scene = m.scenes[0]!;
    m.scenes = Array.from({ length: 0x10000 }, (_, index) => ({ ...scene, index }));
    m.sceneCount = undefined;
  }).filter((i) => i.code === "rbm-out-of-range"),
  ...issuesOfMotion((m) => Object.assign(m, { scenes: "none" })),
  ...issuesOfMotion((m) => Object.assign(m, { text1: 5, raw: { fields: 5, trailing: "" } })),
  ...issuesOfMotion((m) => Object.assign(m.scenes[2]!.servos[3]!, { end: 12.5, start: undefined })),
  ...validateRbm(null as unknown as RbmMotion).errors,
  // The image encoder.
  ...imageIssues((m) => Object.assign(m.servos[2]!, { p: 300 })),
  ...imageIssues((m) => m.scenes[3]!.servos.pop()),
];

/**
 * The English sentence of each case, in order: the sentences protocol/rbm*.ts wrote before the words moved to
 * the catalogue, except that large numbers are now grouped ("70,000 ms"), a motion without scenes "needs at
 * least one", and the image encoder names a servo with its joint.
 */
const ENGLISH: readonly string[] = [
  "A motion file must be read as text.",
  "The file has 1,048,582 characters; a motion file is far smaller (the largest motion that fits the robot is about 90,000), so this is not one.",
  "The motion file is empty.",
  'This is not a Motionbuilder motion file (.rbm): such a file is one line of fields separated by ":", starting with "1:13:" and the 13-digit serial number of a robot.',
  'The file should end with ":", not ":205:205:2:0"; it is truncated or damaged.',
  "The file has only 5 fields; an .rbm file's header alone has 13.",
  "The file has 709 fields, but a motion with 16 servos and 6 scenes has 715; the file is truncated or damaged.",
  'Field 128 (scene 0, servo record 2: start position) should be a whole number but is "x1".',
  'Field 415 (scene 3: frames) should be a whole number but is "many".',
  "Field 3 (the 10-character text) has 18 characters; it holds at most 10.",
  "The length of the motion name is 100; a name in a motion file has at most 99 characters.",
  'The name of scene 1, "WaveOut" has 7 characters, but its length field says 3.',
  'The serial number "0000000000000" has 13 characters, but its length field says 12.',
  "The file says the motion has 0 servos; a motion has 1 to 31.",
  "The motion index is 300; it must fit in one byte (0-255).",
  "The P gain of servo 3 (Left ankle pitch) is 256; it must fit in one byte (0-255).",
  "Scene 2 has frames 7,000 ms apart (70,000 ms / 10 frames); the RBC allows at most 4,550 ms (its frame timer overflows).",
  "Scene 2: frames and time must each fit in 16 bits (0-65,535).",
  "Scene 2 lasts 70,000 ms, longer than Motionbuilder's 10,000 ms.",
  "The zero position of servo 3 (Left ankle pitch) is 300; positions go from 0 to 254.",
  "Scene 1: the end position of servo 4 (Left ankle roll) is 255; positions go from 0 to 254.",
  "Scene 2 starts servo 4 (Left ankle roll) at 108, but scene 1 ended it at 255; the servo will jump.",
  'The serial number "12345" is not 13 digits, the form Motionbuilder writes.',
  "This motion was made for the robot with serial number 1234567890123, but the connected robot is 9999999999999; Motionbuilder refuses such files. Check that the motion suits this robot.",
  "Field 0 (format) is 2; Motionbuilder always writes 1.",
  "Field 8 (platform) is 3; Motionbuilder always writes 1.",
  "Field 10 is 5; Motionbuilder always writes 2.",
  "Field 12 is 7; Motionbuilder always writes 4.",
  "The motion has 6 servos; a HUNO has 16.",
  "Servo record 5 has id 40; servo ids go from 0 to 30.",
  "Scene 0, servo record 5 is for servo 5, but the motion's servo record 5 is servo 40; scene records must follow the servo list.",
  "Scene 1, servo record 5 is for servo 5, but the motion's servo record 5 is servo 40; scene records must follow the servo list.",
  "Scene 2, servo record 5 is for servo 5, but the motion's servo record 5 is servo 40; scene records must follow the servo list.",
  "Scene 3, servo record 5 is for servo 5, but the motion's servo record 5 is servo 40; scene records must follow the servo list.",
  "Scene 4, servo record 5 is for servo 5, but the motion's servo record 5 is servo 40; scene records must follow the servo list.",
  "Scene 5, servo record 5 is for servo 5, but the motion's servo record 5 is servo 40; scene records must follow the servo list.",
  "Servo id 4 is listed twice (records 4 and 5).",
  "Scene 0, servo record 5 is for servo 5, but the motion's servo record 5 is servo 4; scene records must follow the servo list.",
  "Scene 1, servo record 5 is for servo 5, but the motion's servo record 5 is servo 4; scene records must follow the servo list.",
  "Scene 2, servo record 5 is for servo 5, but the motion's servo record 5 is servo 4; scene records must follow the servo list.",
  "Scene 3, servo record 5 is for servo 5, but the motion's servo record 5 is servo 4; scene records must follow the servo list.",
  "Scene 4, servo record 5 is for servo 5, but the motion's servo record 5 is servo 4; scene records must follow the servo list.",
  "Scene 5, servo record 5 is for servo 5, but the motion's servo record 5 is servo 4; scene records must follow the servo list.",
  "Scene 2 is numbered 5; scenes are numbered 0 to 5 in order.",
  "Scene 0 has 0 frames; a scene needs at least 1.",
  "Scene 0 has frames 10 ms apart (200 ms / 20 frames); the RBC needs at least 20 ms. Use fewer frames.",
  "Scene 0 has frames 5,000 ms apart (5,000 ms / 1 frames); the RBC allows at most 4,550 ms (its frame timer overflows).",
  "Scene 0 has 150 frames, more than Motionbuilder's 100.",
  "Scene 0 lasts 12,000 ms, longer than Motionbuilder's 10,000 ms.",
  "Scene 0: the torque of servo 7 (Right knee) is 5; torque goes from 0 to 4.",
  "Scene 0: the port value of servo 8 (Right ankle pitch) is 4; it goes from 0 to 3.",
  "Scene 0: servo 2 (Left knee) goes to 100, outside its safe range 124-254.",
  "Scene 0: servo 2 (Left knee) goes to 100 and 110, outside its safe range 124-254.",
  "Scene 1 starts servo 2 (Left knee) at 199, but scene 0 ended it at 110; the servo will jump.",
  "Scene 1 starts servo 10 (Left shoulder pitch) at 60, but scene 0 ended it at 160; the servo will jump.",
  'The motion name contains ":", which would split the field in an .rbm file.',
  "The motion says it has 5 servos but lists 16.",
  "The motion says it has 9 scenes but lists 6.",
  'The name of scene 1 contains ":", which would split it.',
  "Scene 4 has 15 servo records; the motion has 16 servos.",
  "The motion has 0 servos; a motion has 1 to 31.",
  "The motion has no scenes; a motion needs at least one.",
  "The motion has 65,536 scenes; a motion image holds at most 65,535.",
  'scenes must be a list (it is "none").',
  "text1 must be text (it is 5).",
  "raw, fields is not in the form parseRbm produces.",
  "scene 2, servo record 3, start must be a whole number of 0 or more (it is missing).",
  "scene 2, servo record 3, end must be a whole number of 0 or more (it is 12.5).",
  "A motion must be an object with servos and scenes.",
  "The P gain of servo 2 (Left knee) is 300; the motion image holds whole numbers from 0 to 255 there.",
  "Scene 3 has 15 servo records; the motion has 16 servos.",
];

/** Every issue code written in the parser, the validator and the image encoder. */
function codesInSource(): string[] {
  const files = ["rbm.ts", "rbm-validate.ts", "rbm-shape.ts", "motion-image.ts"];
  const text = files.map((f) => readFileSync(new URL(f, SRC), "utf8")).join("\n");
  return [...new Set([...text.matchAll(/"(rbm-[a-z0-9-]+)"/g)].map((m) => m[1]!))].sort();
}

const hangul = /\p{Script=Hangul}/u;

describe("a motion file's issues in Korean", () => {
  it("covers every code the parser, validator and image encoder produce (the serializer's aside)", () => {
    const produced = [...new Set(CASES.map((i) => i.code))].sort();
    // rbm-unwritable is serializeRbm's: a document that cannot be written, never an issue of a checked file.
    expect(produced).toEqual(codesInSource().filter((c) => c !== "rbm-unwritable"));
    // Codes with several sentences: each of them is driven.
    const kinds = new Set(CASES.map((i) => `${i.code} ${i.values?.kind ?? ""}`.trim()));
    for (const kind of [
      "rbm-shape motion",
      "rbm-shape list",
      "rbm-shape text",
      "rbm-shape form",
      "rbm-not-a-number shape",
      "rbm-not-a-number field",
      "rbm-out-of-range byte",
      "rbm-out-of-range scenes",
      "rbm-out-of-range timing",
      "rbm-servo-count declared",
      "rbm-servo-count range",
      "rbm-servo-count scene",
      "rbm-servo-count file",
      "rbm-servo-id range",
      "rbm-servo-id twice",
      "rbm-servo-id order",
      "rbm-field-count header",
      "rbm-field-count total",
      "rbm-field-too-long text",
      "rbm-field-too-long name",
    ]) {
      expect(kinds, kind).toContain(kind);
    }
  });

  it("says every one of them in Korean, with every placeholder filled", () => {
    const problems = CASES.flatMap((issue) => {
      const words = issueWords(issue, "ko");
      const out: string[] = [];
      if (words.lang !== "ko") out.push(`${issue.code}: kept in English: ${issue.message}`);
      if (!hangul.test(words.text)) out.push(`${issue.code}: not Korean: ${words.text}`);
      if (/\{[A-Za-z]\w*\}|undefined/.test(words.text)) out.push(`${issue.code}: unfilled: ${words.text}`);
      return out;
    });
    expect(problems).toEqual([]);
    expect(CASES.length).toBeGreaterThan(60);
  });

  it("says every one of them in English from the catalogue, the sentences the protocol used to write", () => {
    expect(CASES.map((issue) => issueText(issue, "en"))).toEqual(ENGLISH);
    for (const issue of CASES) {
      expect(issueWords(issue, "en").lang).toBe("en");
      // The issue's own message is a technical line for logs: its code and its facts.
      expect(issue.message.startsWith(issue.code)).toBe(true);
    }
  });

  const korean = (issues: readonly RbmIssue[], code: string) =>
    issues.filter((i) => i.code === code).map((i) => issueText(i, "ko"));

  it("says the RBC's rules with the file's numbers", () => {
    expect(korean(issuesOf(edit(WAVE, [sceneField(W, 0, 4), "200"])), "rbm-frame-interval-short")).toEqual([
      "장면 0의 프레임 간격이 10ms예요 (200ms / 프레임 20개). RBC에는 20ms 이상이 필요해요. 프레임 수를 줄여 주세요.",
    ]);
    expect(korean(issuesOf(edit(WAVE, [recordField(W, 1, 10, 2), "060"])), "rbm-scene-jump")).toEqual([
      "장면 0에서 서보 10번(왼쪽 어깨 앞뒤)의 끝 위치는 160인데, 장면 1에서는 60에서 시작해서 서보가 튀어요.",
    ]);
    expect(korean(issuesOf(edit(WAVE, [servoField(3, 5), "300"])), "rbm-position")).toEqual([
      "서보 3번(왼쪽 발목 앞뒤)의 영점 위치 값이 300인데, 위치는 0부터 254까지예요.",
    ]);
    expect(korean(issuesOf(edit(WAVE, [recordField(W, 1, 4, 3), "255"])), "rbm-position")).toEqual([
      "장면 1에서 서보 4번(왼쪽 발목 좌우)의 끝 위치 값이 255인데, 위치는 0부터 254까지예요.",
    ]);
    const long = edit(WAVE, [sceneField(W, 0, 3), "10"], [sceneField(W, 0, 4), "12000"]);
    expect(korean(issuesOf(long), "rbm-long-scene")).toEqual([
      "장면 0의 길이가 12,000ms로, Motionbuilder의 한도인 10,000ms보다 길어요.",
    ]);
    expect(korean(issuesOf(edit(WAVE, [0, "2"], [10, "5"])), "rbm-header-constant")).toEqual([
      "0번 필드(형식) 값이 2인데, Motionbuilder는 항상 1(으)로 써요.",
      "10번 필드 값이 5인데, Motionbuilder는 항상 2(으)로 써요.",
    ]);
    const twice = edit(WAVE, [recordField(W, 0, 2, 2), "100"], [recordField(W, 0, 2, 3), "110"]);
    expect(korean(issuesOf(twice), "rbm-unsafe-position")).toEqual([
      "장면 0에서 서보 2번(왼쪽 무릎)이 안전 범위(124-254) 밖인 100, 110 위치로 가요.",
    ]);
    expect(korean(issuesOf(ARMS), "rbm-huno-servo-count")).toEqual([
      "모션의 서보가 6개인데, HUNO의 서보는 16개예요.",
    ]);
  });

  it("says what is wrong with a file that cannot be read, naming the field", () => {
    expect(korean(issuesOf(edit(WAVE, [recordField(W, 0, 2, 2), "x1"])), "rbm-not-a-number")).toEqual([
      '128번 필드(장면 0, 서보 레코드 2번의 시작 위치)는 정수여야 해요 (지금 값: "x1").',
    ]);
    expect(korean(issuesOf(edit(WAVE, [1, "12"])), "rbm-length-mismatch")).toEqual([
      '시리얼 번호 "0000000000000"의 길이는 13글자인데, 길이 필드에는 12글자로 적혀 있어요.',
    ]);
    expect(korean(issuesOf(edit(WAVE, [sceneField(W, 1, 1), "03"])), "rbm-length-mismatch")).toEqual([
      expect.stringMatching(
        /^장면 1의 이름 "\w+"의 길이는 \d+글자인데, 길이 필드에는 3글자로 적혀 있어요\.$/,
      ),
    ]);
    expect(korean(issuesOf(`1:13:${"0".repeat(1_100_000)}`), "rbm-too-large")).toEqual([
      "파일이 1,100,005자예요. 모션 파일은 훨씬 작아서(로봇에 들어가는 가장 큰 모션도 약 90,000자) 이 파일은 모션 파일이 아니에요.",
    ]);
  });

  it("keeps an issue it has no sentence for in English, marked as English", () => {
    const unknown = { code: "rbm-something-new", message: "Something new is wrong.", values: { scene: 2 } };
    expect(issueWords(unknown, "ko")).toEqual({ text: "Something new is wrong.", lang: "en" });
    // A known code whose values are missing (an issue made before they existed) or incomplete.
    const jump = issuesOf(edit(WAVE, [recordField(W, 1, 10, 2), "060"])).find(
      (i) => i.code === "rbm-scene-jump",
    )!;
    const bare: RbmIssue = { code: jump.code, message: jump.message, scene: jump.scene, servo: jump.servo };
    expect(issueWords(bare, "ko")).toEqual({ text: jump.message, lang: "en" });
    const partial = { ...jump, values: { scene: 1, servo: 10 } };
    expect(issueWords(partial, "ko")).toEqual({ text: jump.message, lang: "en" });
    const wrongKind = {
      code: "rbm-servo-id",
      message: "Servo id 3 is odd.",
      values: { kind: "strange", id: 3 },
    };
    expect(issueWords(wrongKind, "ko").lang).toBe("en");
  });

  it("leaves the panel's own issues (already in the panel's language) as they are", () => {
    const tooLarge = { code: "too-large", message: "파일이 너무 커서 읽지 않았어요." };
    expect(issueWords(tooLarge, "ko")).toEqual({ text: tooLarge.message, lang: "ko" });
  });
});
