/**
 * The motion layer (pure: no I/O, no timers, no DOM; imports only from protocol/): the motion document and its
 * operations, undo history, the frames of docs/protocol.md §10 for tethered play and the simulator, and the
 * restamp of a motion file for another robot (§7, field 2). See docs/motion-document.md.
 */
export * from "./document.ts";
export * from "./edits.ts";
export * from "./errors.ts";
export * from "./frames.ts";
export * from "./history.ts";
export * from "./mirror.ts";
export * from "./restamp.ts";
export * from "./retime.ts";
export * from "./scenes.ts";
