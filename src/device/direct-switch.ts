import { COMMANDS } from "../protocol/commands.ts";
import { EXIT_DIRECT_MODE } from "../protocol/wck.ts";
import type { DirectUse } from "./activity.ts";
import type { ClientCore } from "./client-core.ts";
import { RbcBadReplyError, RbcTimeoutError } from "./errors.ts";

/**
 * Enters direct mode (0x10, docs/protocol.md §5) for `use`, within the caller's turn. Only from idle: the
 * activity machine refuses it while a motion, a sound or an upload is under way, before anything is sent.
 * Already in direct mode, `use` takes it over.
 */
export async function enterDirect(core: ClientCore, use: DirectUse): Promise<void> {
  const { c, activity } = core;
  if (c.mode === "direct") {
    activity.handDirect(use);
    return;
  }
  activity.requireIdle("enterDirect");
  try {
    await c.request(COMMANDS.enterDirectMode, undefined);
  } catch (e) {
    // The RBC may have switched even though its `01` was lost or garbled; it would then relay every later
    // packet to the servo bus. The exit sequence is harmless garbage in packet mode, so send it blindly.
    if (e instanceof RbcTimeoutError || e instanceof RbcBadReplyError) {
      await c.writeRaw(EXIT_DIRECT_MODE, "leave direct mode (blind, after no reply)").catch(() => {});
      c.parser.reset();
    }
    throw e;
  }
  c.subscription = undefined;
  activity.enterDirect(use);
  c.setState({ mode: "direct", subscription: undefined });
}

/** Leaves direct mode with the 6-byte exit sequence (no reply), within the caller's turn. */
export async function exitDirect(core: ClientCore): Promise<void> {
  const { c, activity } = core;
  if (c.mode !== "direct") return;
  await c.writeRaw(EXIT_DIRECT_MODE, "leave direct mode");
  c.parser.reset();
  if (activity.direct) activity.exitDirect();
  c.setState({ mode: "packet" });
}
