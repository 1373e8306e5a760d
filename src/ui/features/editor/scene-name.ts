import type { EditorTranslator } from "./messages.ts";

/**
 * A scene's name as the Editor shows it. A motion file stores scene names in printable ASCII only (the RBC and
 * Motionbuilder read them as single bytes; `checkName` in src/motion refuses anything else), so a new scene is
 * stored as "Scene_<n>" in every language; the Editor shows that default name in the page's language ("장면_0"),
 * and any other name as it is. The name field shows what the file holds.
 */
export function shownSceneName(name: string, t: EditorTranslator): string {
  const m = /^Scene_(\d+)$/.exec(name);
  return m ? t("editor.scene.defaultName", { n: m[1]! }) : name;
}
