import { defineMessages } from "../../../i18n/catalogue.ts";

/**
 * The card of a browser without Web Serial (unsupported-card.ts): loaded only by such a browser, not in the first
 * page load of the others.
 */
export const unsupportedMessages = defineMessages({
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
});
