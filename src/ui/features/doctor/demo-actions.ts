import type { ServoFaults } from "../../../sim/sim-servo-faults.ts";
import type { ServoBus } from "../../../sim/sim-servos.ts";
import type { AppContext } from "../../context.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import type { DemoFault } from "./state.ts";
import { doctorOf, patchDoctor } from "./state.ts";

/**
 * The demo robot's servo faults, to try the Servo check without a broken robot: the demo robot restarts with
 * new servos carrying the simulator's fault (`ServoFaults`, src/sim/sim-servo-faults.ts), and the session
 * keeps them for the page, so the fault (and an id fixed since) survives a reconnect, as on a real robot.
 * A servo can also be unplugged and plugged back in, as a person does before a guided id fix.
 */

/** What this page chose for the demo robot: kept for the page (page scope), across reconnects. */
class DemoFaultChoice implements Controller {
  fault: DemoFault = { kind: "none", id: 0 };
  /** Joints unplugged from this view (plugged back by "Plug every servo back in"). */
  unplugged: number[] = [];

  /** Nothing to release: the choice is data, and the servos are the session's. */
  dispose(): void {}
}

const DEMO_FAULT = controllerKey("demo servo fault", () => new DemoFaultChoice());

/** The demo robot's servos while the demo robot is the connected robot; undefined for a robot on a cable. */
export function demoBusOf(ctx: AppContext): ServoBus | undefined {
  return ctx.session.demoSim ? ctx.session.demoServos : undefined;
}

/** The demo robot's fault as chosen here, and the servos unplugged here. */
export function demoFaultOf(ctx: AppContext): { fault: DemoFault; unplugged: readonly number[] } {
  const choice = ctx.session.pageScope.peek(DEMO_FAULT);
  if (choice) return { fault: choice.fault, unplugged: choice.unplugged };
  // Nothing chosen in this page: the demo robot's servos may carry a fault kept from before a reload.
  return { fault: faultOfServos(demoBusOf(ctx)?.faults), unplugged: [] };
}

/** The fault a set of the simulator's faults stands for, as the view offers them (one kind, one servo). */
function faultOfServos(faults: ServoFaults | undefined): DemoFault {
  for (const kind of ["replacement", "missing", "duplicate", "loaded"] as const) {
    const id = faults?.[kind]?.[0];
    if (id !== undefined) return { kind, id };
  }
  return { kind: "none", id: 0 };
}

/** The simulator's faults for a choice (a replacement of servo 0 is no fault: servo 0 is at id 0). */
export function servoFaultsOf(fault: DemoFault): ServoFaults {
  if (fault.kind === "none" || (fault.kind === "replacement" && fault.id === 0)) return {};
  return { [fault.kind]: [fault.id] };
}

/** Restarts the demo robot with `fault` on new servos (healthy ones for "none"). */
export async function restartWithFault(ctx: AppContext, fault: DemoFault): Promise<void> {
  if (!demoBusOf(ctx) || doctorOf(ctx.store.get()).busy) return;
  patchDoctor(ctx.store, { busy: "demo" });
  const { demoServoBus } = await import("../../demo-robot.ts");
  ctx.session.demoServos = demoServoBus(servoFaultsOf(fault));
  const connected = await ctx.session.connectDemo({
    bluetooth: ctx.store.get().connection.robot?.link === "bluetooth",
  });
  // The servos are the session's now, connected or not: the next connection of the demo robot gets them.
  const choice = ctx.session.pageScope.get(DEMO_FAULT);
  choice.fault = fault;
  choice.unplugged = [];
  // The new connection started the view afresh (when it failed, the connection card says why).
  patchDoctor(ctx.store, connected ? {} : { busy: undefined });
}

/** Unplugs joint `joint`'s servo from the demo robot's bus, or plugs every servo unplugged here back in. */
export function plug(ctx: AppContext, joint: number | "all-back"): void {
  const bus = demoBusOf(ctx);
  if (!bus) return;
  const choice = ctx.session.pageScope.get(DEMO_FAULT);
  if (joint === "all-back") {
    for (const j of choice.unplugged) bus.connect(j, true);
    choice.unplugged = [];
  } else if (bus.connect(joint, false) && !choice.unplugged.includes(joint)) {
    choice.unplugged = [...choice.unplugged, joint];
  }
  // The store holds no part of the simulator: redraw so the view shows the change.
  patchDoctor(ctx.store, {});
}
