import { defineMessages } from "../../catalogue.ts";

/**
 * Why the motion layer refused an edit, a retime, a mirror or a tethered play (src/motion/, docs/protocol.md §7,
 * §10): one sentence per rule, filled from the refusal's facts (`motionRefusalText`). The `MotionError`'s English
 * `message` is the English here; the Editor says the same entry in the panel's language. What was being set
 * (`{what}`) is worded here too, from the facts' `subject` (`motionSubjectText`), and the Editor's own refusals
 * of what was typed name it with the same words.
 */
export const motionOutcomeMessages = defineMessages({
  // Who a value belongs to, and what was being set.
  "outcome.motion.who.joint": { en: "{joint} (servo {servo})", ko: "{joint}(서보 {servo})" },
  "outcome.motion.who.servo": { en: "servo {servo}", ko: "서보 {servo}번" },
  "outcome.motion.subject.start": { en: "The start position of {who}", ko: "{who}의 시작 위치" },
  "outcome.motion.subject.end": { en: "The end position of {who}", ko: "{who}의 끝 위치" },
  "outcome.motion.subject.torque": { en: "The torque of {who}", ko: "{who}의 토크" },
  "outcome.motion.subject.port": { en: "The extra outputs of {who}", ko: "{who}의 추가 출력" },
  "outcome.motion.subject.zero": { en: "The zero of {who}", ko: "{who}의 영점" },
  "outcome.motion.subject.sceneTorque": { en: "The torque of scene {scene}", ko: "장면 {scene}의 토크" },
  "outcome.motion.subject.frames": {
    en: "Scene {scene}: the number of frames",
    ko: "장면 {scene}의 프레임 수",
  },
  "outcome.motion.subject.time": { en: "Scene {scene}: the time in ms", ko: "장면 {scene}의 시간" },
  "outcome.motion.subject.sceneName": { en: "The name of scene {scene}", ko: "장면 {scene}의 이름" },
  "outcome.motion.subject.newSceneName": { en: "The scene name", ko: "장면 이름" },
  "outcome.motion.subject.motionName": { en: "The motion name", ko: "모션 이름" },
  "outcome.motion.subject.named": { en: "{name}", ko: "{name}" },

  // A value or a name the motion file cannot hold.
  "outcome.motion.whole": {
    en: "{what} must be a whole number from {min} to {max}, not {value}.",
    ko: "{what}에는 {min}에서 {max} 사이의 정수만 쓸 수 있어요. 입력한 값: {value}.",
  },
  "outcome.motion.nameEmpty": { en: "{what} cannot be empty.", ko: "{what}에 한 글자 이상 써 주세요." },
  "outcome.motion.nameLength": {
    en: "{what} has {length} characters; a motion file holds at most {max}.",
    ko: "{what}: {length}자예요. 모션 파일에는 {max}자까지만 들어가요.",
  },
  "outcome.motion.nameColon": {
    en: '{what} cannot contain ":", which separates the fields of a motion file.',
    ko: '{what}에는 ":"을 쓸 수 없어요. 모션 파일에서 칸을 나누는 기호예요.',
  },
  "outcome.motion.nameAscii": {
    en: "{what} can use only plain letters, digits, spaces and punctuation (ASCII), as Motionbuilder does.",
    ko: "{what}에는 영문 글자, 숫자, 공백, 문장 부호(ASCII)만 쓸 수 있어요. Motionbuilder와 같아요.",
  },

  // Frames and time (the RBC's error 6, its frame timer).
  "outcome.motion.intervalShort": {
    en: "{frames} frames in {time} ms are {interval} ms apart; the RBC needs at least {min} ms, so use at most {fewer} frames or at least {longer} ms.",
    ko: "프레임 {frames}개를 {time}ms에 재생하면 프레임 사이가 {interval}ms예요. RBC는 {min}ms 이상이 필요해요. 프레임을 {fewer}개 이하로 하거나 시간을 {longer}ms 이상으로 해 주세요.",
  },
  "outcome.motion.intervalLong": {
    en: "{frames} frames in {time} ms are {interval} ms apart; the RBC allows at most {max} ms, so use at least {more} frames.",
    ko: "프레임 {frames}개를 {time}ms에 재생하면 프레임 사이가 {interval}ms예요. RBC는 {max}ms까지만 허용해요. 프레임을 {more}개 이상으로 해 주세요.",
  },

  // Scenes and servos the motion does not have.
  "outcome.motion.noSuchScene": {
    en: "The motion has scenes 0 to {last}; there is no scene {value}.",
    ko: "모션의 장면은 0부터 {last}까지예요. 장면 {value}은(는) 없어요.",
  },
  "outcome.motion.newScenePosition": {
    en: "A new scene goes at a position from 0 to {max}, not {value}.",
    ko: "새 장면은 0부터 {max}까지의 위치에만 넣을 수 있어요. 입력한 값: {value}.",
  },
  "outcome.motion.rangeBackwards": {
    en: "A range of scenes runs forwards; {from} to {to} does not.",
    ko: "장면 범위는 앞에서 뒤로 가야 해요. {from}에서 {to}까지는 거꾸로예요.",
  },
  "outcome.motion.joinFirst": {
    en: "Scene 0 is the first scene: there is no scene before it to join.",
    ko: "장면 0은 첫 장면이라서 이어 붙일 앞 장면이 없어요.",
  },
  "outcome.motion.noSuchServo": {
    en: "Servo {value} is not in this motion (it has {ids}).",
    ko: "서보 {value}번은 이 모션에 없어요 (있는 서보: {ids}).",
  },
  "outcome.motion.lastScene": {
    en: "A motion needs at least one scene, so its only scene cannot be deleted.",
    ko: "모션에는 장면이 하나 이상 있어야 해서 하나뿐인 장면은 지울 수 없어요.",
  },

  // Retiming.
  "outcome.motion.factor": {
    en: "A time factor must be a number above 0, not {value}.",
    ko: "시간 배수는 0보다 큰 수여야 해요. 입력한 값: {value}.",
  },
  "outcome.motion.sceneShort": {
    en: "Scene {scene} would last {time} ms; a scene lasts at least {min} ms (one frame), so this motion cannot be made that fast.",
    ko: "그러면 장면 {scene}의 시간이 {time}ms가 돼요. 장면은 적어도 {min}ms(프레임 1개)는 걸리므로 모션을 그만큼 빠르게 할 수 없어요.",
  },
  "outcome.motion.sceneLong": {
    en: "Scene {scene} would last {time} ms; a scene lasts at most {max} ms.",
    ko: "그러면 장면 {scene}의 시간이 {time}ms가 돼요. 장면은 {max}ms보다 길 수 없어요.",
  },
  "outcome.motion.duration": {
    en: "A duration must be a whole number of ms above 0, not {value}.",
    ko: "전체 시간은 0보다 큰 ms 단위 정수여야 해요. 입력한 값: {value}.",
  },
  "outcome.motion.zeroDuration": {
    en: "These scenes last 0 ms, so they cannot be stretched to a duration.",
    ko: "이 장면들은 0ms라서 정한 시간으로 늘릴 수 없어요.",
  },

  // Mirroring.
  "outcome.motion.mirrorPlatform": {
    en: "Mirroring knows the joints of a HUNO (platform 1); this motion is for platform {platform}.",
    ko: "좌우 대칭은 HUNO(플랫폼 1)의 관절만 알아요. 이 모션은 플랫폼 {platform}용이에요.",
  },
  "outcome.motion.mirrorOutside": {
    en: "Scene {scene} cannot be mirrored: {positions}, outside the positions 0-254.",
    ko: "장면 {scene}은(는) 좌우 대칭할 수 없어요. {positions}: 위치 0-254를 벗어나요.",
  },
  "outcome.motion.mirrorPosition": { en: "servo {id} would go to {position}", ko: "서보 {id} → {position}" },

  // Tethered play (docs/protocol.md §10).
  "outcome.motion.playInterval": {
    en: "Scene {scene} has frames {interval} ms apart ({time} ms / {frames} frames); the RBC needs at least {min} ms (error 6). Use fewer frames.",
    ko: "장면 {scene}의 프레임 사이가 {interval}ms예요 ({time}ms / 프레임 {frames}개). RBC는 {min}ms 이상이 필요해요 (오류 6). 프레임 수를 줄여 주세요.",
  },
  "outcome.motion.playZeros": {
    en: "The robot's zero table must be 16 whole numbers from 0 to 254.",
    ko: "로봇의 영점 표는 0에서 254 사이의 정수 16개여야 해요.",
  },

  // A refusal whose facts do not say more than its code (one made by another program).
  "outcome.motion.code.noSuchScene": {
    en: "The motion has no such scene.",
    ko: "모션에 그런 장면이 없어요.",
  },
  "outcome.motion.code.noSuchServo": { en: "This motion has no such servo.", ko: "이 모션에 없는 서보예요." },
  "outcome.motion.code.value": {
    en: "The value is outside what the motion file allows.",
    ko: "모션 파일이 허용하는 범위를 벗어난 값이에요.",
  },
  "outcome.motion.code.name": {
    en: "A motion file cannot hold this name.",
    ko: "모션 파일에 쓸 수 없는 이름이에요.",
  },
  "outcome.motion.code.frameInterval": {
    en: "The frames would be closer than 20 ms or further apart than 4,550 ms.",
    ko: "프레임 사이가 20ms보다 짧거나 4,550ms보다 길어져요.",
  },
  "outcome.motion.code.retime": {
    en: "The motion cannot be retimed that way.",
    ko: "모션 시간을 그렇게 조정할 수 없어요.",
  },
  "outcome.motion.code.mirror": {
    en: "This scene cannot be mirrored.",
    ko: "이 장면은 좌우 대칭할 수 없어요.",
  },
  "outcome.motion.code.play": {
    en: "The RBC would refuse to play these scenes.",
    ko: "RBC가 이 장면들을 재생할 수 없어요.",
  },
});
