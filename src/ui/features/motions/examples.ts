import type { AppContext } from "../../context.ts";
import { errorNotice } from "../../error-text.ts";
import { addMotionTexts } from "./files.ts";
import { patchMotionFiles } from "./state.ts";

/**
 * The project's own example motions (examples/*.rbm, safe to try on a held HUNO). Their text is loaded only
 * when one is opened: each file is its own small chunk (Vite's `?raw`), never part of the first page load, and
 * an opened example goes through exactly the same reading and checks as a file the user picked.
 */
export interface ExampleMotion {
  fileName: string;
  /** What the robot does, in a few words. */
  description: string;
  load: () => Promise<{ default: string }>;
}

export const EXAMPLE_MOTIONS: readonly ExampleMotion[] = [
  {
    fileName: "wave.rbm",
    description: "raises its right arm, waves twice, lowers it",
    load: () => import("../../../../examples/wave.rbm?raw"),
  },
  {
    fileName: "bow.rbm",
    description: "bows from the hips and straightens up",
    load: () => import("../../../../examples/bow.rbm?raw"),
  },
  {
    fileName: "squat.rbm",
    description: "holds its arms out in front and squats twice",
    load: () => import("../../../../examples/squat.rbm?raw"),
  },
  {
    fileName: "long-walk.rbm",
    description: "walks 14 small strides; fills the whole motion memory",
    load: () => import("../../../../examples/long-walk.rbm?raw"),
  },
  {
    fileName: "arms-only.rbm",
    description: "moves only the arms (6 servos)",
    load: () => import("../../../../examples/arms-only.rbm?raw"),
  },
];

/** Opens an example as if the user had picked its file. */
export async function openExample(ctx: AppContext, example: ExampleMotion): Promise<void> {
  let text: string;
  try {
    text = (await example.load()).default;
  } catch (e) {
    patchMotionFiles(ctx.store, {
      notice: errorNotice(
        `The example ${example.fileName} could not be loaded (offline before the first visit?).`,
        e,
      ),
    });
    return;
  }
  addMotionTexts(ctx.store, [{ fileName: example.fileName, text }]);
  // Said in the "Opened files" live region, for screen readers (the file's card appears below).
  patchMotionFiles(ctx.store, { notice: { tone: "info", text: `Opened the example ${example.fileName}.` } });
}
