/**
 * Mirroring a pose left↔right on a HUNO.
 *
 * [decision] Joint pairs (servo ids, named from the robot's own point of view, docs/protocol.md §4): left leg 0-4
 * ↔ right leg 5-9 (hip roll, hip pitch, knee, ankle pitch, ankle roll), left arm 10-12 ↔ right arm 13-15
 * (shoulder pitch, shoulder roll, elbow). Each pair's servos are mounted as mirror images, so a mirrored joint angle is the same offset from the
 * servo's zero with the sign reversed, for every joint, pitch and roll alike:
 *
 *     mirrored position on servo j = zero[j] − (position on servo i − zero[i])
 *
 * with the zeros of the motion file's own servo records (the zero posture of the robot it was made on,
 * docs/protocol.md §4). Why not `254 − p`: the zero table is not centred on 127 (its pairs sum to 250-252, not 254),
 * so `254 − p` would shift every mirrored joint by 2 to 4 counts; the offset-from-zero rule maps the basic
 * posture onto itself within 2 counts and, checked against Motionbuilder's own left/right pairs of motions
 * (sidewalk, punch, turn), predicts the opposite side within a few counts where `254 − p` is consistently off.
 *
 * A mirror that would put a servo outside 0-254 is refused (nothing changes). A servo whose partner is not in
 * the motion keeps its position. Only positions are mirrored; torques and ports stay with their servo.
 */

import { RBM_MAX_POSITION } from "../protocol/rbm-validate.ts";
import { HUNO_PLATFORM, type Motion, type SceneSide, sceneAt } from "./document.ts";
import { applyPositions } from "./edits.ts";
import { motionError } from "./errors.ts";

/** [left id, right id] for each of the HUNO's 8 joint pairs (the robot's own left and right). */
export const HUNO_MIRROR_PAIRS: readonly (readonly [left: number, right: number])[] = [
  [0, 5],
  [1, 6],
  [2, 7],
  [3, 8],
  [4, 9],
  [10, 13],
  [11, 14],
  [12, 15],
];

/** The mirror partner of a HUNO servo id, or undefined for an id without one. */
export function mirrorPartner(id: number): number | undefined {
  for (const [l, r] of HUNO_MIRROR_PAIRS) {
    if (id === l) return r;
    if (id === r) return l;
  }
  return undefined;
}

/**
 * "swap": each side takes the mirror of the other (the pose of the other hand); "right-to-left": the left side
 * takes the mirror of the right (a symmetric pose), the right side is unchanged; "left-to-right" the reverse.
 */
export type MirrorMode = "swap" | "right-to-left" | "left-to-right";

export interface MirrorOptions {
  mode?: MirrorMode;
  side?: SceneSide;
  detach?: boolean;
}

/** The mirrored position for servo `to` of a position `p` of servo `from`, with the file's zeros. */
export function mirrorPosition(p: number, fromZero: number, toZero: number): number {
  return toZero - (p - fromZero);
}

/** Mirrors scene k's key pose (or its start, with `side: "start"`), keeping continuity as any pose edit does. */
export function mirrorPose(doc: Motion, k: number, options: MirrorOptions = {}): Motion {
  const scene = sceneAt(doc, k);
  if (doc.platform !== HUNO_PLATFORM) {
    throw motionError("motion-mirror", { rule: "mirror-platform", platform: doc.platform });
  }
  const mode = options.mode ?? "swap";
  const side = options.side ?? "end";
  const indexOf = new Map(doc.servos.map((s, i) => [s.id, i]));
  const positions = new Map<number, number>();
  const outside: { id: number; position: number }[] = [];
  for (const [left, right] of HUNO_MIRROR_PAIRS) {
    const ri = indexOf.get(right);
    const li = indexOf.get(left);
    if (ri === undefined || li === undefined) continue;
    const targets: [from: number, to: number][] =
      mode === "swap"
        ? [
            [ri, li],
            [li, ri],
          ]
        : mode === "right-to-left"
          ? [[ri, li]]
          : [[li, ri]];
    for (const [from, to] of targets) {
      const rec = scene.servos[from]!;
      const p = side === "end" ? rec.end : rec.start;
      const value = mirrorPosition(p, doc.servos[from]!.zero, doc.servos[to]!.zero);
      if (value < 0 || value > RBM_MAX_POSITION) outside.push({ id: doc.servos[to]!.id, position: value });
      positions.set(to, value);
    }
  }
  if (outside.length > 0) {
    throw motionError("motion-mirror", { rule: "mirror-outside", scene: k, positions: outside });
  }
  return applyPositions(doc, k, positions, { side, detach: options.detach ?? false });
}
