/**
 * The shelf file (issue 23 item 2): what `rbc upload` put into which download slot of which robot
 * (src/device/shelf.ts), kept in `shelf.json` in rbc's config folder so that `rbc shelf` and `rbc run` know the
 * motions' names and durations after the cable was pulled. The folder is $RBC_CONFIG_DIR, else
 * $XDG_CONFIG_HOME/rbc, else %APPDATA%\rbc on Windows, else ~/.config/rbc.
 *
 * A file that is not a shelf is never overwritten: reading it fails with a sentence naming it, and nothing is
 * recorded until the person moves it away.
 */
import { mkdir, readFile, rename, writeFile } from "node:fs/promises";
import { homedir } from "node:os";
import { dirname, join } from "node:path";
import type { RobotShelf } from "../device/shelf.ts";
import { said } from "../i18n/said.ts";
import { z } from "../protocol/zod.ts";
import { CliError } from "./errors.ts";
import { cliMessages } from "./messages.ts";

const SlotSchema = z.object({
  slot: z.number().int().min(1).max(20),
  motionNumber: z.number().int(),
  name: z.string(),
  hash: z.string().regex(/^[0-9a-f]{64}$/),
  durationMs: z.number().nonnegative(),
  footprint: z.number().int().positive(),
  storedAt: z.string(),
});

const ShelfFileSchema = z.object({
  format: z.literal("rbc-shelf"),
  version: z.literal(1),
  robots: z.array(z.object({ robot: z.string().min(1), slots: z.array(SlotSchema) })),
});

export type ShelfFile = z.infer<typeof ShelfFileSchema>;

/** Where the shelf file is, from the environment (see the top of this file). */
export function shelfPath(env: NodeJS.ProcessEnv): string {
  const dir =
    env.RBC_CONFIG_DIR ||
    (env.XDG_CONFIG_HOME ? join(env.XDG_CONFIG_HOME, "rbc") : undefined) ||
    (process.platform === "win32" && env.APPDATA ? join(env.APPDATA, "rbc") : undefined) ||
    join(homedir(), ".config", "rbc");
  return join(dir, "shelf.json");
}

/** The shelves in the file, or none when there is no file yet. A file that is not a shelf is refused. */
export async function readShelves(path: string): Promise<ShelfFile> {
  let text: string;
  try {
    text = await readFile(path, "utf8");
  } catch (e) {
    if ((e as NodeJS.ErrnoException).code === "ENOENT")
      return { format: "rbc-shelf", version: 1, robots: [] };
    throw new CliError(
      "shelf-unreadable",
      said(cliMessages, "cli.shelf.unreadable", { path, why: String(e) }),
    );
  }
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch {
    throw new CliError("shelf-invalid", said(cliMessages, "cli.shelf.invalid", { path }));
  }
  const parsed = ShelfFileSchema.safeParse(json);
  if (!parsed.success) throw new CliError("shelf-invalid", said(cliMessages, "cli.shelf.invalid", { path }));
  return parsed.data;
}

/** Writes the shelves whole (a temporary file renamed over the old one, so a crash never leaves half a file). */
export async function writeShelves(path: string, file: ShelfFile): Promise<void> {
  await mkdir(dirname(path), { recursive: true });
  const temporary = `${path}.${process.pid}.tmp`;
  await writeFile(temporary, `${JSON.stringify(file, null, 2)}\n`);
  await rename(temporary, path);
}

/** One robot's shelf from the file (empty when it has none). */
export function shelfOf(file: ShelfFile, robot: string): RobotShelf {
  return file.robots.find((r) => r.robot === robot) ?? { robot, slots: [] };
}

/** The file with `shelf` in place of that robot's (a robot with nothing recorded is left out). */
export function withShelf(file: ShelfFile, shelf: RobotShelf): ShelfFile {
  const others = file.robots.filter((r) => r.robot !== shelf.robot);
  return { ...file, robots: shelf.slots.length > 0 ? [...others, shelf] : others };
}
