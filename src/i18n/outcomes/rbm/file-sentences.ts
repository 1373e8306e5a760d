import type { IssueTranslator } from "./messages.ts";
import { type IssueValues, initial, subject } from "./subject.ts";

/** The reader's issues (protocol/rbm.ts `readRbm`): a text that is not a motion file, or not a whole one. */
export function fromParser(t: IssueTranslator, code: string, r: IssueValues): string | undefined {
  switch (code) {
    case "rbm-not-text":
      return t("outcome.rbm.notText");
    case "rbm-too-large":
      return t("outcome.rbm.tooLarge", {
        characters: r.number("characters"),
        largest: r.number("largest"),
      });
    case "rbm-empty":
      return t("outcome.rbm.empty");
    case "rbm-not-motion":
      return t("outcome.rbm.notMotion");
    case "rbm-end":
      return t("outcome.rbm.end", { ending: r.text("ending") });
    case "rbm-field-count":
      if (r.text("kind") === "header") {
        return t("outcome.rbm.fieldCount.header", {
          fields: r.number("fields"),
          header: r.number("header"),
        });
      }
      if (r.text("kind") !== "total") return undefined;
      return t("outcome.rbm.fieldCount.total", {
        fields: r.number("fields"),
        servos: r.number("servos"),
        scenes: r.number("scenes"),
        expected: r.number("expected"),
      });
    case "rbm-field-too-long": {
      const kind = r.text("kind");
      const sizes = { what: subject(t, r), length: r.number("length"), max: r.number("max") };
      if (kind === "text") {
        return initial(t("outcome.rbm.fieldTooLong.text", sizes));
      }
      return kind === "name" ? t("outcome.rbm.fieldTooLong.name", sizes) : undefined;
    }
    case "rbm-length-mismatch": {
      const sizes = { text: r.text("text"), length: r.number("length"), declared: r.number("declared") };
      if (r.has("scene"))
        return t("outcome.rbm.lengthMismatch.scene", { scene: r.ordinal("scene"), ...sizes });
      return initial(t("outcome.rbm.lengthMismatch", { what: subject(t, r), ...sizes }));
    }
    default:
      return undefined;
  }
}
