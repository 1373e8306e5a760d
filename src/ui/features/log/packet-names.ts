import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";

/**
 * The names of the RBC's packets in the Log view, by type byte (docs/protocol.md §4): in English the protocol's
 * own names (src/protocol/commands.ts `commandName`, checked equal by tests/unit/log-packet-names.test.ts), in
 * Korean translated (issue 33). Raw bytes and the device's notes stay as the device wrote them, and so does the
 * copied and downloaded log (a packet trace, like the CLI's).
 */
export const packetNameMessages = defineMessages({
  "packet.0x01": { en: "Write motion", ko: "모션 쓰기" },
  "packet.0x02": { en: "Write action", ko: "액션 쓰기" },
  "packet.0x0b": { en: "Read zero positions", ko: "영점 위치 읽기" },
  "packet.0x0c": { en: "Read serial number", ko: "일련번호 읽기" },
  "packet.0x0e": { en: "Write zero positions", ko: "영점 위치 쓰기" },
  "packet.0x0f": { en: "Read available memory", ko: "남은 메모리 읽기" },
  "packet.0x10": { en: "Direct control mode on", ko: "직접 제어 모드 켜기" },
  "packet.0x11": { en: "Read error code", ko: "오류 코드 읽기" },
  "packet.0x12": { en: "Read firmware version", ko: "펌웨어 버전 읽기" },
  "packet.0x14": { en: "Run motion", ko: "모션 실행" },
  "packet.0x15": { en: "Run sound", ko: "소리 재생" },
  "packet.0x16": { en: "Distance sensor", ko: "거리 센서" },
  "packet.0x17": { en: "Sound input", ko: "소리 입력" },
  "packet.0x18": { en: "Button press", ko: "버튼 누름" },
  "packet.0x19": { en: "Remote control", ko: "리모컨" },
  "packet.0x1a": { en: "Accelerometer", ko: "가속도 센서" },
  "packet.0x1e": { en: "Execution status", ko: "실행 상태" },
  "packet.0x1f": { en: "Reset memory pointer", ko: "메모리 포인터 초기화" },
});

type PacketKey = keyof typeof packetNameMessages;

/** Each named type's key, by the type written as in docs/protocol.md ("0x12"). */
const KEYS: Readonly<Partial<Record<string, PacketKey>>> = {
  "0x01": "packet.0x01",
  "0x02": "packet.0x02",
  "0x0b": "packet.0x0b",
  "0x0c": "packet.0x0c",
  "0x0e": "packet.0x0e",
  "0x0f": "packet.0x0f",
  "0x10": "packet.0x10",
  "0x11": "packet.0x11",
  "0x12": "packet.0x12",
  "0x14": "packet.0x14",
  "0x15": "packet.0x15",
  "0x16": "packet.0x16",
  "0x17": "packet.0x17",
  "0x18": "packet.0x18",
  "0x19": "packet.0x19",
  "0x1a": "packet.0x1a",
  "0x1e": "packet.0x1e",
  "0x1f": "packet.0x1f",
};

/** A packet's name in `locale`, or undefined for a type the protocol does not name (then the device's words). */
export function packetName(type: number, locale: Locale): string | undefined {
  const key = KEYS[`0x${type.toString(16).padStart(2, "0")}`];
  return key ? translator(packetNameMessages, locale)(key) : undefined;
}
