import { imageHash, recordUpload, shelfKey } from "../device/shelf.ts";
import { translator } from "../i18n/translate.ts";
import { localeOf, type RunEnv } from "./command.ts";
import { errorLine } from "./errors.ts";
import { cliMessages } from "./messages.ts";
import { readShelves, shelfOf, shelfPath, withShelf, writeShelves } from "./shelf-file.ts";

/** What `rbc upload` knows of a motion it stored into a known slot. */
export interface StoredMotion {
  robot: { serialNumber: string | undefined; port: string };
  slot: number;
  name: string;
  image: Uint8Array;
  durationMs: number;
  footprint: number;
}

/**
 * Records a stored motion on the robot's shelf (src/device/shelf.ts, src/cli/shelf-file.ts). The upload itself
 * succeeded whatever happens here: a shelf that cannot be read or written is said in one note, and the
 * upload's result stands.
 */
export function recordOnShelf(env: RunEnv, stored: StoredMotion, now = new Date()): Promise<void> {
  // One record at a time in this process (several robots upload at once with --ports): each reads the file
  // the one before it wrote.
  const next = queue.then(() => record(env, stored, now));
  queue = next;
  return next;
}

let queue: Promise<void> = Promise.resolve();

async function record(env: RunEnv, stored: StoredMotion, now: Date): Promise<void> {
  const path = shelfPath(env.env);
  try {
    const file = await readShelves(path);
    const key = shelfKey(stored.robot.serialNumber, stored.robot.port);
    const shelf = recordUpload(shelfOf(file, key), {
      slot: stored.slot,
      name: stored.name,
      hash: await imageHash(stored.image),
      durationMs: stored.durationMs,
      footprint: stored.footprint,
      storedAt: now.toISOString(),
    });
    await writeShelves(path, withShelf(file, shelf));
  } catch (e) {
    const t = translator(cliMessages, localeOf(env));
    env.out.note(`rbc: ${t("cli.shelf.notRecorded", { why: errorLine(e, localeOf(env)) })}`);
  }
}
