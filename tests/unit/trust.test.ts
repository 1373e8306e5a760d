import fc from "fast-check";
import { describe, expect, it } from "vitest";
import type { LogEntry } from "../../src/device/index.ts";
import { HEADER, STANDARD_ZEROS, toHex } from "../../src/protocol/index.ts";
import { EX } from "../fixtures/protocol-examples.ts";
import { makeRig } from "../support/rig.ts";

/** Never report what did not happen: corrupted sizes, late replies and the raw log (issue: trust). */

describe("a corrupted reply costs at most its own request", () => {
  it("a flipped bit in a reply's size byte (size 257) does not swallow the replies after it", async () => {
    const { client, run, port, clock } = await makeRig({ client: { retries: 0 } });
    // Byte 12 is the second-lowest size byte: 00 00 00 01 becomes 00 00 01 01 (257 content bytes).
    port.faults.corruptByte(12, { xor: 0x01 });
    const first = await run(client.resetMemoryPointer("motion").catch((e) => e));
    expect(first).toMatchObject({ code: "timeout" });
    for (let i = 0; i < 4; i++) {
      const started = clock.now();
      expect(await run(client.resetMemoryPointer("motion"))).toBe(1);
      // Answered at once (a fence read first, at most), not after a timeout.
      expect(clock.now() - started).toBeLessThan(client.timeouts.quickMs);
    }
  });

  it("14 bytes of noise shaped like a header with a large size do not stall the next reply", async () => {
    const { client, run, port } = await makeRig({ client: { retries: 0 } });
    const noise = [...HEADER, 0x1f, 0x01, 0x00, 0x00, 0x0f, 0x00];
    expect(noise).toHaveLength(14);
    port.faults.garbageBeforeReply(noise);
    expect(await run(client.resetMemoryPointer("motion"))).toBe(1);
    expect(await run(client.readAvailableMemory("motion"))).toBe(24_576);
  });

  it("a played sound is not reported as a timeout because an earlier reply was corrupted", async () => {
    const { client, run, port } = await makeRig({ client: { retries: 0 } });
    port.faults.corruptByte(12, { xor: 0x04 });
    await run(client.readErrorCode().catch(() => undefined));
    expect(await run(client.runSound(4))).toBe(4);
  });
});

describe("a reply can never answer a request sent after it", () => {
  it("a distance reply that comes after its request timed out does not answer the next distance read", async () => {
    const { client, run, port, sim } = await makeRig({ client: { retries: 0 } });
    sim.setDistance(40);
    port.faults.delayReplies(700); // later than the 400 ms quick timeout
    // 0x12 answered at once, 0x16 not: asked once more (docs/protocol.md §3.6); the late reply pays its debt by
    // count and the second one answers, with the value the robot held then.
    expect(await run(client.readDistance())).toBe(40);
    sim.setDistance(12);
    expect(await run(client.readDistance())).toBe(12);
  });

  it("a late zero-table reply does not make the next write's read-back report verify-failed", async () => {
    const { client, run, port, sim } = await makeRig({ client: { retries: 0 } });
    const table = STANDARD_ZEROS.map((v, i) => (i === 4 ? v - 2 : v));
    port.faults.delayReplies(700);
    expect(await run(client.readZeros().catch((e) => e))).toMatchObject({ code: "timeout" });
    const result = await run(client.writeZeros(table));
    expect(result.readBack).toEqual(table);
    expect(sim.zeros).toEqual(table);
  });

  it("for every read, with late replies at random delays, a value is never older than its request", async () => {
    await fc.assert(
      fc.asyncProperty(
        fc.array(
          fc.record({
            read: fc.constantFrom("distance", "zeros", "memory", "errorCode", "version"),
            delayMs: fc.integer({ min: 0, max: 1500 }),
            value: fc.integer({ min: 10, max: 50 }),
          }),
          { minLength: 2, maxLength: 8 },
        ),
        async (steps) => {
          const { client, run, port, sim } = await makeRig({ client: { retries: 1 } });
          for (const [n, step] of steps.entries()) {
            // A value the robot holds only from now on, so that an older reply would show.
            sim.setDistance(step.value);
            if (step.delayMs > 0) port.faults.delayReplies(step.delayMs);
            const zeros = STANDARD_ZEROS.map((v, i) => (i === n % 16 ? v + (step.value % 15) : v));
            if (step.read === "zeros") await run(client.writeZeros(zeros).catch(() => undefined));
            const got = await run(
              (step.read === "distance"
                ? client.readDistance()
                : step.read === "zeros"
                  ? client.readZeros()
                  : step.read === "memory"
                    ? client.readAvailableMemory("motion")
                    : step.read === "errorCode"
                      ? client.readErrorCode()
                      : client.readFirmwareVersion()) as Promise<unknown>,
            ).catch((e) => ({ failed: e.code }));
            if (typeof got === "object" && got && "failed" in got) {
              expect(["timeout", "bad-reply", "busy"]).toContain((got as { failed: string }).failed);
              continue;
            }
            if (step.read === "distance") expect(got).toBe(step.value);
            if (step.read === "zeros") expect(got).toEqual(sim.zeros);
          }
        },
      ),
      { numRuns: 25, seed: 20261123 },
    );
  });
});

describe("the packet log shows what crossed the wire", () => {
  it("keeps the accelerometer reply's firmware checksum (FD), not a re-encoded 02", async () => {
    const { client, run, sim } = await makeRig();
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    sim.setAccelerometer(4, 3, -6);
    expect(await run(client.readAccelerometer())).toEqual({ x: 4, y: 3, z: -6 });
    const reply = log.find((e) => e.direction === "in" && e.type === 0x1a);
    expect(toHex(reply!.bytes)).toBe(EX.accel);
  });
});
