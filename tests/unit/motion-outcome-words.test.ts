/**
 * Issue 19 item 1 for the motion layer: a refused edit, retime, mirror or tethered play is a `MotionError` with a
 * stable code and its facts (its own message is a technical line), and its English and Korean are the outcome catalogue's sentences
 * (src/i18n/outcomes/motion/), the same entry the Editor says in Korean. Each case below makes the refusal with
 * the real operation and compares both languages with the sentences written out here, never with the code's own
 * output fed back to it. The zero table's count (protocol, simulator) and a refused restamp come from their
 * catalogues the same way.
 */
import { describe, expect, it } from "vitest";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import { motionRefusalText, motionSubjectText } from "../../src/i18n/outcomes/motion/motion-words.ts";
import { zeroProblemText } from "../../src/i18n/outcomes/zero-words.ts";
import {
  addScene,
  apply,
  checkTiming,
  commit,
  createHistory,
  deleteScene,
  frameIntervalMs,
  joinScene,
  type Motion,
  MotionError,
  mirrorPose,
  newMotion,
  playFrames,
  RestampError,
  resolveRange,
  restampRbm,
  retime,
  saveMotion,
  sceneAt,
  servoIndex,
  setDuration,
  setPort,
  setSceneName,
  setSceneTorque,
  setTiming,
  setTorque,
  undo,
  undoLabel,
} from "../../src/motion/index.ts";
import { COMMANDS, ZeroTableError } from "../../src/protocol/index.ts";
import { SimulatedRbc } from "../../src/sim/index.ts";
import { motionRefusal as refusal } from "../support/motion-refusal.ts";

/** The refusal's sentence in each language: the catalogue's, and the one a person reads of the error. */
function said(e: MotionError) {
  return { en: motionRefusalText(e, "en"), ko: motionRefusalText(e, "ko"), errorText: errorText(e, "en") };
}

const both = (en: string, ko: string) => ({ en, ko, errorText: en });

const one = newMotion();
const platform2: Motion = { ...one, platform: 2 };

describe("the motion layer's refusals, worded by the outcome catalogue", () => {
  it.each<[string, () => unknown, string, { en: string; ko: string; errorText: string }]>([
    [
      "a torque outside 0-4",
      () => setTorque(one, 0, 12, 7),
      "motion-value",
      both(
        "The torque of Left elbow (servo 12) must be a whole number from 0 to 4, not 7.",
        "왼쪽 팔꿈치(서보 12)의 토크에는 0에서 4 사이의 정수만 쓸 수 있어요. 입력한 값: 7.",
      ),
    ],
    [
      "a port value outside 0-3",
      () => setPort(one, 0, 0, 9),
      "motion-value",
      both(
        "The extra outputs of Left hip roll (servo 0) must be a whole number from 0 to 3, not 9.",
        "왼쪽 엉덩이 좌우(서보 0)의 추가 출력에는 0에서 3 사이의 정수만 쓸 수 있어요. 입력한 값: 9.",
      ),
    ],
    [
      "a scene's torque",
      () => setSceneTorque(one, 0, -1),
      "motion-value",
      both(
        "The torque of scene 0 must be a whole number from 0 to 4, not -1.",
        "장면 0의 토크에는 0에서 4 사이의 정수만 쓸 수 있어요. 입력한 값: -1.",
      ),
    ],
    [
      "no frames",
      () => setTiming(one, 0, { frames: 0 }),
      "motion-value",
      both(
        "Scene 0: the number of frames must be a whole number from 1 to 65,535, not 0.",
        "장면 0의 프레임 수에는 1에서 65,535 사이의 정수만 쓸 수 있어요. 입력한 값: 0.",
      ),
    ],
    [
      "a zero of a new motion",
      () => newMotion({ zeros: [...Array(15).fill(100), 300] }),
      "motion-value",
      both(
        "The zero of Right elbow (servo 15) must be a whole number from 0 to 254, not 300.",
        "오른쪽 팔꿈치(서보 15)의 영점에는 0에서 254 사이의 정수만 쓸 수 있어요. 입력한 값: 300.",
      ),
    ],
    [
      "a zero table of 3 values",
      () => newMotion({ zeros: [1, 2, 3] }),
      "motion-value",
      both("A zero table has 16 values, not 3.", "영점 표에는 값이 16개 있어야 해요. 받은 값은 3개예요."),
    ],
    [
      "an empty scene name",
      () => setSceneName(one, 0, ""),
      "motion-name",
      both("The name of scene 0 cannot be empty.", "장면 0의 이름에 한 글자 이상 써 주세요."),
    ],
    [
      "a new scene's name with a colon",
      () => addScene(one, 1, { name: "a:b" }),
      "motion-name",
      both(
        'The scene name cannot contain ":", which separates the fields of a motion file.',
        '장면 이름에는 ":"을 쓸 수 없어요. 모션 파일에서 칸을 나누는 기호예요.',
      ),
    ],
    [
      "frames more than 4,550 ms apart",
      () => setTiming(one, 0, { frames: 2, timeMs: 10_000 }),
      "motion-frame-interval",
      both(
        "2 frames in 10,000 ms are 5,000.0 ms apart; the RBC allows at most 4,550 ms, so use at least 3 frames.",
        "프레임 2개를 10,000ms에 재생하면 프레임 사이가 5,000.0ms예요. RBC는 4,550ms까지만 허용해요. 프레임을 3개 이상으로 해 주세요.",
      ),
    ],
    [
      "a scene the motion does not have",
      () => sceneAt(one, 4),
      "motion-no-such-scene",
      both(
        "The motion has scenes 0 to 0; there is no scene 4.",
        "모션의 장면은 0부터 0까지예요. 장면 4은(는) 없어요.",
      ),
    ],
    [
      "a new scene past the end",
      () => addScene(one, 5),
      "motion-no-such-scene",
      both(
        "A new scene goes at a position from 0 to 1, not 5.",
        "새 장면은 0부터 1까지의 위치에만 넣을 수 있어요. 입력한 값: 5.",
      ),
    ],
    [
      "a range that runs backwards",
      () => resolveRange(addScene(one), { from: 1, to: 0 }),
      "motion-no-such-scene",
      both(
        "A range of scenes runs forwards; 1 to 0 does not.",
        "장면 범위는 앞에서 뒤로 가야 해요. 1에서 0까지는 거꾸로예요.",
      ),
    ],
    [
      "joining the first scene",
      () => joinScene(one, 0),
      "motion-no-such-scene",
      both(
        "Scene 0 is the first scene: there is no scene before it to join.",
        "장면 0은 첫 장면이라서 이어 붙일 앞 장면이 없어요.",
      ),
    ],
    [
      "a servo the motion does not have",
      () => servoIndex({ ...one, servos: one.servos.slice(0, 3) }, 9),
      "motion-no-such-servo",
      both(
        "Servo 9 is not in this motion (it has 0, 1, 2).",
        "서보 9번은 이 모션에 없어요 (있는 서보: 0, 1, 2).",
      ),
    ],
    [
      "deleting the only scene",
      () => deleteScene(one, 0),
      "motion-last-scene",
      both(
        "A motion needs at least one scene, so its only scene cannot be deleted.",
        "모션에는 장면이 하나 이상 있어야 해서 하나뿐인 장면은 지울 수 없어요.",
      ),
    ],
    [
      "a time factor of 0",
      () => retime(one, 0),
      "motion-retime",
      both(
        "A time factor must be a number above 0, not 0.",
        "시간 배수는 0보다 큰 수여야 해요. 입력한 값: 0.",
      ),
    ],
    [
      "a scene made longer than 65,535 ms",
      () => retime(one, 200),
      "motion-retime",
      both(
        "Scene 0 would last 100,000 ms; a scene lasts at most 65,535 ms.",
        "그러면 장면 0의 시간이 100,000ms가 돼요. 장면은 65,535ms보다 길 수 없어요.",
      ),
    ],
    [
      "a duration of 1.5 ms",
      () => setDuration(one, 1.5),
      "motion-retime",
      both(
        "A duration must be a whole number of ms above 0, not 1.5.",
        "전체 시간은 0보다 큰 ms 단위 정수여야 해요. 입력한 값: 1.5.",
      ),
    ],
    [
      "mirroring a motion for platform 2",
      () => mirrorPose(platform2, 0),
      "motion-mirror",
      both(
        "Mirroring knows the joints of a HUNO (platform 1); this motion is for platform 2.",
        "좌우 대칭은 HUNO(플랫폼 1)의 관절만 알아요. 이 모션은 플랫폼 2용이에요.",
      ),
    ],
    [
      "a scene without frames, played",
      () => frameIntervalMs(0, 500, 3),
      "motion-play",
      both(
        "Scene 3 has 0 frames; a scene needs at least 1.",
        "장면 3의 프레임이 0개예요. 장면에는 프레임이 1개 이상 있어야 해요.",
      ),
    ],
    [
      "frames 16 ms apart, played",
      () => frameIntervalMs(30, 500, 1),
      "motion-play",
      both(
        "Scene 1 has frames 16 ms apart (500 ms / 30 frames); the RBC needs at least 20 ms (error 6). Use fewer frames.",
        "장면 1의 프레임 사이가 16ms예요 (500ms / 프레임 30개). RBC는 20ms 이상이 필요해요 (오류 6). 프레임 수를 줄여 주세요.",
      ),
    ],
    [
      "a robot zero table of 15 values, played",
      () => playFrames(one, { robotZeros: Array(15).fill(100), platform: 1 }),
      "motion-play",
      both(
        "The robot's zero table must be 16 whole numbers from 0 to 254.",
        "로봇의 영점 표는 0에서 254 사이의 정수 16개여야 해요.",
      ),
    ],
  ])("%s", (_case, change, code, expected) => {
    const e = refusal(change);
    expect(e.code).toBe(code);
    expect(said(e)).toEqual(expected);
    // The error's own message is a technical line: its code and facts.
    expect(e.message.startsWith(code)).toBe(true);
  });

  it("names what was being set as data, and says it from there in each language", () => {
    const e = refusal(() => setTorque(one, 0, 12, 7));
    expect(e.facts).toEqual({
      rule: "whole",
      subject: { field: "torque", scene: 0, servo: 12 },
      value: 7,
      min: 0,
      max: 4,
    });
    expect(motionSubjectText({ field: "start", scene: 2, servo: 20 }, "en")).toBe(
      "The start position of servo 20",
    );
    expect(motionSubjectText({ field: "start", scene: 2, servo: 20 }, "ko")).toBe("서보 20번의 시작 위치");
    expect(motionSubjectText({ field: "motionName" }, "ko")).toBe("모션 이름");
  });

  it("keeps a program's own name for what was set (a string, as before), said as it is", () => {
    const e = refusal(() => checkTiming(0, 500, "Scene 7"));
    expect(motionRefusalText(e, "en")).toBe(
      "Scene 7: the number of frames must be a whole number from 1 to 65,535, not 0.",
    );
    expect(refusal(() => checkTiming(10, 100, 2)).facts).toMatchObject({ rule: "interval-short", scene: 2 });
  });

  it("says a refusal another program made without facts by its code", () => {
    const bare = new MotionError("motion-play", "Not playable.");
    expect(motionRefusalText(bare, "en")).toBe("The RBC would refuse to play these scenes.");
    expect(motionRefusalText(bare, "ko")).toBe("RBC가 이 장면들을 재생할 수 없어요.");
  });
});

describe("sentences the protocol and the simulator share", () => {
  it("a zero table of 15 values: the same facts from the command table and the simulated robot, worded by the catalogue", () => {
    const fifteen = Array(15).fill(125);
    let e: unknown;
    try {
      COMMANDS.writeZeros.request(fifteen);
    } catch (caught) {
      e = caught;
    }
    expect(e).toBeInstanceOf(ZeroTableError);
    expect(e).toMatchObject({ code: "bad-argument", problems: [{ id: -1, value: 15 }] });
    expect(zeroProblemText({ id: -1, value: 15 }, "en")).toBe("A zero table has 16 values, not 15.");
    expect(errorText(e, "en")).toBe(
      "Not written: A zero table has 16 values, not 15. Nothing was sent to the robot.",
    );
    expect(errorText(e, "ko")).toBe(
      "쓰지 않았어요: 영점 표에는 값이 16개 있어야 해요. 받은 값은 15개예요. 로봇에 아무것도 보내지 않았어요.",
    );
    // The simulated robot's option check is for programs: the protocol's technical line.
    expect(() => new SimulatedRbc({ zeros: fifteen })).toThrow(
      new RangeError("zeros: 16 values expected, got 15"),
    );
  });

  it("a refused restamp: the catalogue's sentence, with its code and facts", () => {
    const text = saveMotion(one);
    let e: unknown;
    try {
      restampRbm(text, "12345");
    } catch (caught) {
      e = caught;
    }
    expect(e).toBeInstanceOf(RestampError);
    expect((e as RestampError).code).toBe("restamp-bad-serial");
    expect((e as RestampError).facts).toEqual({ value: "12345" });
    expect((e as RestampError).message).toBe('restamp-bad-serial (value "12345")');
    expect(errorText(e, "en")).toBe(
      'The serial number "12345" cannot be written into a motion file: it must be 13 digits (0-9).',
    );
  });
});

describe("the undo history's step names", () => {
  it("are whatever the caller gives: a message kept as data as well as a string", () => {
    type Step = { readonly key: string; readonly scene: number };
    const opened: Step = { key: "open", scene: 0 };
    const added: Step = { key: "add", scene: 1 };
    let h = createHistory<Step>(one, opened);
    h = commit(h, addScene(one), added);
    expect(undoLabel(h)).toBe(added);
    expect(undo(h).label).toBe(opened);
    expect(undoLabel(undo(h))).toBeUndefined();
    const plain = apply(createHistory(one), (d) => addScene(d), "Add scene 1");
    expect(undoLabel(plain)).toBe("Add scene 1");
  });
});
