import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { describePort } from "../../serial-ports.ts";
import { connectionMessages } from "./messages.ts";
import type { RobotLabel } from "./state.ts";

/**
 * The robot as the panel names it, in the panel's language: "Demo robot", "Demo robot (Bluetooth)", or the
 * port's description ("FTDI USB serial adapter (0403:6001)"). The top bar, the device card and the page title
 * all name it so.
 */
export function robotName(robot: RobotLabel, locale: Locale): string {
  const t = translator(connectionMessages, locale);
  if (robot.kind === "demo") {
    return robot.link === "bluetooth" ? t("connection.demoRobotBluetooth") : t("connection.demoRobot");
  }
  return robot.info ? describePort(robot.info, locale) : robot.name;
}
