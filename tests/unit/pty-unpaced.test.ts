import { spawnSync } from "node:child_process";
import { mkdtemp, rm, symlink } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { createPtyPair } from "../../src/cli/pty.ts";
import { isPseudoTerminal } from "../../src/link/node-serial-transport.ts";
import { makeRig } from "../support/rig.ts";

/**
 * A pseudo terminal takes no wire time (socat's pair between `rbc play` and `rbc sim`): a servo's reply can come
 * sooner than its bytes would take at 115200 baud. Judged by the time the switch into direct mode took alone, a
 * loaded machine made such a link look paced, and a genuine reply that came 0.3 ms after its read was refused
 * as "early" ("still playing something"), which tethered play's read-back reported as a lost connection after
 * all its frames (tests/unit/cli-play.test.ts "over a socat PTY pair", about 1 run in 7 under load).
 */

const HAS_SOCAT = spawnSync("socat", ["-V"]).status === 0;

describe("a link that takes no wire time", () => {
  it("a servo reply sooner than its wire time is the answer on a link known to be unpaced, however slowly direct mode was entered", async () => {
    // Paced bytes make the switch take its wire time, as a loaded machine would on a pseudo terminal; the
    // servos are silent, so the only reply is the one given here, 0.1 ms after the read (0.52 ms on a wire).
    const rig = await makeRig({ sim: { servosSilent: true }, port: { baudPacing: true } });
    Object.defineProperty(rig.transport, "unpaced", { value: true });
    await rig.run(rig.client.enterDirectMode());
    const read = rig.client.servos.read(12);
    rig.port.injectToPc([0x00, 0x99], 0.1);
    await rig.run(read);
    expect(rig.client.mode).toBe("direct");
  });

  it.skipIf(!HAS_SOCAT)(
    "knows socat's pseudo terminals, and a link to one, from a serial device",
    async () => {
      const pty = await createPtyPair();
      const dir = await mkdtemp(join(tmpdir(), "rbc-pty-"));
      try {
        expect(isPseudoTerminal(pty.clientPath)).toBe(true);
        expect(isPseudoTerminal(pty.simPath)).toBe(true);
        const link = join(dir, "ttyRBC");
        await symlink(pty.clientPath, link);
        expect(isPseudoTerminal(link)).toBe(true);
        expect(isPseudoTerminal("/dev/ttyUSB0")).toBe(false);
        expect(isPseudoTerminal("/dev/ttyS0")).toBe(false);
      } finally {
        await pty.close();
        await rm(dir, { recursive: true, force: true });
      }
    },
  );
});
