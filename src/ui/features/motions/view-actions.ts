import type { AppContext } from "../../context.ts";
import { focusSoon } from "../../focus.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import type { RunNow } from "../shelf/index.ts";
import type { MotionsKey } from "./messages.ts";
import { requestRun } from "./run-actions.ts";
import { type MotionsTab, motionFilesOf, patchMotionFiles, patchMotions, robotBusyReason } from "./state.ts";

/** What the Motions view's own controls do: choose a tab, show or hide a file's scenes, press a Run button. */

/** The tabs, each with the key of its label. */
export const MOTIONS_TABS: readonly { id: MotionsTab; label: MotionsKey }[] = [
  { id: "files", label: "motions.tab.files" },
  { id: "uploads", label: "motions.tab.memory" },
  { id: "run", label: "motions.tab.run" },
  { id: "sounds", label: "motions.tab.sounds" },
];

export const tabId = (tab: MotionsTab) => `motions-tab-${tab}`;
export const panelId = (tab: MotionsTab) => `motions-panel-${tab}`;

export function showMotionsTab(ctx: AppContext, tab: MotionsTab, focus = false): void {
  if (motionFilesOf(ctx.store.get()).tab !== tab) patchMotionFiles(ctx.store, { tab });
  if (focus) focusSoon(tabId(tab));
}

/** "Show scenes and chart" / "Hide scenes and chart" on a file card: one file's scenes are shown at a time. */
export function toggleScenes(ctx: AppContext, id: number): void {
  const files = motionFilesOf(ctx.store.get());
  patchMotionFiles(ctx.store, { selected: files.selected === id ? undefined : id });
}

/** "Preview in 3D" / "Close 3D preview" on a file card: one file's preview is open at a time. */
export function togglePreview(ctx: AppContext, id: number): void {
  const files = motionFilesOf(ctx.store.get());
  patchMotionFiles(ctx.store, { previewed: files.previewed === id ? undefined : id });
}

/** The Run tab's "Show the robot in 3D" / "Hide the robot in 3D" (kept for the connection). */
export function toggleLiveRobot(ctx: AppContext): void {
  patchMotions(ctx.store, (m) => ({ robot3dShown: !m.robot3dShown }));
}

/** A Run button: remembers which one, so that the confirmation, progress and result show beside it. */
export function pressRun(ctx: AppContext, number: number): void {
  patchMotions(ctx.store, { runFrom: number });
  requestRun(ctx, number);
}

/** "Run now" beside a motion on the shelf: to the Run tab, where the run's confirmation, progress and result show. */
export function runNow(ctx: ViewContext): RunNow {
  return {
    busy: robotBusyReason(ctx.state) !== undefined,
    run: (number) => {
      showMotionsTab(ctx, "run");
      pressRun(ctx, number);
    },
  };
}
