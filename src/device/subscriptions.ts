import { COMMANDS } from "../protocol/commands.ts";
import { encodePacket } from "../protocol/packet.ts";
import { type RbcConnection, SUBSCRIPTIONS } from "./rbc-connection.ts";
import type { SubscriptionKind } from "./types.ts";

/** `RbcClient.subscribe`: the subscription is kept by the connection, which re-arms it after every other turn. */
export function subscribe(c: RbcConnection, kind: SubscriptionKind, threshold: number): Promise<void> {
  const spec = SUBSCRIPTIONS[kind];
  const contents =
    kind === "sound"
      ? COMMANDS.subscribeSound.request(threshold)
      : kind === "buttons"
        ? COMMANDS.subscribeButtons.request()
        : COMMANDS.subscribeRemote.request();
  const request = encodePacket(spec.type, contents);
  return c.exclusive(
    async () => {
      c.requirePacketMode(spec.name);
      c.subscription = { kind, request };
      c.setState({ subscription: kind });
      await c.writePacket(request, spec.type);
    },
    undefined,
    { rearm: false },
  );
}

/** Ends the subscription: the RBC stops when the next packet header arrives, so a harmless read is sent. */
export async function unsubscribe(c: RbcConnection): Promise<void> {
  if (!c.subscription) return;
  c.subscription = undefined;
  c.setState({ subscription: undefined });
  await c.command(COMMANDS.readErrorCode, undefined).catch(() => {});
}
