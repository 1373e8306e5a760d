import {
  ACTION_AREA_BYTES,
  errorCodeText,
  MOTION_AREA_BYTES,
  NO_ERROR,
  platformName,
} from "../../protocol/catalog.ts";
import { formatFirmware } from "../../shared/format.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import type { CommandDef } from "../command.ts";
import { connectRobot } from "../connect.ts";
import { EXIT } from "../errors.ts";

/** "no error" or "3: too many motions, or motion memory full". */
export function errorCodeWords(code: number): string {
  return code === NO_ERROR ? "no error" : `${code}: ${errorCodeText(code)}`;
}

export const infoCommand: CommandDef = {
  name: "info",
  summary: "firmware, serial number, platform, error code and free memory",
  usage: "rbc info (--port PATH | --demo) [--json]",
  description: `
Connects, then reads the firmware version, the 13-digit serial number (when the firmware answers it), the
robot's platform (HUNO, DINO, DOGY or PF2, from the platform byte of its replies), the last error code in words, and the free bytes of the
motion memory (24,576 when empty) and the action memory (8,192 when empty). Changes nothing on the robot.`,
  options: [],
  examples: ["rbc info --port /dev/ttyUSB0", "rbc info --demo --json"],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("info", env.argv, {});
    noExtraArguments("info", positionals, 0);
    const robot = await connectRobot("info", values, env);
    const { client } = robot;
    // 0x0C is optional: some firmware builds never answer it (PROTOCOL.md §3.5).
    const { serialNumber, warnings } = await client.identify();
    const errorCode = await client.readErrorCode();
    const freeMotion = await client.readAvailableMemory("motion");
    const freeAction = await client.readAvailableMemory("action");
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
      freeMemory: { motion: freeMotion, action: freeAction },
      warnings,
      // Replies no request asked for (late, or repeated by a firmware that repeats them), discarded so far.
      unaskedReplies: client.stats.unansweredReplies,
    });
    const n = (v: number) => v.toLocaleString("en-US");
    env.out.line(robot.demo ? "The demo robot (simulated)" : `Robot on ${robot.where}`);
    env.out.line(`  Firmware       ${firmware}`);
    env.out.line(`  Serial number  ${serialNumber ?? "not reported (the robot did not answer 0x0C)"}`);
    const name = platformName(platform);
    env.out.line(`  Platform       ${name.startsWith("unknown") ? name : `${name} (${platform})`}`);
    env.out.line(`  Error code     ${errorCodeWords(errorCode)}`);
    env.out.line(
      `  Free memory    motion ${n(freeMotion)} of ${n(MOTION_AREA_BYTES)} bytes, action ${n(freeAction)} of ${n(ACTION_AREA_BYTES)} bytes`,
    );
    for (const warning of warnings) env.out.note(`Warning: ${warning}`);
    return EXIT.ok;
  },
};
