import type { LinkFacts, LinkReason } from "../../link/transport.ts";
import type { KeysWithoutParams } from "../catalogue.ts";
import { defineMessages } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";

/**
 * Why the serial link failed or was lost (src/link: a `LinkError`'s facts, a lost transport's `cause`), in
 * words: the link gives the reason as a code, with the port's path and the system's own detail where known.
 */
export const linkOutcomeMessages = defineMessages({
  "outcome.link.alreadyOpen": { en: "The port is already open.", ko: "포트가 이미 열려 있어요." },
  "outcome.link.inAnotherTab": {
    en: "The port is already open, perhaps in another tab of this browser. Close it there and try again.",
    ko: "포트가 이미 열려 있어요. 이 브라우저의 다른 탭에서 열었을 수 있어요. 그 탭에서 닫고 다시 해 보세요.",
  },
  "outcome.link.inUseOrStarting": {
    en: "The port could not be opened. Another program (Motionbuilder, a serial monitor, another browser) may be using it, or the adapter is still starting: wait a moment and try again.",
    ko: "포트를 열 수 없어요. 다른 프로그램(Motionbuilder, 시리얼 모니터, 다른 브라우저)이 쓰고 있거나 어댑터가 아직 준비 중일 수 있어요. 잠시 기다렸다가 다시 해 보세요.",
  },
  "outcome.link.noWritable": {
    en: "The port opened without a writable stream.",
    ko: "포트는 열렸지만 데이터를 보낼 스트림이 없어요.",
  },
  "outcome.link.busyOrDenied": {
    en: "{path} is busy or not permitted ({detail}). Close other programs using it; on Linux add yourself to the dialout group.",
    ko: "{path}을(를) 다른 프로그램이 쓰고 있거나 사용 권한이 없어요 ({detail}). 그 포트를 쓰는 다른 프로그램을 닫아 주세요. Linux에서는 사용자를 dialout 그룹에 추가해 주세요.",
  },
  "outcome.link.openError": {
    en: "{path} could not be opened: {detail}",
    ko: "{path}을(를) 열 수 없어요: {detail}",
  },
  "outcome.link.openCancelled": { en: "Opening {path} was cancelled.", ko: "{path} 열기를 취소했어요." },
  "outcome.link.notOpen": { en: "The port is not open.", ko: "포트가 열려 있지 않아요." },
  "outcome.link.lost": { en: "The robot is disconnected.", ko: "로봇과의 연결이 끊겨 있어요." },
  "outcome.link.writeFailed": {
    en: "Writing to the port failed; the adapter may have been unplugged.",
    ko: "포트에 데이터를 보내지 못했어요. 어댑터가 뽑혔을 수 있어요.",
  },
  "outcome.link.writeError": {
    en: "Writing to {path} failed: {detail}",
    ko: "{path}에 데이터를 보내지 못했어요: {detail}",
  },
  "outcome.link.usbUnplugged": {
    en: "The USB cable was unplugged or the adapter was removed.",
    ko: "USB 케이블이 뽑혔거나 어댑터가 빠졌어요.",
  },
  "outcome.link.connectionLost": {
    en: "The connection to the robot was lost.",
    ko: "로봇과의 연결이 끊겼어요.",
  },
  "outcome.link.deviceUnplugged": { en: "The serial device was unplugged.", ko: "시리얼 장치가 뽑혔어요." },
  "outcome.link.closedUnexpectedly": {
    en: "The serial port was closed unexpectedly.",
    ko: "시리얼 포트가 예기치 않게 닫혔어요.",
  },
  "outcome.link.portError": {
    en: "The serial port reported an error: {detail}",
    ko: "시리얼 포트에서 오류가 났어요: {detail}",
  },
});

type Key = KeysWithoutParams<typeof linkOutcomeMessages>;

/** The reasons whose sentence needs no facts. */
const PLAIN: Partial<Readonly<Record<LinkReason, Key>>> = {
  "already-open": "outcome.link.alreadyOpen",
  "in-another-tab": "outcome.link.inAnotherTab",
  "in-use-or-starting": "outcome.link.inUseOrStarting",
  "no-writable": "outcome.link.noWritable",
  "not-open": "outcome.link.notOpen",
  lost: "outcome.link.lost",
  "write-failed": "outcome.link.writeFailed",
  "usb-unplugged": "outcome.link.usbUnplugged",
  "connection-lost": "outcome.link.connectionLost",
  "device-unplugged": "outcome.link.deviceUnplugged",
  "closed-unexpectedly": "outcome.link.closedUnexpectedly",
};

/** Why the link failed or was lost, in `locale`, from its facts; undefined when they give no reason. */
export function linkReasonText(facts: LinkFacts, locale: Locale): string | undefined {
  const t = translator(linkOutcomeMessages, locale);
  const { reason, path = "?", detail = "?" } = facts;
  if (reason === undefined) return undefined;
  const plain = PLAIN[reason];
  if (plain !== undefined) return t(plain);
  switch (reason) {
    case "busy-or-denied":
      return t("outcome.link.busyOrDenied", { path, detail });
    case "open-error":
      return t("outcome.link.openError", { path, detail });
    case "open-cancelled":
      return t("outcome.link.openCancelled", { path });
    case "write-error":
      return t("outcome.link.writeError", { path, detail });
    default:
      return t("outcome.link.portError", { detail });
  }
}
