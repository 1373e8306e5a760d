import type { RbmIssueValues } from "../../../protocol/rbm-validate.ts";
import type { KeysWithoutParams } from "../../catalogue.ts";
import { jointOf } from "../../joint-names/joint-name.ts";
import type { IssueTranslator, rbmIssueMessages } from "./messages.ts";

/**
 * Reads an issue's `values` for its sentence, and remembers whether one the sentence needs was missing (or of
 * the wrong type): such a sentence is not said, the English one is (`rbmIssueSentence`).
 */
export class IssueValues {
  complete = true;
  constructor(private readonly values: RbmIssueValues) {}

  has(key: string): boolean {
    return this.values[key] !== undefined;
  }

  /** A quantity (frames, a position, a time): the translator formats it for the language ("10,000"). */
  number(key: string): number {
    const v = this.values[key];
    if (typeof v === "number") return v;
    this.complete = false;
    return 0;
  }

  /** A number that names something (scene 3, servo record 12, field 7): written as it is, never grouped. */
  ordinal(key: string): string {
    return String(this.number(key));
  }

  /** A text (a serial number, a file's field as it reads, a kind), as it is. */
  text(key: string): string {
    const v = this.values[key];
    if (typeof v === "string") return v;
    this.complete = false;
    return "";
  }

  /** A value that is a number when it is one (a value that does not fit the image may be "1.5" or "NaN"). */
  value(key: string): number | string {
    const v = this.values[key];
    if (v !== undefined) return v;
    this.complete = false;
    return "";
  }
}

type Key = KeysWithoutParams<typeof rbmIssueMessages>;

/** The fields by their name in `RbmMotion` (protocol/rbm.ts), or a length field's ("nameLength"). */
const FIELDS: Readonly<Record<string, Key>> = {
  format: "outcome.rbm.field.format",
  serialNumber: "outcome.rbm.field.serialNumber",
  serialNumberLength: "outcome.rbm.field.serialNumberLength",
  text1: "outcome.rbm.field.text1",
  text2: "outcome.rbm.field.text2",
  motionIndex: "outcome.rbm.field.motionIndex",
  platform: "outcome.rbm.field.platform",
  sceneCount: "outcome.rbm.field.sceneCount",
  servoCount: "outcome.rbm.field.servoCount",
  unknown10: "outcome.rbm.field.unknown10",
  unknown12: "outcome.rbm.field.unknown12",
  imageSize: "outcome.rbm.field.imageSize",
  index: "outcome.rbm.field.index",
  name: "outcome.rbm.field.name",
  nameLength: "outcome.rbm.field.nameLength",
  frames: "outcome.rbm.field.frames",
  timeMs: "outcome.rbm.field.timeMs",
  id: "outcome.rbm.field.id",
  p: "outcome.rbm.field.p",
  d: "outcome.rbm.field.d",
  i: "outcome.rbm.field.i",
  portEnable: "outcome.rbm.field.portEnable",
  zero: "outcome.rbm.field.zero",
  reserved: "outcome.rbm.field.reserved",
  start: "outcome.rbm.field.start",
  end: "outcome.rbm.field.end",
  torque: "outcome.rbm.field.torque",
  port: "outcome.rbm.field.port",
};

/** The motion's own name (no scene given): "the motion name", not a scene's "name". */
const MOTION_FIELDS: Readonly<Record<string, Key>> = {
  name: "outcome.rbm.field.motionName",
  nameLength: "outcome.rbm.field.motionNameLength",
};

/** The field named by `values.field`, in words: "P gain" / "P 게인". */
export function fieldName(t: IssueTranslator, r: IssueValues): string {
  const field = r.text("field");
  const key = (r.has("scene") ? undefined : MOTION_FIELDS[field]) ?? FIELDS[field];
  if (key === undefined) {
    r.complete = false;
    return "";
  }
  return t(key);
}

/** A servo by id, with its HUNO joint when it has one: "서보 2번(왼쪽 무릎)", "서보 20번". */
export function servoName(t: IssueTranslator, id: number): string {
  const joint = jointOf(id, t.locale);
  return joint === undefined
    ? t("outcome.rbm.servo", { id: String(id) })
    : t("outcome.rbm.servoJoint", { id: String(id), joint });
}

/**
 * The field an issue is about, with whose it is (`values.scene`, `servo`, `record`): "장면 2에서 서보 3번(왼쪽
 * 발목 앞뒤)의 시작 위치", "서보 레코드 4번의 P 게인", "모션 번호".
 */
export function subject(t: IssueTranslator, r: IssueValues): string {
  const field = fieldName(t, r);
  const scene = r.has("scene") ? r.ordinal("scene") : undefined;
  const servo = r.has("servo") ? servoName(t, r.number("servo")) : undefined;
  const record = r.has("record") ? r.ordinal("record") : undefined;
  if (scene !== undefined && servo !== undefined) {
    return t("outcome.rbm.ofSceneServo", { scene, servo, field });
  }
  if (scene !== undefined && record !== undefined) {
    return t("outcome.rbm.ofSceneRecord", { scene, record, field });
  }
  if (scene !== undefined) return t("outcome.rbm.ofScene", { scene, field });
  if (servo !== undefined) return t("outcome.rbm.ofServo", { servo, field });
  if (record !== undefined) return t("outcome.rbm.ofRecord", { record, field });
  return field;
}

/** A sentence that begins with its subject ("the P gain of servo 3 …"), with a capital letter where it has one. */
export function initial(text: string): string {
  return text.charAt(0).toUpperCase() + text.slice(1);
}
