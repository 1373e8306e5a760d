import { HUNO_PLATFORM, type Motion, newMotion, TRANSITION_TORQUE } from "../../../../motion/index.ts";
import { RBC_MIN_FRAME_MS } from "../../../../protocol/rbm-validate.ts";
import { zeroPose } from "./trim-model.ts";

/**
 * The zero pose as a one-scene motion, for tethered play (docs/protocol.md §10): played with the robot's own
 * zeros as the file's zeros (zeroDelta 0), its transition frames lead gently from wherever the servos are to
 * the pose (gap/3 frames, 20 ms apart, torque 3: the firmware's own transition), then one frame sends the pose.
 * That is how trim live reaches the zero pose and how Cancel returns to it, with tethered play's checks, Stop
 * and read-back, not a copy of them.
 */
export function zeroPoseMotion(zeros: readonly number[]): Motion {
  const pose = zeroPose(zeros);
  const doc = newMotion({ name: "ZeroPose", zeros });
  const scene = doc.scenes[0]!;
  return {
    ...doc,
    platform: HUNO_PLATFORM,
    scenes: [
      {
        ...scene,
        frames: 1,
        timeMs: RBC_MIN_FRAME_MS,
        servos: scene.servos.map((r) => ({
          ...r,
          start: pose[r.id]!,
          end: pose[r.id]!,
          torque: TRANSITION_TORQUE,
        })),
      },
    ],
  };
}
