import { defineMessages } from "../i18n/catalogue.ts";

/**
 * The panel's own words outside the views: its name and version, the update prompt, what a reload would
 * interrupt, and failures in a person's terms (error-text.ts).
 *
 * error.*: what the panel says around a failure (connecting, the port chooser). The device's errors
 * themselves are worded in src/device/messages.ts (shared with the command line).
 */
export const uiMessages = defineMessages({
  "panel.name": { en: "RBC Panel", ko: "RBC 패널" },
  "version.number": { en: "Version {version}", ko: "버전 {version}" },
  "version.numberCommit": { en: "Version {version} ({commit})", ko: "버전 {version} ({commit})" },
  "version.whatChanged": { en: "What changed", ko: "변경 사항" },

  "busy.stillRunning": { en: "Still running: {list}.", ko: "아직 실행 중이에요: {list}." },

  "update.ready": { en: "A new version of the panel is ready.", ko: "패널의 새 버전이 준비됐어요." },
  "update.reloading": { en: "Reloading with the new version…", ko: "새 버전으로 새로 고치는 중…" },
  "update.elsewhere": {
    en: "The panel was updated in another tab. Reload this page when nothing is running to use the new version.",
    ko: "다른 탭에서 패널을 업데이트했어요. 새 버전을 쓰려면 실행 중인 작업이 없을 때 이 페이지를 새로 고쳐 주세요.",
  },
  "update.blocked": { en: "{busy} Reload when it has finished.", ko: "{busy} 끝난 뒤에 새로 고쳐 주세요." },
  "update.reload": { en: "Reload", ko: "새로 고침" },
  "update.later": { en: "Later", ko: "나중에" },

  // Serial ports (serial-ports.ts) and the session's sentences about the connection (session.ts).
  "port.bluetooth": { en: "Bluetooth serial port", ko: "블루투스 시리얼 포트" },
  "port.builtIn": { en: "Serial port (Bluetooth or built in)", ko: "시리얼 포트 (블루투스 또는 내장)" },
  "port.usbAdapter": { en: "{vendor} USB serial adapter ({ids})", ko: "{vendor} USB 시리얼 어댑터 ({ids})" },
  "port.usbDevice": { en: "USB serial device ({ids})", ko: "USB 시리얼 장치 ({ids})" },

  "session.stoppedWaiting": {
    en: "Stopped waiting for the port chooser. Connect robot opens it again; if the browser's list is still open, close it first.",
    ko: "포트 선택 창을 더 기다리지 않아요. 로봇 연결을 누르면 다시 열려요. 브라우저의 목록이 아직 열려 있으면 먼저 닫아 주세요.",
  },
  "session.demoFailed": { en: "The demo robot could not start.", ko: "데모 로봇을 시작하지 못했어요." },
  "session.codeNotLoaded": {
    en: "The panel's connection code did not load.",
    ko: "패널의 연결 코드를 불러오지 못했어요.",
  },
  "session.disconnectedWhileRunning": {
    en: "Disconnected while this was running: {list}. It did not finish; check the result after reconnecting.",
    ko: "실행 중에 연결을 끊었어요: {list}. 끝나지 않았으니 다시 연결한 뒤 결과를 확인해 주세요.",
  },

  "error.couldNotConnect": { en: "Could not connect.", ko: "연결하지 못했어요." },
  "error.chooserNotFound": {
    en: "No port was chosen. If your robot's port was not in the list, the checks below usually find why.",
    ko: "포트를 고르지 않았어요. 로봇의 포트가 목록에 없었다면 아래 확인 사항에서 대개 이유를 찾을 수 있어요.",
  },
  "error.chooserSecurity": {
    en: "The browser did not allow this page to use serial ports. Check the site's permissions (the icon left of the address) or your organisation's browser policy, then try again.",
    ko: "브라우저가 이 페이지의 시리얼 포트 사용을 허용하지 않았어요. 사이트 권한(주소 왼쪽의 아이콘)이나 기관의 브라우저 정책을 확인한 뒤 다시 시도해 주세요.",
  },
  "error.chooserFailed": { en: "The port chooser failed.", ko: "포트 선택 창에 문제가 생겼어요." },
});
