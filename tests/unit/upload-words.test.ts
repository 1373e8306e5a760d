import { describe, expect, it } from "vitest";
import { RbcUploadError, type UploadFailureFacts } from "../../src/device/errors.ts";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import { robotErrorText } from "../../src/i18n/outcomes/robot-error.ts";
import { uploadFailureText } from "../../src/i18n/outcomes/upload-words.ts";

/**
 * A failed upload is facts, worded once per language by the outcome catalogue (issue 19 item 1): the device's
 * English message and the Korean sentence say the same things (where it stopped, the bytes acknowledged, what
 * the robot's memory shows, its error code, what to do).
 */
const STOPPED: UploadFailureFacts = {
  area: "motion",
  stop: "stopped-acknowledging",
  acknowledged: 128,
  total: 624,
  outcome: "nothing-recorded",
  freeBefore: 24576,
  freeNow: 24576,
  footprint: 640,
  deviceErrorCode: 2,
};

describe("an upload's failure in words", () => {
  it("says where it stopped, what the robot reports and what its memory shows, in both languages", () => {
    expect(uploadFailureText(STOPPED, "en")).toBe(
      "The robot stopped acknowledging (128 of 624 bytes were acknowledged). The robot reports: checksum error (an upload chunk was corrupted) (which this program's own abandon bytes also cause). The robot recorded nothing: its free motion memory is unchanged (24,576 bytes). Upload it again.",
    );
    expect(uploadFailureText(STOPPED, "ko")).toBe(
      "로봇이 확인 응답을 멈췄어요 (624바이트 중 128바이트를 받았다고 확인했어요). 로봇이 알려 온 오류: 체크섬 오류 (업로드한 조각이 손상됨) (이 프로그램이 업로드를 그만둘 때 보내는 바이트도 이 오류를 일으켜요). 로봇은 아무것도 기록하지 않았어요. 남은 모션 메모리가 그대로예요 (24,576바이트). 다시 업로드해 주세요.",
    );
  });

  it("a lost link: after the last chunk the file may be recorded; before it, the robot still waits", () => {
    const lost = { ...STOPPED, stop: "lost" as const, freeNow: undefined, deviceErrorCode: undefined };
    expect(uploadFailureText({ ...lost, outcome: "unknown" }, "en")).toBe(
      "The connection was lost during the upload (128 of 624 bytes were acknowledged). The last chunk had been sent, so the robot may have recorded the file: switch it off and on, then check its free memory or upload again.",
    );
    expect(uploadFailureText({ ...lost, outcome: "interrupted" }, "en")).toMatch(
      /still waiting for the rest of the file and has recorded nothing/,
    );
  });

  it("every chunk acknowledged but memory changed by something else: uncertain, with the numbers", () => {
    const odd: UploadFailureFacts = {
      ...STOPPED,
      stop: "unconfirmed",
      acknowledged: 624,
      outcome: "unknown",
      freeNow: 24000,
      deviceErrorCode: 0xff,
    };
    expect(uploadFailureText(odd, "en")).toBe(
      "Every chunk of the 624-byte motion file was acknowledged, but the robot's free memory does not show the file. The robot's free motion memory is now 24,000 bytes (was 24,576; the file needs 640), so whether it recorded the file is unknown. Switch it off and on, reset its motion memory and upload again.",
    );
  });

  it("the device's error carries the facts, said in English and in Korean with the same numbers", () => {
    const e = RbcUploadError.of("upload-failed", STOPPED);
    expect(errorText(e, "en")).toBe(uploadFailureText(STOPPED, "en"));
    expect(e.facts).toEqual(STOPPED);
    expect(errorText(e, "ko")).toBe(uploadFailureText(STOPPED, "ko"));
    expect(errorText(e, "ko")).toContain("24,576바이트");
  });

  it("the robot's error codes from one catalogue", () => {
    expect(robotErrorText(0xff, "en")).toBe("no error");
    expect(robotErrorText(11, "en")).toBe("a servo did not answer");
    expect(robotErrorText(11, "ko")).toBe("응답하지 않은 서보가 있음");
    expect(robotErrorText(42, "en")).toBe("unknown error code 42");
  });
});
