import type { BadReplyError } from "../../protocol/commands.ts";
import { defineMessages } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";

/** A reply the protocol could not decode (src/protocol/commands.ts `BadReplyError`), from its facts. */
export const protocolOutcomeMessages = defineMessages({
  "outcome.badReply.length": {
    en: 'The robot\'s reply to "{command}" was not understood: expected {expected} bytes, got {got}.',
    ko: '로봇이 "{command}" 요청에 보낸 응답을 이해하지 못했어요. {expected}바이트여야 하는데 {got}바이트였어요.',
  },
  "outcome.badReply.notPrintable": {
    en: 'The robot\'s reply to "{command}" was not understood: the serial number is not printable text.',
    ko: '로봇이 "{command}" 요청에 보낸 응답을 이해하지 못했어요. 시리얼 번호가 읽을 수 있는 문자가 아니에요.',
  },
});

/** Why a reply was not understood, in `locale`; undefined for one made without these facts. */
export function badReplyText(e: BadReplyError, locale: Locale): string | undefined {
  const t = translator(protocolOutcomeMessages, locale);
  const { command, expected, got, problem } = e.facts;
  if (command === undefined) return undefined;
  if (problem === "not-printable") return t("outcome.badReply.notPrintable", { command: String(command) });
  if (expected === undefined || got === undefined) return undefined;
  return t("outcome.badReply.length", {
    command: String(command),
    expected: String(expected),
    got: String(got),
  });
}
