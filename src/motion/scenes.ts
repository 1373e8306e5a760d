/**
 * Structural edits: add, duplicate, delete and reorder scenes.
 *
 * [decision] Continuity across structural edits. Ends (the key poses) travel with their scene; starts are
 * re-derived wherever a scene gets a new predecessor: for every servo that was joined to its old predecessor
 * (see edits.ts), the start becomes the new predecessor's end; a servo that jumped keeps its stored start. The
 * motion's first pose (scene 0's start) belongs to the motion, not to scene 0: a scene that becomes first starts
 * from it, so deleting or moving the first scene keeps the motion starting from the same posture. A new scene
 * (added or duplicated) starts where its predecessor ends.
 *
 * Scenes keep their objects when nothing in them changes (only renumbered or re-joined scenes are new), and
 * `raw` texts follow their scene to its new position.
 */
import { checkName, type Motion, type MotionScene, sceneAt } from "./document.ts";
import { motionError } from "./errors.ts";

interface Placed {
  scene: MotionScene;
  /** Position in the document before the edit; undefined for a new scene. */
  from?: number;
}

const FIRST = Symbol("first pose");

function rebuild(doc: Motion, placed: readonly Placed[]): Motion {
  const firstPose = doc.scenes[0]!.servos.map((r) => r.start);
  const scenes: MotionScene[] = [];
  placed.forEach(({ scene, from }, p) => {
    const oldPred = from === undefined ? undefined : from === 0 ? FIRST : doc.scenes[from - 1];
    const newPred = p === 0 ? FIRST : placed[p - 1]!.scene;
    let next = scene;
    if (oldPred !== newPred) {
      const predEnds = p === 0 ? firstPose : scenes[p - 1]!.servos.map((r) => r.end);
      let servos: MotionScene["servos"][number][] | undefined;
      scene.servos.forEach((rec, i) => {
        const joined = oldPred === undefined || oldPred === FIRST || oldPred.servos[i]?.end === rec.start;
        const start = predEnds[i]!;
        if (joined && rec.start !== start) {
          servos ??= scene.servos.slice();
          servos[i] = { ...rec, start };
        }
      });
      if (servos !== undefined) next = { ...next, servos };
    }
    if (next.index !== p) next = { ...next, index: p };
    scenes.push(next);
  });
  const out: Motion = { ...doc, scenes, sceneCount: scenes.length };
  const raw = doc.raw;
  if (raw === undefined) return out;
  const fields: Record<string, string> = {};
  for (const [key, text] of Object.entries(raw.fields)) if (!/^c\d+\./.test(key)) fields[key] = text;
  placed.forEach(({ from }, p) => {
    if (from === undefined) return;
    const prefix = `c${from}.`;
    for (const [key, text] of Object.entries(raw.fields)) {
      if (key.startsWith(prefix)) fields[`c${p}.${key.slice(prefix.length)}`] = text;
    }
  });
  return { ...out, raw: { fields, trailing: raw.trailing } };
}

function existing(doc: Motion): Placed[] {
  return doc.scenes.map((scene, from) => ({ scene, from }));
}

export interface AddSceneOptions {
  /** Name of the new scene; "Scene_<position>" by default. */
  name?: string;
}

/**
 * Inserts a new scene at position `at` (0..S; the end by default) that holds the pose it starts from (the
 * previous scene's end, or the motion's first pose at position 0), with the neighbouring scene's frames, time,
 * torques and ports. The user then poses it.
 */
export function addScene(doc: Motion, at: number = doc.scenes.length, options: AddSceneOptions = {}): Motion {
  if (!Number.isInteger(at) || at < 0 || at > doc.scenes.length) {
    throw motionError("motion-no-such-scene", {
      rule: "new-scene-position",
      value: typeof at === "number" ? at : String(at),
      max: doc.scenes.length,
    });
  }
  const name = options.name ?? `Scene_${at}`;
  checkName(name, { field: "newSceneName" });
  const model = doc.scenes[Math.max(0, at - 1)]!;
  const pose = at === 0 ? doc.scenes[0]!.servos.map((r) => r.start) : model.servos.map((r) => r.end);
  const scene: MotionScene = {
    index: at,
    name,
    frames: model.frames,
    timeMs: model.timeMs,
    servos: model.servos.map((r, i) => ({ ...r, start: pose[i]!, end: pose[i]! })),
  };
  const placed = existing(doc);
  placed.splice(at, 0, { scene });
  return rebuild(doc, placed);
}

/**
 * Inserts a copy of scene k right after it. The copy reaches the same key pose with the same timing, torques,
 * ports and name; it starts where scene k ends (continuity), so it holds that pose.
 */
export function duplicateScene(doc: Motion, k: number): Motion {
  const scene = sceneAt(doc, k);
  const placed = existing(doc);
  placed.splice(k + 1, 0, { scene });
  return rebuild(doc, placed);
}

/** Deletes scene k; the scene after it starts where the one before it ends. A motion keeps at least one scene. */
export function deleteScene(doc: Motion, k: number): Motion {
  sceneAt(doc, k);
  if (doc.scenes.length === 1) {
    throw motionError("motion-last-scene", { scene: k });
  }
  const placed = existing(doc);
  placed.splice(k, 1);
  return rebuild(doc, placed);
}

/** Moves scene `from` so that it ends up at position `to` (both 0..S−1). */
export function moveScene(doc: Motion, from: number, to: number): Motion {
  sceneAt(doc, from);
  sceneAt(doc, to);
  if (from === to) return doc;
  const placed = existing(doc);
  const [moved] = placed.splice(from, 1);
  placed.splice(to, 0, moved!);
  return rebuild(doc, placed);
}
