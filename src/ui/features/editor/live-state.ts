/**
 * The editor's live part, one per connection (the session resets it to undefined, which `liveOf` reads as the
 * initial value): teach-in (servos made passive, posed by hand, read into a scene, held) and tethered play (a
 * scene, a range or the whole motion played frame by frame in direct mode, docs/protocol.md §10), and the
 * document last uploaded from the Editor (docs/protocol.md §6).
 */
import type { Motion } from "../../../motion/index.ts";
import type { Notice } from "../../notices.ts";
import type { Store } from "../../store.ts";
import type { ConnectionState } from "../connection/index.ts";
import type { BookEntry } from "../motions/index.ts";

/** The HUNO's limbs, by which teach-in chooses the servos to make passive. */
export type Limb = "right-leg" | "left-leg" | "right-arm" | "left-arm";

export interface TeachInState {
  /**
   * `asking`: "Start teach-in" was pressed and the panel asks to hold the robot. `starting`: reading the zeros
   * and entering direct mode. `on`: in direct mode (while the connection says so). `ending`: holding, then
   * leaving direct mode.
   */
  phase: "off" | "asking" | "starting" | "on" | "ending";
  /** The limbs chosen to go limp. */
  limbs: readonly Limb[];
  /** "Make limp" with every servo chosen: the panel asks again, the robot cannot stand. */
  confirmingAll: boolean;
  /** Servos that confirmed the passive command (the robot answered), by id, ascending. */
  passive: readonly number[];
  /** The robot's positions by id 0-15: from the demo robot's servos as they move, or from the last read. */
  positions: readonly (number | undefined)[];
  /** Servos that did not answer the last read or command. */
  silent: readonly number[];
  /** The robot's stored zero table, read as teach-in started (to convert read positions to the motion's zeros). */
  robotZeros?: readonly number[];
  busy?: "limp" | "reading" | "holding";
  notice?: Notice;
}

/** What the play panel plays: the selected scene, a range of scenes, or the whole motion. */
export type PlayChoice = "scene" | "range" | "all";

/** The last frame tethered play reported (`onFrame`). */
export interface PlayProgress {
  /** Frame number in the whole play (1-based) and the number of frames. */
  index: number;
  total: number;
  /** The scene of the frame (its position in the motion), -1 while moving to the first pose. */
  scene: number;
  /** The frame's number within its scene (1..frames) or within the move to the first pose. */
  frame: number;
  /** Positions sent, by servo id (undefined for a servo the motion does not list). */
  positions: readonly (number | undefined)[];
  elapsedMs: number;
  durationMs: number;
}

export interface PlayRun {
  /** The scenes played, inclusive (positions in the motion). */
  from: number;
  to: number;
  progress?: PlayProgress;
}

export interface PlayState {
  choice: PlayChoice;
  /** The range's ends as the user set them (scene positions; clamped to the motion when used). */
  rangeFrom: number;
  rangeTo: number;
  /** The play the panel asks about: scenes, frames and duration, before anything moves. */
  confirming?: { from: number; to: number; frames: number; durationMs: number };
  running?: PlayRun;
  notice?: Notice;
}

/**
 * The Editor's document as the robot stored it in this connection ("Upload to robot" in the Play tab): the
 * document sent and the slot the Motions upload path recorded for it (its Run number follows from the slot).
 */
export interface RobotCopy {
  /** The document uploaded (documents are values: an edit after the upload makes a new one). */
  doc: Motion;
  /** Its download slot, as the Motions view's slot book recorded it. */
  entry: BookEntry;
}

export interface EditorLiveState {
  teach: TeachInState;
  play: PlayState;
  /** The last upload from the Editor that the robot stored, in this connection. */
  robotCopy?: RobotCopy;
  /** The motion number last run from the Editor, so that its question, progress and result show there. */
  runFrom?: number;
  /**
   * Which of the Editor's Run buttons it was, so that they show right under it: "Run now" under the upload's
   * result (`result`), Basic posture's (`posture`), or "Run on robot" (`card`, the default).
   */
  runAt?: EditorRunPlace;
}

/** Where in the Editor's "Store on the robot" card a Run was pressed (`EditorLiveState.runAt`). */
export type EditorRunPlace = "result" | "posture" | "card";

/** Servo ids 0-15, by id. */
export const LIVE_SERVO_COUNT = 16;

export function initialTeachIn(): TeachInState {
  return {
    phase: "off",
    limbs: [],
    confirmingAll: false,
    passive: [],
    positions: Array.from({ length: LIVE_SERVO_COUNT }, () => undefined),
    silent: [],
  };
}

export function initialPlay(): PlayState {
  return { choice: "scene", rangeFrom: 0, rangeTo: 0 };
}

export function initialEditorLive(): EditorLiveState {
  return { teach: initialTeachIn(), play: initialPlay() };
}

/** The part of the app state this feature owns (src/ui/app-state.ts composes the parts). */
export interface EditorLiveSlice {
  editorLive?: EditorLiveState;
}

/** The live part and the connection it lives on: what tells whether teach-in is on. */
export interface EditorLiveOnConnection extends EditorLiveSlice {
  connection: ConnectionState;
}

export function liveOf(state: EditorLiveSlice): EditorLiveState {
  return state.editorLive ?? initialEditorLive();
}

export function patchTeachIn(
  store: Store<EditorLiveSlice>,
  p: Partial<TeachInState> | ((x: TeachInState) => Partial<TeachInState>),
): void {
  store.update((s) => {
    const cur = liveOf(s);
    return {
      editorLive: { ...cur, teach: { ...cur.teach, ...(typeof p === "function" ? p(cur.teach) : p) } },
    };
  });
}

export function patchPlay(
  store: Store<EditorLiveSlice>,
  p: Partial<PlayState> | ((x: PlayState) => Partial<PlayState>),
): void {
  store.update((s) => {
    const cur = liveOf(s);
    return { editorLive: { ...cur, play: { ...cur.play, ...(typeof p === "function" ? p(cur.play) : p) } } };
  });
}

/**
 * Teach-in is on while its phase says so and the robot is still in direct mode (leaving servo control in the
 * Servos view, running a motion or a lost link end it with the mode).
 */
export function teachInOn(state: EditorLiveOnConnection): boolean {
  const phase = liveOf(state).teach.phase;
  return (
    state.connection.phase === "connected" &&
    state.connection.mode === "direct" &&
    (phase === "on" || phase === "ending")
  );
}

/**
 * The number people read for a scene: its position in the motion, from 0, as the editor's scene list, the
 * motion core's messages, the device layer's and Motionbuilder's names (`Scene_0`) number it.
 */
export function sceneNumber(scene: number): number {
  return scene;
}

/**
 * The pose the editor's 3D view should show instead of the selected scene's: the frame last sent during
 * tethered play; the live robot during teach-in (the demo robot's servos as they move, or the positions last
 * read from hardware); undefined to show the scene. 16 positions by servo id, as the robot holds them (the
 * robot's own zeros, not converted to the motion's).
 */
export function livePoseOf(state: EditorLiveOnConnection): readonly (number | undefined)[] | undefined {
  if (state.connection.phase !== "connected") return undefined;
  const live = state.editorLive;
  if (!live) return undefined;
  const frame = live.play.running?.progress;
  if (frame) return frame.positions;
  if (teachInOn(state) && live.teach.positions.some((p) => p !== undefined)) return live.teach.positions;
  return undefined;
}
