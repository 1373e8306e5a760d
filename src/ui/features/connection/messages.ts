import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/**
 * The connection: the connect card and its help, the card of a browser without Web Serial, the top bar with
 * Stop and Limp, and the sentences of their actions. In the first page load: keep it lean.
 */
export const connectionMessages = defineMessages({
  "connection.demoRobot": { en: "Demo robot", ko: "데모 로봇" },
  "connection.demoRobotBluetooth": { en: "Demo robot (Bluetooth)", ko: "데모 로봇 (블루투스)" },
  "connection.robot": { en: "Robot", ko: "로봇" },

  "connection.title": { en: "Connect your robot", ko: "로봇 연결하기" },
  "connection.intro": {
    en: "Plug the robot's serial cable into this computer (or pair its Bluetooth module), switch the robot on, then choose its port.",
    ko: "로봇의 시리얼 케이블을 이 컴퓨터에 꽂고(또는 블루투스 모듈을 페어링하고) 로봇을 켠 다음, 로봇의 포트를 골라 주세요.",
  },
  "connection.connectRobot": { en: "Connect robot", ko: "로봇 연결" },
  "connection.openRecovery": { en: "Go to the firmware recovery", ko: "펌웨어 복구로 가기" },
  "connection.tryDemo": { en: "Try the demo robot", ko: "데모 로봇 써 보기" },
  "connection.showAllPorts": {
    en: "Show all serial ports (other adapters, built-in ports)",
    ko: "모든 시리얼 포트 보기 (다른 어댑터, 내장 포트)",
  },
  "connection.demoBluetooth": {
    en: "Demo robot over a simulated Bluetooth link",
    ko: "가상 블루투스 연결로 데모 로봇 써 보기",
  },
  "connection.demoBluetoothHint": {
    en: "Its replies come {mean}\u00a0±\u00a0{jitter}\u00a0ms late and in bursts, as over Bluetooth.",
    ko: "블루투스처럼 응답이 {mean}\u00a0±\u00a0{jitter}ms 늦게, 몰려서 와요.",
  },
  "connection.demoNote": {
    en: "The demo robot is a simulated controller inside this page: nothing is sent to any hardware.",
    ko: "데모 로봇은 이 페이지 안의 가상 컨트롤러예요. 하드웨어에는 아무것도 보내지 않아요.",
  },
  "connection.choosing": {
    en: "Waiting for you to choose a port in the browser's list…",
    ko: "브라우저 목록에서 포트를 고르기를 기다리는 중…",
  },
  "connection.opening": { en: "Opening the port…", ko: "포트를 여는 중…" },
  "connection.handshaking": {
    en: "Port open. Asking the robot for its firmware and serial number…",
    ko: "포트를 열었어요. 로봇에게 펌웨어와 시리얼 번호를 묻는 중…",
  },
  "connection.slowBluetooth": {
    en: "Replies are slower over Bluetooth: the first one may take a second or two.",
    ko: "블루투스는 응답이 느려요. 첫 응답은 1~2초 걸릴 수 있어요.",
  },
  "connection.connecting": { en: "Connecting", ko: "연결 중" },
  "connection.cancel": { en: "Cancel", ko: "취소" },
  "connection.lostDemo": { en: "The demo robot was disconnected.", ko: "데모 로봇과의 연결이 끊겼어요." },
  "connection.lost": { en: "The robot was disconnected.", ko: "로봇과의 연결이 끊겼어요." },
  "connection.didNotFinish": {
    en: "Did not finish: {list}. Check the result after reconnecting.",
    ko: "끝나지 않은 작업: {list}. 다시 연결한 뒤 결과를 확인해 주세요.",
  },
  "connection.checkCable": {
    en: "Check the cable and the robot's power switch, then connect again.",
    ko: "케이블과 로봇의 전원 스위치를 확인한 뒤 다시 연결해 주세요.",
  },
  "connection.knownPorts": { en: "Ports used before", ko: "전에 쓴 포트" },
  "connection.connect": { en: "Connect", ko: "연결" },
  "connection.connectTo": { en: "Connect to {port}", ko: "{port}에 연결" },
  "connection.forget": { en: "Forget", ko: "지우기" },
  "connection.forgetPort": { en: "Forget {port}", ko: "{port} 지우기" },
  "connection.cannotForget": {
    en: "This browser cannot forget ports. Remove the permission in the site settings instead.",
    ko: "이 브라우저는 포트를 지울 수 없어요. 대신 사이트 설정에서 권한을 없애 주세요.",
  },
  "connection.forgetFailed": { en: "The port could not be forgotten.", ko: "포트를 지우지 못했어요." },

  "connection.help.title": { en: "Can't find your robot?", ko: "로봇을 찾을 수 없나요?" },

  "connection.status.notConnected": { en: "Not connected", ko: "연결 안 됨" },
  "connection.status.lost": { en: "Disconnected — link lost", ko: "연결 끊김 — 통신이 끊어짐" },
  "connection.status.choosing": { en: "Choosing a port…", ko: "포트를 고르는 중…" },
  "connection.status.opening": {
    en: "Connecting to the robot: opening the port…",
    ko: "로봇에 연결하는 중: 포트를 여는 중…",
  },
  "connection.status.openingDemo": {
    en: "Connecting to the demo robot: opening the port…",
    ko: "데모 로봇에 연결하는 중: 포트를 여는 중…",
  },
  "connection.status.handshaking": {
    en: "Connecting to the robot: handshaking…",
    ko: "로봇에 연결하는 중: 통신을 확인하는 중…",
  },
  "connection.status.handshakingDemo": {
    en: "Connecting to the demo robot: handshaking…",
    ko: "데모 로봇에 연결하는 중: 통신을 확인하는 중…",
  },
  "connection.status.connected": { en: "Connected", ko: "연결됨" },
  "connection.status.bluetooth": { en: "Bluetooth", ko: "블루투스" },
  "connection.status.firmware": { en: "fw {version}", ko: "펌웨어 {version}" },
  "connection.status.serialNumber": { en: "SN {serial}", ko: "시리얼 번호 {serial}" },
  "connection.status.limp": { en: "servos limp", ko: "서보 힘 빠짐" },
  "connection.status.servoControl": { en: "servo control", ko: "서보 제어 중" },

  "connection.stop": { en: "Stop", ko: "정지" },
  "connection.dismiss": { en: "Dismiss", ko: "닫기" },
  "connection.stopTitle": {
    en: "End what the robot is doing (Escape).",
    ko: "로봇이 하던 일을 끝내요 (Esc).",
  },
  "connection.limpAsk": { en: "Limp…", ko: "힘 빼기…" },
  "connection.limpTitle": {
    en: "Make every servo passive: the robot falls unless someone holds it (asks first)",
    ko: "모든 서보의 힘을 빼요. 누가 잡고 있지 않으면 로봇이 넘어져요 (먼저 물어봐요)",
  },
  "connection.limpExplain": {
    en: "Limp is for when the robot must go slack.",
    ko: "힘 빼기는 로봇의 힘을 완전히 빼야 할 때 써요.",
  },
  "connection.limp": { en: "Limp", ko: "힘 빼기" },
});

export type ConnectionTranslator = Translator<typeof connectionMessages>;
