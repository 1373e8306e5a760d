/**
 * The Sensors view, the Servos view and the 3D robot in Korean (issue #14 item 1): the sentences made outside
 * templates (events, refusals of a typed target, the live robot's captions, the motion preview's times) in both
 * languages, literal strings; and the English words that must stay those of the protocol layer (the built-in
 * motions, the distance warning the CLI prints too).
 */
import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { distanceWarning } from "../../src/i18n/outcomes/plausibility.ts";
import { translator } from "../../src/i18n/translate.ts";
import { openMotion } from "../../src/motion/index.ts";
import { BUILT_IN_MOTIONS } from "../../src/protocol/catalog.ts";
import { HUNO_BASIC_POSTURE } from "../../src/protocol/servo-limits.ts";
import { distanceWarningText } from "../../src/ui/features/sensors/distance-warning.ts";
import { builtInMotionName, describeEvent } from "../../src/ui/features/sensors/events.ts";
import { sensorsMessages } from "../../src/ui/features/sensors/messages.ts";
import { checkTypedTarget } from "../../src/ui/features/servos/state.ts";
import { Robot3dError, robot3dErrorText } from "../../src/ui/robot3d/errors.ts";
import { hardwarePicture } from "../../src/ui/robot3d/live-robot.ts";
import { describeTime, formatPreviewTime } from "../../src/ui/robot3d/motion-preview.ts";

const WAVE = openMotion(readFileSync(new URL("../../examples/wave.rbm", import.meta.url), "latin1"));

describe("the Sensors view's words", () => {
  it("describe events in Korean", () => {
    expect(describeEvent({ kind: "buttons", value: 2 }, "ko")).toBe("PF2 눌림");
    expect(describeEvent({ kind: "buttons", value: 3 }, "ko")).toBe("버튼 3번 눌림");
    expect(describeEvent({ kind: "remote", value: 7 }, "ko")).toBe("IR 키 7번 (기본 자세)");
    expect(describeEvent({ kind: "remote", value: 2 }, "ko")).toBe("IR 키 2번 (일어나기 B (누워서))");
    expect(describeEvent({ kind: "remote", value: 200 }, "ko")).toBe("IR 키 200번");
    expect(describeEvent({ kind: "sound", value: 1200 }, "ko")).toBe("소리 크기 1,200");
    expect(describeEvent({ kind: "buttons", value: 1 }, "en")).toBe("PF1 pressed");
  });

  it("name the built-in motions as protocol/catalog.ts does in English", () => {
    const en = translator(sensorsMessages, "en");
    expect(BUILT_IN_MOTIONS.map((m) => builtInMotionName(en, m.number))).toEqual(
      BUILT_IN_MOTIONS.map((m) => m.name),
    );
    const ko = translator(sensorsMessages, "ko");
    expect(builtInMotionName(ko, 4)).toBe("앞으로 걷기");
    expect(builtInMotionName(ko, 12)).toBeUndefined();
  });

  it("warn about an implausible distance with the CLI's English sentence, and in Korean", () => {
    const en = translator(sensorsMessages, "en");
    for (const cm of [0, 9, 51, 60, 1200, 12.5])
      expect(distanceWarningText(en, cm)).toBe(distanceWarning(cm));
    for (const cm of [10, 30, 50]) expect(distanceWarningText(en, cm)).toBeUndefined();
    expect(distanceWarningText(translator(sensorsMessages, "ko"), 60)).toBe(
      "거리 센서가 60cm를 알려 왔어요. 이 센서가 잴 수 있는 10-50cm를 벗어나요. 값은 그대로 보여 주지만 믿기 어려운 값이에요.",
    );
  });
});

describe("the Servos view's words", () => {
  it("refuse a typed target in Korean, saying why and that nothing was sent", () => {
    // Servo 12: lower 1, upper 198; servo 3: 40-130.
    expect(checkTypedTarget(12, "300", "ko")).toEqual({
      problem:
        "서보 12번: 300은(는) 안전 범위(1–198) 밖이에요. 아무것도 보내지 않았고, 서보는 그대로 있어요.",
    });
    expect(checkTypedTarget(3, "12.5", "ko")).toEqual({
      problem:
        '서보 3번: "12.5"은(는) 정수가 아니에요. 40~130 사이의 값을 써 주세요. 아무것도 보내지 않았어요.',
    });
    expect(checkTypedTarget(3, "", "ko")).toEqual({
      problem: "서보 3번: 40~130 사이의 위치를 입력해 주세요. 아무것도 보내지 않았어요.",
    });
    expect(checkTypedTarget(3, "-1200", "en")).toEqual({
      problem:
        "Servo 3: -1200 is outside its safe range 40–130. Nothing was sent; the servo stays where it is.",
    });
    expect(checkTypedTarget(3, "100", "ko")).toEqual({ position: 100 });
  });
});

describe("the 3D robot's words", () => {
  const at = new Date(2026, 10, 21, 9, 2, 11).getTime();
  const someRead = HUNO_BASIC_POSTURE.map((p, id) => (id === 3 || id === 7 ? undefined : p));

  it("caption a robot on a cable in English as before", () => {
    const none = hardwarePicture({ positions: [], at: undefined }, undefined);
    expect(none.caption).toBe("No positions read yet: drawn in the basic posture");
    const two = hardwarePicture({ positions: someRead, at }, undefined);
    expect(two.caption).toBe("Last read positions, 09:02:11");
    expect(two.unreadText).toBe(
      "Servos 3 and 7 were never read (or did not answer): drawn at the basic posture, not where they are.",
    );
    expect(two.label).toBe(
      "3D view of the robot at its last read positions, 09:02:11; servos 3 and 7 never read, drawn at the basic posture",
    );
    const one = hardwarePicture(
      { positions: HUNO_BASIC_POSTURE.map((p, id) => (id === 9 ? undefined : p)), at },
      [],
    );
    expect(one.unreadText).toBe(
      "Servo 9 was never read (or did not answer): drawn at the basic posture, not where it is.",
    );
    expect(hardwarePicture({ positions: [...HUNO_BASIC_POSTURE], at: undefined }, undefined).caption).toBe(
      "Last read positions",
    );
  });

  it("caption a robot on a cable in Korean", () => {
    const none = hardwarePicture({ positions: [], at: undefined }, undefined, "ko");
    expect(none.caption).toBe("아직 읽은 위치가 없어요: 기본 자세로 그렸어요");
    expect(none.label).toBe("기본 자세로 그린 로봇의 3D 보기: 읽은 위치가 하나도 없어요");
    const two = hardwarePicture({ positions: someRead, at }, undefined, "ko");
    expect(two.caption).toBe("마지막으로 읽은 위치, 09:02:11");
    expect(two.unreadText).toBe(
      "서보 3, 7번은 읽지 못했어요 (또는 응답하지 않았어요). 실제 위치가 아니라 기본 자세로 그렸어요.",
    );
    expect(two.label).toBe(
      "마지막으로 읽은 위치(09:02:11)에 있는 로봇의 3D 보기; 서보 3, 7번은 읽지 않아 기본 자세로 그림",
    );
  });

  it("write the preview's times and scenes in both languages", () => {
    expect(formatPreviewTime(800)).toBe("0.8 s");
    expect(formatPreviewTime(3200, "ko")).toBe("3.2초");
    expect(formatPreviewTime(-5, "ko")).toBe("0.0초");
    expect(describeTime(WAVE, 400)).toBe("scene 0, RaiseArm");
    expect(describeTime(WAVE, 400, undefined, "ko")).toBe("장면 0, RaiseArm");
    expect(describeTime(WAVE, 800, undefined, "ko")).toBe("장면 0 끝, RaiseArm");
    expect(describeTime(WAVE, 1600)).toBe("end of scene 2, WaveIn");
    expect(describeTime(WAVE, 1600, undefined, "ko")).toBe("장면 2 끝, WaveIn");
  });

  it("say why the view cannot draw, in English in the error and in the panel's language on the page", () => {
    const error = new Robot3dError("robot3d-no-webgl");
    expect(error.code).toBe("robot3d-no-webgl");
    expect(error.message).toMatch(/^The 3D view needs WebGL 2, /);
    expect(robot3dErrorText("robot3d-no-webgl", "ko")).toMatch(/^3D 보기에는 WebGL 2가 필요한데/);
    expect(robot3dErrorText("robot3d-load-failed", "ko")).toBe(
      "3D 보기를 불러오지 못했어요 (패널을 연 뒤 오프라인이 되었나요?). 장면 표에서 모션을 글로 볼 수 있어요.",
    );
  });
});
