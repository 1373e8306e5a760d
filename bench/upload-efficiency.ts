import { benchMotion } from "./motion.ts";
import { makeBenchRig } from "./rig.ts";
import { median } from "./stats.ts";
import { ADAPTER_LATENCY_MS, idealUpload, PAGE_WRITE_MS, type UploadIdeal } from "./upload-ideal.ts";
import { type TimedUpload, timedUpload } from "./upload-timing.ts";

/**
 * Upload of a real motion image (bench/motion.ts) in process: RbcClient → WebSerialTransport → MockSerialPort
 * (115200 baud pacing, 16 ms adapter latency) → SimulatedRbc (5 ms EEPROM page write per chunk). In real time the
 * mock and the simulator run on `wireClock()` (bench/wire-clock.ts), whose timers never fire early, so the mock
 * never carries bytes faster than the wire; the client runs on Node's ordinary timers.
 *
 * - `efficiencyReal` (the headline): first-principles ideal (bench/upload-ideal.ts) ÷ the download phase's time
 *   on the real clock, median of `runs` fresh rigs. It pays for everything the client, the transport, the
 *   streams and Node's timers add to the bare link.
 * - `idleGapCheck`: the same upload on a virtual clock, where only the simulator's timing model advances time.
 *   That model charges the same wire time, latency and page writes as the ideal, so the ratio is 1.000 exactly
 *   when the client leaves no idle gap of its own on the wire (a sleep, a timer hop, a chunk sent late); a gap
 *   shows as a value below 1. It checks the client's sequencing; it is not a speed.
 * - `wirePercent`: payload bytes per second of the real-time download phase as a percentage of 11,520 B/s.
 * The bytes counted at the client's transport must equal the ideal's byte counts, or the run fails.
 */

export interface UploadFigures {
  motion: string;
  ideal: UploadIdeal;
  virtual: TimedUpload;
  realRuns: TimedUpload[];
  realDownloadMs: number;
  realWholeMs: number;
  efficiencyReal: number;
  efficiencyWholeCallReal: number;
  idleGapCheck: number;
  bytesPerSecondReal: number;
}

/** Throws unless the bytes counted at the client's transport are the ones the ideal charges for. */
export function checkBytes(run: TimedUpload, ideal: UploadIdeal, where: string): void {
  const phases = [
    ["download phase", run.download, ideal.download],
    ["whole call", run.wholeCall, ideal.wholeCall],
  ] as const;
  for (const [phase, got, want] of phases) {
    if (got.pc !== want.pcBytes || got.rbc !== want.rbcBytes) {
      throw new Error(
        `${where}: the ${phase} moved ${got.pc} bytes out and ${got.rbc} in; the protocol says ${want.pcBytes} and ${want.rbcBytes}`,
      );
    }
  }
}

async function uploadOnRig(virtual: boolean, image: Uint8Array): Promise<TimedUpload> {
  const rig = await makeBenchRig({
    virtual,
    baudPacing: true,
    latencyMs: ADAPTER_LATENCY_MS,
    pageWriteMs: PAGE_WRITE_MS,
    preciseWire: true,
  });
  try {
    // Warm the request path once so the real-time figure does not include first-call compilation.
    await rig.run(rig.client.readAvailableMemory("motion"));
    const run = await timedUpload(rig.client, rig.transport, image, {
      now: () => rig.clock.now(),
      run: rig.run,
    });
    if (rig.sim.motions.length !== 1) throw new Error("the simulated RBC did not record the motion");
    return run;
  } finally {
    await rig.dispose();
  }
}

export async function measureUpload(realRuns = 7): Promise<UploadFigures> {
  const { file, image } = benchMotion();
  const ideal = idealUpload(image.length);
  const virtual = await uploadOnRig(true, image);
  checkBytes(virtual, ideal, "virtual clock");
  const runs: TimedUpload[] = [];
  for (let i = 0; i < realRuns; i++) {
    const run = await uploadOnRig(false, image);
    checkBytes(run, ideal, "real time");
    runs.push(run);
  }
  const realDownloadMs = median(runs.map((r) => r.downloadMs));
  const realWholeMs = median(runs.map((r) => r.wholeMs));
  return {
    motion: file,
    ideal,
    virtual,
    realRuns: runs,
    realDownloadMs,
    realWholeMs,
    efficiencyReal: ideal.download.totalMs / realDownloadMs,
    efficiencyWholeCallReal: ideal.wholeCall.totalMs / realWholeMs,
    idleGapCheck: ideal.download.totalMs / virtual.downloadMs,
    bytesPerSecondReal: image.length / (realDownloadMs / 1000),
  };
}
