import { RbcCancelledError } from "../../device/errors.ts";
import { SOUND_COUNT, soundLengthMs } from "../../protocol/catalog.ts";
import { intArgument, noExtraArguments, parseCommand } from "../args.ts";
import type { CommandDef } from "../command.ts";
import { connectRobot } from "../connect.ts";
import { EXIT } from "../errors.ts";

export const soundCommand: CommandDef = {
  name: "sound",
  summary: "play one of the robot's 25 built-in sounds",
  usage: "rbc sound N (--port PATH | --demo)",
  description: `
Plays built-in sound N (1-25) and waits until the robot reports it finished (200 ms plus the sound's
length, 0.3 to 5.9 s). The RBC handles nothing else while a sound plays. Ctrl-C stops waiting (exit 130).`,
  options: [],
  examples: ["rbc sound 3 --demo", "rbc sound 1 --port /dev/ttyUSB0"],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("sound", env.argv, {});
    noExtraArguments("sound", positionals, 1);
    const sound = intArgument("sound", "The sound number", positionals[0], 1, SOUND_COUNT);
    const robot = await connectRobot("sound", values, env, { handlesInterrupt: true });
    const started = robot.clock.now();
    env.out.line(`Playing sound ${sound} (${soundLengthMs(sound)} ms)…`);
    try {
      await robot.client.runSound(sound, { signal: env.signal });
    } catch (e) {
      if (e instanceof RbcCancelledError && env.signal.aborted) {
        env.out.note(
          "rbc: stopped waiting; the robot plays the sound to the end. Wait until it ends before the next rbc command (the robot answers nothing while it plays).",
        );
        env.out.result({ ok: false, sound, error: { code: "interrupted", message: "Interrupted." } });
        return EXIT.interrupted;
      }
      throw e;
    }
    const elapsedMs = Math.round(robot.clock.now() - started);
    env.out.result({ ok: true, sound, lengthMs: soundLengthMs(sound), elapsedMs });
    env.out.line(`Done in ${(elapsedMs / 1000).toFixed(1)} s.`);
    return EXIT.ok;
  },
};
