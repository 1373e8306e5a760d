import { defineMessages } from "../../../../i18n/catalogue.ts";
import type { Translator } from "../../../../i18n/translate.ts";

/** The Remote card of the Sensors view: the IR remote's key map (docs/protocol.md §3.1) and the key pressed. */
export const remoteMessages = defineMessages({
  "sensors.remote.title": { en: "Remote", ko: "리모컨" },
  "sensors.remote.intro": {
    en: "What each key of the IR remote plays on this robot. A key sends its code, and the robot plays as if that motion number had been run.",
    ko: "IR 리모컨의 각 키가 이 로봇에서 무엇을 재생하는지 보여 줘요. 키는 코드를 보내고, 로봇은 그 번호의 모션을 실행한 것처럼 재생해요.",
  },
  "sensors.remote.listenHint": {
    en: "Choose IR remote under Events to see the key you press light up.",
    ko: "눌린 키가 켜지는 것을 보려면 이벤트에서 IR 리모컨을 골라 주세요.",
  },
  "sensors.remote.listening": {
    en: "Listening to the IR remote: the key you press lights up.",
    ko: "IR 리모컨을 듣고 있어요. 누른 키가 켜져요.",
  },
  "sensors.remote.lastKey": {
    en: "Last key: {key} (code {code}), at {time}.",
    ko: "마지막 키: {key} (코드 {code}), {time}.",
  },
  "sensors.remote.lastUnknown": {
    en: "Last key: code {code} at {time}, a code this key map does not list.",
    ko: "마지막 키: 코드 {code}, {time}. 이 키 배치에 없는 코드예요.",
  },
  "sensors.remote.keysFold": { en: "The remote's {count} keys", ko: "리모컨 키 {count}개" },
  "sensors.remote.noKeyYet": { en: "No key pressed yet.", ko: "아직 누른 키가 없어요." },
  "sensors.remote.pressed": { en: "pressed", ko: "눌림" },

  "sensors.remote.group.builtin": { en: "Built-in motions (codes 1-11)", ko: "내장 모션 (코드 1-11)" },
  "sensors.remote.group.number": {
    en: "Number keys: the first ten uploaded motions (codes 12-21)",
    ko: "숫자 키: 처음 업로드한 모션 10개 (코드 12-21)",
  },
  "sensors.remote.group.star": {
    en: "* + number key: the next ten (codes 33-42)",
    ko: "* + 숫자 키: 그다음 10개 (코드 33-42)",
  },
  "sensors.remote.group.hash": { en: "# + key: special functions", ko: "# + 키: 특수 기능" },

  "sensors.remote.face.builtin": { en: "code {code}", ko: "코드 {code}" },
  "sensors.remote.face.number": { en: "key {face}", ko: "{face} 키" },
  "sensors.remote.face.star": { en: "* + {face}", ko: "* + {face}" },
  "sensors.remote.face.hash": { en: "# + {face}", ko: "# + {face}" },
  "sensors.remote.code": { en: "code {code}", ko: "코드 {code}" },

  "sensors.remote.plays.download": {
    en: "{name} (uploaded in this connection)",
    ko: "{name} (이번 연결에서 업로드함)",
  },
  "sensors.remote.plays.unknown": {
    en: "An uploaded motion, if the robot holds one: it does not say which",
    ko: "로봇에 있다면 업로드한 모션. 로봇은 어떤 모션인지 알려 주지 않아요",
  },
  "sensors.remote.plays.empty": {
    en: "Nothing stored",
    ko: "저장된 모션 없음",
  },
  "sensors.remote.userKey9": {
    en: "On the official “user” firmware: an endless walk that only switching the robot off ends",
    ko: "공식 “user” 펌웨어에서는 로봇을 꺼야만 멈추는 끝없는 걷기",
  },
  "sensors.remote.plays.userNothing": {
    en: "Nothing on this firmware (it plays no uploads)",
    ko: "이 펌웨어에서는 없음 (업로드한 모션을 재생하지 않아요)",
  },
  "sensors.remote.plays.userFlashDemo": {
    en: "A demo motion kept in the firmware",
    ko: "펌웨어에 들어 있는 데모 모션",
  },
  "sensors.remote.plays.userEndlessWalk": {
    en: "An endless walk: only switching the robot off ends it",
    ko: "끝없이 걷기: 로봇을 꺼야만 멈춰요",
  },
  "sensors.remote.plays.charging": {
    en: "Starts battery charging when a charger is connected",
    ko: "충전기가 연결되어 있으면 배터리 충전을 시작해요",
  },
  "sensors.remote.plays.zeroPose": {
    en: "Moves every servo to its stored zero (the raw zero pose) at once",
    ko: "모든 서보를 저장된 영점으로 바로 움직여요 (영점 자세 그대로)",
  },
  "sensors.remote.hazard": { en: "Hazard", ko: "위험" },

  "sensors.remote.firmwareUser": {
    en: "This robot reports firmware 9.99, as the official “user” firmware (and a homebrew port of it) does: on that build keys 1-8 and every * key play nothing, 0 plays a demo motion kept in the firmware, and 9 starts an obstacle-avoidance walk that neither Stop nor any other request ends: only switching the robot off does.",
    ko: "이 로봇은 펌웨어 9.99를 알려 와요. 공식 “user” 펌웨어(와 그것을 옮긴 자작 펌웨어)가 알려 주는 버전이에요. 그 펌웨어에서는 1-8 키와 모든 * 키가 아무것도 재생하지 않고, 0은 펌웨어에 들어 있는 데모 모션을, 9는 장애물을 피하며 끝없이 걷기를 시작해요. 이 걷기는 정지나 다른 어떤 요청으로도 멈추지 않고, 로봇을 꺼야만 멈춰요.",
  },
  "sensors.remote.firmwareOther": {
    en: "This robot reports firmware {version}: its number keys play the uploaded motions. On the official “user” firmware (which reports 9.99) key 9 instead starts an endless walk that only switching the robot off ends.",
    ko: "이 로봇은 펌웨어 {version}을(를) 알려 와요. 숫자 키는 업로드한 모션을 재생해요. 공식 “user” 펌웨어(9.99를 알려 줘요)에서는 9 키가 로봇을 꺼야만 멈추는 끝없는 걷기를 시작해요.",
  },
  "sensors.remote.firmwareUnknown": {
    en: "The firmware version is not known yet. On the official “user” firmware (which reports 9.99) key 9 starts an endless walk that only switching the robot off ends.",
    ko: "펌웨어 버전을 아직 몰라요. 공식 “user” 펌웨어(9.99를 알려 줘요)에서는 9 키가 로봇을 꺼야만 멈추는 끝없는 걷기를 시작해요.",
  },
});

export type RemoteTranslator = Translator<typeof remoteMessages>;
