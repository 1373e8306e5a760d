import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/** The Robot view: the device card, its facts and the robot's memory. */
export const robotMessages = defineMessages({
  "robot.title": { en: "Robot", ko: "로봇" },
  "robot.refresh": { en: "Refresh", ko: "다시 읽기" },
  "robot.reading": { en: "Reading…", ko: "읽는 중…" },
  "robot.disconnect": { en: "Disconnect", ko: "연결 끊기" },
  "robot.connectedTo": { en: "Connected to", ko: "연결된 로봇" },
  "robot.demoDescription": {
    en: "Demo robot (a simulated RBC in this page, not hardware)",
    ko: "데모 로봇 (이 페이지 안의 가상 RBC이며, 실제 하드웨어가 아니에요)",
  },
  "robot.demoBluetoothDescription": {
    en: "Demo robot over a simulated Bluetooth link (a simulated RBC in this page, not hardware)",
    ko: "가상 블루투스로 연결한 데모 로봇 (이 페이지 안의 가상 RBC이며, 실제 하드웨어가 아니에요)",
  },
  "robot.firmware": { en: "Firmware", ko: "펌웨어" },
  "robot.platform": { en: "Platform", ko: "플랫폼" },
  "robot.platformHuno": { en: "HUNO (humanoid)", ko: "HUNO (휴머노이드)" },
  "robot.platformDino": { en: "DINO (dinosaur)", ko: "DINO (공룡)" },
  "robot.platformDogy": { en: "DOGY (dog)", ko: "DOGY (강아지)" },
  "robot.platformPf2": { en: "PF2 (user mode)", ko: "PF2 (사용자 모드)" },
  "robot.identityWarning": {
    en: "Something the robot reports about itself looks wrong.",
    ko: "로봇이 알려 준 정보 중에 이상해 보이는 값이 있어요.",
  },
  "robot.codeNumber": { en: "(code {code})", ko: "(코드 {code})" },
  "robot.memoryTitle": { en: "Memory on the robot", ko: "로봇의 메모리" },
  "robot.motionArea": { en: "Motion area", ko: "모션 영역" },
  "robot.actionArea": { en: "Action area", ko: "액션 영역" },
  "robot.bytesUsed": { en: "{used} of {size} bytes used", ko: "{size}바이트 중 {used}바이트 사용" },
  "robot.nothingStored": {
    en: { one: "Nothing stored ({count} byte free).", other: "Nothing stored ({count} bytes free)." },
    ko: "저장된 것이 없어요 ({count}바이트 남음).",
  },
  "robot.full": { en: "Full: no bytes free.", ko: "가득 찼어요. 남은 공간이 없어요." },
  "robot.bytesFree": {
    en: { one: "{count} byte free.", other: "{count} bytes free." },
    ko: "{count}바이트 남았어요.",
  },
  "robot.readAt": { en: "Read from the robot at {time}.", ko: "{time}에 로봇에서 읽었어요." },
  "robot.resultLabel": { en: "Device card result", ko: "로봇 정보 결과" },
  "robot.readingInfo": { en: "Reading device info", ko: "로봇 정보 읽기" },
  "robot.readFailed": { en: "Reading the robot's details failed.", ko: "로봇 정보를 읽지 못했어요." },
});

export type RobotTranslator = Translator<typeof robotMessages>;
