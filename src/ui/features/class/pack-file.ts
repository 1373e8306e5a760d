import { z } from "../../../protocol/zod.ts";

/**
 * A motion pack as one file: a small JSON document holding the .rbm files byte for byte (base64), so a teacher
 * prepares the pack once and opens it again before the next lesson.
 *
 *   { "format": "rbc-motion-pack", "version": 1, "files": [{ "name": "wave.rbm", "base64": "…" }] }
 *
 * Opening checks the document with zod; anything else is refused with a `PackFileError` whose `problem` says
 * why (the view words it), and nothing of the pack already open changes.
 */

export const PACK_FORMAT = "rbc-motion-pack";
export const PACK_VERSION = 1;
/** The RBC has 20 download slots (docs/protocol.md §6.1): a pack never holds more motions than that. */
export const PACK_MAX_FILES = 20;
/** Far above any motion file (see the Motions view's MAX_RBM_BYTES). */
export const PACK_MAX_FILE_BYTES = 1_000_000;
/** A pack file bigger than this is not read at all. */
export const PACK_MAX_BYTES = 30_000_000;

const BASE64 = /^[A-Za-z0-9+/]*={0,2}$/;

const packSchema = z.object({
  format: z.literal(PACK_FORMAT),
  version: z.literal(PACK_VERSION),
  files: z
    .array(
      z.object({
        name: z.string().min(1).max(255),
        base64: z
          .string()
          .max(Math.ceil(PACK_MAX_FILE_BYTES / 3) * 4)
          .regex(BASE64),
      }),
    )
    .min(1)
    .max(PACK_MAX_FILES),
});

/** Why a file is not a motion pack: not JSON, another document, a later version, or damaged content. */
export type PackProblem = "too-large" | "not-json" | "not-pack" | "wrong-version" | "damaged";

export class PackFileError extends Error {
  override name = "PackFileError";
  constructor(
    readonly problem: PackProblem,
    detail: string,
  ) {
    super(detail);
  }
}

export interface PackedFile {
  name: string;
  bytes: Uint8Array;
}

export function bytesToBase64(bytes: Uint8Array): string {
  let binary = "";
  for (let i = 0; i < bytes.length; i += 0x8000) {
    binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  }
  return btoa(binary);
}

export function base64ToBytes(text: string): Uint8Array {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

/** The pack as the file's text (pretty-printed JSON, ending with a new line). */
export function serializePack(files: readonly PackedFile[]): string {
  const doc = {
    format: PACK_FORMAT,
    version: PACK_VERSION,
    files: files.map((f) => ({ name: f.name, base64: bytesToBase64(f.bytes) })),
  };
  return `${JSON.stringify(doc, null, 2)}\n`;
}

/** "rbc-motion-pack-2026-11-26.json" (local date). */
export function packFileName(date: Date): string {
  const pad = (n: number) => String(n).padStart(2, "0");
  return `rbc-motion-pack-${date.getFullYear()}-${pad(date.getMonth() + 1)}-${pad(date.getDate())}.json`;
}

/** Reads a pack file's text, or throws a `PackFileError`; the files come back byte for byte. */
export function parsePack(text: string): PackedFile[] {
  if (text.length > PACK_MAX_BYTES) throw new PackFileError("too-large", `${text.length} characters`);
  let doc: unknown;
  try {
    doc = JSON.parse(text);
  } catch (e) {
    throw new PackFileError("not-json", e instanceof Error ? e.message : String(e));
  }
  const head = doc as { format?: unknown; version?: unknown } | null;
  if (typeof head !== "object" || head === null || head.format !== PACK_FORMAT) {
    throw new PackFileError("not-pack", `format is not "${PACK_FORMAT}"`);
  }
  if (head.version !== PACK_VERSION) {
    throw new PackFileError(
      "wrong-version",
      `version ${String(head.version)}, this panel reads ${PACK_VERSION}`,
    );
  }
  const parsed = packSchema.safeParse(doc);
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    throw new PackFileError("damaged", `${issue?.path.join(".") ?? ""}: ${issue?.message ?? "invalid"}`);
  }
  return parsed.data.files.map((f) => {
    let bytes: Uint8Array;
    try {
      bytes = base64ToBytes(f.base64);
    } catch (e) {
      throw new PackFileError("damaged", `${f.name}: ${e instanceof Error ? e.message : String(e)}`);
    }
    if (bytes.length > PACK_MAX_FILE_BYTES) throw new PackFileError("damaged", `${f.name} is too large`);
    return { name: f.name, bytes };
  });
}
