/**
 * The panel's and the command line's languages: the catalogues' type (`defineMessages`), the translator, the
 * language of a browser, and numbers, units, dates and times written for a language. Pure: no DOM, no I/O.
 * docs/i18n.md says how to use it.
 */
export type {
  Catalogue,
  KeysWithoutParams,
  Message,
  MessageText,
  ParamNames,
  Params,
  PluralText,
} from "./catalogue.ts";
export { defineMessages } from "./catalogue.ts";
export { HUNO_JOINT_NAMES } from "./joint-names/huno-joint-names.ts";
export { servoLabel } from "./joint-names/joint-name.ts";
export { isLocale, LOCALE_NAMES, LOCALES, type Locale, pickLocale } from "./locale.ts";
// The words of the device's outcomes, which stand above the device layer (they left src/device/index.ts, whose
// layer no longer imports src/i18n): a device error in a person's language, and the catalogue of its entries.
export { UPLOAD_NOTICES, type UploadNotice, uploadNoticeText } from "./outcomes/device.ts";
export { type ErrorTextOptions, errorText, uploadOutcomeText } from "./outcomes/error-text.ts";
export { lowerErrorText } from "./outcomes/lower-error-text.ts";
export { deviceOutcomeMessages, deviceOutcomeMessages as deviceErrorMessages } from "./outcomes/messages.ts";
// The words of the protocol's and the motion layer's outcomes (they left src/protocol/index.ts and
// src/motion/index.ts, whose layers do not import src/i18n).
export { distanceWarning, platformWarning } from "./outcomes/plausibility.ts";
export { remoteKeyWords } from "./outcomes/remote-key.ts";
export { errorCodeText, robotErrorText } from "./outcomes/robot-error.ts";
export {
  backupRefusalText,
  serialMismatchWarning,
  zeroProblemText,
  zerosNotWrittenText,
} from "./outcomes/zero-words.ts";
export { formatDecimal, formatNumber, placeholdersOf, type Translator, translator } from "./translate.ts";
export {
  formatBytes,
  formatDate,
  formatDateTime,
  formatKilobytes,
  formatMilliseconds,
  formatSeconds,
  formatTime,
} from "./units.ts";
