/**
 * Teach-in's actions (issue #12 item 3): enter servo control, make the chosen limbs limp, pose them by hand
 * (on the demo robot with sliders), read the robot's pose into the selected scene, hold, end. Nothing but the
 * chosen servos is ever made passive; Stop (top bar) cancels what is queued and never makes a servo passive.
 */
import { RbcCancelledError, RbcTimeoutError } from "../../../device/errors.ts";
import { errorSaid } from "../../../i18n/error-said.ts";
import { said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { MotionError, PLATFORM_PF2, setPose } from "../../../motion/index.ts";
import { HUNO_SERVO_IDS } from "../../../protocol/servo-limits.ts";
import type { SimulatedRbc } from "../../../sim/simulated-rbc.ts";
import { noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice, technicalDetail } from "../../error-text.ts";
import { focusSoon } from "../../focus.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { isLimp } from "../connection/index.ts";
import type { EditorHost } from "./host.ts";
import { type Limb, liveOf, patchTeachIn, sceneNumber, teachInOn } from "./live-state.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import { refusalWords } from "./refusal-text.ts";
import { choosesAll, chosenIds, limpNotice, readNotice, sceneReading } from "./teach-in-model.ts";

/** The demo robot's servos, watched while teach-in is on (the hand moves them; the 3D view follows). */
export class TeachInWatch implements Controller {
  private stop: (() => void) | undefined;

  constructor(private readonly ctx: AppContext) {}

  /** Follows `sim`'s servo positions into the teach-in state until `end()`. */
  follow(sim: SimulatedRbc): void {
    this.end();
    const update = (positions: readonly number[]): void => {
      if (liveOf(this.ctx.store.get()).teach.phase === "off") return;
      patchTeachIn(this.ctx.store, { positions: HUNO_SERVO_IDS.map((id) => positions[id]) });
    };
    this.stop = sim.onServos((positions) => update(positions));
    update(sim.servoPositions());
  }

  end(): void {
    this.stop?.();
    this.stop = undefined;
  }

  dispose(): void {
    this.end();
  }
}

export const TEACH_IN_WATCH = controllerKey("teach-in watch", (ctx: AppContext) => new TeachInWatch(ctx));

/** Teach-in's words in the panel's language of the moment. */
function words(ctx: AppContext): EditorTranslator {
  return translator(editorMessages, ctx.store.get().locale);
}

/** "Start teach-in": asks first (the chosen servos will go limp). */
export function askTeachIn(ctx: AppContext): void {
  if (!ctx.session.current) return;
  patchTeachIn(ctx.store, { phase: "asking", notice: undefined });
  focusSoon("confirm-teach-in");
}

export function cancelTeachIn(ctx: AppContext): void {
  patchTeachIn(ctx.store, { phase: "off" });
  focusSoon("start-teach-in");
}

/**
 * Teach-in confirmed: reads the robot's zeros unless this connection already has them (in packet mode, so that
 * read positions can be converted to the motion's zeros), enters direct mode, and follows the demo robot's
 * servos or reads every servo of a robot on a cable.
 */
export async function startTeachIn(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const client = session.current;
  if (!client) return;
  const t = words(ctx);
  // `passive` is kept: servos an earlier teach-in made limp and could not hold again are still limp.
  patchTeachIn(store, {
    phase: "starting",
    notice: undefined,
    silent: [],
    confirmingAll: false,
  });
  const state = store.get();
  let robotZeros = liveOf(state).teach.robotZeros ?? state.zeros.stored;
  // The zeros are read in packet mode. Leaving servo control to read them changes nothing on the servos, but
  // after Limp the panel would no longer know that every servo is limp: then the positions are stored as read.
  const readZeros = robotZeros === undefined && !(client.mode === "direct" && isLimp(state.connection));
  try {
    await session.run(
      said(editorMessages, "editor.teach.run.start"),
      async (c) => {
        if (readZeros) {
          if (c.mode === "direct") await c.exitDirectMode();
          robotZeros = await c.readZeros().catch(() => undefined);
        }
        await c.enterDirectMode("teach-in");
      },
      { packetMode: false },
    );
  } catch (e) {
    patchTeachIn(store, {
      phase: "off",
      notice: errorNotice(
        said(
          editorMessages,
          session.current?.mode === "direct"
            ? "editor.teach.startFailedDirect"
            : "editor.teach.startFailedNormal",
        ),
        e,
        t.locale,
      ),
    });
    return;
  }
  const limp = isLimp(store.get().connection);
  patchTeachIn(store, {
    phase: "on",
    robotZeros,
    notice: noticeOf(limp ? "warning" : "info", t.locale, [
      said(editorMessages, limp ? "editor.teach.onAllLimp" : "editor.teach.on"),
    ]),
  });
  const sim = session.demoSim;
  if (sim) {
    session.connectionScope.get(TEACH_IN_WATCH).follow(sim);
    return;
  }
  try {
    const { silent } = await readPositions(ctx);
    if (silent.length > 0) {
      const ids = { ids: silent.join(", ") };
      patchTeachIn(store, {
        notice: noticeOf("warning", t.locale, [
          said(
            editorMessages,
            silent.length === 1 ? "editor.teach.onSilentOne" : "editor.teach.onSilentMany",
            ids,
          ),
        ]),
      });
    }
  } catch (e) {
    patchTeachIn(store, {
      notice: errorNotice(said(editorMessages, "editor.teach.onReadFailed"), e, t.locale),
    });
  }
}

/** Reads every servo (hardware: the live pose is the last read). */
async function readPositions(
  ctx: AppContext,
): Promise<{ reads: { id: number; position: number }[]; silent: number[] }> {
  const { servos, silent } = await ctx.session.run(
    said(editorMessages, "editor.teach.run.read"),
    (c) => c.servos.readAll(HUNO_SERVO_IDS),
    { packetMode: false },
  );
  const reads = servos.map((s) => ({ id: s.id, position: s.position }));
  patchTeachIn(ctx.store, (t) => {
    const positions = [...t.positions];
    for (const r of reads) positions[r.id] = r.position;
    return { positions, silent };
  });
  return { reads, silent };
}

export function toggleLimb(ctx: AppContext, limb: Limb, on: boolean): void {
  patchTeachIn(ctx.store, (t) => ({
    limbs: on ? [...t.limbs.filter((l) => l !== limb), limb] : t.limbs.filter((l) => l !== limb),
    confirmingAll: false,
  }));
}

export function chooseLimbs(ctx: AppContext, limbs: readonly Limb[]): void {
  patchTeachIn(ctx.store, { limbs: [...limbs], confirmingAll: false });
}

/**
 * "Make limp": sends the passive command to exactly the chosen servos. With every servo chosen, asks first
 * (the robot cannot stand): `confirmed` is true when that question was answered.
 */
export async function makeChosenLimp(ctx: AppContext, confirmed = false): Promise<void> {
  const { store, session } = ctx;
  const teach = liveOf(store.get()).teach;
  const ids = chosenIds(teach.limbs);
  if (!teachInOn(store.get()) || ids.length === 0 || teach.busy) return;
  if (choosesAll(teach.limbs) && !confirmed) {
    patchTeachIn(store, { confirmingAll: true });
    focusSoon("cancel-limp-all");
    return;
  }
  patchTeachIn(store, { busy: "limp", confirmingAll: false, notice: undefined });
  const t = words(ctx);
  const done: number[] = [];
  const silent: number[] = [];
  let stopped = false;
  try {
    await session.run(
      said(editorMessages, "editor.teach.run.limp"),
      async (c) => {
        for (const id of ids) {
          try {
            await c.servos.passive(id);
            done.push(id);
          } catch (e) {
            if (!(e instanceof RbcTimeoutError)) throw e;
            silent.push(id);
          }
        }
      },
      { packetMode: false },
    );
  } catch (e) {
    if (!(e instanceof RbcCancelledError)) {
      patchTeachIn(store, (x) => ({
        busy: undefined,
        passive: merge(x.passive, done),
        notice: noticeOf(
          "danger",
          t.locale,
          [
            said(editorMessages, "editor.teach.limpFailed", {
              error: errorSaid(e),
              after:
                done.length > 0
                  ? said(editorMessages, "editor.teach.wentLimp", { ids: done.join(", ") })
                  : said(editorMessages, "editor.teach.noneWentLimp"),
            }),
          ],
          technicalDetail(e),
        ),
      }));
      return;
    }
    stopped = true;
  }
  patchTeachIn(store, (x) => ({
    busy: undefined,
    passive: merge(x.passive, done),
    silent,
    notice: limpNotice(done, silent, stopped, t.locale),
  }));
}

export function cancelLimpAll(ctx: AppContext): void {
  patchTeachIn(ctx.store, { confirmingAll: false });
  focusSoon("make-limp");
}

function merge(a: readonly number[], b: readonly number[]): number[] {
  return [...new Set([...a, ...b])].sort((x, y) => x - y);
}

/** The demo robot's slider: the hand moves a passive servo (the simulator refuses a holding one). */
export function poseByHand(ctx: AppContext, id: number, position: number): void {
  const sim = ctx.session.demoSim;
  if (!sim) return;
  if (!sim.poseByHand(id, position)) {
    const holds = said(editorMessages, "editor.teach.holdsTorque", { id: String(id) });
    patchTeachIn(ctx.store, { notice: noticeOf("warning", ctx.store.get().locale, [holds]) });
  }
}

/** "Read pose into scene N": reads every servo and puts the positions into the scene's end pose (one undo step). */
export async function readIntoScene(ctx: AppContext, host: EditorHost): Promise<void> {
  const { store } = ctx;
  if (!teachInOn(store.get()) || liveOf(store.get()).teach.busy) return;
  const scene = host.scene;
  const t = words(ctx);
  const n = String(sceneNumber(scene));
  patchTeachIn(store, { busy: "reading", notice: undefined });
  try {
    const { reads, silent } = await readPositions(ctx);
    const teach = liveOf(store.get()).teach;
    const platform = store.get().connection.platform;
    const reading = sceneReading(host.doc, reads, teach.robotZeros, platform);
    if (reading.pose.size > 0) {
      host.commit(
        setPose(host.doc, scene, reading.pose),
        said(editorMessages, "editor.teach.readInto", { scene: n }),
      );
    }
    const zerosKnown = teach.robotZeros !== undefined || platform === PLATFORM_PF2;
    patchTeachIn(store, {
      busy: undefined,
      notice: readNotice(scene, reading, silent, zerosKnown, t.locale),
    });
  } catch (e) {
    patchTeachIn(store, {
      busy: undefined,
      notice:
        e instanceof MotionError
          ? noticeOf("danger", t.locale, [
              said(editorMessages, "editor.teach.sceneUnchanged", { reason: refusalWords(e) }),
            ])
          : errorNotice(said(editorMessages, "editor.teach.readFailed", { scene: n }), e, t.locale),
    });
  }
}
