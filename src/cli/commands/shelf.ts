import { type RobotShelf, reconcile, type ShelfSlot, shelfKey } from "../../device/shelf.ts";
import type { Locale } from "../../i18n/locale.ts";
import { remoteKeyWords } from "../../i18n/outcomes/remote-key.ts";
import { translator } from "../../i18n/translate.ts";
import { formatSeconds } from "../../i18n/units.ts";
import { remoteKeyOf } from "../../protocol/catalog.ts";
import { noExtraArguments, parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { connectRobot } from "../connect.ts";
import { EXIT } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { displayWidth } from "../help/render.ts";
import { readShelves, shelfOf, shelfPath, withShelf, writeShelves } from "../shelf-file.ts";
import { commandMessages } from "./messages.ts";

/**
 * `rbc shelf`: the motions rbc uploaded, by robot and slot, with the number Run takes and its remote key
 * (issue 23 item 2; src/device/shelf.ts). Without --port/--demo it lists what this computer recorded, for
 * every robot, reading no robot. With one it reads that robot's free motion memory first and drops the
 * records that memory shows were lost (a reset, another tool), saying so; what stays is "may still be there".
 */

type T = ReturnType<typeof translator<typeof commandMessages>>;

function slotLine(s: ShelfSlot, t: T, locale: Locale): string {
  const when = s.storedAt.slice(0, 16).replace("T", " ");
  const key = remoteKeyWords(s.motionNumber, locale);
  const keyColumn = `${key}${" ".repeat(Math.max(0, 10 - displayWidth(key)))}`;
  const duration = formatSeconds(s.durationMs / 1000, locale);
  return `  ${String(s.motionNumber).padStart(2)}  ${keyColumn}  ${s.name}  ${duration}  ${t("cmd.shelf.stored", { when })}`;
}

function robotWords(shelf: RobotShelf, t: T): string {
  const [kind, id] = [
    shelf.robot.slice(0, shelf.robot.indexOf(":")),
    shelf.robot.slice(shelf.robot.indexOf(":") + 1),
  ];
  return kind === "serial"
    ? t("cmd.shelf.robotSerial", { serial: id })
    : t("cmd.shelf.robotPort", { port: id });
}

function shelfJson(shelf: RobotShelf) {
  return {
    robot: shelf.robot,
    slots: shelf.slots.map((s) => ({ ...s, remoteKey: remoteKeyOf(s.motionNumber) ?? null })),
  };
}

export const shelfCommand: CommandDef = {
  name: "shelf",
  usage: "rbc shelf [--port PATH | --demo] [--json]",
  help: COMMAND_HELP.shelf,
  examples: ["rbc shelf", "rbc shelf --port /dev/ttyUSB0", "rbc shelf --json"],
  talksToRobot: true,
  async run(env) {
    const { values, positionals } = parseCommand("shelf", env.argv, {});
    noExtraArguments("shelf", positionals, 0);
    const locale = localeOf(env);
    const t = translator(commandMessages, locale);
    const path = shelfPath(env.env);
    const file = await readShelves(path);
    const oneRobot = values.demo === true || values.port !== undefined || (env.env.RBC_PORT ?? "") !== "";
    if (!oneRobot) {
      env.out.result({ file: path, robots: file.robots.map(shelfJson) });
      if (file.robots.length === 0) {
        env.out.line(t("cmd.shelf.nothing", { path }));
        return EXIT.ok;
      }
      env.out.line(t("cmd.shelf.recorded", { path }));
      for (const shelf of file.robots) {
        env.out.line(robotWords(shelf, t));
        for (const s of [...shelf.slots].sort((a, b) => a.slot - b.slot))
          env.out.line(slotLine(s, t, locale));
      }
      return EXIT.ok;
    }
    const robot = await connectRobot("shelf", values, env);
    const { serialNumber } = await robot.client.identify();
    const key = shelfKey(serialNumber, robot.where);
    const free = await robot.client.readFreeMemory("motion");
    let shelf = shelfOf(file, key);
    let dropped: number[] = [];
    let usedBytes = 0;
    if (free !== undefined) {
      const checked = reconcile(shelf, free);
      shelf = checked.shelf;
      dropped = checked.dropped.slots;
      usedBytes = checked.dropped.usedBytes;
      if (dropped.length > 0) await writeShelves(path, withShelf(file, shelf));
    }
    env.out.result({
      file: path,
      ...shelfJson(shelf),
      freeMotionBytes: free ?? null,
      dropped,
      checked: free !== undefined,
    });
    env.out.line(robotWords(shelf, t));
    if (shelf.slots.length === 0) env.out.line(`  ${t("cmd.shelf.empty")}`);
    for (const s of shelf.slots) env.out.line(slotLine(s, t, locale));
    if (dropped.length > 0) {
      env.out.line(t("cmd.shelf.dropped", { slots: dropped.join(", "), used: String(usedBytes) }));
    }
    env.out.line(free === undefined ? t("cmd.shelf.unchecked") : t("cmd.shelf.checked"));
    return EXIT.ok;
  },
};
