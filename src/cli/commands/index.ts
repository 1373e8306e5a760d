import type { CommandDef } from "../command.ts";
import { flashCommand } from "./flash.ts";
import { infoCommand } from "./info.ts";
import { limpCommand } from "./limp.ts";
import { logCommand } from "./log.ts";
import { playCommand } from "./play.ts";
import { portsCommand } from "./ports.ts";
import { rbmCommand } from "./rbm/rbm-command.ts";
import { runCommand } from "./run.ts";
import { sensorsCommand } from "./sensors.ts";
import { servosCommand } from "./servos.ts";
import { shelfCommand } from "./shelf.ts";
import { simCommand } from "./sim.ts";
import { soundCommand } from "./sound.ts";
import { stopCommand } from "./stop.ts";
import { uploadCommand } from "./upload.ts";
import { zerosCommand } from "./zeros.ts";

/** Every subcommand, in the order `rbc --help` lists them. */
export const COMMAND_LIST: readonly CommandDef[] = [
  portsCommand,
  infoCommand,
  zerosCommand,
  uploadCommand,
  shelfCommand,
  runCommand,
  playCommand,
  stopCommand,
  limpCommand,
  servosCommand,
  rbmCommand,
  soundCommand,
  sensorsCommand,
  logCommand,
  flashCommand,
  simCommand,
];

export function findCommand(name: string): CommandDef | undefined {
  return COMMAND_LIST.find((c) => c.name === name);
}
