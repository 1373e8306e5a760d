import { defineMessages } from "../../catalogue.ts";
import type { Translator } from "../../translate.ts";

/**
 * The motion file checker's sentences (protocol/rbm.ts, rbm-validate.ts, motion-image.ts), one per issue code
 * and kind, filled from the issue's `values` (`rbmIssueSentence`), in every language, in the panel and in `rbc`
 * alike (the issue's own `message` is a technical line for logs). A servo is "서보 2번(왼쪽 무릎)": its head
 * word is 번, so "{servo}의" and "{servo}이" read right. English capitalises a sentence that begins with its
 * subject (`initial`); the fields of the motion itself are named with "the" ("the motion index").
 */
export const rbmIssueMessages = defineMessages({
  // Who a value belongs to, and the fields by name.
  "outcome.rbm.servo": { en: "servo {id}", ko: "서보 {id}번" },
  "outcome.rbm.servoJoint": { en: "servo {id} ({joint})", ko: "서보 {id}번({joint})" },
  "outcome.rbm.ofSceneServo": {
    en: "scene {scene}: the {field} of {servo}",
    ko: "장면 {scene}에서 {servo}의 {field}",
  },
  "outcome.rbm.ofSceneRecord": {
    en: "scene {scene}, servo record {record}: {field}",
    ko: "장면 {scene}, 서보 레코드 {record}번의 {field}",
  },
  "outcome.rbm.ofRecord": { en: "servo record {record}: {field}", ko: "서보 레코드 {record}번의 {field}" },
  "outcome.rbm.ofServo": { en: "the {field} of {servo}", ko: "{servo}의 {field}" },
  "outcome.rbm.ofScene": { en: "scene {scene}: {field}", ko: "장면 {scene}의 {field}" },
  "outcome.rbm.numberedField.format": { en: "field 0 (format)", ko: "0번 필드(형식)" },
  "outcome.rbm.numberedField.platform": { en: "field 8 (platform)", ko: "8번 필드(플랫폼)" },
  "outcome.rbm.field.format": { en: "the format", ko: "형식" },
  "outcome.rbm.field.serialNumber": { en: "the serial number", ko: "시리얼 번호" },
  "outcome.rbm.field.serialNumberLength": { en: "the length of the serial number", ko: "시리얼 번호의 길이" },
  "outcome.rbm.field.text1": {
    en: "field 3 (the 10-character text)",
    ko: "3번 필드(10글자 텍스트)",
  },
  "outcome.rbm.field.text2": { en: "field 4 (the text)", ko: "4번 필드(텍스트)" },
  "outcome.rbm.field.motionName": { en: "the motion name", ko: "모션 이름" },
  "outcome.rbm.field.motionNameLength": { en: "the length of the motion name", ko: "모션 이름의 길이" },
  "outcome.rbm.field.motionIndex": { en: "the motion index", ko: "모션 번호" },
  "outcome.rbm.field.platform": { en: "the platform", ko: "플랫폼" },
  "outcome.rbm.field.sceneCount": { en: "the number of scenes", ko: "장면 수" },
  "outcome.rbm.field.servoCount": { en: "the number of servos", ko: "서보 수" },
  "outcome.rbm.field.unknown10": { en: "field 10", ko: "10번 필드" },
  "outcome.rbm.field.unknown12": { en: "field 12", ko: "12번 필드" },
  "outcome.rbm.field.imageSize": { en: "the image size", ko: "이미지 크기" },
  "outcome.rbm.field.index": { en: "index", ko: "번호" },
  "outcome.rbm.field.name": { en: "name", ko: "이름" },
  "outcome.rbm.field.nameLength": { en: "length of the name", ko: "이름의 길이" },
  "outcome.rbm.field.frames": { en: "frames", ko: "프레임 수" },
  "outcome.rbm.field.timeMs": { en: "time", ko: "시간" },
  "outcome.rbm.field.id": { en: "id", ko: "ID" },
  "outcome.rbm.field.p": { en: "P gain", ko: "P 게인" },
  "outcome.rbm.field.d": { en: "D gain", ko: "D 게인" },
  "outcome.rbm.field.i": { en: "I gain", ko: "I 게인" },
  "outcome.rbm.field.portEnable": { en: "port enable", ko: "포트 사용 설정" },
  "outcome.rbm.field.zero": { en: "zero position", ko: "영점 위치" },
  "outcome.rbm.field.reserved": { en: "first field", ko: "첫 필드" },
  "outcome.rbm.field.start": { en: "start position", ko: "시작 위치" },
  "outcome.rbm.field.end": { en: "end position", ko: "끝 위치" },
  "outcome.rbm.field.torque": { en: "torque", ko: "토크" },
  "outcome.rbm.field.port": { en: "port value", ko: "포트 값" },
  "outcome.rbm.place.scene": { en: "scene {scene}", ko: "장면 {scene}" },
  "outcome.rbm.place.record": { en: "servo record {record}", ko: "서보 레코드 {record}번" },
  "outcome.rbm.got.missing": { en: "it is missing", ko: "값이 없음" },
  "outcome.rbm.got.list": { en: "it is a list", ko: "목록임" },
  "outcome.rbm.got.object": { en: "it is an object", ko: "객체임" },
  "outcome.rbm.got.value": { en: "it is {value}", ko: "지금 값: {value}" },

  // A motion built in code that does not have the shape of one (a draft, a file's parsed form).
  "outcome.rbm.shape.motion": {
    en: "A motion must be an object with servos and scenes.",
    ko: "모션은 서보 목록과 장면 목록이 있는 객체여야 해요.",
  },
  "outcome.rbm.shape.list": {
    en: "{path} must be a list ({got}).",
    ko: "모션 데이터의 {path} 항목은 목록이어야 해요 ({got}).",
  },
  "outcome.rbm.shape.text": {
    en: "{path} must be text ({got}).",
    ko: "모션 데이터의 {path} 항목은 텍스트여야 해요 ({got}).",
  },
  "outcome.rbm.shape.form": {
    en: "{path} is not in the form parseRbm produces.",
    ko: "모션 데이터의 {path} 항목이 모션 파일을 읽어 만든 형식(parseRbm)이 아니에요.",
  },
  "outcome.rbm.shape.number": {
    en: "{path} must be a whole number of 0 or more ({got}).",
    ko: "모션 데이터의 {path} 항목은 0 이상의 정수여야 해요 ({got}).",
  },

  // The RBC's rules (docs/protocol.md §7): errors.
  "outcome.rbm.outOfRange.byte": {
    en: "{what} is {value}; it must fit in one byte (0-{max}).",
    ko: "{what} 값이 {value}인데, 1바이트(0-{max}) 안에 들어가야 해요.",
  },
  "outcome.rbm.outOfRange.scenes": {
    en: "The motion has {scenes} scenes; a motion image holds at most {max}.",
    ko: "모션의 장면이 {scenes}개인데, 모션 이미지에는 최대 {max}개까지 들어가요.",
  },
  "outcome.rbm.outOfRange.timing": {
    en: "Scene {scene}: frames and time must each fit in 16 bits (0-{max}).",
    ko: "장면 {scene}: 프레임 수와 시간은 각각 16비트(0-{max}) 안에 들어가야 해요.",
  },
  "outcome.rbm.position": {
    en: "{what} is {value}; positions go from 0 to {max}.",
    ko: "{what} 값이 {value}인데, 위치는 0부터 {max}까지예요.",
  },
  "outcome.rbm.text": {
    en: '{what} contains ":", which would split the field in an .rbm file.',
    ko: '{what}에 ":" 문자가 있어서, .rbm 파일에 쓰면 필드가 둘로 나뉘어요.',
  },
  "outcome.rbm.text.scene": {
    en: 'The name of scene {scene} contains ":", which would split it.',
    ko: '장면 {scene}의 이름에 ":" 문자가 있어서, .rbm 파일에 쓰면 필드가 둘로 나뉘어요.',
  },
  "outcome.rbm.servoCount.declared": {
    en: "The motion says it has {declared} servos but lists {listed}.",
    ko: "모션에 서보가 {declared}개라고 적혀 있지만, 실제로 나열된 서보는 {listed}개예요.",
  },
  "outcome.rbm.servoCount.range": {
    en: "The motion has {servos} servos; a motion has {min} to {max}.",
    ko: "모션의 서보가 {servos}개인데, 모션에는 서보가 {min}-{max}개 있어야 해요.",
  },
  "outcome.rbm.servoCount.scene": {
    en: "Scene {scene} has {records} servo records; the motion has {servos} servos.",
    ko: "장면 {scene}의 서보 레코드가 {records}개인데, 모션의 서보는 {servos}개예요.",
  },
  "outcome.rbm.servoCount.file": {
    en: "The file says the motion has {servos} servos; a motion has {min} to {max}.",
    ko: "파일에 적힌 모션의 서보 수가 {servos}개인데, 모션에는 서보가 {min}-{max}개 있어야 해요.",
  },
  "outcome.rbm.sceneCount": {
    en: "The motion says it has {declared} scenes but lists {listed}.",
    ko: "모션에 장면이 {declared}개라고 적혀 있지만, 실제로 나열된 장면은 {listed}개예요.",
  },
  "outcome.rbm.noScenes": {
    en: "The motion has no scenes; a motion needs at least one.",
    ko: "모션에 장면이 없어요. 모션에는 장면이 1개 이상 있어야 해요.",
  },
  "outcome.rbm.servoId.range": {
    en: "Servo record {record} has id {id}; servo ids go from 0 to {max}.",
    ko: "서보 레코드 {record}번의 ID가 {id}인데, 서보 ID는 0부터 {max}까지예요.",
  },
  "outcome.rbm.servoId.twice": {
    en: "Servo id {id} is listed twice (records {first} and {second}).",
    ko: "서보 ID {id}번이 두 번 나와요 (서보 레코드 {first}번과 {second}번).",
  },
  "outcome.rbm.servoId.order": {
    en: "Scene {scene}, servo record {record} is for servo {id}, but the motion's servo record {record} is servo {listed}; scene records must follow the servo list.",
    ko: "장면 {scene}의 서보 레코드 {record}번은 서보 {id}번의 것인데, 모션의 서보 레코드 {record}번은 서보 {listed}번이에요. 장면의 레코드는 서보 목록과 같은 순서여야 해요.",
  },
  "outcome.rbm.sceneIndex": {
    en: "Scene {scene} is numbered {index}; scenes are numbered 0 to {last} in order.",
    ko: "장면 {scene}의 번호가 {index}(으)로 적혀 있어요. 장면 번호는 0부터 {last}까지 차례대로 매겨야 해요.",
  },
  "outcome.rbm.frames": {
    en: "Scene {scene} has {frames} frames; a scene needs at least {min}.",
    ko: "장면 {scene}의 프레임이 {frames}개예요. 장면에는 프레임이 {min}개 이상 있어야 해요.",
  },
  "outcome.rbm.frameIntervalShort": {
    en: "Scene {scene} has frames {interval} ms apart ({time} ms / {frames} frames); the RBC needs at least {min} ms. Use fewer frames.",
    ko: "장면 {scene}의 프레임 간격이 {interval}ms예요 ({time}ms / 프레임 {frames}개). RBC에는 {min}ms 이상이 필요해요. 프레임 수를 줄여 주세요.",
  },
  "outcome.rbm.frameIntervalLong": {
    en: "Scene {scene} has frames {interval} ms apart ({time} ms / {frames} frames); the RBC allows at most {max} ms (its frame timer overflows).",
    ko: "장면 {scene}의 프레임 간격이 {interval}ms예요 ({time}ms / 프레임 {frames}개). RBC는 최대 {max}ms까지만 허용해요 (더 길면 프레임 타이머가 넘쳐요).",
  },
  "outcome.rbm.torque": {
    en: "Scene {scene}: the torque of {servo} is {value}; torque goes from 0 to {max}.",
    ko: "장면 {scene}에서 {servo}의 토크가 {value}인데, 토크는 0부터 {max}까지예요.",
  },
  "outcome.rbm.port": {
    en: "Scene {scene}: the port value of {servo} is {value}; it goes from 0 to {max}.",
    ko: "장면 {scene}에서 {servo}의 포트 값이 {value}인데, 포트 값은 0부터 {max}까지예요.",
  },
  "outcome.rbm.imageRange": {
    en: "{what} is {value}; the motion image holds whole numbers from 0 to {max} there.",
    ko: "{what} 값이 {value}인데, 모션 이미지의 이 자리에는 0부터 {max}까지의 정수만 들어가요.",
  },

  // The RBC's rules: warnings.
  "outcome.rbm.serialFormat": {
    en: 'The serial number "{serial}" is not 13 digits, the form Motionbuilder writes.',
    ko: '시리얼 번호 "{serial}"은(는) Motionbuilder가 쓰는 13자리 숫자가 아니에요.',
  },
  "outcome.rbm.serialMismatch": {
    en: "This motion was made for the robot with serial number {serial}, but the connected robot is {connected}; Motionbuilder refuses such files. Check that the motion suits this robot.",
    ko: "이 모션은 시리얼 번호 {serial} 로봇용으로 만들었는데, 지금 연결된 로봇은 시리얼 번호 {connected} 로봇이에요. Motionbuilder는 이런 파일을 거부해요. 이 로봇에 맞는 모션인지 확인해 주세요.",
  },
  "outcome.rbm.headerConstant": {
    en: "{what} is {value}; Motionbuilder always writes {usual}.",
    ko: "{what} 값이 {value}인데, Motionbuilder는 항상 {usual}(으)로 써요.",
  },
  "outcome.rbm.hunoServoCount": {
    en: "The motion has {servos} servos; a HUNO has {huno}.",
    ko: "모션의 서보가 {servos}개인데, HUNO의 서보는 {huno}개예요.",
  },
  "outcome.rbm.manyFrames": {
    en: "Scene {scene} has {frames} frames, more than Motionbuilder's {max}.",
    ko: "장면 {scene}의 프레임이 {frames}개로, Motionbuilder의 한도인 {max}개보다 많아요.",
  },
  "outcome.rbm.longScene": {
    en: "Scene {scene} lasts {time} ms, longer than Motionbuilder's {max} ms.",
    ko: "장면 {scene}의 길이가 {time}ms로, Motionbuilder의 한도인 {max}ms보다 길어요.",
  },
  "outcome.rbm.unsafePosition": {
    en: "Scene {scene}: {servo} goes to {position}, outside its safe range {min}-{max}.",
    ko: "장면 {scene}에서 {servo}이 안전 범위({min}-{max}) 밖인 {position} 위치로 가요.",
  },
  "outcome.rbm.unsafePositions": {
    en: "Scene {scene}: {servo} goes to {position} and {other}, outside its safe range {min}-{max}.",
    ko: "장면 {scene}에서 {servo}이 안전 범위({min}-{max}) 밖인 {position}, {other} 위치로 가요.",
  },
  "outcome.rbm.sceneJump": {
    en: "Scene {scene} starts {servo} at {start}, but scene {previous} ended it at {end}; the servo will jump.",
    ko: "장면 {previous}에서 {servo}의 끝 위치는 {end}인데, 장면 {scene}에서는 {start}에서 시작해서 서보가 튀어요.",
  },

  // A text that is not a motion file, or not a whole one (the parser).
  "outcome.rbm.notText": {
    en: "A motion file must be read as text.",
    ko: "모션 파일은 텍스트로 읽어야 해요.",
  },
  "outcome.rbm.tooLarge": {
    en: "The file has {characters} characters; a motion file is far smaller (the largest motion that fits the robot is about {largest}), so this is not one.",
    ko: "파일이 {characters}자예요. 모션 파일은 훨씬 작아서(로봇에 들어가는 가장 큰 모션도 약 {largest}자) 이 파일은 모션 파일이 아니에요.",
  },
  "outcome.rbm.empty": { en: "The motion file is empty.", ko: "모션 파일이 비어 있어요." },
  "outcome.rbm.notMotion": {
    en: 'This is not a Motionbuilder motion file (.rbm): such a file is one line of fields separated by ":", starting with "1:13:" and the 13-digit serial number of a robot.',
    ko: 'Motionbuilder 모션 파일(.rbm)이 아니에요. 모션 파일은 ":" 문자로 구분한 필드가 한 줄로 이어진 파일이고, "1:13:" 다음에 로봇의 13자리 시리얼 번호가 오는 형태로 시작해요.',
  },
  "outcome.rbm.end": {
    en: 'The file should end with ":", not {ending}; it is truncated or damaged.',
    ko: '파일은 ":" 문자로 끝나야 하는데 {ending}(으)로 끝나요. 파일이 잘렸거나 손상됐어요.',
  },
  "outcome.rbm.fieldCount.header": {
    en: "The file has only {fields} fields; an .rbm file's header alone has {header}.",
    ko: "파일의 필드가 {fields}개뿐이에요. .rbm 파일은 헤더만 해도 필드가 {header}개예요.",
  },
  "outcome.rbm.fieldCount.total": {
    en: "The file has {fields} fields, but a motion with {servos} servos and {scenes} scenes has {expected}; the file is truncated or damaged.",
    ko: "파일의 필드가 {fields}개인데, 서보 {servos}개와 장면 {scenes}개로 된 모션에는 필드가 {expected}개 있어야 해요. 파일이 잘렸거나 손상됐어요.",
  },
  "outcome.rbm.notANumber": {
    en: "Field {index} ({what}) should be a whole number but is {text}.",
    ko: "{index}번 필드({what})는 정수여야 해요 (지금 값: {text}).",
  },
  "outcome.rbm.fieldTooLong.text": {
    en: "{what} has {length} characters; it holds at most {max}.",
    ko: "{what}의 길이가 {length}글자예요. 이 필드에는 최대 {max}글자까지 들어가요.",
  },
  "outcome.rbm.fieldTooLong.name": {
    en: "The length of {what} is {length}; a name in a motion file has at most {max} characters.",
    ko: "{what}의 길이가 {length}(으)로 적혀 있어요. 모션 파일의 이름은 최대 {max}글자예요.",
  },
  "outcome.rbm.lengthMismatch.scene": {
    en: "The name of scene {scene}, {text} has {length} characters, but its length field says {declared}.",
    ko: "장면 {scene}의 이름 {text}의 길이는 {length}글자인데, 길이 필드에는 {declared}글자로 적혀 있어요.",
  },
  "outcome.rbm.moreProblems": {
    en: { one: "{first} ({count} more problem found)", other: "{first} ({count} more problems found)" },
    ko: "{first} (문제가 {count}개 더 있어요)",
  },
  "outcome.rbm.lengthMismatch": {
    en: "{what} {text} has {length} characters, but its length field says {declared}.",
    ko: "{what} {text}의 길이는 {length}글자인데, 길이 필드에는 {declared}글자로 적혀 있어요.",
  },
});

export type IssueTranslator = Translator<typeof rbmIssueMessages>;
