/**
 * The editor's part of the app state (kept across connections: the motion being made lives on this computer).
 * Skeleton: the editor view fills this in.
 */
// biome-ignore lint/complexity/noBannedTypes: filled in by the editor view
export type EditorState = {};
