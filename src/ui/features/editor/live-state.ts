/**
 * The editor's live part, one per connection (the session resets it): teach-in and tethered play.
 * Skeleton: the teach-in and play panels fill this in.
 */
import type { AppState } from "../../app-state.ts";

// biome-ignore lint/complexity/noBannedTypes: filled in by the teach-in and play panels
export type EditorLiveState = {};

/**
 * The pose the editor's 3D view should show instead of the selected scene's: the live robot during teach-in,
 * the frame last sent during tethered play; undefined to show the scene. 16 positions by servo id.
 */
export function livePoseOf(_state: AppState): readonly (number | undefined)[] | undefined {
  return undefined;
}
