/**
 * The Motions feature as the rest of the panel uses it (docs/architecture.md, "Features"): the Editor's
 * upload and run (with the Motions view's parts it shows), a motion file's checks and issue words (the Class
 * view's pack), the slot book. Its view loads lazily (shell/registry.ts), never through this file.
 */
export { checkEntry, inspectMotionText } from "./files.ts";
export { groupWarnings, type WarningGroup, weightWord } from "./issue-groups.ts";
export { issueWords } from "./issue-text.ts";
export { showMemory } from "./memory.ts";
export { type MotionsTranslator, motionsMessages } from "./messages.ts";
export { formatSeconds } from "./plot-data.ts";
export { restampOffer } from "./restamp/restamp-offer.ts";
export { saveRestampedCopy } from "./restamp/restamp-save.ts";
export { type BookEntry, motionNumberOf, type SlotBook } from "./slot-book.ts";
export { motionsOf, robotBusyReason, type UploadTarget } from "./state.ts";
export { requestUpload, startUpload, uploadPayload } from "./upload-actions.ts";
export { pressRun } from "./view-actions.ts";
export { motionMemoryStrip } from "./views/memory-card.ts";
export { confirmMove, runningPanel } from "./views/run-section.ts";
export { type RunHere, uploadInPlace } from "./views/upload-in-place.ts";
