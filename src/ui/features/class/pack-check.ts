import { downloadedMotionNumber, MOTION_AREA_BYTES, memoryFootprint } from "../../../protocol/catalog.ts";
import { motionDurationMs, type RbmMotion } from "../../../protocol/rbm.ts";
import type { RbmIssue } from "../../../protocol/rbm-validate.ts";
import { checkEntry, inspectMotionText } from "../motions/index.ts";
import { PACK_MAX_FILES } from "./pack-file.ts";
import type { PackFile } from "./state.ts";

/**
 * The pack checked once, before anything is sent: each file read and checked by the project's motion parser and
 * the RBC's rules (the Motions view's `inspectMotionText`, docs/protocol.md §7), and the whole pack against the
 * motion memory. The upload resets each robot's motion memory first, so file k goes into download slot k and is
 * run as the same motion number on every robot (12-21, then 33-42).
 */

export interface CheckedPackFile {
  file: PackFile;
  motion?: RbmMotion;
  errors: readonly RbmIssue[];
  warnings: readonly RbmIssue[];
  /** The Run Motion number it will have on every robot (slot k after the reset). */
  number: number;
  durationMs?: number;
  /** Bytes of its motion image (what the upload sends); 0 when it has errors. */
  imageBytes: number;
  /** Bytes of motion memory it takes (its image rounded up to 64-byte blocks); 0 when it has errors. */
  footprint: number;
}

export interface PackCheck {
  files: CheckedPackFile[];
  /** Files with errors the robot would refuse: none may be uploaded while there are any. */
  withErrors: number;
  footprint: number;
  /** The pack fits an empty motion memory (24,576 bytes). */
  fits: boolean;
  tooMany: boolean;
  /** Every file is clean, there is at least one, they fit and there are at most 20. */
  uploadable: boolean;
}

export function checkPack(pack: readonly PackFile[]): PackCheck {
  const decoder = new TextDecoder();
  const files = pack.map((file, i): CheckedPackFile => {
    const entry = inspectMotionText(file.fileName, decoder.decode(file.bytes), file.bytes.length, file.id);
    const checked = checkEntry(entry, undefined);
    const clean = checked.errors.length === 0 && entry.image !== undefined;
    return {
      file,
      motion: entry.motion,
      errors: checked.errors,
      warnings: checked.warnings,
      number: downloadedMotionNumber(Math.min(i + 1, PACK_MAX_FILES)),
      durationMs: entry.motion ? motionDurationMs(entry.motion) : undefined,
      imageBytes: clean && entry.image ? entry.image.length : 0,
      footprint: clean && entry.image ? memoryFootprint(entry.image.length) : 0,
    };
  });
  const withErrors = files.filter((f) => f.errors.length > 0 || !f.motion).length;
  const footprint = files.reduce((sum, f) => sum + f.footprint, 0);
  const fits = footprint <= MOTION_AREA_BYTES;
  const tooMany = files.length > PACK_MAX_FILES;
  return {
    files,
    withErrors,
    footprint,
    fits,
    tooMany,
    uploadable: files.length > 0 && withErrors === 0 && fits && !tooMany,
  };
}
