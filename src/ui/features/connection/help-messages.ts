import { defineMessages } from "../../../i18n/catalogue.ts";

/**
 * "Can't find your robot?": the body of the connect card's help (its title is in messages.ts, drawn at once).
 * Loaded just after the first paint with connect-help.ts, not in the first page load.
 */
export const connectHelpMessages = defineMessages({
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
});
