/** The joints' names live in the catalogue (src/i18n/joint-names/), where a motion file's problems name them too. */
export { jointName, sidesNote } from "../../../../i18n/joint-names/joint-name.ts";
