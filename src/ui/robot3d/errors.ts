import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { robot3dMessages } from "./messages.ts";

/**
 * Why the 3D view cannot draw. The view shows the sentence for the `code` in the panel's language in place of
 * the picture (`robot3dErrorText`); the `code` is stable for programs and tests, the message is English.
 */
export class Robot3dError extends Error {
  override name = "Robot3dError";
  constructor(readonly code: Robot3dErrorCode) {
    super(robot3dErrorText(code, "en"));
  }
}

export type Robot3dErrorCode =
  /** The browser offers no WebGL 2 here (switched off, blocked, or no graphics driver). */
  | "robot3d-no-webgl"
  /** The 3D module could not be loaded (offline before it was first fetched). */
  | "robot3d-load-failed";

/** What the person reads in place of the picture, in `locale`. */
export function robot3dErrorText(code: Robot3dErrorCode, locale: Locale): string {
  const t = translator(robot3dMessages, locale);
  return code === "robot3d-no-webgl" ? t("robot3d.noWebgl") : t("robot3d.loadFailed");
}
