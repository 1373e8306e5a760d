/**
 * Tethered play's pure part: which scenes the panel plays, what it asks before the robot moves, how progress
 * reads, and the one sentence of what the robot confirmed at the end.
 */
import type { Motion } from "../../../motion/index.ts";
import { frameIntervalMs } from "../../../motion/index.ts";
import type { Notice } from "../../app-state.ts";
import type { PlayChoice, PlayProgress } from "./live-state.ts";
import { sceneNumber } from "./live-state.ts";

/** The scenes to play (positions in the motion, inclusive), each end kept inside the motion. */
export function playRange(
  doc: Motion,
  choice: PlayChoice,
  selected: number,
  rangeFrom: number,
  rangeTo: number,
): { from: number; to: number } {
  const last = doc.scenes.length - 1;
  const clamp = (k: number): number => Math.max(0, Math.min(last, Math.trunc(k)));
  if (choice === "all") return { from: 0, to: last };
  if (choice === "scene") return { from: clamp(selected), to: clamp(selected) };
  const a = clamp(rangeFrom);
  const b = clamp(rangeTo);
  return { from: Math.min(a, b), to: Math.max(a, b) };
}

/**
 * The frames and duration of scenes from..to as the RBC plays them (PROTOCOL.md §10: `frames` frames
 * `floor(timeMs / frames)` ms apart). Throws the motion core's `MotionError` for a scene whose frames are under
 * 20 ms apart (the RBC's error 6): then nothing may move. The move to the first pose, when the robot is not
 * there, comes on top.
 */
export function playSpan(doc: Motion, from: number, to: number): { frames: number; durationMs: number } {
  let frames = 0;
  let durationMs = 0;
  for (let k = from; k <= to; k++) {
    const scene = doc.scenes[k]!;
    const interval = frameIntervalMs(scene.frames, scene.timeMs, sceneNumber(k));
    frames += scene.frames;
    durationMs += scene.frames * interval;
  }
  return { frames, durationMs };
}

/** "scene 2" or "scenes 1–3", numbered for people. */
export function scenesText(from: number, to: number): string {
  return from === to ? `scene ${sceneNumber(from)}` : `scenes ${sceneNumber(from)}–${sceneNumber(to)}`;
}

/** Seconds with one decimal: "1.5 s". */
export function secondsText(ms: number): string {
  return `${(ms / 1000).toFixed(1)} s`;
}

/** The one question before the robot moves. */
export function playQuestion(from: number, to: number, durationMs: number): string {
  return `The robot will move through ${scenesText(from, to)} (${secondsText(durationMs)}). Hold it or make sure it can stand.`;
}

/** Where play is, for the progress line: "Scene 2 of 3 (scene 2), frame 4 of 10". */
export function progressText(
  progress: PlayProgress | undefined,
  from: number,
  to: number,
  framesOf: (k: number) => number,
): string {
  if (!progress) return "Starting: entering servo control and reading where the servos are…";
  if (progress.scene < 0) return `Moving to the first pose: step ${progress.frame}`;
  const k = progress.scene - from + 1;
  const n = to - from + 1;
  const frames = framesOf(progress.scene);
  return n === 1
    ? `Scene ${sceneNumber(progress.scene)}, frame ${progress.frame} of ${frames}`
    : `Scene ${k} of ${n} (scene ${sceneNumber(progress.scene)}), frame ${progress.frame} of ${frames}`;
}

/** What tethered play returned (the device layer's `TetheredPlayResult`, the fields the sentence needs). */
export interface PlayOutcome {
  outcome: "finished" | "stopped";
  framesSent: number;
  durationMs: number;
  /** The last frame sent: its scene (-1 for the move to the first pose) and its number there. */
  lastFrame?: { scene: number; frame: number };
  /** Finished only: the servos read after the last frame. */
  readBack?: { silent: readonly number[] };
}

/** Where play got to: "scene 2, frame 4", "the move to the first pose (step 3)". */
export function whereText(frame: { scene: number; frame: number }): string {
  return frame.scene < 0
    ? `the move to the first pose (step ${frame.frame})`
    : `scene ${sceneNumber(frame.scene)}, frame ${frame.frame}`;
}

/** The one sentence of what the robot did, no more certain than it confirmed. */
export function playResultNotice(result: PlayOutcome, from: number, to: number): Notice {
  if (result.outcome === "finished") {
    const silent = result.readBack?.silent ?? [];
    const text = `Played ${scenesText(from, to)} (${result.framesSent} frames, ${secondsText(result.durationMs)}); the servos hold the last frame.`;
    return silent.length === 0
      ? { tone: "ok", text }
      : {
          tone: "warning",
          text: `${text} Servo ${silent.join(", ")} did not answer the read afterwards: check ${silent.length === 1 ? "its cable" : "their cables"}.`,
        };
  }
  if (result.framesSent === 0 || !result.lastFrame) {
    return { tone: "info", text: "Stopped before the first frame: nothing moved." };
  }
  return { tone: "info", text: `Stopped at ${whereText(result.lastFrame)}; the servos hold that pose.` };
}

/** What the servos hold after a failed play (the device layer's `TetheredPlayError.holds`). */
export type PlayHolds = "nothing-sent" | "last-frame" | "unknown";

/** Play failed: how far it got and the state the robot is in (the error's own message follows). */
export function playFailureText(
  holds: PlayHolds,
  last: { scene: number; frame: number } | undefined,
  direct: boolean,
): string {
  const mode = direct ? "in servo control (direct mode)" : "in its normal mode";
  switch (holds) {
    case "nothing-sent":
      return `Tethered play did not start: nothing moved; the robot is ${mode}.`;
    case "last-frame":
      return `Tethered play failed${last ? ` after ${whereText(last)}` : ""}: the robot is ${mode} and its servos hold the last frame sent.`;
    case "unknown":
      return `Tethered play failed${last ? ` after ${whereText(last)}` : ""}: whether the robot got the last frame is not known. Hold it.`;
  }
}
