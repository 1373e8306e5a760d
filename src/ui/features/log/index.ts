/**
 * The packet log as the rest of the panel uses it (docs/architecture.md, "Features"): its type. The session
 * loads the log itself lazily, by its own file.
 */
export type { PacketLog } from "./packet-log.ts";
