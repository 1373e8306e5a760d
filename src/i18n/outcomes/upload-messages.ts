import { defineMessages } from "../catalogue.ts";

/**
 * Where an upload stopped and what the robot's memory then showed (docs/protocol.md §6; `RbcUploadError.facts`):
 * part of the one outcome catalogue (docs/i18n.md "Outcomes"), worded by `upload-words.ts` for the device's
 * error message, `rbc upload` and the panel alike.
 */
export const uploadOutcomeMessages = defineMessages({
  "outcome.area.motion": { en: "motion", ko: "모션" },
  "outcome.area.action": { en: "action", ko: "액션" },
  "outcome.uploadCancelledEarly": {
    en: "Upload cancelled before any byte was sent.",
    ko: "바이트를 하나도 보내기 전에 업로드를 취소했어요.",
  },
  "outcome.uploadCancelledEarlyByStop": {
    en: "Upload cancelled by Stop before any byte was sent.",
    ko: "바이트를 하나도 보내기 전에 정지로 업로드를 취소했어요.",
  },
  "outcome.uploadStop.lost": {
    en: "The connection was lost during the upload ({acknowledged} of {total} bytes were acknowledged).",
    ko: "업로드 중에 연결이 끊겼어요 ({total}바이트 중 {acknowledged}바이트를 받았다고 확인했어요).",
  },
  "outcome.uploadStop.cancelled": {
    en: "Upload cancelled ({acknowledged} of {total} bytes were acknowledged).",
    ko: "업로드를 취소했어요 ({total}바이트 중 {acknowledged}바이트를 받았다고 확인했어요).",
  },
  "outcome.uploadStop.startNotAcknowledged": {
    en: "The robot did not acknowledge the start of the upload ({acknowledged} of {total} bytes were acknowledged); it may have refused it.",
    ko: "로봇이 업로드 시작을 확인하지 않았어요 ({total}바이트 중 {acknowledged}바이트를 받았다고 확인했어요). 거부했을 수도 있어요.",
  },
  "outcome.uploadStop.stoppedAcknowledging": {
    en: "The robot stopped acknowledging ({acknowledged} of {total} bytes were acknowledged).",
    ko: "로봇이 확인 응답을 멈췄어요 ({total}바이트 중 {acknowledged}바이트를 받았다고 확인했어요).",
  },
  "outcome.uploadStop.extraAck": {
    en: "An acknowledgement came when none was due, so the upload stopped there ({acknowledged} of {total} bytes were acknowledged).",
    ko: "확인 응답이 올 때가 아닌데 와서 업로드를 거기서 멈췄어요 ({total}바이트 중 {acknowledged}바이트를 받았다고 확인했어요).",
  },
  "outcome.uploadStop.earlyAck": {
    en: "An acknowledgement came sooner than its part could have reached the robot, so the upload stopped there ({acknowledged} of {total} bytes were acknowledged).",
    ko: "조각이 로봇에 닿을 수 있는 시간보다 먼저 확인 응답이 와서 업로드를 거기서 멈췄어요 ({total}바이트 중 {acknowledged}바이트를 받았다고 확인했어요).",
  },
  "outcome.uploadStop.unconfirmed": {
    en: "Every chunk of the {total}-byte {area} file was acknowledged, but the robot's free memory does not show the file.",
    ko: "{total}바이트 {area} 파일의 모든 조각을 받았다고 확인했지만, 로봇의 남은 메모리에는 파일이 보이지 않아요.",
  },
  "outcome.uploadState.nothingRecorded": {
    en: "The robot recorded nothing: its free {area} memory is unchanged ({free} bytes). Upload it again.",
    ko: "로봇은 아무것도 기록하지 않았어요. 남은 {area} 메모리가 그대로예요 ({free}바이트). 다시 업로드해 주세요.",
  },
  "outcome.uploadState.noAnswerAfter": {
    en: "The robot did not answer the memory check afterwards, so whether it recorded the file is unknown. Switch it off and on, then upload again.",
    ko: "로봇이 그 뒤의 메모리 확인에 응답하지 않아서, 파일을 기록했는지 알 수 없어요. 로봇을 껐다가 다시 켠 뒤 다시 업로드해 주세요.",
  },
  "outcome.uploadState.uncertain": {
    en: "The robot's free {area} memory is now {now} bytes (was {before}; the file needs {footprint}), so whether it recorded the file is unknown. Switch it off and on, reset its {area} memory and upload again.",
    ko: "로봇의 남은 {area} 메모리가 이제 {now}바이트예요 (전에는 {before}바이트, 파일에는 {footprint}바이트가 필요해요). 그래서 파일을 기록했는지 알 수 없어요. 로봇을 껐다가 다시 켜고, {area} 메모리를 초기화한 뒤 다시 업로드해 주세요.",
  },
  "outcome.uploadState.mayHaveRecorded": {
    en: "The last chunk had been sent, so the robot may have recorded the file: switch it off and on, then check its free memory or upload again.",
    ko: "마지막 조각까지 보냈으니 로봇이 파일을 기록했을 수도 있어요. 로봇을 껐다가 다시 켠 뒤 남은 메모리를 확인하거나 다시 업로드해 주세요.",
  },
  "outcome.uploadRobotReports": {
    en: "The robot reports: {error}.",
    ko: "로봇이 알려 온 오류: {error}.",
  },
  "outcome.uploadRobotReportsChecksum": {
    en: "The robot reports: {error} (which this program's own abandon bytes also cause).",
    ko: "로봇이 알려 온 오류: {error} (이 프로그램이 업로드를 그만둘 때 보내는 바이트도 이 오류를 일으켜요).",
  },
});
