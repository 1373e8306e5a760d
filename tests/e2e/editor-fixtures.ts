import type { Page } from "playwright-core";
import { loadConnected } from "./connected-page.ts";

/**
 * What several Editor browser tests do the same way: open the Editor with the demo robot connected, and store a
 * draft record straight into the panel's IndexedDB (as an older panel, or a broken write, left it).
 */

/**
 * Loads the panel at `url` in the Editor with the demo robot connected (a page opened with the start option
 * `DEMO`), and waits for its pose table.
 */
export async function openEditorOnDemo(page: Page, url: string): Promise<void> {
  await loadConnected(page, url, "editor");
  await page.getByTestId("pose-table").waitFor();
}

/** Stores a draft record straight into the panel's IndexedDB (database "rbc-panel-drafts", store "drafts"). */
export async function storeDraft(page: Page, key: string, record: unknown): Promise<void> {
  await page.evaluate(
    ({ key, record }) =>
      new Promise<void>((resolve, reject) => {
        const open = indexedDB.open("rbc-panel-drafts");
        open.onupgradeneeded = () => open.result.createObjectStore("drafts");
        open.onerror = () => reject(open.error);
        open.onsuccess = () => {
          const db = open.result;
          const tx = db.transaction("drafts", "readwrite");
          tx.objectStore("drafts").put(record, key);
          tx.oncomplete = () => {
            db.close();
            resolve();
          };
          tx.onerror = () => reject(tx.error);
        };
      }),
    { key, record },
  );
}
