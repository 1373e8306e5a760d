/**
 * The robot's shelf as the rest of the panel uses it (docs/architecture.md, "Features"): load, check and record
 * what this browser uploaded to a robot, its words, and the demo robot's reset. It imports no other feature.
 */
export { demoResetOffer } from "./demo-reset.ts";
export { shelfMessages } from "./messages.ts";
export {
  checkAgainst,
  loadShelf,
  recordOnRobotShelf,
  recordShelf,
  type StoredUpload,
  shelfKeyOf,
} from "./shelf-actions.ts";
export { type RunNow, runNowButton, shelfDropNotice, shelfList, shelfRecordedNote } from "./shelf-list.ts";
export { panelShelfKey, type ShelfStorage } from "./shelf-store.ts";
export { remoteKeyWords, type StoredWay, storedSentence, storedWords } from "./shelf-words.ts";
