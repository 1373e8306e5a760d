import { said } from "../../../i18n/said.ts";
import { noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice } from "../../error-text.ts";
import { addMotionTexts } from "./files.ts";
import { type MotionsKey, motionsMessages } from "./messages.ts";
import { patchMotionFiles } from "./state.ts";

/**
 * The project's own example motions (examples/*.rbm, safe to try on a held HUNO). Their text is loaded only
 * when one is opened: each file is its own small chunk (Vite's `?raw`), never part of the first page load, and
 * an opened example goes through exactly the same reading and checks as a file the user picked.
 */
export interface ExampleMotion {
  fileName: string;
  /** What the robot does, in a few words. */
  description: MotionsKey;
  load: () => Promise<{ default: string }>;
}

export const EXAMPLE_MOTIONS: readonly ExampleMotion[] = [
  {
    fileName: "wave.rbm",
    description: "motions.example.wave",
    load: () => import("../../../../examples/wave.rbm?raw"),
  },
  {
    fileName: "bow.rbm",
    description: "motions.example.bow",
    load: () => import("../../../../examples/bow.rbm?raw"),
  },
  {
    fileName: "squat.rbm",
    description: "motions.example.squat",
    load: () => import("../../../../examples/squat.rbm?raw"),
  },
  {
    fileName: "long-walk.rbm",
    description: "motions.example.longWalk",
    load: () => import("../../../../examples/long-walk.rbm?raw"),
  },
  {
    fileName: "arms-only.rbm",
    description: "motions.example.armsOnly",
    load: () => import("../../../../examples/arms-only.rbm?raw"),
  },
];

/** Opens an example as if the user had picked its file. */
export async function openExample(ctx: AppContext, example: ExampleMotion): Promise<void> {
  const { locale } = ctx.store.get();
  const file = example.fileName;
  let text: string;
  try {
    text = (await example.load()).default;
  } catch (e) {
    patchMotionFiles(ctx.store, {
      notice: errorNotice(said(motionsMessages, "motions.example.loadFailed", { file }), e, locale),
    });
    return;
  }
  addMotionTexts(ctx.store, [{ fileName: file, text }]);
  // Said in the "Opened files" live region, for screen readers (the file's card appears below).
  patchMotionFiles(ctx.store, {
    notice: noticeOf("info", locale, [said(motionsMessages, "motions.example.opened", { file })]),
  });
}
