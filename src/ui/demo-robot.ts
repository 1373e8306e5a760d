import { MockSerialPort, SimulatedRbc } from "../sim/index.ts";

let currentSim: SimulatedRbc | undefined;

/**
 * The demo robot: a simulated RBC (firmware 2.23, HUNO) behind a mock serial port with a small adapter
 * latency. Its accelerometer reads with a little seeded noise around an upright robot, so the Sensors view
 * shows something alive. Loaded with a dynamic import, so the simulator is not part of the initial bundle.
 */
export function createDemoPort(): MockSerialPort {
  const sim = new SimulatedRbc({ accelerometerNoise: { seed: Date.now() & 0xffff, amplitude: 3 } });
  sim.setAccelerometer(2, -4, 62);
  currentSim = sim;
  return new MockSerialPort(sim, { latencyMs: 2 });
}

/**
 * The simulated RBC of the demo robot created last, so that the Sensors view can "press" its buttons, send IR
 * keys and change what its sensors see. Only meaningful while the demo robot is the connected robot.
 */
export function demoSim(): SimulatedRbc | undefined {
  return currentSim;
}
