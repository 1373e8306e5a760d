import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/**
 * The Log view. The device's notes and raw bytes' names stay in English (they come from the device, like
 * the technical detail), and so does the exported log (a packet trace, like the CLI's).
 */
export const logMessages = defineMessages({
  "log.title": { en: "Packet log", ko: "패킷 로그" },
  "log.pause": { en: "Pause", ko: "일시 정지" },
  "log.resume": { en: "Resume", ko: "계속" },
  "log.clear": { en: "Clear", ko: "지우기" },
  "log.copy": { en: "Copy", ko: "복사" },
  "log.download": { en: "Download .txt", ko: "다운로드 (.txt)" },
  "log.count": {
    en: {
      one: "{count} entry (the newest {capacity} are kept, and at most {size} of bytes).",
      other: "{count} entries (the newest {capacity} are kept, and at most {size} of bytes).",
    },
    ko: "항목 {count}개 (최근 항목 {capacity}개까지, 바이트는 최대 {size}까지 보관해요).",
  },
  "log.countDropped": {
    en: {
      one: "{count} entry (the newest {capacity} are kept, and at most {size} of bytes; {dropped} older dropped).",
      other:
        "{count} entries (the newest {capacity} are kept, and at most {size} of bytes; {dropped} older dropped).",
    },
    ko: "항목 {count}개 (최근 항목 {capacity}개까지, 바이트는 최대 {size}까지 보관해요. 오래된 항목 {dropped}개는 지웠어요).",
  },
  "log.coalesced": {
    en: "Bytes discarded one after another make one entry.",
    ko: "연달아 버린 바이트는 한 항목으로 묶어요.",
  },
  "log.paging": {
    en: "Shown {rows} to a page; Copy and Download take all.",
    ko: "한 쪽에 {rows}개씩 보여요. '복사'와 '다운로드'는 전체를 가져가요.",
  },
  "log.paused": {
    en: "{paused} new packets are still recorded, not shown.",
    ko: "{paused} 새 패킷은 계속 기록하지만 화면에는 보여 주지 않아요.",
  },
  "log.pausedLabel": { en: "Paused:", ko: "일시 정지됨:" },
  "log.resultLabel": { en: "Log action result", ko: "로그 작업 결과" },
  "log.empty": {
    en: "No packets yet. Connect a robot (or the demo robot): every packet in and out appears here.",
    ko: "아직 패킷이 없어요. 로봇(또는 데모 로봇)을 연결하면 주고받는 모든 패킷이 여기에 나와요.",
  },
  "log.caption": { en: "Packets, newest first", ko: "패킷 (최신순)" },
  "log.colTime": { en: "Time", ko: "시간" },
  "log.colDir": { en: "Dir", ko: "방향" },
  "log.colType": { en: "Type", ko: "종류" },
  "log.colBytes": { en: "Bytes (hex)", ko: "바이트 (16진수)" },
  "log.out": { en: "out", ko: "보냄" },
  "log.in": { en: "in", ko: "받음" },
  "log.discarded": { en: "Discarded bytes", ko: "버린 바이트" },
  "log.badChecksum": {
    en: { one: "{count} frame with a bad checksum", other: "{count} frames with a bad checksum" },
    ko: "체크섬이 틀린 프레임 {count}개",
  },
  "log.oversize": {
    en: { one: "{count} frame too long for its type", other: "{count} frames too long for their type" },
    ko: "종류에 비해 너무 긴 프레임 {count}개",
  },
  "log.stray": { en: "stray bytes", ko: "프레임이 아닌 바이트" },
  "log.until": { en: "{what}, until {time}", ko: "{what}, {time}까지" },
  "log.firstShown": {
    en: { one: "first {count} byte shown", other: "first {count} bytes shown" },
    ko: "처음 {count}바이트만 표시",
  },
  "log.noteAndShown": { en: "{note}; {shown}", ko: "{note}; {shown}" },
  "log.pages": { en: "Log pages", ko: "로그 쪽" },
  "log.newer": { en: "Newer", ko: "더 최근" },
  "log.older": { en: "Older", ko: "더 이전" },
  "log.rows": {
    en: "Rows {first}–{last} of {total}, newest first",
    ko: "{total}개 중 {first}–{last}번째 (최신순)",
  },

  // What the actions say.
  "log.copied": {
    en: { one: "Copied {count} line to the clipboard.", other: "Copied {count} lines to the clipboard." },
    ko: "{count}줄을 클립보드에 복사했어요.",
  },
  "log.copyFailed": {
    en: "Copying failed; use Download instead.",
    ko: "복사하지 못했어요. 대신 '다운로드'를 써 주세요.",
  },
  "log.saved": {
    en: { one: "Saved {count} line as {file}.", other: "Saved {count} lines as {file}." },
    ko: "{count}줄을 {file}(으)로 저장했어요.",
  },
});

export type LogTranslator = Translator<typeof logMessages>;
