import { defineMessages } from "../../../i18n/catalogue.ts";

/**
 * What `rbc rbm` prints for people beyond the restamp's outcome (that is in src/i18n/outcomes/restamp): its
 * usage errors, the file names and where the serial number came from.
 */
export const rbmCommandMessages = defineMessages({
  "cmd.rbm.noAction": {
    en: "Say what to do: rbc rbm restamp FILE [--serial N | --zeros] [-o OUT].",
    ko: "할 일을 알려 주세요: rbc rbm restamp FILE [--serial N | --zeros] [-o OUT].",
  },
  "cmd.rbm.unknownAction": {
    en: 'Unknown action "{action}": use restamp.',
    ko: '알 수 없는 동작 "{action}"이에요. restamp를 써 주세요.',
  },
  "cmd.rbm.noFile": {
    en: "Name the motion file to restamp: rbc rbm restamp FILE.",
    ko: "시리얼 번호를 바꿀 모션 파일을 알려 주세요: rbc rbm restamp FILE.",
  },
  "cmd.rbm.serialOrZeros": {
    en: "Give --serial N or --zeros, not both.",
    ko: "--serial N과 --zeros 중 하나만 써 주세요.",
  },
  "cmd.rbm.whichSerial": {
    en: "Say which serial number to write: --serial N (13 digits), --zeros, or --port PATH / --demo to take the connected robot's.",
    ko: "어떤 시리얼 번호를 쓸지 알려 주세요: --serial N(숫자 13자리), --zeros, 또는 연결한 로봇의 번호를 쓰려면 --port PATH / --demo.",
  },
  "cmd.rbm.notMotion": {
    en: "{file}: {reason}. Nothing was written.",
    ko: "{file}: {reason}. 아무것도 쓰지 않았어요.",
  },
  "cmd.rbm.refused": {
    en: "{reason} Nothing was written.",
    ko: "{reason} 아무것도 쓰지 않았어요.",
  },
  "cmd.rbm.outputExists": {
    en: "{path} exists already; rbc does not overwrite it unless you name it with -o.",
    ko: "{path}이(가) 이미 있어요. -o로 그 파일을 지정하지 않으면 rbc는 덮어쓰지 않아요.",
  },
  "cmd.rbm.cannotWrite": {
    en: "Cannot write {path}: {why}.",
    ko: "{path}에 쓸 수 없어요: {why}.",
  },
  "cmd.rbm.fromRobot": {
    en: "The serial number of {robot}: {serial}.",
    ko: "{robot}의 시리얼 번호: {serial}.",
  },
  "cmd.rbm.written": {
    en: "Wrote {output} (from {file}).",
    ko: "{output}에 썼어요 ({file}에서).",
  },
  "cmd.rbm.nothingWritten": {
    en: "No file was written.",
    ko: "파일을 쓰지 않았어요.",
  },
});
