import { RbcTimeoutError } from "../../device/errors.ts";
import { platformWarning } from "../../i18n/outcomes/plausibility.ts";
import { robotFactText } from "../../i18n/outcomes/robot-facts.ts";
import { busyNowText } from "../../i18n/outcomes/stop-words.ts";
import { translator } from "../../i18n/translate.ts";
import { ACTION_AREA_BYTES, MOTION_AREA_BYTES, platformName } from "../../protocol/catalog.ts";
import { formatFirmware } from "../../shared/format.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { connectRobot } from "../connect.ts";
import { EXIT } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { displayWidth } from "../help/render.ts";
import { errorCodeWords, platformWords } from "../robot-words.ts";
import { commandMessages } from "./messages.ts";

export { errorCodeWords };

/** "  Firmware       2.23": labels padded to one column (Hangul counts two), values after them. */
function labelledRows(rows: ReadonlyArray<readonly [string, string]>): string[] {
  const width = Math.max(13, ...rows.map(([label]) => displayWidth(label)));
  return rows.map(([label, value]) => `  ${label}${" ".repeat(width - displayWidth(label) + 2)}${value}`);
}

export const infoCommand: CommandDef = {
  name: "info",
  usage: "rbc info (--port PATH | --demo) [--json]",
  help: COMMAND_HELP.info,
  examples: ["rbc info --port /dev/ttyUSB0", "rbc info --demo --json"],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("info", env.argv, {});
    noExtraArguments("info", positionals, 0);
    const robot = await connectRobot("info", values, env);
    const { client } = robot;
    // 0x0C is optional: some firmware builds never answer it (docs/protocol.md §3.5).
    const { serialNumber } = await client.identify();
    const errorCode = await client.readErrorCode();
    // 0x0F is not answered by every firmware either (docs/protocol.md §3.5): "not reported".
    const freeMotion = await client.readFreeMemory("motion");
    const freeAction = freeMotion === undefined ? undefined : await client.readFreeMemory("action");
    // Busy, not gone (docs/protocol.md §3.6): the busy probe, last, since its 0x16 waits out a playing motion.
    // Undefined when neither it nor the firmware version was answered.
    const busy = await client.probeBusy().then(
      (r) => r === "busy",
      (e: unknown) => {
        if (e instanceof RbcTimeoutError) return undefined;
        throw e;
      },
    );
    const platform = client.state.platform ?? robot.identity.platform;
    const firmware = formatFirmware(robot.identity.firmware);
    env.out.result({
      port: robot.demo ? "demo" : robot.where,
      firmware,
      firmwareVersion: robot.identity.firmware,
      serialNumber: serialNumber ?? null,
      platform,
      platformName: platformName(platform),
      errorCode,
      error: errorCodeWords(errorCode),
      freeMemory: freeMotion === undefined ? null : { motion: freeMotion, action: freeAction ?? null },
      // The identity's warnings (an unknown platform) in the catalogue's English, the sentences scripts read.
      warnings: [platformWarning(platform)].filter((w) => w !== undefined),
      busy: busy ?? null,
      // Replies no request asked for (late, or repeated by a firmware that repeats them), discarded so far.
      unaskedReplies: client.stats.unansweredReplies,
    });
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    env.out.line(robot.demo ? t("cmd.info.demoRobot") : t("cmd.info.robotOn", { port: robot.where }));
    const known = !platformName(platform).startsWith("unknown");
    const rows: Array<readonly [string, string]> = [
      [t("cmd.info.firmware"), firmware],
      [robotFactText("serialNumber", locale), serialNumber ?? t("cmd.info.serialNotReported")],
      [
        t("cmd.info.platform"),
        known ? `${platformName(platform)} (${platform})` : platformWords(platform, locale),
      ],
      [robotFactText("errorCode", locale), errorCodeWords(errorCode, locale)],
      [
        t("cmd.info.freeMemory"),
        freeMotion === undefined || freeAction === undefined
          ? t("cmd.info.memoryNotReported")
          : t("cmd.info.free", {
              motion: freeMotion,
              motionSize: MOTION_AREA_BYTES,
              action: freeAction,
              actionSize: ACTION_AREA_BYTES,
            }),
      ],
    ];
    for (const line of labelledRows(rows)) env.out.line(line);
    if (busy) env.out.line(`${busyNowText(locale)} ${t("cmd.run.stopHint")}`);
    const warning = platformWarning(platform, locale);
    if (warning !== undefined) env.out.note(t("cmd.warning", { warning }));
    return EXIT.ok;
  },
};
