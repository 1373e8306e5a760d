import { describe, expect, it } from "vitest";
import { RbcCancelledError } from "../../src/device/index.ts";
import { errorText } from "../../src/i18n/index.ts";
import { makeRig } from "../support/rig.ts";

/**
 * A request queued behind another when Stop or Limp comes is cancelled before anything is sent for it, and its
 * error says which of the two cancelled it (issue 21 item 6: "Cancelled by Stop" was said for Limp too).
 */
describe("a queued request cancelled by Stop or Limp says which", () => {
  for (const by of ["stop", "limp"] as const) {
    it(`cancelled by ${by === "stop" ? "Stop" : "Limp"}`, async () => {
      const rig = await makeRig();
      // The first read takes its turn at once; the second waits behind it.
      const first = rig.client.readDistance();
      const queued = rig.client.readZeros();
      const outcome = queued.then(
        () => undefined,
        (e: unknown) => e,
      );
      const ending = by === "stop" ? rig.client.stopActivity() : rig.client.limp();
      await rig.run(Promise.allSettled([first, ending]));
      const e = await rig.run(outcome);
      expect(e).toBeInstanceOf(RbcCancelledError);
      const cancelled = e as RbcCancelledError;
      expect(cancelled.by).toBe(by);
      expect(cancelled.situation).toEqual({ kind: "cancelled-by", by });
      expect(errorText(cancelled, "en")).toBe(
        by === "stop"
          ? "Cancelled by Stop: it had not started yet."
          : "Cancelled by Limp: every servo is being made limp.",
      );
    });
  }
});
