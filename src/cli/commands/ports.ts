import { translator } from "../../i18n/translate.ts";
import { parseCommand } from "../args.ts";
import { type CommandDef, localeOf } from "../command.ts";
import { EXIT } from "../errors.ts";
import { COMMAND_HELP } from "../help/command-help.ts";
import { commandMessages } from "./messages.ts";

export const portsCommand: CommandDef = {
  name: "ports",
  usage: "rbc ports [--json]",
  help: COMMAND_HELP.ports,
  examples: ["rbc ports", "rbc ports --json"],
  talksToRobot: false,
  async run(env) {
    parseCommand("ports", env.argv, {});
    const t = translator(commandMessages, localeOf(env));
    const { NodeSerialTransport } = await import("../../link/node-serial-transport.ts");
    const ports = await NodeSerialTransport.list();
    env.out.result(ports);
    if (ports.length === 0) {
      env.out.line(t("cmd.ports.none"));
      return EXIT.ok;
    }
    for (const p of ports) {
      const ids = p.vendorId && p.productId ? ` (USB ${p.vendorId}:${p.productId})` : "";
      const ftdi = p.vendorId?.toLowerCase() === "0403" ? `  ${t("cmd.ports.ftdi")}` : "";
      env.out.line(`${p.path}${p.manufacturer ? `  ${p.manufacturer}` : ""}${ids}${ftdi}`);
    }
    return EXIT.ok;
  },
};
