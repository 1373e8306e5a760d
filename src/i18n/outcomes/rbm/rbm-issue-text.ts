import type { RbmIssue } from "../../../protocol/rbm-validate.ts";
import type { Locale } from "../../locale.ts";
import { translator } from "../../translate.ts";
import { fromParser } from "./file-sentences.ts";
import { type IssueTranslator, rbmIssueMessages } from "./messages.ts";
import { IssueValues, initial, servoName, subject } from "./subject.ts";

/**
 * The motion file checker's issues (protocol/rbm.ts, rbm-validate.ts, motion-image.ts) said from their code and
 * `values`: the outcome catalogue's one wording of a motion file's problems, used by the panel (Motions view,
 * Editor) and by `rbc upload`, `rbc play` and `rbc rbm` alike. English is the protocol's own sentence
 * (`issue.message`); every code those produce has its sentences here (tests/unit/rbm-issue-text.test.ts drives
 * each one). Types only from src/protocol (this folder stays pure).
 */

/** What a value was in a motion built in code: "값이 없음", "지금 값: 12.5". */
function got(t: IssueTranslator, r: IssueValues): string {
  switch (r.text("got")) {
    case "missing":
      return t("outcome.rbm.got.missing");
    case "list":
      return t("outcome.rbm.got.list");
    case "object":
      return t("outcome.rbm.got.object");
    case "value":
      return t("outcome.rbm.got.value", { value: r.text("value") });
    default:
      r.complete = false;
      return "";
  }
}

/**
 * Where in a motion built in code a value is, from its path: "scenes.2.servos.3.end" → "scene 2, servo record 3,
 * end".
 */
function place(t: IssueTranslator, r: IssueValues): string {
  const keys = r.text("path").split(".");
  const parts: string[] = [];
  for (let i = 0; i < keys.length; i++) {
    const [key, next] = [keys[i], keys[i + 1]];
    if ((key === "scenes" || key === "servos") && next !== undefined && /^[0-9]+$/.test(next)) {
      parts.push(
        key === "scenes"
          ? t("outcome.rbm.place.scene", { scene: next })
          : t("outcome.rbm.place.record", { record: next }),
      );
      i++;
    } else {
      parts.push(key ?? "");
    }
  }
  return parts.join(", ");
}

function shape(t: IssueTranslator, r: IssueValues): string | undefined {
  switch (r.text("kind")) {
    case "motion":
      return t("outcome.rbm.shape.motion");
    case "list":
      return t("outcome.rbm.shape.list", { path: place(t, r), got: got(t, r) });
    case "text":
      return t("outcome.rbm.shape.text", { path: place(t, r), got: got(t, r) });
    case "form":
      return t("outcome.rbm.shape.form", { path: place(t, r) });
    default:
      return undefined;
  }
}

function notANumber(t: IssueTranslator, r: IssueValues): string | undefined {
  switch (r.text("kind")) {
    case "shape":
      return t("outcome.rbm.shape.number", { path: place(t, r), got: got(t, r) });
    case "field":
      return t("outcome.rbm.notANumber", {
        index: r.ordinal("index"),
        what: subject(t, r),
        text: r.text("text"),
      });
    default:
      return undefined;
  }
}

function outOfRange(t: IssueTranslator, r: IssueValues): string | undefined {
  const max = r.number("max");
  switch (r.text("kind")) {
    case "byte":
      return initial(
        t("outcome.rbm.outOfRange.byte", { what: subject(t, r), value: r.number("value"), max }),
      );
    case "scenes":
      return t("outcome.rbm.outOfRange.scenes", { scenes: r.number("scenes"), max });
    case "timing":
      return t("outcome.rbm.outOfRange.timing", { scene: r.ordinal("scene"), max });
    default:
      return undefined;
  }
}

function servoCount(t: IssueTranslator, r: IssueValues): string | undefined {
  switch (r.text("kind")) {
    case "declared":
      return t("outcome.rbm.servoCount.declared", {
        declared: r.number("declared"),
        listed: r.number("listed"),
      });
    case "range":
      return t("outcome.rbm.servoCount.range", {
        servos: r.number("servos"),
        min: r.number("min"),
        max: r.number("max"),
      });
    case "file":
      return t("outcome.rbm.servoCount.file", {
        servos: r.number("servos"),
        min: r.number("min"),
        max: r.number("max"),
      });
    case "scene":
      return t("outcome.rbm.servoCount.scene", {
        scene: r.ordinal("scene"),
        records: r.number("records"),
        servos: r.number("servos"),
      });
    default:
      return undefined;
  }
}

function servoId(t: IssueTranslator, r: IssueValues): string | undefined {
  switch (r.text("kind")) {
    case "range":
      return t("outcome.rbm.servoId.range", {
        record: r.ordinal("record"),
        id: r.ordinal("id"),
        max: r.number("max"),
      });
    case "twice":
      return t("outcome.rbm.servoId.twice", {
        id: r.ordinal("id"),
        first: r.ordinal("first"),
        second: r.ordinal("second"),
      });
    case "order":
      return t("outcome.rbm.servoId.order", {
        scene: r.ordinal("scene"),
        record: r.ordinal("record"),
        id: r.ordinal("servo"),
        listed: r.ordinal("listed"),
      });
    default:
      return undefined;
  }
}

/** A header field that is not what Motionbuilder writes: "0번 필드(형식)", "10번 필드". */
function headerConstant(t: IssueTranslator, r: IssueValues): string {
  const field = r.text("field");
  const what =
    field === "format"
      ? t("outcome.rbm.numberedField.format")
      : field === "platform"
        ? t("outcome.rbm.numberedField.platform")
        : subject(t, r);
  return initial(
    t("outcome.rbm.headerConstant", { what, value: r.number("value"), usual: r.number("usual") }),
  );
}

function timing(r: IssueValues) {
  return {
    scene: r.ordinal("scene"),
    interval: r.number("interval"),
    time: r.number("time"),
    frames: r.number("frames"),
  };
}

function fromRules(t: IssueTranslator, code: string, r: IssueValues): string | undefined {
  switch (code) {
    case "rbm-shape":
      return shape(t, r);
    case "rbm-not-a-number":
      return notANumber(t, r);
    case "rbm-out-of-range":
      return outOfRange(t, r);
    case "rbm-position":
      return initial(
        t("outcome.rbm.position", { what: subject(t, r), value: r.number("value"), max: r.number("max") }),
      );
    case "rbm-text":
      return r.has("scene")
        ? t("outcome.rbm.text.scene", { scene: r.ordinal("scene") })
        : initial(t("outcome.rbm.text", { what: subject(t, r) }));
    case "rbm-servo-count":
      return servoCount(t, r);
    case "rbm-scene-count":
      return t("outcome.rbm.sceneCount", { declared: r.number("declared"), listed: r.number("listed") });
    case "rbm-no-scenes":
      return t("outcome.rbm.noScenes");
    case "rbm-servo-id":
      return servoId(t, r);
    case "rbm-scene-index":
      return t("outcome.rbm.sceneIndex", {
        scene: r.ordinal("scene"),
        index: r.ordinal("index"),
        last: r.ordinal("last"),
      });
    case "rbm-frames":
      return t("outcome.rbm.frames", {
        scene: r.ordinal("scene"),
        frames: r.number("frames"),
        min: r.number("min"),
      });
    case "rbm-frame-interval-short":
      return t("outcome.rbm.frameIntervalShort", { ...timing(r), min: r.number("min") });
    case "rbm-frame-interval-long":
      return t("outcome.rbm.frameIntervalLong", { ...timing(r), max: r.number("max") });
    case "rbm-torque":
    case "rbm-port": {
      const params = {
        scene: r.ordinal("scene"),
        servo: servoName(t, r.number("servo")),
        value: r.number("value"),
        max: r.number("max"),
      };
      return code === "rbm-torque" ? t("outcome.rbm.torque", params) : t("outcome.rbm.port", params);
    }
    case "rbm-image-range":
      return initial(
        t("outcome.rbm.imageRange", { what: subject(t, r), value: r.value("value"), max: r.number("max") }),
      );
    default:
      return fromWarnings(t, code, r);
  }
}

function fromWarnings(t: IssueTranslator, code: string, r: IssueValues): string | undefined {
  switch (code) {
    case "rbm-serial-format":
      return t("outcome.rbm.serialFormat", { serial: r.text("serial") });
    case "rbm-serial-mismatch":
      return t("outcome.rbm.serialMismatch", { serial: r.text("serial"), connected: r.text("connected") });
    case "rbm-header-constant":
      return headerConstant(t, r);
    case "rbm-huno-servo-count":
      return t("outcome.rbm.hunoServoCount", { servos: r.number("servos"), huno: r.number("huno") });
    case "rbm-many-frames":
      return t("outcome.rbm.manyFrames", {
        scene: r.ordinal("scene"),
        frames: r.number("frames"),
        max: r.number("max"),
      });
    case "rbm-long-scene":
      return t("outcome.rbm.longScene", {
        scene: r.ordinal("scene"),
        time: r.number("time"),
        max: r.number("max"),
      });
    case "rbm-unsafe-position": {
      const place = {
        scene: r.ordinal("scene"),
        servo: servoName(t, r.number("servo")),
        position: r.number("position"),
        min: r.number("min"),
        max: r.number("max"),
      };
      return r.has("other")
        ? t("outcome.rbm.unsafePositions", { ...place, other: r.number("other") })
        : t("outcome.rbm.unsafePosition", place);
    }
    case "rbm-scene-jump":
      return t("outcome.rbm.sceneJump", {
        scene: r.ordinal("scene"),
        servo: servoName(t, r.number("servo")),
        start: r.number("start"),
        previous: r.ordinal("previous"),
        end: r.number("end"),
      });
    default:
      return fromParser(t, code, r);
  }
}

/** What the words of an issue come from: its code and its facts (`message` is the technical line, kept for logs). */
export type RbmIssueFacts = Pick<RbmIssue, "code" | "message" | "values">;

/**
 * An issue's sentence in `locale` from its code and values, or undefined when there is none (a code this does
 * not know, or values missing): then the technical `issue.message` is shown, marked as English.
 */
export function rbmIssueSentence(issue: RbmIssueFacts, locale: Locale): string | undefined {
  if (issue.values === undefined) return undefined;
  const r = new IssueValues(issue.values);
  const text = fromRules(translator(rbmIssueMessages, locale), issue.code, r);
  return r.complete ? text : undefined;
}

/** The issue's sentence and the language it is in: "en" for an English line kept in another language. */
export interface RbmIssueWords {
  text: string;
  lang: Locale;
}

/**
 * A motion file's problem in `locale`: the catalogue's sentence with the issue's facts, or the issue's technical
 * line (and `lang: "en"`) when there is none.
 */
export function rbmIssueWords(issue: RbmIssueFacts, locale: Locale): RbmIssueWords {
  const text = rbmIssueSentence(issue, locale);
  return text === undefined ? { text: issue.message, lang: "en" } : { text, lang: locale };
}

/** A motion file's problem in `locale` (`rbmIssueWords`'s text). */
export function rbmIssueText(issue: RbmIssueFacts, locale: Locale): string {
  return rbmIssueWords(issue, locale).text;
}

/** A file refused for its issues: the first one's sentence, and how many more were found. */
export function rbmErrorText(issues: readonly RbmIssueFacts[], locale: Locale): string | undefined {
  const [first, ...rest] = issues;
  if (first === undefined) return undefined;
  const text = rbmIssueText(first, locale);
  if (rest.length === 0) return text;
  return translator(rbmIssueMessages, locale)("outcome.rbm.moreProblems", {
    first: text,
    count: rest.length,
  });
}
