import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/** The Sensors view: live distance and accelerometer, the events, the demo robot's world. */
export const sensorsMessages = defineMessages({
  "sensors.title": { en: "Sensors", ko: "센서" },
  "sensors.intro": {
    en: "Live readings from the robot. Reading stops when you leave this view or hide the tab.",
    ko: "로봇에서 실시간으로 읽은 값이에요. 이 화면을 떠나거나 탭을 숨기면 읽기를 멈춰요.",
  },

  // Distance and accelerometer
  "sensors.pollTitle": { en: "Distance and accelerometer", ko: "거리와 가속도" },
  "sensors.rateLabel": { en: "Read", ko: "읽기" },
  "sensors.rateOption": { en: "{rate} times a second", ko: "1초에 {rate}번" },
  "sensors.pause": { en: "Pause", ko: "일시 정지" },
  "sensors.resume": { en: "Resume", ko: "계속" },
  "sensors.status.reading": { en: "Reading {rate} times a second.", ko: "1초에 {rate}번 읽고 있어요." },
  "sensors.status.readingAt": {
    en: "Reading {rate} times a second; last reading at {time}.",
    ko: "1초에 {rate}번 읽고 있어요. 마지막으로 {time}에 읽었어요.",
  },
  "sensors.status.readingLimited": {
    en: "Reading {rate} times a second (at most {max} while listening to sound, so the robot can report it).",
    ko: "1초에 {rate}번 읽고 있어요 (소리를 듣는 동안에는 로봇이 소리를 알려 줄 수 있도록 최대 {max}번).",
  },
  "sensors.status.readingLimitedAt": {
    en: "Reading {rate} times a second (at most {max} while listening to sound, so the robot can report it); last reading at {time}.",
    ko: "1초에 {rate}번 읽고 있어요 (소리를 듣는 동안에는 로봇이 소리를 알려 줄 수 있도록 최대 {max}번). 마지막으로 {time}에 읽었어요.",
  },
  "sensors.status.notReading": { en: "Not reading right now.", ko: "지금은 읽고 있지 않아요." },
  "sensors.status.paused": { en: "Paused.", ko: "일시 정지했어요." },
  "sensors.resumeReading": { en: "Resume reading", ko: "계속 읽기" },
  "sensors.distance": { en: "Distance", ko: "거리" },
  "sensors.cm": { en: "{cm} cm", ko: "{cm}cm" },
  "sensors.distanceHint": {
    en: "10 cm means nothing in front (or no sensor)",
    ko: "10cm이면 앞에 아무것도 없어요 (또는 센서가 없어요)",
  },
  "sensors.accelerometer": { en: "Accelerometer", ko: "가속도 센서" },
  "sensors.accelValue": { en: "X {x} · Y {y} · Z {z}", ko: "X {x} · Y {y} · Z {z}" },
  "sensors.accelHint": {
    en: "how the robot tilts and shakes, in the sensor's own units (the numbers change as it moves)",
    ko: "로봇이 기울고 흔들리는 정도, 센서 자체 단위 (로봇이 움직이면 숫자가 바뀌어요)",
  },
  "sensors.distanceCaption": { en: "Distance (cm), last 30 s", ko: "거리 (cm), 최근 30초" },
  "sensors.accelCaption": { en: "Accelerometer X, Y, Z, last 30 s", ko: "가속도 X, Y, Z, 최근 30초" },

  // The charts (charts.ts)
  "sensors.chart.now": { en: "now", ko: "지금" },
  "sensors.chart.secondsAgo": { en: "Seconds ago", ko: "초 전" },
  "sensors.chart.distanceTitle": {
    en: "Distance in cm over the last 30 seconds",
    ko: "최근 30초 동안의 거리 (cm)",
  },
  "sensors.chart.distanceLine": { en: "Distance (cm)", ko: "거리 (cm)" },
  "sensors.chart.cm": { en: "cm", ko: "cm" },
  "sensors.chart.accelTitle": {
    en: "Accelerometer X, Y and Z over the last 30 seconds",
    ko: "최근 30초 동안의 가속도 X, Y, Z",
  },
  "sensors.chart.reading": { en: "Reading", ko: "측정값" },

  // Sound, PF buttons and IR remote
  "sensors.eventsTitle": { en: "Sound, PF buttons and IR remote", ko: "소리, PF 버튼, IR 리모컨" },
  "sensors.eventsIntro": {
    en: "The robot reports only one of these at a time, so choose which one to listen to.",
    ko: "로봇은 이 중 한 가지만 알려 줄 수 있어요. 어떤 것을 들을지 골라 주세요.",
  },
  "sensors.listenTo": { en: "Listen to", ko: "들을 것" },
  "sensors.listen.none": { en: "Nothing", ko: "없음" },
  "sensors.listen.sound": { en: "Sound level", ko: "소리 크기" },
  "sensors.listen.buttons": { en: "PF buttons", ko: "PF 버튼" },
  "sensors.listen.remote": { en: "IR remote", ko: "IR 리모컨" },
  "sensors.thresholdLabel": { en: "Report sound levels from", ko: "알려 줄 소리 크기" },
  "sensors.thresholdHint": {
    en: "(0-255; the robot sends the level about 10 times a second while it is at least this loud)",
    ko: "(0-255, 소리가 이 크기 이상인 동안 로봇이 1초에 10번쯤 크기를 보내요)",
  },
  "sensors.soundLevel": { en: "Sound level", ko: "소리 크기" },
  "sensors.soundAt": { en: "{level} at {time}", ko: "{level} ({time})" },
  "sensors.nothingHeard": { en: "nothing heard yet", ko: "아직 들린 소리 없음" },
  "sensors.notListening": { en: "Not listening.", ko: "듣고 있지 않아요." },
  "sensors.listening.sound": { en: "Listening to Sound level.", ko: "소리 크기를 듣고 있어요." },
  "sensors.listening.buttons": { en: "Listening to PF buttons.", ko: "PF 버튼을 듣고 있어요." },
  "sensors.listening.remote": { en: "Listening to IR remote.", ko: "IR 리모컨을 듣고 있어요." },
  "sensors.listeningPaused": {
    en: "Not listening right now (paused).",
    ko: "지금은 듣고 있지 않아요 (일시 정지).",
  },
  "sensors.listenInterrupted": {
    en: "Each sensor reading interrupts the listening for a moment (the robot ends it at every request and the panel starts it again). Pause the readings above to catch every event.",
    ko: "센서를 읽을 때마다 듣기가 잠깐 끊겨요 (로봇은 요청을 받을 때마다 듣기를 끝내고, 패널이 다시 시작해요). 이벤트를 빠짐없이 받으려면 위에서 읽기를 일시 정지해 주세요.",
  },
  "sensors.listenResult": { en: "Listening", ko: "듣기" },
  "sensors.events": { en: "Events", ko: "이벤트" },
  "sensors.noEvents": { en: "No events yet.", ko: "아직 이벤트가 없어요." },

  // Events in the list (events.ts)
  "sensors.event.pf": { en: "PF{button} pressed", ko: "PF{button} 눌림" },
  "sensors.event.button": { en: "Button {button} pressed", ko: "버튼 {button}번 눌림" },
  "sensors.event.irKey": { en: "IR key {key}", ko: "IR 키 {key}번" },
  "sensors.event.irKeyMotion": { en: "IR key {key} ({motion})", ko: "IR 키 {key}번 ({motion})" },
  "sensors.event.sound": { en: "Sound level {level}", ko: "소리 크기 {level}" },

  // The built-in motions an IR key plays (protocol/catalog.ts BUILT_IN_MOTIONS)

  // The watch's notices (watch.ts)
  "sensors.inServoControl": {
    en: "Paused: the robot is in servo control (the Servos view, or Limp), where it reads no sensors. Resume returns it to normal mode (the servos keep their state).",
    ko: "일시 정지했어요. 로봇이 서보 제어 중(서보 화면이나 힘 빼기)이라 센서를 읽지 않아요. '계속 읽기'를 누르면 일반 모드로 돌아가요 (서보는 지금 상태를 유지해요).",
  },
  "sensors.tabHidden": {
    en: "Paused while this tab is hidden.",
    ko: "이 탭이 숨겨져 있는 동안 일시 정지했어요.",
  },
  "sensors.leavingServoControl": { en: "Leaving servo control", ko: "서보 제어 끝내기" },
  "sensors.normalModeFailed": {
    en: "Could not return to normal mode.",
    ko: "일반 모드로 돌아가지 못했어요.",
  },
  "sensors.listenFailed": { en: "Listening could not start.", ko: "듣기를 시작하지 못했어요." },
  "sensors.readFailures": {
    en: "Paused: reading the sensors failed {failures} times in a row.",
    ko: "일시 정지했어요. 센서 읽기가 {failures}번 연속으로 실패했어요.",
  },

  // The demo robot's world (demo-world.ts)
  "sensors.demo.title": { en: "Demo robot's world", ko: "데모 로봇의 주변 환경" },
  "sensors.demo.intro": {
    en: "Only for the demo robot: change what its simulated sensors see, press its buttons and its remote.",
    ko: "데모 로봇에서만 쓸 수 있어요. 가상 센서가 느끼는 것을 바꾸고, 버튼과 리모컨을 눌러 보세요.",
  },
  "sensors.demo.objectInFront": { en: "Object in front: {distance}", ko: "앞에 있는 물체: {distance}" },
  "sensors.demo.noise": { en: "Noise in the room: {level}", ko: "방 안의 소음: {level}" },
  "sensors.demo.press": { en: "Press PF{button}", ko: "PF{button} 누르기" },
  "sensors.demo.irKey": { en: "IR key", ko: "IR 키" },
  "sensors.demo.irKeyOption": { en: "{key} {motion}", ko: "{key} {motion}" },
  "sensors.demo.sendIrKey": { en: "Send IR key", ko: "IR 키 보내기" },
  "sensors.demo.listening": {
    en: "Presses and sounds show in the event list above when you listen to them.",
    ko: "듣고 있는 동안에는 누른 버튼과 소리가 위의 이벤트 목록에 나타나요.",
  },
  "sensors.demo.chooseListen": {
    en: "Choose PF buttons, IR remote or Sound level above to see these in the event list.",
    ko: "위에서 PF 버튼, IR 리모컨, 소리 크기 중 하나를 고르면 이벤트 목록에서 볼 수 있어요.",
  },
  "sensors.demo.accelNoise": {
    en: "The accelerometer reads with a little noise, as a real one does.",
    ko: "가속도 센서 값은 실제 센서처럼 조금씩 흔들려요.",
  },
});

export type SensorsTranslator = Translator<typeof sensorsMessages>;
