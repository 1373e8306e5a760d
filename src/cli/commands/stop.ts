import { RbcError } from "../../device/errors.ts";
import type { StopActivityResult } from "../../device/rbc-client.ts";
import { BASIC_POSTURE_MOTION } from "../../protocol/catalog.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import type { CommandDef } from "../command.ts";
import { connectRobot } from "../connect.ts";
import { CliError, EXIT } from "../errors.ts";

/**
 * What Stop did to a motion, in one sentence, never more certain than the robot's reply (used by `rbc run` on
 * Ctrl-C). Undefined when no motion was playing.
 */
export function stoppedMotionSentence(result: StopActivityResult | undefined, name: string): string {
  switch (result?.motion?.outcome) {
    case "stopped":
      return `sent 7: motion ${name} stopped at the end of its scene (the robot confirmed with 07). The robot keeps standing in that pose; \`rbc run 7\` straightens it.`;
    case "ended-then-posture":
      return `motion ${name} had just ended; the robot took the 7 as Basic posture and confirmed it (07).`;
    case "posture":
      return "Basic posture (7) cannot be interrupted; it finished (the robot confirmed with 07).";
    case "unconfirmed":
      return `sent 7 to stop motion ${name}, but the robot did not confirm. If it still moves, hold it (\`rbc limp\` makes every servo passive).`;
    default:
      return `motion ${name} was no longer playing; nothing was sent.`;
  }
}

export const stopCommand: CommandDef = {
  name: "stop",
  summary: "end a running motion with 7; the robot keeps standing",
  usage: "rbc stop (--port PATH | --demo)",
  description: `
Sends 7, the one request the RBC takes while a motion plays: the motion stops at the end of its current
scene and the robot answers once, 07, holding the pose it stopped in. rbc says whether that answer came.
No servo is made passive (that is \`rbc limp\`).

rbc cannot tell whether another program's motion is playing. With nothing playing, the robot takes the 7
as Basic posture and stands up straight (it answers 07 when that is done, after about 1.8 s).
While a sound plays the robot receives nothing, so a new rbc cannot connect until the sound ends.

Ctrl-C during \`rbc run\` does the same to the motion that rbc started.`,
  options: [],
  examples: ["rbc stop --port /dev/ttyUSB0", "rbc stop --demo --json"],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("stop", env.argv, {});
    noExtraArguments("stop", positionals, 0);
    const robot = await connectRobot("stop", values, env);
    const started = robot.clock.now();
    env.out.line(`Sending 7 to ${robot.where}…`);
    try {
      await robot.client.stopMotion();
    } catch (e) {
      if (e instanceof RbcError && (e.code === "timeout" || e.code === "motion-ignored")) {
        throw new CliError(
          "not-confirmed",
          "Sent 7, but the robot did not confirm with 07. If it still moves, hold it (`rbc limp` makes every servo passive).",
          EXIT.failed,
          { sent: BASIC_POSTURE_MOTION, confirmed: false },
        );
      }
      throw e;
    }
    const elapsedMs = Math.round(robot.clock.now() - started);
    env.out.line(
      `The robot confirmed with 07 after ${(elapsedMs / 1000).toFixed(1)} s: a motion that was playing stopped at the end of its scene and the robot holds that pose; with nothing playing, it went to Basic posture. No servo was made passive.`,
    );
    env.out.result({ ok: true, sent: BASIC_POSTURE_MOTION, confirmed: true, elapsedMs });
    return EXIT.ok;
  },
};
