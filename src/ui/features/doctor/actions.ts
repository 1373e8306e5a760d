import type { ScanResult, SetIdResult } from "../../../device/servo-doctor/index.ts";
import { type Said, said } from "../../../i18n/said.ts";
import type { AppContext } from "../../context.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { stopAll } from "../../stop-all.ts";
import { doctorMessages } from "./messages.ts";
import { ALL_SERVO_IDS, checkFixIds, HUNO_SERVO_IDS, suggestedFix } from "./model.ts";
import { type DoctorFix, type DoctorState, doctorOf, patchDoctor } from "./state.ts";

/**
 * The Servo check's actions, each on the device's servo doctor (src/device/servo-doctor): a scan, one servo's
 * settings, the wiggle test, the guided id fix. The device enters direct mode only when the robot is idle and
 * leaves it at the end; Stop (the top bar's) ends an operation through the device's servo-bus session, and the
 * result says so. One operation at a time.
 */

/**
 * The device's servo doctor and the words of failures load when an operation starts, not with the view: the
 * view's first draw (and the page's list of what each view needs) stays free of the device's servo code.
 */
const servoDoctor = async () => (await import("../../robot-link.ts")).servoDoctor;
const failureWords = () => import("../../failure-words.ts");

/** The operation under way on this connection: its cancel, and the id fix's one question while it is asked. */
class DoctorRun implements Controller {
  private abort: AbortController | undefined;
  private answer: ((yes: boolean) => void) | undefined;

  start(): AbortSignal {
    this.abort = new AbortController();
    return this.abort.signal;
  }

  cancel(): void {
    this.abort?.abort();
    this.answer?.(false);
  }

  /** Waits for the person's answer to the id fix's question (false when cancelled or the connection ends). */
  ask(): Promise<boolean> {
    return new Promise((resolve) => {
      this.answer = resolve;
    });
  }

  reply(yes: boolean): void {
    const answer = this.answer;
    this.answer = undefined;
    answer?.(yes);
  }

  dispose(): void {
    this.cancel();
  }
}

const DOCTOR_RUN = controllerKey("servo check", () => new DoctorRun());

/**
 * A scan the lost link ended (a cable pulled), kept for the page: the view of that connection is gone with it,
 * so the next connection's view says which ids were read before the link was lost.
 */
class LostScan implements Controller {
  result: ScanResult | undefined;

  dispose(): void {
    this.result = undefined;
  }
}

const LOST_SCAN = controllerKey("servo check: scan ended by a lost link", () => new LostScan());

/** The scan a lost link ended, on an earlier connection of this page, if any. */
export function lostScanOf(ctx: AppContext): ScanResult | undefined {
  return ctx.session.pageScope.peek(LOST_SCAN)?.result;
}

function runOf(ctx: AppContext): DoctorRun {
  return ctx.session.connectionScope.get(DOCTOR_RUN);
}

/** The Servo check's name while it works (worded in the language of the moment). */
function label(_ctx: AppContext): Said {
  return said(doctorMessages, "doctor.title");
}

/** A failure of the operation: the robot refusing direct mode (not idle) offers Stop beside it. */
async function failed(ctx: AppContext, e: unknown): Promise<void> {
  // The device's codes (RbcError), read without loading its error classes here.
  const code = e instanceof Error && "code" in e ? e.code : undefined;
  const refused = code === "wrong-mode" || code === "not-idle";
  const { failureNotice } = await failureWords();
  const notice = failureNotice(said(doctorMessages, "doctor.failed"), e, ctx.store.get().locale);
  patchDoctor(ctx.store, { busy: undefined, scanning: undefined, notice, refused });
}

/** Starts an operation if none runs: marks it busy and clears the last refusal. */
function begin(
  ctx: AppContext,
  busy: NonNullable<DoctorState["busy"]>,
  patch: Partial<DoctorState> = {},
): boolean {
  if (doctorOf(ctx.store.get()).busy || !ctx.session.current) return false;
  patchDoctor(ctx.store, { busy, notice: undefined, refused: false, ...patch });
  return true;
}

export function setAllIds(ctx: AppContext, allIds: boolean): void {
  patchDoctor(ctx.store, { allIds });
}

/** Scans ids 0-15 (or all 31), one reading at a time into the table and the figure as it comes. */
export async function scan(ctx: AppContext): Promise<void> {
  const ids = [...(doctorOf(ctx.store.get()).allIds ? ALL_SERVO_IDS : HUNO_SERVO_IDS)];
  if (!begin(ctx, "scan", { scanning: { ids, readings: [] } })) return;
  const lost = ctx.session.pageScope.get(LOST_SCAN);
  lost.result = undefined;
  const signal = runOf(ctx).start();
  try {
    const { scanServos } = await servoDoctor();
    const result = await ctx.session.run(
      label(ctx),
      (client) =>
        scanServos(client, {
          ids,
          signal,
          onProgress: ({ reading }) =>
            patchDoctor(ctx.store, (d) => ({
              scanning: { ids, readings: [...(d.scanning?.readings ?? []), reading] },
            })),
        }),
      { packetMode: false },
    );
    if (result.stopped?.code === "disconnected") lost.result = result;
    patchDoctor(ctx.store, (d) => {
      const fix = suggestedFix(result);
      const empty = d.fix.from === "" && d.fix.to === "";
      const garbled = result.servos.filter((r) => r.status === "garbled").map((r) => r.id);
      return {
        busy: undefined,
        scanning: undefined,
        scan: result,
        scanCleared: undefined,
        // A scan with nothing to report ends what was asked to be unplugged (it is all back, or never was).
        shared: result.findings.length === 0 ? [] : [...new Set([...(d.shared ?? []), ...garbled])],
        fix: fix && empty ? { from: String(fix.from), to: String(fix.to) } : d.fix,
      };
    });
  } catch (e) {
    await failed(ctx, e);
  }
}

/** Cancel: the scan or wiggle under way stops before its next command; the id fix's question says no. */
export function cancel(ctx: AppContext): void {
  ctx.session.connectionScope.peek(DOCTOR_RUN)?.cancel();
}

/** Stop, offered beside a refusal: the top bar's Stop. */
export function stopRobot(ctx: AppContext): void {
  void stopAll(ctx);
}

/** Picks a servo for a closer look (from the table or the figure). */
export function pick(ctx: AppContext, id: number): void {
  patchDoctor(ctx.store, (d) =>
    d.picked === id ? {} : { picked: id, info: undefined, wiggle: undefined, wiggleAsked: false },
  );
}

/** Reads the picked servo's status and settings. */
export async function readInfo(ctx: AppContext): Promise<void> {
  const id = doctorOf(ctx.store.get()).picked;
  if (id === undefined || !begin(ctx, "info", { info: undefined })) return;
  const signal = runOf(ctx).start();
  try {
    const { servoInfo } = await servoDoctor();
    const info = await ctx.session.run(label(ctx), (client) => servoInfo(client, id, { signal }), {
      packetMode: false,
    });
    patchDoctor(ctx.store, { busy: undefined, info });
  } catch (e) {
    await failed(ctx, e);
  }
}

export function askWiggle(ctx: AppContext, asked: boolean): void {
  patchDoctor(ctx.store, { wiggleAsked: asked });
}

/** The wiggle test, after its question was answered. */
export async function wiggle(ctx: AppContext): Promise<void> {
  const id = doctorOf(ctx.store.get()).picked;
  if (id === undefined || !begin(ctx, "wiggle", { wiggle: undefined, wiggleAsked: false })) return;
  const signal = runOf(ctx).start();
  try {
    const { wiggleServo, WIGGLE_COUNTS } = await servoDoctor();
    const result = await ctx.session.run(label(ctx), (client) => wiggleServo(client, id, { signal }), {
      packetMode: false,
    });
    patchDoctor(ctx.store, { busy: undefined, wiggle: { result, counts: WIGGLE_COUNTS } });
  } catch (e) {
    await failed(ctx, e);
  }
}

export function editFix(ctx: AppContext, patch: Partial<Pick<DoctorFix, "from" | "to">>): void {
  patchDoctor(ctx.store, (d) => ({ fix: { ...d.fix, ...patch, problem: undefined } }));
}

/**
 * The guided id fix: the device checks (one servo at FROM, none at TO), the view asks once, the device sends the
 * id set and reads both ids after; its outcome says what it read either way.
 */
export async function fixId(ctx: AppContext): Promise<void> {
  const d = doctorOf(ctx.store.get());
  const checked = checkFixIds(d.fix);
  if ("problem" in checked) {
    patchDoctor(ctx.store, { fix: { ...d.fix, problem: checked.problem, result: undefined } });
    return;
  }
  const fix: DoctorFix = { from: d.fix.from, to: d.fix.to };
  if (!begin(ctx, "fix", { fix })) return;
  const run = runOf(ctx);
  const signal = run.start();
  try {
    const { setServoId } = await servoDoctor();
    const result = await ctx.session.run(
      label(ctx),
      (client) =>
        setServoId(client, checked.from, checked.to, {
          signal,
          confirm: (asking) => {
            patchDoctor(ctx.store, (x) => ({ fix: { ...x.fix, asking } }));
            return run.ask();
          },
        }),
      { packetMode: false },
    );
    patchDoctor(ctx.store, (x) => ({
      busy: undefined,
      fix: { ...x.fix, asking: undefined, result },
      // More than one servo at FROM: the guide asks to unplug the others (its ending names them again).
      ...(result.outcome === "refused" && result.reason === "from-garbled"
        ? { shared: [...new Set([...(x.shared ?? []), result.from])] }
        : {}),
      // An id set was sent: the scan taken before it no longer shows the bus, and is cleared (the view says so).
      ...(idSetSent(result)
        ? {
            scan: undefined,
            scanCleared: {
              from: result.from,
              to: result.to,
              silent: (x.scan?.servos ?? [])
                .filter((r) => r.status === "silent" && r.id !== result.from && r.id !== result.to)
                .map((r) => r.id),
            },
          }
        : {}),
    }));
  } catch (e) {
    patchDoctor(ctx.store, (x) => ({ fix: { ...x.fix, asking: undefined } }));
    await failed(ctx, e);
  }
}

/** Whether the id fix sent its id set (the servos may have changed since the last scan). */
function idSetSent(result: SetIdResult): boolean {
  return (
    result.outcome === "done" || result.outcome === "failed" || (result.outcome === "stopped" && result.sent)
  );
}

/** The answer to the id fix's one question. */
export function answerFix(ctx: AppContext, yes: boolean): void {
  ctx.session.connectionScope.peek(DOCTOR_RUN)?.reply(yes);
}
