import { formatDecimal, translator } from "../../../i18n/translate.ts";
import { MotionError, type MotionErrorFacts } from "../../../motion/index.ts";
import { inEveryLanguage, type LocalText } from "../../said.ts";
import { type EditorKey, type EditorTranslator, editorMessages } from "./messages.ts";

/**
 * A refused edit in the panel's language. The motion core refuses with a `MotionError`: an English sentence, a
 * stable code and the values it checked (`facts`). In English the panel shows the core's sentence, as it always
 * has; in Korean it says the same from the rule and the values, with what was being set (`what`, a noun phrase
 * the action makes: "왼쪽 무릎(서보 2)의 끝 위치"). The editor's own checks of what was typed are worded in the
 * panel's language when they are made (`TypedValueError`).
 */

/** A value typed into a field that is not a number: refused by the editor itself, its message already in the panel's language. */
export class TypedValueError extends MotionError {
  override name = "TypedValueError";
}

/** What each code means when the refusal carries no rule the panel words more precisely. */
const CODE_TEXT: Readonly<Record<MotionError["code"], EditorKey>> = {
  "motion-no-such-scene": "editor.refusal.noSuchScene",
  "motion-no-such-servo": "editor.refusal.noSuchServo",
  "motion-value": "editor.refusal.value",
  "motion-name": "editor.refusal.name",
  "motion-frame-interval": "editor.refusal.frameInterval",
  "motion-retime": "editor.refusal.retime",
  "motion-last-scene": "editor.refusal.lastScene",
  "motion-mirror": "editor.refusal.mirror",
  "motion-play": "editor.refusal.play",
};

const num = (n: number | string | undefined): string => (n === undefined ? "?" : String(n));

/** The sentence for a refusal with a rule and the values it needs; undefined when they are not all there. */
function byRule(t: EditorTranslator, f: MotionErrorFacts, what: string | undefined): string | undefined {
  const { frames, timeMs, min, max, scene } = f;
  switch (f.rule) {
    case "whole":
      if (what === undefined || min === undefined || max === undefined) return undefined;
      return t("editor.refusal.whole", { what, min, max, value: num(f.value) });
    case "name-empty":
      return what === undefined ? undefined : t("editor.refusal.nameEmpty", { what });
    case "name-length":
      if (what === undefined || f.length === undefined || max === undefined) return undefined;
      return t("editor.refusal.nameLength", { what, length: f.length, max });
    case "name-colon":
      return what === undefined ? undefined : t("editor.refusal.nameColon", { what });
    case "name-ascii":
      return what === undefined ? undefined : t("editor.refusal.nameAscii", { what });
    case "interval-short":
      if (frames === undefined || timeMs === undefined || min === undefined) return undefined;
      return t("editor.refusal.intervalShort", {
        frames,
        time: timeMs,
        interval: formatDecimal(timeMs / frames, t.locale, 1),
        min,
        fewer: Math.max(1, Math.floor(timeMs / min)),
        longer: min * frames,
      });
    case "interval-long":
      if (frames === undefined || timeMs === undefined || max === undefined) return undefined;
      return t("editor.refusal.intervalLong", {
        frames,
        time: timeMs,
        interval: formatDecimal(timeMs / frames, t.locale, 1),
        max,
        more: Math.ceil(timeMs / max),
      });
    case "scene-short":
      if (scene === undefined || timeMs === undefined || min === undefined) return undefined;
      return t("editor.refusal.sceneShort", { scene: String(scene), time: timeMs, min });
    case "scene-long":
      if (scene === undefined || timeMs === undefined || max === undefined) return undefined;
      return t("editor.refusal.sceneLong", { scene: String(scene), time: timeMs, max });
    case "duration":
      return t("editor.refusal.duration", { value: num(f.value) });
    case "zero-duration":
      return t("editor.refusal.zeroDuration");
    case "mirror-platform":
      return t("editor.refusal.mirrorPlatform", { platform: num(f.platform) });
    case "mirror-outside": {
      if (scene === undefined || !f.positions?.length) return undefined;
      const positions = f.positions
        .map((p) => t("editor.refusal.mirrorPosition", { id: String(p.id), position: String(p.position) }))
        .join(", ");
      return t("editor.refusal.mirrorOutside", { scene: String(scene), positions });
    }
    case "play-frames":
      if (scene === undefined || frames === undefined) return undefined;
      return t("editor.refusal.playFrames", { scene: String(scene), frames: String(frames) });
    case "play-interval":
      if (scene === undefined || frames === undefined || timeMs === undefined || min === undefined) {
        return undefined;
      }
      return t("editor.refusal.playInterval", {
        scene: String(scene),
        interval: num(f.intervalMs),
        time: timeMs,
        frames,
        min,
      });
    default:
      return undefined;
  }
}

/**
 * The sentence a person reads about a refused edit: the core's English sentence in English; in Korean one made
 * from the rule and values (or, where they are not carried, from the code). `what` names what was being set.
 */
export function refusalText(e: MotionError, t: EditorTranslator, what?: string): string {
  if (t.locale === "en" || e instanceof TypedValueError) return e.message;
  return byRule(t, e.facts, what) ?? t(CODE_TEXT[e.code]);
}

/**
 * A refusal in every language (`refusalText` for each), for a notice kept as a message: it follows a language
 * switch. `what` names what was being set, in every language.
 */
export function refusalWords(e: MotionError, what?: LocalText): LocalText {
  return inEveryLanguage((locale) => refusalText(e, translator(editorMessages, locale), what?.[locale]));
}
