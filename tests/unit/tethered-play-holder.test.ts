/**
 * What holds direct mode after tethered play (issue 33 item 4), as the device's activity tells it: a play that
 * entered direct mode itself leaves it held by tethered play (the servos hold the last frame until Stop leaves
 * direct mode), so the panel can name tethered play and Stop; a play inside servo control or teach-in hands
 * direct mode back to that use.
 */
import { describe, expect, it } from "vitest";
import { openMotion } from "../../src/motion/index.ts";
import { FACTORY_ZEROS } from "../../src/protocol/index.ts";
import { makeRig } from "../support/rig.ts";

/** Servos 0 and 2 in two short scenes; its first pose is the simulator's power-up pose (tethered-play.test.ts). */
const PAIR =
  "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:4:Pair:0:1:2:2:2:4:" +
  "00:020:030:000:0:125:02:020:030:000:0:160:" +
  "000:01:A:2:50:0:00:126:120:2:0:0:02:197:201:3:0:" +
  "001:01:B:3:70:0:00:120:130:0:0:0:02:201:205:2:0:";

const options = { robotZeros: FACTORY_ZEROS, platform: 1 };

describe("direct mode after tethered play", () => {
  it("entered by the play: held by tethered play until Stop leaves it", async () => {
    const rig = await makeRig();
    await rig.run(rig.client.playTethered(openMotion(PAIR), options));
    expect(rig.client.activity.doing).toMatchObject({ kind: "direct", use: "tethered-play" });
    await rig.run(rig.client.stopActivity());
    expect(rig.client.activity.doing.kind).toBe("idle");
    expect(rig.sim.directMode).toBe(false);
  });

  it("inside servo control or teach-in: handed back to it", async () => {
    for (const use of ["servo-control", "teach-in"] as const) {
      const rig = await makeRig();
      await rig.run(rig.client.enterDirectMode(use));
      await rig.run(rig.client.playTethered(openMotion(PAIR), options));
      expect(rig.client.activity.doing).toMatchObject({ kind: "direct", use });
    }
  });
});
