import { downloadedMotionNumber } from "../protocol/catalog.ts";
import type { MemoryArea } from "../protocol/commands.ts";
import { motionImage } from "../protocol/motion-image.ts";
import type { RbmMotion } from "../protocol/rbm.ts";
import { validateRbm } from "../protocol/rbm-validate.ts";
import { RbcInvalidArgumentError } from "./errors.ts";
import type { UploadOptions, UploadResult } from "./types.ts";

export type UploadPhase = "resetting" | "checking" | "sending" | "verifying";

export interface FileUploadOptions extends UploadOptions {
  /**
   * Reset the area's memory pointer first (0x1F): the robot forgets every downloaded motion (or action) of
   * that area, and this file becomes download 1 (Run Motion 12 for a motion).
   */
  resetFirst?: boolean;
  /** Told when the upload moves on to its next step, for a progress line. */
  onPhase?: (phase: UploadPhase) => void;
}

export interface FileUploadResult extends UploadResult {
  /** The memory pointer was reset first (the robot's earlier downloads of this area are forgotten). */
  reset: boolean;
  /** Download slot 1-20 the file went into, when known (after a reset: 1). */
  slot: number | undefined;
  /** The Run Motion number that plays it, when known (after a reset: 12). */
  motionNumber: number | undefined;
}

/** What `RbcClient.uploadMotion` needs from the client: the two requests around the download. */
export interface UploadHost {
  /** Reads the free memory; `RbcNotSupportedError` when the firmware does not answer 0x0F (memory-read.ts). */
  readFreeMemory(area: MemoryArea): Promise<number>;
  resetMemoryPointer(area: MemoryArea): Promise<number>;
  upload(area: MemoryArea, bytes: Uint8Array, options: UploadOptions): Promise<UploadResult>;
}

/**
 * The motion image the robot gets for `motion` (docs/protocol.md §6.3), or a typed refusal: a file with errors
 * under the RBC's rules (§7) never gets a byte sent.
 */
export function motionPayload(motion: RbmMotion): Uint8Array {
  const { errors } = validateRbm(motion);
  if (errors.length > 0) {
    throw new RbcInvalidArgumentError(undefined, {
      kind: "motion-invalid",
      name: motion.name,
      count: errors.length,
      first: errors[0]!,
    });
  }
  return motionImage(motion);
}

/**
 * One upload of a file into an area, end to end: the payload is built and checked before anything is sent,
 * then the optional reset, the free-memory check, the download chunk by chunk and the verification against the
 * robot's own memory accounting (all in `host.upload`).
 */
export async function uploadFileTo(
  host: UploadHost,
  area: MemoryArea,
  payload: Uint8Array,
  options: FileUploadOptions,
): Promise<FileUploadResult> {
  const { resetFirst = false, onPhase, ...rest } = options;
  if (resetFirst) {
    // Without 0x0F the upload cannot be checked: refused before the reset forgets anything (§3.5).
    await host.readFreeMemory(area);
    onPhase?.("resetting");
    await host.resetMemoryPointer(area);
  }
  onPhase?.("checking");
  let sending = false;
  const result = await host.upload(area, payload, {
    ...rest,
    onProgress: (p) => {
      if (!sending) {
        sending = true;
        onPhase?.("sending");
      }
      rest.onProgress?.(p);
      if (p.acknowledged === p.total) onPhase?.("verifying");
    },
  });
  const slot = resetFirst ? 1 : undefined;
  return {
    ...result,
    reset: resetFirst,
    slot,
    motionNumber: area === "motion" && slot !== undefined ? downloadedMotionNumber(slot) : undefined,
  };
}
