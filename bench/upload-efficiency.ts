import { readFileSync } from "node:fs";
import { DOWNLOAD_CHUNK, motionImage, parseRbm } from "../src/protocol/index.ts";
import { makeBenchRig } from "./rig.ts";
import { median } from "./stats.ts";

/**
 * Upload speed of a real motion: the image of WalkJump.rbm (4,322 bytes, 68 chunks) through RbcClient →
 * WebSerialTransport → MockSerialPort (115200 baud pacing, 16 ms adapter latency) → SimulatedRbc (5 ms EEPROM
 * page write per chunk).
 *
 * Two figures per run:
 * - download phase (the headline, `uploadEfficiency`): from the first progress report (just before the
 *   14-byte first part is written) to the last one (the last chunk's `40` received). Its link-ideal time is
 *   every byte of the phase at 11,520 B/s, both directions added (PC: first part + payload + one checksum per
 *   chunk; RBC: one `40` per part), plus one adapter latency per part (first part and each chunk) and one page
 *   write per chunk (the simulated RBC writes no page for the first part). Nothing else.
 * - whole call (`uploadEfficiencyWholeCall`): the whole `writeMotion` call, which also reads free memory before
 *   and error code + free memory after. Its ideal adds those three requests' bytes both ways and one adapter
 *   latency each.
 * Efficiency = ideal / measured. Bytes/s = image bytes / measured download-phase seconds.
 */

export const WALK_JUMP = new URL("../../shared/fixtures/rbm/WalkJump.rbm", import.meta.url);
export const LINK_BYTES_PER_SECOND = 11_520;
export const ADAPTER_LATENCY_MS = 16;
export const PAGE_WRITE_MS = 5;

export function walkJumpImage(): Uint8Array {
  return motionImage(parseRbm(readFileSync(WALK_JUMP, "latin1")));
}

export interface UploadRun {
  downloadMs: number;
  wholeMs: number;
  downloadPcBytes: number;
  downloadRbcBytes: number;
  wholePcBytes: number;
  wholeRbcBytes: number;
}

export interface UploadIdeal {
  downloadMs: number;
  wholeMs: number;
}

/** The link-ideal times for an image of `total` bytes (see the module comment). */
export function idealUploadMs(total: number): UploadIdeal & { chunks: number; pc: number; rbc: number } {
  const chunks = Math.ceil(total / DOWNLOAD_CHUNK);
  const pc = 14 + total + chunks;
  const rbc = chunks + 1;
  const byteMs = 1000 / LINK_BYTES_PER_SECOND;
  const downloadMs = (pc + rbc) * byteMs + (chunks + 1) * ADAPTER_LATENCY_MS + chunks * PAGE_WRITE_MS;
  // Free memory (request 16 bytes, reply 19), error code (16, 17), free memory again (16, 19).
  const extraBytes = 16 + 19 + 16 + 17 + 16 + 19;
  const wholeMs = downloadMs + extraBytes * byteMs + 3 * ADAPTER_LATENCY_MS;
  return { downloadMs, wholeMs, chunks, pc, rbc };
}

/** One upload on a fresh rig, timed on its clock. */
export async function uploadOnce(virtual: boolean, image: Uint8Array): Promise<UploadRun> {
  const rig = await makeBenchRig({
    virtual,
    baudPacing: true,
    latencyMs: ADAPTER_LATENCY_MS,
    pageWriteMs: PAGE_WRITE_MS,
  });
  const { clock, port, client } = rig;
  try {
    // Warm the request path once so the real-time figure does not include first-call compilation.
    await rig.run(client.readAvailableMemory("motion"));
    const t0 = clock.now();
    const pc0 = port.stats.bytesFromPc;
    const rbc0 = port.stats.bytesToPc;
    let downloadStart: [number, number, number] | undefined;
    let downloadEnd: [number, number, number] | undefined;
    const result = await rig.run(
      client.writeMotion(image, {
        onProgress: (p) => {
          const mark: [number, number, number] = [clock.now(), port.stats.bytesFromPc, port.stats.bytesToPc];
          if (p.acknowledged === 0) downloadStart = mark;
          if (p.acknowledged === p.total) downloadEnd = mark;
        },
      }),
    );
    const t1 = clock.now();
    if (!downloadStart || !downloadEnd) throw new Error("the upload reported no progress");
    if (result.total !== image.length || rig.sim.motions.length !== 1) {
      throw new Error("the upload did not record the file");
    }
    return {
      downloadMs: downloadEnd[0] - downloadStart[0],
      wholeMs: t1 - t0,
      downloadPcBytes: downloadEnd[1] - downloadStart[1],
      downloadRbcBytes: downloadEnd[2] - downloadStart[2],
      wholePcBytes: port.stats.bytesFromPc - pc0,
      wholeRbcBytes: port.stats.bytesToPc - rbc0,
    };
  } finally {
    await rig.dispose();
  }
}

export interface UploadFigures {
  imageBytes: number;
  chunks: number;
  idealDownloadMs: number;
  idealWholeMs: number;
  virtual: UploadRun;
  real: UploadRun;
  realRuns: UploadRun[];
  efficiencyVirtual: number;
  efficiencyReal: number;
  efficiencyWholeCallVirtual: number;
  efficiencyWholeCallReal: number;
  bytesPerSecondVirtual: number;
  bytesPerSecondReal: number;
}

export async function measureUpload(realRuns = 5): Promise<UploadFigures> {
  const image = walkJumpImage();
  const ideal = idealUploadMs(image.length);
  const virtual = await uploadOnce(true, image);
  if (virtual.downloadPcBytes !== ideal.pc || virtual.downloadRbcBytes !== ideal.rbc) {
    throw new Error(
      `download moved ${virtual.downloadPcBytes}/${virtual.downloadRbcBytes} bytes, expected ${ideal.pc}/${ideal.rbc}`,
    );
  }
  const runs: UploadRun[] = [];
  for (let i = 0; i < realRuns; i++) runs.push(await uploadOnce(false, image));
  const real: UploadRun = {
    downloadMs: median(runs.map((r) => r.downloadMs)),
    wholeMs: median(runs.map((r) => r.wholeMs)),
    downloadPcBytes: virtual.downloadPcBytes,
    downloadRbcBytes: virtual.downloadRbcBytes,
    wholePcBytes: virtual.wholePcBytes,
    wholeRbcBytes: virtual.wholeRbcBytes,
  };
  return {
    imageBytes: image.length,
    chunks: ideal.chunks,
    idealDownloadMs: ideal.downloadMs,
    idealWholeMs: ideal.wholeMs,
    virtual,
    real,
    realRuns: runs,
    efficiencyVirtual: ideal.downloadMs / virtual.downloadMs,
    efficiencyReal: ideal.downloadMs / real.downloadMs,
    efficiencyWholeCallVirtual: ideal.wholeMs / virtual.wholeMs,
    efficiencyWholeCallReal: ideal.wholeMs / real.wholeMs,
    bytesPerSecondVirtual: image.length / (virtual.downloadMs / 1000),
    bytesPerSecondReal: image.length / (real.downloadMs / 1000),
  };
}
