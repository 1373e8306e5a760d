export type { PacketLog } from "./packet-log.ts";
