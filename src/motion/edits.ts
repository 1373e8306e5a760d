/**
 * Edits of one scene's fields: names, timing, positions, torque and port, and copying a pose.
 *
 * [decision] "Validated as you type": an edit whose value breaks a rule the RBC enforces (an error of
 * `validateRbm`: a position outside 0-254, a torque above 4, a port above 3, no frames, frames closer than 20 ms
 * or further apart than 4,550 ms, a name an .rbm file cannot hold) is refused with a `MotionError` and changes
 * nothing. An edit that only earns a warning (a position outside the servo's safe range, a jump between scenes,
 * more than 100 frames or 10,000 ms) is applied, and `motionIssues` reports it, as it does for a file.
 *
 * [decision] Continuity: a scene starts where the previous one ended unless the user says otherwise. Servo i is
 * *joined* across the boundary of scenes k−1 and k when scene k−1's end equals scene k's start. Changing a
 * position on one side of a joined boundary moves the other side with it, so a joined motion stays joined;
 * `{ detach: true }` changes only the side named (the user says otherwise, the validator then warns of the
 * jump). A boundary that is already a jump (as in some Motionbuilder files) is left alone; `joinScene` closes it.
 * Edits that change nothing return the same document (so the history can skip them).
 */
import {
  RBC_MAX_FRAME_MS,
  RBC_MIN_FRAME_MS,
  RBM_MAX_PORT,
  RBM_MAX_POSITION,
  RBM_MAX_TORQUE,
} from "../protocol/rbm-validate.ts";
import {
  checkName,
  checkWhole,
  type Motion,
  type MotionScene,
  poseOf,
  type SceneRecord,
  type SceneSide,
  sceneAt,
  servoIndex,
  withScenes,
} from "./document.ts";
import { type MotionSubject, motionError } from "./errors.ts";

/** Largest frames or time a motion image holds (16 bits, docs/protocol.md §6.3). */
export const MAX_U16 = 0xffff;

export interface PositionOptions {
  /** The side of the scene to change: its key pose ("end", the default) or the pose it starts from. */
  side?: SceneSide;
  /** Change only this side, even where it is joined to the neighbouring scene (leaves a jump). */
  detach?: boolean;
}

export function setMotionName(doc: Motion, name: string): Motion {
  checkName(name, { field: "motionName" });
  return name === doc.name ? doc : { ...doc, name };
}

export function setSceneName(doc: Motion, k: number, name: string): Motion {
  const scene = sceneAt(doc, k);
  checkName(name, { field: "sceneName", scene: k });
  return name === scene.name ? doc : withScenes(doc, new Map([[k, { ...scene, name }]]));
}

/** The scene's frames and time as subjects of a refusal; a program's own name for the scene ("Scene 3") as well. */
function timingSubjects(scene: number | string): [frames: MotionSubject, time: MotionSubject] {
  return typeof scene === "number"
    ? [
        { field: "frames", scene },
        { field: "time", scene },
      ]
    : [
        { field: "named", name: `${scene}: the number of frames` },
        { field: "named", name: `${scene}: the time in ms` },
      ];
}

/**
 * Throws `motion-frame-interval` unless frames and time give an interval the RBC plays (20..4,550 ms). `scene`
 * is the scene's position (or a program's own name for it, said as it is).
 */
export function checkTiming(frames: number, timeMs: number, scene: number | string): void {
  const [framesSubject, timeSubject] = timingSubjects(scene);
  checkWhole(frames, 1, MAX_U16, framesSubject);
  checkWhole(timeMs, 0, MAX_U16, timeSubject);
  const at = typeof scene === "number" ? { scene } : {};
  const timing = { ...at, frames, timeMs, intervalMs: timeMs / frames };
  if (timeMs < RBC_MIN_FRAME_MS * frames) {
    throw motionError("motion-frame-interval", { rule: "interval-short", ...timing, min: RBC_MIN_FRAME_MS });
  }
  if (timeMs > RBC_MAX_FRAME_MS * frames) {
    throw motionError("motion-frame-interval", { rule: "interval-long", ...timing, max: RBC_MAX_FRAME_MS });
  }
}

/** Sets a scene's frames and/or time together (so that a change of both is checked as one). */
export function setTiming(doc: Motion, k: number, timing: { frames?: number; timeMs?: number }): Motion {
  const scene = sceneAt(doc, k);
  const frames = timing.frames ?? scene.frames;
  const timeMs = timing.timeMs ?? scene.timeMs;
  checkTiming(frames, timeMs, k);
  if (frames === scene.frames && timeMs === scene.timeMs) return doc;
  return withScenes(doc, new Map([[k, { ...scene, frames, timeMs }]]));
}

/** Replaces some records of a scene (by record position); returns the scene itself when nothing changed. */
function patchRecords(scene: MotionScene, patches: ReadonlyMap<number, Partial<SceneRecord>>): MotionScene {
  let servos: SceneRecord[] | undefined;
  for (const [i, patch] of patches) {
    const rec = scene.servos[i]!;
    const changed = (Object.keys(patch) as (keyof SceneRecord)[]).some((key) => patch[key] !== rec[key]);
    if (!changed) continue;
    servos ??= scene.servos.slice();
    servos[i] = { ...rec, ...patch };
  }
  return servos === undefined ? scene : { ...scene, servos };
}

/**
 * Sets positions of one side of scene k (by record position), keeping joined neighbours joined unless
 * `detach`. The shared core of every pose edit.
 */
export function applyPositions(
  doc: Motion,
  k: number,
  positions: ReadonlyMap<number, number>,
  options: PositionOptions = {},
): Motion {
  const scene = sceneAt(doc, k);
  const side = options.side ?? "end";
  const here = new Map<number, Partial<SceneRecord>>();
  const there = new Map<number, Partial<SceneRecord>>();
  const neighbourIndex = side === "end" ? k + 1 : k - 1;
  const neighbour = doc.scenes[neighbourIndex];
  for (const [i, value] of positions) {
    const rec = scene.servos[i]!;
    checkWhole(value, 0, RBM_MAX_POSITION, { field: side, scene: k, servo: rec.id });
    const old = side === "end" ? rec.end : rec.start;
    here.set(i, side === "end" ? { end: value } : { start: value });
    const other = neighbour?.servos[i];
    if (options.detach !== true && other !== undefined) {
      if (side === "end" && other.start === old) there.set(i, { start: value });
      if (side === "start" && other.end === old) there.set(i, { end: value });
    }
  }
  const changes = new Map<number, MotionScene>();
  const a = patchRecords(scene, here);
  if (a !== scene) changes.set(k, a);
  if (neighbour !== undefined) {
    const b = patchRecords(neighbour, there);
    if (b !== neighbour) changes.set(neighbourIndex, b);
  }
  return withScenes(doc, changes);
}

/** Sets one servo's position (by servo id) in scene k. */
export function setPosition(
  doc: Motion,
  k: number,
  id: number,
  value: number,
  options: PositionOptions = {},
): Motion {
  sceneAt(doc, k);
  return applyPositions(doc, k, new Map([[servoIndex(doc, id), value]]), options);
}

/**
 * Sets several servos' positions (by servo id) in scene k: teach-in reads the robot's pose into a scene, paste
 * puts a copied one back. Servos not in the map keep their positions; every id must be in the motion.
 */
export function setPose(
  doc: Motion,
  k: number,
  pose: ReadonlyMap<number, number>,
  options: PositionOptions = {},
): Motion {
  sceneAt(doc, k);
  const byIndex = new Map<number, number>();
  for (const [id, value] of pose) byIndex.set(servoIndex(doc, id), value);
  return applyPositions(doc, k, byIndex, options);
}

/** Copies scene `from`'s key pose (its end) into scene `to`'s key pose, keeping continuity. */
export function copyPose(doc: Motion, from: number, to: number, options: PositionOptions = {}): Motion {
  sceneAt(doc, to);
  return setPose(doc, to, poseOf(doc, from, "end"), options);
}

/** Makes scene k start where scene k−1 ends, for every servo (closes jumps). */
export function joinScene(doc: Motion, k: number): Motion {
  const scene = sceneAt(doc, k);
  if (k === 0) throw motionError("motion-no-such-scene", { rule: "join-first", scene: 0 });
  const previous = doc.scenes[k - 1]!;
  const patches = new Map(previous.servos.map((r, i) => [i, { start: r.end }]));
  const joined = patchRecords(scene, patches);
  return joined === scene ? doc : withScenes(doc, new Map([[k, joined]]));
}

/** Sets one servo's torque (0 strongest .. 4 weakest) in scene k. */
export function setTorque(doc: Motion, k: number, id: number, torque: number): Motion {
  const scene = sceneAt(doc, k);
  const i = servoIndex(doc, id);
  checkWhole(torque, 0, RBM_MAX_TORQUE, { field: "torque", scene: k, servo: id });
  const next = patchRecords(scene, new Map([[i, { torque }]]));
  return next === scene ? doc : withScenes(doc, new Map([[k, next]]));
}

/** Sets the torque of every servo in scene k. */
export function setSceneTorque(doc: Motion, k: number, torque: number): Motion {
  const scene = sceneAt(doc, k);
  checkWhole(torque, 0, RBM_MAX_TORQUE, { field: "sceneTorque", scene: k });
  const next = patchRecords(scene, new Map(scene.servos.map((_, i) => [i, { torque }])));
  return next === scene ? doc : withScenes(doc, new Map([[k, next]]));
}

/** Sets one servo's port value (0-3, written to the servo's two I/O outputs as the scene starts) in scene k. */
export function setPort(doc: Motion, k: number, id: number, port: number): Motion {
  const scene = sceneAt(doc, k);
  const i = servoIndex(doc, id);
  checkWhole(port, 0, RBM_MAX_PORT, { field: "port", scene: k, servo: id });
  const next = patchRecords(scene, new Map([[i, { port }]]));
  return next === scene ? doc : withScenes(doc, new Map([[k, next]]));
}
