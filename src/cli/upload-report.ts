import { memoryFootprint } from "../protocol/catalog.ts";
import { motionDurationMs, type RbmMotion } from "../protocol/rbm.ts";
import type { RbmIssue, RbmValidation } from "../protocol/rbm-validate.ts";

/** The validation report of `rbc upload`, in words. */

function where(issue: RbmIssue): string {
  const parts = [
    issue.scene === undefined ? undefined : `scene ${issue.scene}`,
    issue.servo === undefined ? undefined : `servo ${issue.servo}`,
  ].filter((p) => p !== undefined);
  return parts.length > 0 ? `(${parts.join(", ")}) ` : "";
}

export function issueLines(kind: "error" | "warning", issues: readonly RbmIssue[]): string[] {
  return issues.map((i) => `  ${kind}: ${where(i)}${i.message}`);
}

export function validationSummary(validation: RbmValidation): string {
  const e = validation.errors.length;
  const w = validation.warnings.length;
  const plural = (n: number, word: string) => `${n} ${word}${n === 1 ? "" : "s"}`;
  if (e === 0 && w === 0) return "Checked: no errors, no warnings.";
  return `Checked: ${plural(e, "error")}, ${plural(w, "warning")}.`;
}

export function motionSummary(file: string, motion: RbmMotion, imageBytes: number): string {
  const seconds = (motionDurationMs(motion) / 1000).toFixed(1);
  return `${file}: motion "${motion.name}", ${motion.servos.length} servos, ${motion.scenes.length} scenes, plays about ${seconds} s; image ${imageBytes} bytes (takes ${memoryFootprint(imageBytes)} bytes of motion memory).`;
}

export function issuesJson(validation: RbmValidation) {
  return { errors: validation.errors, warnings: validation.warnings };
}
