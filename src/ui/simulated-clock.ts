import { type Clock, realClock } from "../shared/clock.ts";

/**
 * Where a simulated port (the browser tests' fake `navigator.serial`) carries the clock its simulator runs on,
 * so that the client keeps the same time and every duration and timeout keeps its proportions. A real Web
 * Serial port never has it, so a robot on a cable always runs on real time.
 */
export const SIMULATED_CLOCK: unique symbol = Symbol.for("rbc-panel.simulated-clock");

function isClock(value: unknown): value is Clock {
  const c = value as Partial<Clock> | undefined;
  return (
    typeof c?.now === "function" && typeof c.setTimeout === "function" && typeof c.clearTimeout === "function"
  );
}

/** The clock a simulated port says its robot runs on, or real time. */
export function clockOfPort(port: object): Clock {
  const carried: unknown = (port as Record<symbol, unknown>)[SIMULATED_CLOCK];
  return isClock(carried) ? carried : realClock;
}
