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
  "connection.help.cable": { en: "Cable", ko: "케이블" },
  "connection.help.cableText": {
    en: "use the robot's serial cable and USB adapter; try another USB socket.",
    ko: "로봇의 시리얼 케이블과 USB 어댑터를 쓰고, 다른 USB 단자에도 꽂아 보세요.",
  },
  "connection.help.power": { en: "Power", ko: "전원" },
  "connection.help.powerText": {
    en: "the robot's power switch must be on (the RBC's LEDs lit).",
    ko: "로봇의 전원 스위치가 켜져 있어야 해요 (RBC의 LED에 불이 들어와요).",
  },
  "connection.help.drivers": { en: "Drivers", ko: "드라이버" },
  "connection.help.driversText": {
    en: "Windows and older macOS need the adapter's driver: FTDI (VCP driver) or WCH CH340/CH341. Prolific and Silicon Labs adapters have their own.",
    ko: "Windows와 이전 macOS에는 어댑터의 드라이버가 필요해요: FTDI (VCP 드라이버) 또는 WCH CH340/CH341. Prolific과 Silicon Labs 어댑터는 각자의 드라이버가 있어요.",
  },
  "connection.help.linux": { en: "Linux permissions", ko: "Linux 권한" },
  "connection.help.linuxText": {
    en: "add yourself to the {group} group ({command}), then log out and in again.",
    ko: "내 계정을 {group} 그룹에 추가한 다음({command}) 로그아웃했다가 다시 로그인해 주세요.",
  },
  "connection.help.brltty": { en: "Linux brltty", ko: "Linux의 brltty" },
  "connection.help.brlttyText": {
    en: "the braille-display service can grab USB serial adapters (CH340 especially). Remove it ({command}) or unplug and replug after stopping it.",
    ko: "점자 디스플레이 서비스가 USB 시리얼 어댑터(특히 CH340)를 차지할 수 있어요. 서비스를 지우거나({command}), 서비스를 멈춘 뒤 어댑터를 뺐다가 다시 꽂아 주세요.",
  },
  "connection.help.snap": { en: "Chromium from a snap", ko: "snap으로 설치한 Chromium" },
  "connection.help.snapText": {
    en: "allow it to see USB devices with {command}, then restart the browser.",
    ko: "{command} 명령으로 USB 장치를 볼 수 있게 허용한 다음, 브라우저를 다시 시작해 주세요.",
  },
  "connection.help.inUse": { en: "Port in use", ko: "사용 중인 포트" },
  "connection.help.inUseText": {
    en: "close Motionbuilder, a serial monitor, or another browser tab that has the port open. Only one program can use it at a time.",
    ko: "포트를 열어 둔 Motionbuilder, 시리얼 모니터, 다른 브라우저 탭을 닫아 주세요. 한 번에 한 프로그램만 포트를 쓸 수 있어요.",
  },
  "connection.help.bluetooth": { en: "Bluetooth module", ko: "블루투스 모듈" },
  "connection.help.bluetoothText": {
    en: 'switch the robot on, then pair the module in the computer\'s Bluetooth settings first; if it asks for a PIN, it is often {pin} or {otherPin}. Then press Connect robot: paired modules are listed as "Bluetooth serial port" beside USB adapters (Chrome or Edge 117 or newer; on an older browser tick "Show all serial ports"). Replies are slower over Bluetooth than over the cable (a few hundred milliseconds): the panel measures them and waits longer. Use the cable for a firmware update: it switches the robot off and on, and the Bluetooth link may not survive that.',
    ko: '먼저 로봇을 켜고 컴퓨터의 블루투스 설정에서 모듈을 페어링해 주세요. PIN을 물으면 {pin} 또는 {otherPin}인 경우가 많아요. 그런 다음 로봇 연결을 누르면 페어링한 모듈이 USB 어댑터와 함께 "블루투스 시리얼 포트"로 나와요 (Chrome 또는 Edge 117 이상. 이전 브라우저에서는 "모든 시리얼 포트 보기"를 체크해 주세요). 블루투스는 케이블보다 응답이 느려요 (수백 밀리초). 패널이 응답 시간을 재서 그만큼 더 기다려요. 펌웨어 업데이트는 케이블로 해 주세요. 업데이트하면 로봇이 꺼졌다 켜지는데, 블루투스 연결은 이때 끊어질 수 있어요.',
  },

  "connection.unsupported.title": {
    en: "This browser cannot reach the robot",
    ko: "이 브라우저로는 로봇에 연결할 수 없어요",
  },
  "connection.unsupported.webSerial": {
    en: "The panel talks to the robot's controller through {webSerial}, which lets a web page open a USB serial port once you pick it. It is available in desktop {browsers}.",
    ko: "패널은 {webSerial}을 통해 로봇의 컨트롤러와 통신해요. 사용자가 고른 USB 시리얼 포트를 웹 페이지가 열 수 있게 해 주는 기능으로, 데스크톱용 {browsers}에서 쓸 수 있어요.",
  },
  "connection.unsupported.browsers": {
    en: "Chrome, Edge and Opera (version 89 or later)",
    ko: "Chrome, Edge, Opera (버전 89 이상)",
  },
  "connection.unsupported.elsewhere": {
    en: "Firefox, Safari, and browsers on phones and tablets do not offer Web Serial, so from them no web page can open the robot's port. Open this page in one of the browsers above on a computer.",
    ko: "Firefox, Safari, 그리고 휴대폰과 태블릿의 브라우저에는 Web Serial이 없어서 어떤 웹 페이지도 로봇의 포트를 열 수 없어요. 컴퓨터에서 위의 브라우저 중 하나로 이 페이지를 열어 주세요.",
  },
  "connection.unsupported.insecure": {
    en: "This page was opened over plain {http}. Browsers only offer Web Serial to secure pages: use {https} or {localhost}.",
    ko: "이 페이지는 암호화되지 않은 {http}(으)로 열렸어요. 브라우저는 보안 페이지에만 Web Serial을 제공해요. {https} 또는 {localhost}을(를) 써 주세요.",
  },
  "connection.unsupported.demo": {
    en: "Meanwhile you can try every part of the panel with the demo robot, a simulated controller in this page.",
    ko: "그동안 이 페이지 안의 가상 컨트롤러인 데모 로봇으로 패널의 모든 기능을 써 볼 수 있어요.",
  },
  "connection.unsupported.starting": { en: "Starting the demo robot…", ko: "데모 로봇을 시작하는 중…" },

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
  "connection.status.platformUnknown": { en: "unknown ({platform})", ko: "알 수 없는 플랫폼 ({platform})" },
  "connection.status.firmware": { en: "fw {version}", ko: "펌웨어 {version}" },
  "connection.status.serialNumber": { en: "SN {serial}", ko: "시리얼 번호 {serial}" },
  "connection.status.limp": { en: "servos limp", ko: "서보 힘 빠짐" },
  "connection.status.servoControl": { en: "servo control", ko: "서보 제어 중" },

  "connection.stop": { en: "Stop", ko: "정지" },
  "connection.dismiss": { en: "Dismiss", ko: "닫기" },
  "connection.stopTitle": {
    en: "End what the robot is doing; it keeps standing (Escape)",
    ko: "로봇이 하던 일을 끝내요. 로봇은 선 채로 있어요 (Esc)",
  },
  "connection.limpAsk": { en: "Limp…", ko: "힘 빼기…" },
  "connection.limpTitle": {
    en: "Make every servo passive: the robot falls unless someone holds it (asks first)",
    ko: "모든 서보의 힘을 빼요. 누가 잡고 있지 않으면 로봇이 넘어져요 (먼저 물어봐요)",
  },
  "connection.limpQuestion": {
    en: "Hold the robot: every servo will go passive and it will fall if nobody holds it.",
    ko: "로봇을 잡아 주세요. 모든 서보의 힘이 빠져서, 아무도 잡고 있지 않으면 로봇이 넘어져요.",
  },
  "connection.limpExplain": {
    en: "Stop (Esc) ends a motion and keeps the robot standing; Limp is for when the robot must go slack.",
    ko: "정지(Esc)는 모션을 끝내고 로봇을 선 채로 두어요. 힘 빼기는 로봇의 힘을 완전히 빼야 할 때 써요.",
  },
  "connection.limp": { en: "Limp", ko: "힘 빼기" },
});

export type ConnectionTranslator = Translator<typeof connectionMessages>;
