import { said } from "../../../i18n/said.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice } from "../../error-text.ts";
import { robotMessages } from "./messages.ts";

/** Reads what the device card shows: identity, error code and free memory of both areas. */
export async function refreshDeviceInfo(ctx: AppContext): Promise<void> {
  const { session, store } = ctx;
  if (store.get().device.loading || !session.current) return;
  // Its failure is kept as a message, worded when drawn (it follows a language switch).
  const { locale } = store.get();
  store.update((s) => ({ device: { ...s.device, loading: true, notice: undefined } }));
  try {
    // Firmware and serial number were read when connecting; what changes is read here.
    const info = await session.run(said(robotMessages, "robot.readingInfo"), async (client) => {
      const errorCode = await client.readErrorCode();
      const freeMotion = await client.readAvailableMemory("motion");
      const freeAction = await client.readAvailableMemory("action");
      return { errorCode, freeMotion, freeAction, platform: client.state.platform };
    });
    store.update((s) => ({
      connection: {
        ...s.connection,
        platform: info.platform ?? s.connection.platform,
      },
      device: {
        loading: false,
        errorCode: info.errorCode,
        freeMotion: info.freeMotion,
        freeAction: info.freeAction,
        readAt: Date.now(),
      },
    }));
  } catch (e) {
    store.update((s) => ({
      device: {
        ...s.device,
        loading: false,
        notice: errorNotice(said(robotMessages, "robot.readFailed"), e, locale),
      },
    }));
  }
}
