import { parseCommand } from "../args.ts";
import type { CommandDef } from "../command.ts";
import { EXIT } from "../errors.ts";

export const portsCommand: CommandDef = {
  name: "ports",
  summary: "list the serial ports of this computer",
  usage: "rbc ports [--json]",
  description: `
Lists the serial ports the operating system knows of, with the USB adapter's maker and ids when known.
The RBC's cable is a USB serial adapter, usually an FTDI one (vendor 0403, product 6001): on Linux it
appears as /dev/ttyUSB0, on macOS as /dev/tty.usbserial-…, on Windows as COM3 or similar. Pass that path
to other commands with --port. Pseudo terminals (such as the one \`rbc sim --pty\` prints) are not listed.`,
  options: [],
  examples: ["rbc ports", "rbc ports --json"],
  talksToRobot: false,
  async run(env) {
    parseCommand("ports", env.argv, {});
    const { NodeSerialTransport } = await import("../../link/node-serial-transport.ts");
    const ports = await NodeSerialTransport.list();
    env.out.result(ports);
    if (ports.length === 0) {
      env.out.line(
        "No serial ports found. Plug in the robot's USB cable (and switch the robot on), then try again.",
      );
      return EXIT.ok;
    }
    for (const p of ports) {
      const ids = p.vendorId && p.productId ? ` (USB ${p.vendorId}:${p.productId})` : "";
      const ftdi =
        p.vendorId?.toLowerCase() === "0403" ? "  ← an FTDI adapter, likely the robot's cable" : "";
      env.out.line(`${p.path}${p.manufacturer ? `  ${p.manufacturer}` : ""}${ids}${ftdi}`);
    }
    return EXIT.ok;
  },
};
