import { offerDownload } from "./save-file.ts";

/** Saves text as a file through the browser's download (no server involved). */
export function downloadTextFile(fileName: string, text: string, type = "text/plain"): void {
  offerDownload(fileName, new Blob([text], { type: `${type};charset=utf-8` }));
}
