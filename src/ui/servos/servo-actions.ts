import { DirectMode } from "../../device/direct-mode.ts";
import { RbcError } from "../../device/errors.ts";
import { HUNO_BASIC_POSTURE, HUNO_SERVO_COUNT } from "../../protocol/servo-limits.ts";
import type { AppState } from "../app-state.ts";
import { errorNotice } from "../error-text.ts";
import type { Session } from "../session.ts";
import type { Store } from "../store.ts";
import { LatestMoveSender } from "./move-sender.ts";
import type { ServosState } from "./servos-state.ts";

/** The Servos view's actions: direct mode on and off, reading, moving within safe ranges, basic posture. */

interface Ctx {
  session: Session;
  store: Store<AppState>;
}

export const SERVO_IDS: readonly number[] = Array.from({ length: HUNO_SERVO_COUNT }, (_, i) => i);
export const DEFAULT_TORQUE = 2;

export function clampToSafe(id: number, position: number): number {
  const { min, max } = DirectMode.safeRange(id);
  return Math.max(min, Math.min(max, Math.round(position)));
}

export function servosOf(s: AppState): ServosState {
  return (
    s.servos ?? {
      positions: SERVO_IDS.map(() => undefined),
      targets: SERVO_IDS.map((id) => clampToSafe(id, HUNO_BASIC_POSTURE[id] ?? 127)),
      torques: SERVO_IDS.map(() => DEFAULT_TORQUE),
      silent: [],
      confirmingPosture: false,
      speed: 4,
    }
  );
}

export function patchServos(
  store: Store<AppState>,
  p: Partial<ServosState> | ((x: ServosState) => Partial<ServosState>),
): void {
  store.update((s) => {
    const cur = servosOf(s);
    return { servos: { ...cur, ...(typeof p === "function" ? p(cur) : p) } };
  });
}

function setAt<T>(list: readonly T[], i: number, value: T): T[] {
  const out = [...list];
  out[i] = value;
  return out;
}

export function acknowledgeSafety(store: Store<AppState>): void {
  store.update((s) => ({ acks: { ...s.acks, servos: true } }));
}

let sender: LatestMoveSender<{ position: number; torque: number }> | undefined;
let senderFor: Ctx | undefined;

function moveSender(ctx: Ctx) {
  if (!sender || senderFor?.session !== ctx.session) {
    senderFor = ctx;
    sender = new LatestMoveSender(async (id, { position, torque }) => {
      const client = ctx.session.current;
      if (client?.mode !== "direct") {
        sender?.clear();
        return;
      }
      try {
        const status = await client.servos.move(id, position, torque);
        ctx.session.servosTaken();
        patchServos(ctx.store, (x) => ({
          positions: setAt(x.positions, id, status.position),
          silent: x.silent.filter((s) => s !== id),
        }));
      } catch (e) {
        if (e instanceof RbcError && e.code === "cancelled") {
          sender?.clear();
          return;
        }
        patchServos(ctx.store, (x) => ({
          notice: errorNotice(`Servo ${id} did not take the move.`, e),
          silent:
            e instanceof RbcError && e.code === "timeout" && !x.silent.includes(id)
              ? [...x.silent, id]
              : x.silent,
        }));
      }
    });
  }
  return sender;
}

export async function startServoControl(ctx: Ctx): Promise<void> {
  const { store, session } = ctx;
  if (!store.get().acks?.servos || servosOf(store.get()).busy) return;
  patchServos(store, { busy: "entering", notice: undefined });
  try {
    await session.run("Starting servo control", (client) => client.enterDirectMode(), { packetMode: false });
    patchServos(store, { busy: undefined });
  } catch (e) {
    patchServos(store, { busy: undefined, notice: errorNotice("Servo control could not start.", e) });
    return;
  }
  await readAllPositions(ctx);
}

export async function leaveServoControl(ctx: Ctx): Promise<void> {
  const { store, session } = ctx;
  sender?.clear();
  patchServos(store, { busy: "leaving", notice: undefined, confirmingPosture: false });
  try {
    await session.run("Leaving servo control", (client) => client.exitDirectMode(), { packetMode: false });
    patchServos(store, {
      busy: undefined,
      notice: {
        tone: "info",
        text: "Servo control ended: the robot is back in its normal mode. The servos keep their last position.",
      },
    });
  } catch (e) {
    patchServos(store, { busy: undefined, notice: errorNotice("Leaving servo control failed.", e) });
  }
}

export async function readAllPositions(ctx: Ctx): Promise<void> {
  const { store, session } = ctx;
  if (session.current?.mode !== "direct") return;
  patchServos(store, { busy: "reading" });
  try {
    const { servos, silent } = await session.run(
      "Reading servo positions",
      (client) => client.servos.readAll(SERVO_IDS),
      { packetMode: false },
    );
    patchServos(store, (x) => {
      const positions = [...x.positions];
      const targets = [...x.targets];
      for (const s of servos) {
        positions[s.id] = s.position;
        targets[s.id] = clampToSafe(s.id, s.position);
      }
      for (const id of silent) positions[id] = undefined;
      return {
        busy: undefined,
        positions,
        targets,
        drafts: {},
        silent,
        readAt: Date.now(),
        notice:
          silent.length === 0
            ? { tone: "ok", text: `Read all ${servos.length} servos.` }
            : {
                tone: "warning",
                text: `Servo ${silent.join(", ")} did not answer (${servos.length} of ${SERVO_IDS.length} read). Check their cables; their controls are disabled.`,
              },
      };
    });
  } catch (e) {
    patchServos(store, { busy: undefined, notice: errorNotice("Reading the servos failed.", e) });
  }
}

/** A slider or number changed: move that servo (clamped to its safe range), latest request wins. */
export function moveServo(ctx: Ctx, id: number, position: number): void {
  const target = clampToSafe(id, position);
  const s = servosOf(ctx.store.get());
  const { [id]: _typed, ...drafts } = s.drafts ?? {};
  patchServos(ctx.store, { targets: setAt(s.targets, id, target), drafts, notice: undefined });
  moveSender(ctx).request(id, { position: target, torque: s.torques[id] ?? DEFAULT_TORQUE });
}

/**
 * The number box of servo `id` was changed: move it to the typed position (clamped to its safe range). An empty
 * or unreadable box moves nothing and shows the current target again.
 */
export function applyTypedTarget(ctx: Ctx, id: number, text: string): void {
  const position = text.trim() === "" ? Number.NaN : Number(text);
  if (Number.isFinite(position)) {
    moveServo(ctx, id, Math.round(position));
    return;
  }
  patchServos(ctx.store, (x) => {
    const { [id]: _typed, ...drafts } = x.drafts ?? {};
    return { drafts };
  });
}

/** Keeps what is being typed into servo `id`'s number box until it is applied (change event). */
export function draftTarget(store: Store<AppState>, id: number, text: string): void {
  patchServos(store, (x) => ({ drafts: { ...x.drafts, [id]: text } }));
}

export function setTorque(store: Store<AppState>, id: number, torque: number): void {
  patchServos(store, (x) => ({ torques: setAt(x.torques, id, Math.max(0, Math.min(4, torque))) }));
}

export async function basicPosture(ctx: Ctx): Promise<void> {
  const { store, session } = ctx;
  const speed = servosOf(store.get()).speed;
  sender?.clear();
  patchServos(store, { busy: "posture", confirmingPosture: false, notice: undefined });
  try {
    await session.run("Moving to basic posture", (client) => client.servos.basicPosture(speed), {
      packetMode: false,
    });
    session.servosTaken();
    patchServos(store, {
      busy: undefined,
      targets: SERVO_IDS.map((id) => clampToSafe(id, HUNO_BASIC_POSTURE[id] ?? 127)),
      drafts: {},
      notice: {
        tone: "ok",
        text: `Sent: all ${SERVO_IDS.length} servos move to the basic posture at speed ${speed}. The servos do not answer this command: press Read all positions to see where they are.`,
      },
    });
  } catch (e) {
    patchServos(store, { busy: undefined, notice: errorNotice("The basic posture command failed.", e) });
  }
}

/** The view is left or the robot disconnected: drop moves still waiting. */
export function dropPendingMoves(): void {
  sender?.clear();
}
