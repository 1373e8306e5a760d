import { LinkError } from "../../link/transport.ts";
import { MotionError } from "../../motion/errors.ts";
import { RestampError } from "../../motion/restamp.ts";
import { BootloaderError } from "../../protocol/bootloader.ts";
import { BadReplyError } from "../../protocol/commands.ts";
import { IntelHexError } from "../../protocol/intel-hex.ts";
import { RbmError } from "../../protocol/rbm.ts";
import { ZeroTableError } from "../../protocol/zeros.ts";
import type { Locale } from "../locale.ts";
import { firmwareFailureText, hexProblemText } from "./firmware/firmware-words.ts";
import { linkReasonText } from "./link-words.ts";
import { motionRefusalText } from "./motion/motion-words.ts";
import { badReplyText } from "./protocol-words.ts";
import { rbmErrorText } from "./rbm/rbm-issue-text.ts";
import { restampRefusalText } from "./restamp/restamp-words.ts";
import { zerosNotWrittenText } from "./zero-words.ts";

/**
 * The errors of the layers below the device (src/protocol, src/link, src/motion) for a person, in their
 * language, from their code and facts: `errorText` asks here first. The errors' own `message` is a technical
 * line for logs. Undefined for an error this does not word (a link error made without its facts, say).
 */
export function lowerErrorText(e: unknown, locale: Locale): string | undefined {
  if (e instanceof LinkError) return linkReasonText(e.facts, locale);
  if (e instanceof MotionError) return motionRefusalText(e, locale);
  if (e instanceof RestampError) return restampRefusalText(e, locale);
  if (e instanceof RbmError) return rbmErrorText(e.issues, locale);
  if (e instanceof IntelHexError) return hexProblemText(e, locale);
  if (e instanceof BootloaderError) {
    const { code: failure, holds, line, waitedMs, tries } = e;
    return firmwareFailureText({ failure, holds, line, waitedMs, tries }, locale);
  }
  if (e instanceof BadReplyError) return badReplyText(e, locale);
  if (e instanceof ZeroTableError) return zerosNotWrittenText(e.problems, locale);
  return undefined;
}
