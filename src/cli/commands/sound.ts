import { RbcCancelledError } from "../../device/errors.ts";
import type { SoundReport } from "../../device/sound.ts";
import { soundOutcomeMessages } from "../../i18n/outcomes/sound-messages.ts";
import { said } from "../../i18n/said.ts";
import { soundName } from "../../i18n/sound-names/sound-name.ts";
import { translator } from "../../i18n/translate.ts";
import { formatSeconds } from "../../i18n/units.ts";
import { SOUND_COUNT, soundLengthMs } from "../../protocol/catalog.ts";
import { intArgument, noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { connectRobot } from "../connect.ts";
import { EXIT } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { commandMessages } from "./messages.ts";

export const soundCommand: CommandDef = {
  name: "sound",
  usage: "rbc sound N (--port PATH | --demo)",
  help: COMMAND_HELP.sound,
  examples: ["rbc sound 3 --demo", "rbc sound 1 --port /dev/ttyUSB0"],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("sound", env.argv, {});
    noExtraArguments("sound", positionals, 1);
    const what = said(commandMessages, "cmd.sound.number");
    const sound = intArgument("sound", what, positionals[0], 1, SOUND_COUNT);
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    const robot = await connectRobot("sound", values, env, { handlesInterrupt: true });
    const started = robot.clock.now();
    // The length as the catalogue gives it (2300 ms), not grouped by thousands.
    // Its name from the catalogue the panel's sound buttons use (src/i18n/sound-names/).
    const name = soundName(sound, locale) ?? "";
    env.out.line(
      t("cmd.sound.playing", { sound: String(sound), name, length: String(soundLengthMs(sound)) }),
    );
    let report: SoundReport;
    try {
      report = await robot.client.playSound(sound, { signal: env.signal });
    } catch (e) {
      if (e instanceof RbcCancelledError && env.signal.aborted) {
        env.out.note(`rbc: ${t("cmd.sound.stoppedWaiting")}`);
        env.out.result({ ok: false, sound, error: { code: "interrupted", message: "Interrupted." } });
        return EXIT.interrupted;
      }
      throw e;
    }
    const elapsedMs = Math.round(robot.clock.now() - started);
    env.out.result({
      ok: true,
      sound,
      name: soundName(sound, "en"),
      lengthMs: soundLengthMs(sound),
      elapsedMs,
      replyAfterMs: Math.round(report.replyAfterMs),
      repliedAtOnce: report.repliedAtOnce,
    });
    if (report.repliedAtOnce) {
      env.out.line(
        translator(soundOutcomeMessages, locale)("outcome.sound.repliedAtOnce", {
          reply: formatSeconds(report.replyAfterMs / 1000, locale),
          length: formatSeconds(report.expectedMs / 1000, locale),
        }),
      );
      return EXIT.ok;
    }
    env.out.line(t("cmd.sound.done", { duration: formatSeconds(elapsedMs / 1000, locale) }));
    return EXIT.ok;
  },
};
