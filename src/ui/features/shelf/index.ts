export { demoResetOffer } from "./demo-reset.ts";
export { type ShelfTranslator, shelfMessages } from "./messages.ts";
export {
  checkAgainst,
  loadShelf,
  recordOnRobotShelf,
  recordShelf,
  type StoredUpload,
  shelfKeyOf,
} from "./shelf-actions.ts";
export { panelShelfKey, type ShelfStorage } from "./shelf-store.ts";
export { remoteKeyWords, storedSentence, storedWords } from "./shelf-words.ts";
