import type { AccelerometerNoise } from "./sim-sensors.ts";
import type { SimulatedRbcOptions } from "./sim-types.ts";
import { SimulatedRbc } from "./simulated-rbc.ts";

/**
 * The demo robot's world, one for every demo robot: the panel's ("Demo robot" in the connect card) and the
 * CLI's (`--demo`). A HUNO standing upright on a table: its accelerometer reads gravity on Z with a little
 * seeded noise, as a real one does, so a reading looks alive and not like a dead sensor's 0, 0, 0; nothing is
 * in front of its distance sensor (10 cm, the firmware's "nothing seen"); the room is quiet.
 *
 * Unit tests keep using a plain `SimulatedRbc`, whose sensors read exactly what the test sets.
 */

/** The upright robot's accelerometer reading before noise (X, Y, Z; Z carries gravity). */
export const DEMO_ACCELEROMETER = { x: 2, y: -4, z: 62 } as const;
/** Each axis moves by up to this much from one reading to the next. */
export const DEMO_ACCELEROMETER_NOISE = 3;

/** The world's options for a `SimulatedRbc`: a new noise seed each time unless `seed` is given. */
export function demoWorldOptions(seed: number = Date.now() & 0xffff): {
  accelerometerNoise: AccelerometerNoise;
} {
  return { accelerometerNoise: { seed, amplitude: DEMO_ACCELEROMETER_NOISE } };
}

/**
 * A simulated RBC in the demo world: `options` (clock, firmware variant, …) as for `new SimulatedRbc`, with
 * the world's accelerometer noise unless `options` sets its own.
 */
export function createDemoRbc(options: SimulatedRbcOptions = {}): SimulatedRbc {
  const sim = new SimulatedRbc({ ...demoWorldOptions(), ...options });
  const { x, y, z } = DEMO_ACCELEROMETER;
  sim.setAccelerometer(x, y, z);
  return sim;
}
