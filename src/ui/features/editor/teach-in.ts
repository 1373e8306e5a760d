/**
 * Teach-in's actions (issue #12 item 3): enter servo control, make the chosen limbs limp, pose them by hand
 * (on the demo robot with sliders), read the robot's pose into the selected scene, hold, end. Nothing but the
 * chosen servos is ever made passive; Stop (top bar) cancels what is queued and never makes a servo passive.
 */
import { RbcCancelledError, RbcTimeoutError } from "../../../device/errors.ts";
import { MotionError, PLATFORM_PF2, setPose } from "../../../motion/index.ts";
import { HUNO_SERVO_IDS } from "../../../protocol/servo-limits.ts";
import type { SimulatedRbc } from "../../../sim/simulated-rbc.ts";
import type { AppContext } from "../../context.ts";
import { errorMessage, errorNotice, technicalDetail } from "../../error-text.ts";
import { focusSoon } from "../../focus.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import type { EditorHost } from "./host.ts";
import { type Limb, liveOf, patchTeachIn, sceneNumber, teachInOn } from "./live-state.ts";
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
  patchTeachIn(store, {
    phase: "starting",
    notice: undefined,
    passive: [],
    silent: [],
    confirmingAll: false,
  });
  const state = store.get();
  let robotZeros = liveOf(state).teach.robotZeros ?? state.zeros.stored;
  // The zeros are read in packet mode. Leaving servo control to read them changes nothing on the servos, but
  // after Limp the panel would no longer know that every servo is limp: then the positions are stored as read.
  const readZeros = robotZeros === undefined && !(client.mode === "direct" && state.connection.limp === true);
  try {
    await session.run(
      "Starting teach-in",
      async (c) => {
        if (readZeros) {
          if (c.mode === "direct") await c.exitDirectMode();
          robotZeros = await c.readZeros().catch(() => undefined);
        }
        await c.enterDirectMode();
      },
      { packetMode: false },
    );
  } catch (e) {
    patchTeachIn(store, {
      phase: "off",
      notice: errorNotice(
        `Teach-in could not start; the robot is ${session.current?.mode === "direct" ? "in servo control" : "in its normal mode"} and no servo was made limp.`,
        e,
      ),
    });
    return;
  }
  const limp = store.get().connection.limp === true;
  patchTeachIn(store, {
    phase: "on",
    robotZeros,
    notice: {
      tone: limp ? "warning" : "info",
      text: limp
        ? "Teach-in is on (servo control). Every servo is limp (Limp): hold the robot, pose it, then read the pose or press Hold."
        : "Teach-in is on (servo control): choose the limbs to pose by hand and press Make limp. Every servo holds until then.",
    },
  });
  const sim = session.demoSim;
  if (sim) {
    session.connectionScope.get(TEACH_IN_WATCH).follow(sim);
    return;
  }
  try {
    const { silent } = await readPositions(ctx);
    if (silent.length > 0) {
      patchTeachIn(store, {
        notice: {
          tone: "warning",
          text: `Teach-in is on, but servo ${silent.join(", ")} did not answer: check ${silent.length === 1 ? "its cable" : "their cables"}.`,
        },
      });
    }
  } catch (e) {
    patchTeachIn(store, { notice: errorNotice("Teach-in is on, but reading the servos failed.", e) });
  }
}

/** Reads every servo (hardware: the live pose is the last read). */
async function readPositions(
  ctx: AppContext,
): Promise<{ reads: { id: number; position: number }[]; silent: number[] }> {
  const { servos, silent } = await ctx.session.run(
    "Teach-in: reading the servos",
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
  const done: number[] = [];
  const silent: number[] = [];
  let stopped = false;
  try {
    await session.run(
      "Teach-in: making servos limp",
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
      patchTeachIn(store, (t) => ({
        busy: undefined,
        passive: merge(t.passive, done),
        notice: {
          tone: "danger",
          text: `Making servos limp failed: ${errorMessage(e)} ${done.length > 0 ? `Servo ${done.join(", ")} went limp; hold the robot.` : "No servo went limp."}`,
          detail: technicalDetail(e),
        },
      }));
      return;
    }
    stopped = true;
  }
  patchTeachIn(store, (t) => ({
    busy: undefined,
    passive: merge(t.passive, done),
    silent,
    notice: limpNotice(done, silent, stopped),
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
    patchTeachIn(ctx.store, {
      notice: {
        tone: "warning",
        text: `Servo ${id} holds its position (torque on): make it limp first to pose it by hand.`,
      },
    });
  }
}

/** "Read pose into scene N": reads every servo and puts the positions into the scene's end pose (one undo step). */
export async function readIntoScene(ctx: AppContext, host: EditorHost): Promise<void> {
  const { store } = ctx;
  if (!teachInOn(store.get()) || liveOf(store.get()).teach.busy) return;
  const scene = host.scene;
  patchTeachIn(store, { busy: "reading", notice: undefined });
  try {
    const { reads, silent } = await readPositions(ctx);
    const teach = liveOf(store.get()).teach;
    const platform = store.get().connection.platform;
    const reading = sceneReading(host.doc, reads, teach.robotZeros, platform);
    if (reading.pose.size > 0) {
      host.commit(setPose(host.doc, scene, reading.pose), `Read pose into scene ${sceneNumber(scene)}`);
    }
    patchTeachIn(store, {
      busy: undefined,
      notice: readNotice(scene, reading, silent, teach.robotZeros !== undefined || platform === PLATFORM_PF2),
    });
  } catch (e) {
    patchTeachIn(store, {
      busy: undefined,
      notice:
        e instanceof MotionError
          ? { tone: "danger", text: `${e.message} The scene did not change.` }
          : errorNotice(`Reading the pose failed; scene ${sceneNumber(scene)} did not change.`, e),
    });
  }
}
