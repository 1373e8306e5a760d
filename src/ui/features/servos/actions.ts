import { RbcError } from "../../../device/errors.ts";
import type { ParamArgs } from "../../../i18n/catalogue.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { type LocalText, type Said, said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { failureNotice } from "../../failure-notice.ts";
import { focusSoon } from "../../focus.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { servosMessages } from "./messages.ts";
import { LatestMoveSender } from "./move-sender.ts";
import {
  basicPostureTargets,
  checkTyped,
  clampToSafe,
  DEFAULT_TORQUE,
  patchServos,
  SERVO_IDS,
  servosOf,
} from "./state.ts";

/**
 * The Servos view's actions: direct mode on and off, reading, moving within safe ranges, basic posture. Their
 * notices are kept as messages (said.ts), worded when drawn, so they follow a language switch.
 */

function wordsOf(ctx: AppContext) {
  const { locale } = ctx.store.get();
  return { locale, t: translator(servosMessages, locale) };
}

const say = <K extends keyof typeof servosMessages & string>(
  key: K,
  ...facts: ParamArgs<(typeof servosMessages)[K], Said | LocalText>
): Said => said(servosMessages, key, ...facts);

/** A servos notice of one message. */
function servoNotice(tone: Notice["tone"], locale: Locale, message: Said): Notice {
  return noticeOf(tone, locale, [message]);
}

function setAt<T>(list: readonly T[], i: number, value: T): T[] {
  const out = [...list];
  out[i] = value;
  return out;
}

export function acknowledgeSafety(ctx: AppContext): void {
  ctx.store.update((s) => ({ acks: { ...s.acks, servos: true } }));
}

interface Move {
  position: number;
  torque: number;
}

/** The servo moves of this connection: one in flight at a time, the latest target per servo wins. */
export class ServoMoves implements Controller {
  readonly sender: LatestMoveSender<Move>;

  constructor(ctx: AppContext) {
    this.sender = new LatestMoveSender(async (id, { position, torque }) => {
      const client = ctx.session.current;
      if (client?.mode !== "direct") {
        this.sender.clear();
        return;
      }
      try {
        const status = await client.servos.move(id, position, torque);
        patchServos(ctx.store, (x) => ({
          positions: setAt(x.positions, id, status.position),
          positionsAt: Date.now(),
          silent: x.silent.filter((s) => s !== id),
        }));
      } catch (e) {
        if (e instanceof RbcError && e.code === "cancelled") {
          this.sender.clear();
          return;
        }
        const { locale } = wordsOf(ctx);
        patchServos(ctx.store, (x) => ({
          notice: failureNotice(say("servos.moveFailed", { id: String(id) }), e, locale),
          silent:
            e instanceof RbcError && e.code === "timeout" && !x.silent.includes(id)
              ? [...x.silent, id]
              : x.silent,
        }));
      }
    });
  }

  dispose(): void {
    this.sender.clear();
  }
}

export const SERVO_MOVES = controllerKey("servo moves", (ctx: AppContext) => new ServoMoves(ctx));

/** Drops the moves still waiting (the move in flight finishes). */
function dropMoves(ctx: AppContext): void {
  ctx.session.connectionScope.peek(SERVO_MOVES)?.sender.clear();
}

export async function startServoControl(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  if (!store.get().acks?.servos || servosOf(store.get()).busy) return;
  const { locale } = wordsOf(ctx);
  patchServos(store, { busy: "entering", notice: undefined });
  try {
    await session.run(said(servosMessages, "servos.starting"), (client) => client.enterDirectMode(), {
      packetMode: false,
    });
    patchServos(store, { busy: undefined });
  } catch (e) {
    patchServos(store, { busy: undefined, notice: failureNotice(say("servos.startFailed"), e, locale) });
    return;
  }
  await readAllPositions(ctx);
}

export async function leaveServoControl(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const { locale } = wordsOf(ctx);
  dropMoves(ctx);
  patchServos(store, { busy: "leaving", notice: undefined, confirmingPosture: false });
  try {
    await session.run(said(servosMessages, "servos.leaving"), (client) => client.exitDirectMode(), {
      packetMode: false,
    });
    patchServos(store, { busy: undefined, notice: servoNotice("info", locale, say("servos.ended")) });
  } catch (e) {
    patchServos(store, { busy: undefined, notice: failureNotice(say("servos.leaveFailed"), e, locale) });
  }
}

export async function readAllPositions(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  if (session.current?.mode !== "direct") return;
  const { locale } = wordsOf(ctx);
  patchServos(store, { busy: "reading" });
  try {
    const { servos, silent } = await session.run(
      said(servosMessages, "servos.readingPositions"),
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
        positionsAt: Date.now(),
        notice:
          silent.length === 0
            ? servoNotice("ok", locale, say("servos.readAllDone", { total: servos.length }))
            : servoNotice(
                "warning",
                locale,
                say("servos.silentServos", {
                  ids: silent.join(", "),
                  read: servos.length,
                  total: SERVO_IDS.length,
                }),
              ),
      };
    });
  } catch (e) {
    patchServos(store, { busy: undefined, notice: failureNotice(say("servos.readFailed"), e, locale) });
  }
}

/**
 * The slider moved (or a checked typed value): move that servo, latest request wins. The slider only gives
 * positions within the safe range; the clamp guards the command layer all the same.
 */
export function moveServo(ctx: AppContext, id: number, position: number): void {
  const target = clampToSafe(id, position);
  const s = servosOf(ctx.store.get());
  const { [id]: _typed, ...drafts } = s.drafts ?? {};
  const { [id]: _refused, ...refused } = s.refused ?? {};
  patchServos(ctx.store, { targets: setAt(s.targets, id, target), drafts, refused, notice: undefined });
  ctx.session.connectionScope
    .get(SERVO_MOVES)
    .sender.request(id, { position: target, torque: s.torques[id] ?? DEFAULT_TORQUE });
}

/**
 * The number box of servo `id` was changed: move it to the typed position. A value outside the servo's safe
 * range, or not a whole number, is refused with a sentence that says why (as the zeros editor does): nothing
 * is sent, and the typed text stays so it can be corrected.
 */
export function applyTypedTarget(ctx: AppContext, id: number, text: string): void {
  const checked = checkTyped(id, text);
  const { locale } = ctx.store.get();
  if ("position" in checked) {
    moveServo(ctx, id, checked.position);
    return;
  }
  patchServos(ctx.store, (x) => ({
    drafts: { ...x.drafts, [id]: text },
    refused: { ...x.refused, [id]: checked.problem },
    notice: servoNotice("danger", locale, checked.problem),
  }));
}

/** Keeps what is being typed into servo `id`'s number box until it is applied (change event). */
export function draftTarget(ctx: AppContext, id: number, text: string): void {
  patchServos(ctx.store, (x) => ({ drafts: { ...x.drafts, [id]: text } }));
}

export function setTorque(ctx: AppContext, id: number, torque: number): void {
  patchServos(ctx.store, (x) => ({ torques: setAt(x.torques, id, Math.max(0, Math.min(4, torque))) }));
}

export async function basicPosture(ctx: AppContext): Promise<void> {
  const { store, session } = ctx;
  const speed = servosOf(store.get()).speed;
  const { locale } = wordsOf(ctx);
  dropMoves(ctx);
  patchServos(store, { busy: "posture", confirmingPosture: false, notice: undefined });
  try {
    await session.run(
      said(servosMessages, "servos.movingToPosture"),
      (client) => client.servos.basicPosture(speed),
      {
        packetMode: false,
      },
    );
    patchServos(store, {
      busy: undefined,
      targets: basicPostureTargets(),
      drafts: {},
      notice: servoNotice(
        "ok",
        locale,
        say("servos.postureSent", { count: SERVO_IDS.length, speed: String(speed) }),
      ),
    });
  } catch (e) {
    patchServos(store, { busy: undefined, notice: failureNotice(say("servos.postureFailed"), e, locale) });
  }
}

/** "All to basic posture…": asks once, in place. */
export function askForPosture(ctx: AppContext): void {
  patchServos(ctx.store, { confirmingPosture: true });
  focusSoon("confirm-posture");
}

export function cancelPosture(ctx: AppContext): void {
  patchServos(ctx.store, { confirmingPosture: false });
}

export function setPostureSpeed(ctx: AppContext, speed: number): void {
  patchServos(ctx.store, { speed });
}

/** "Show the robot in 3D" / "Hide the robot in 3D" (kept for the connection). */
export function toggleLiveRobot(ctx: AppContext): void {
  patchServos(ctx.store, (x) => ({ robot3dShown: !x.robot3dShown }));
}

/** The view is left (or the robot disconnected, which ends the sender with its scope): drop waiting moves. */
export function dropPendingMoves(ctx: AppContext): void {
  dropMoves(ctx);
}
