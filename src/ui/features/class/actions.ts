import { said } from "../../../i18n/said.ts";
import { noticeOf } from "../../app-state.ts";
import { CLASS_SLOT } from "../../class-stop.ts";
import type { AppContext } from "../../context.ts";
import { downloadTextFile } from "../../download-file.ts";
import { focusSoon } from "../../focus.ts";
import { choosePort, describePort, webSerial } from "../../serial-ports.ts";
import { stopAll as stopEveryRobot } from "../../stop-all.ts";
import { refreshKnownPorts } from "../connection/index.ts";
import { recordOnRobotShelf } from "../shelf/index.ts";
import { idbBackupStorage } from "../zeros/index.ts";
import { ClassRoom } from "./class-room.ts";
import { testClock } from "./demo-robots.ts";
import { classMessages } from "./messages.ts";
import { idbNameStorage } from "./names.ts";
import type { PackCheck } from "./pack-check.ts";
import {
  PACK_MAX_BYTES,
  PACK_MAX_FILE_BYTES,
  PackFileError,
  packFileName,
  parsePack,
  serializePack,
} from "./pack-file.ts";
import { type ClassState, chosenRobots, classOf, type PackFile, patchClass, patchRobot } from "./state.ts";

/** The Class view's actions: robots in and out, names, the pack, and what is done to all robots. */

/** The class's robots (made when the view is first used; they live as long as the page). */
export function classRoom(ctx: AppContext): ClassRoom {
  const slot = ctx.session.pageScope.get(CLASS_SLOT);
  if (slot.room instanceof ClassRoom) return slot.room;
  const room = new ClassRoom(ctx.store, {
    demoClock: testClock(),
    names: idbNameStorage,
    backups: idbBackupStorage,
    now: () => performance.now(),
    shelf: (key, stored) => recordOnRobotShelf(ctx, key, stored),
  });
  slot.room = room;
  void room.loadKept();
  return room;
}

/** The pack as checked once (kept while the pack is the same list). */
export function packCheck(ctx: AppContext, c: ClassState = classOf(ctx.store.get())): PackCheck {
  return classRoom(ctx).checkedPack(c.pack);
}

/** "Add robot": the browser's port chooser; the chosen port joins the class. Call it straight from a click. */
export function addRobot(ctx: AppContext): void {
  const serial = webSerial();
  if (!serial) return;
  let request: Promise<SerialPort>;
  try {
    request = choosePort(serial, ctx.store.get().showAllPorts);
  } catch (e) {
    request = Promise.reject(e);
  }
  request.then(
    (port) => {
      void refreshKnownPorts(ctx.store);
      void classRoom(ctx).addPort(port, describePort(port.getInfo(), ctx.store.get().locale));
    },
    () => {
      // Closed without choosing: nothing changes.
    },
  );
}

/** A port the browser remembers, connected with one click. */
export function addKnownPort(ctx: AppContext, port: SerialPort): void {
  void classRoom(ctx).addPort(port, describePort(port.getInfo(), ctx.store.get().locale));
}

export function addDemoRobot(ctx: AppContext): void {
  void classRoom(ctx).addDemo();
}

export function removeRobot(ctx: AppContext, id: number): void {
  void classRoom(ctx).remove(id);
}

export function refreshRobot(ctx: AppContext, id: number): void {
  void classRoom(ctx).readFacts(id);
}

export function setSelected(ctx: AppContext, id: number, selected: boolean): void {
  patchRobot(ctx.store, id, { selected });
}

export function selectAll(ctx: AppContext, selected: boolean): void {
  patchClass(ctx.store, (c) => ({ robots: c.robots.map((r) => ({ ...r, selected })) }));
}

export function startNaming(ctx: AppContext, id: number): void {
  patchClass(ctx.store, { naming: id });
  focusSoon(`class-name-${id}`);
}

export function cancelNaming(ctx: AppContext, id: number): void {
  patchClass(ctx.store, { naming: undefined });
  focusSoon(`class-rename-${id}`);
}

export function saveName(ctx: AppContext, id: number, serialNumber: string, typed: string): void {
  void classRoom(ctx).setName(serialNumber, typed);
  focusSoon(`class-rename-${id}`);
}

export function chooseBackup(ctx: AppContext, id: string): void {
  patchClass(ctx.store, { backupId: id || undefined });
}

// ---- The pack ------------------------------------------------------------------------------------------

async function readBytes(file: File): Promise<Uint8Array | undefined> {
  return file.size > PACK_MAX_FILE_BYTES ? undefined : new Uint8Array(await file.arrayBuffer());
}

/** .rbm files chosen: they join the pack (a file of the same name replaces its earlier copy). */
export async function addPackFiles(ctx: AppContext, files: readonly File[]): Promise<void> {
  const read = await Promise.all(files.map(async (f) => ({ name: f.name, bytes: await readBytes(f) })));
  const { locale } = ctx.store.get();
  const tooLarge = read.filter((r) => r.bytes === undefined).map((r) => r.name);
  addToPack(
    ctx,
    read.flatMap((r) => (r.bytes ? [{ name: r.name, bytes: r.bytes }] : [])),
  );
  if (tooLarge.length > 0) {
    patchClass(ctx.store, {
      packNotice: noticeOf("warning", locale, [
        said(classMessages, "class.pack.tooLarge", { files: tooLarge.join(", ") }),
      ]),
    });
  }
}

function addToPack(
  ctx: AppContext,
  files: readonly { name: string; bytes: Uint8Array }[],
  replace = false,
): void {
  patchClass(ctx.store, (c) => {
    const names = new Set(files.map((f) => f.name));
    const kept = replace ? [] : c.pack.filter((f) => !names.has(f.fileName));
    const added: PackFile[] = files.map((f, i) => ({
      id: c.nextFileId + i,
      fileName: f.name,
      bytes: f.bytes,
    }));
    return { pack: [...kept, ...added], nextFileId: c.nextFileId + files.length, packNotice: undefined };
  });
}

/** A saved pack opened: it replaces the pack, or a clear error says why not (the pack stays as it was). */
export async function openPack(ctx: AppContext, file: File): Promise<void> {
  const { locale } = ctx.store.get();
  try {
    if (file.size > PACK_MAX_BYTES) throw new PackFileError("too-large", `${file.size} bytes`);
    const files = parsePack(await file.text());
    addToPack(ctx, files, true);
    patchClass(ctx.store, {
      packNotice: noticeOf("info", locale, [
        said(classMessages, "class.pack.opened", { file: file.name, count: files.length }),
      ]),
    });
  } catch (e) {
    const problem = e instanceof PackFileError ? e.problem : "not-json";
    const detail = e instanceof Error ? `${e.name}: ${e.message}` : String(e);
    const key = {
      "too-large": "class.pack.problem.tooLarge",
      "not-json": "class.pack.problem.notJson",
      "not-pack": "class.pack.problem.notPack",
      "wrong-version": "class.pack.problem.wrongVersion",
      damaged: "class.pack.problem.damaged",
    } as const;
    patchClass(ctx.store, {
      packNotice: noticeOf(
        "danger",
        locale,
        [said(classMessages, key[problem], { file: file.name })],
        detail,
      ),
    });
  }
}

export function savePack(ctx: AppContext): void {
  const { pack } = classOf(ctx.store.get());
  if (pack.length === 0) return;
  const name = packFileName(new Date());
  downloadTextFile(
    name,
    serializePack(pack.map((f) => ({ name: f.fileName, bytes: f.bytes }))),
    "application/json",
  );
  patchClass(ctx.store, {
    packNotice: noticeOf("info", ctx.store.get().locale, [
      said(classMessages, "class.pack.saved", { file: name }),
    ]),
  });
}

export function removePackFile(ctx: AppContext, id: number): void {
  patchClass(ctx.store, (c) => ({ pack: c.pack.filter((f) => f.id !== id), packNotice: undefined }));
}

export function clearPack(ctx: AppContext): void {
  patchClass(ctx.store, { pack: [], packNotice: undefined });
}

// ---- Together ------------------------------------------------------------------------------------------

/**
 * Upload pressed: it resets every chosen robot's motion memory, so it asks once for the class first, naming the
 * robots and what is erased (demo robots too: their memory is kept as a real robot's is). Nothing is sent yet.
 */
export function askUpload(ctx: AppContext): void {
  const c = classOf(ctx.store.get());
  if (!packCheck(ctx, c).uploadable || chosenRobots(c).length === 0) return;
  patchClass(ctx.store, { asking: "upload" });
  focusSoon("class-cancel-question");
}

export async function uploadNow(ctx: AppContext): Promise<void> {
  const c = classOf(ctx.store.get());
  const check = packCheck(ctx, c);
  patchClass(ctx.store, { asking: undefined, summary: undefined });
  if (!check.uploadable) return;
  await classRoom(ctx).uploadPack(check);
}

export function cancelRobot(ctx: AppContext, id: number): void {
  classRoom(ctx).cancel(id);
}

export function cancelAll(ctx: AppContext): void {
  classRoom(ctx).cancelAll();
}

export function setRunNumber(ctx: AppContext, number: number): void {
  patchClass(ctx.store, { runNumber: number });
}

/**
 * Run on all pressed: the robots will move, so it asks once for the class first, as the Motions view asks one
 * robot (demo robots too), naming the robots and warning when they are not known to have run Basic posture.
 * Asked every time: the robots chosen change between runs. Nothing is sent yet.
 */
export function askRun(ctx: AppContext): void {
  const c = classOf(ctx.store.get());
  if (chosenRobots(c).length === 0) return;
  patchClass(ctx.store, { asking: "run" });
  focusSoon("class-cancel-question");
}

export async function runNow(ctx: AppContext): Promise<void> {
  const { runNumber } = classOf(ctx.store.get());
  patchClass(ctx.store, { asking: undefined, summary: undefined });
  await classRoom(ctx).runOnAll(runNumber);
}

/** "Stop all": the page's Stop, for every robot of the page (the top-bar robot too); never Limp. */
export function stopAll(ctx: AppContext): void {
  patchClass(ctx.store, { asking: undefined });
  void stopEveryRobot(ctx);
}

/** "Limp all…": asks once, naming how many robots will fall; Cancel is focused first. */
export function askLimp(ctx: AppContext): void {
  if (classRoom(ctx).connectedCount() === 0) return;
  patchClass(ctx.store, { asking: "limp" });
  focusSoon("class-cancel-question");
}

export function limpNow(ctx: AppContext): void {
  patchClass(ctx.store, { asking: undefined });
  void classRoom(ctx).limpAll();
}

export function cancelQuestion(ctx: AppContext): void {
  const { asking } = classOf(ctx.store.get());
  patchClass(ctx.store, { asking: undefined });
  focusSoon(asking === "limp" ? "class-limp" : asking === "run" ? "class-run" : "class-upload");
}
