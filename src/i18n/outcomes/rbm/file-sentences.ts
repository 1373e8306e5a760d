import type { IssueTranslator } from "./messages.ts";
import { type IssueValues, subject } from "./subject.ts";

/** The reader's issues (protocol/rbm.ts `readRbm`): a text that is not a motion file, or not a whole one. */
export function fromParser(t: IssueTranslator, code: string, r: IssueValues): string | undefined {
  switch (code) {
    case "rbm-not-text":
      return t("motions.issue.notText");
    case "rbm-too-large":
      return t("motions.issue.tooLarge", {
        characters: r.number("characters"),
        largest: r.number("largest"),
      });
    case "rbm-empty":
      return t("motions.issue.empty");
    case "rbm-not-motion":
      return t("motions.issue.notMotion");
    case "rbm-end":
      return t("motions.issue.end", { ending: r.text("ending") });
    case "rbm-field-count":
      if (r.text("kind") === "header") {
        return t("motions.issue.fieldCount.header", {
          fields: r.number("fields"),
          header: r.number("header"),
        });
      }
      if (r.text("kind") !== "total") return undefined;
      return t("motions.issue.fieldCount.total", {
        fields: r.number("fields"),
        servos: r.number("servos"),
        scenes: r.number("scenes"),
        expected: r.number("expected"),
      });
    case "rbm-field-too-long": {
      const kind = r.text("kind");
      const sizes = { what: subject(t, r), length: r.number("length"), max: r.number("max") };
      if (kind === "text") return t("motions.issue.fieldTooLong.text", sizes);
      return kind === "name" ? t("motions.issue.fieldTooLong.name", sizes) : undefined;
    }
    case "rbm-length-mismatch":
      return t("motions.issue.lengthMismatch", {
        what: subject(t, r),
        text: r.text("text"),
        length: r.number("length"),
        declared: r.number("declared"),
      });
    default:
      return undefined;
  }
}
