import { COMMANDS } from "../protocol/commands.ts";
import { ACCELEROMETER_TYPE, encodePacket } from "../protocol/packet.ts";
import type { TimerId } from "../shared/clock.ts";
import { seededRandom } from "../shared/random.ts";
import type { SimTimers } from "./sim-timers.ts";

/**
 * The simulated robot's sensors and the event subscriptions 0x17 (sound), 0x18 (buttons) and 0x19 (remote)
 * of docs/protocol.md §3.4. At most one subscription runs: any packet header from the PC ends it.
 */

export const SOUND_TYPE = COMMANDS.subscribeSound.type;
export const BUTTON_TYPE = COMMANDS.subscribeButtons.type;
export const REMOTE_TYPE = COMMANDS.subscribeRemote.type;
/** The type byte of a subscription command (0x17, 0x18 or 0x19). */
export type SubscriptionType = number;

/** While subscribed, sound level events come this often (level >= threshold). */
export const SOUND_EVENT_INTERVAL_MS = 100;
/**
 * The firmware's pace (docs/protocol.md §3.6): its main loop sends a 0x17 event on every pass while the level
 * meets the threshold, about every 3.5 ms (≈ 285 packets/s). The simulator uses it with `firmwareEventPace`.
 */
export const FIRMWARE_SOUND_EVENT_INTERVAL_MS = 3.5;
/** While subscribed and a button is held, button events come this often. */
export const BUTTON_EVENT_INTERVAL_MS = 200;

export interface AccelerometerNoise {
  /** Seed of the deterministic generator. */
  seed: number;
  /** Each axis gets a whole number in [-amplitude, amplitude] added per read. */
  amplitude: number;
}

export interface SensorState {
  distanceCm: number;
  soundLevel: number;
  accelerometer: { x: number; y: number; z: number };
  /** The button held down and until when (clock ms), if any. */
  heldButton: { button: 1 | 2; until: number } | undefined;
  subscription: SubscriptionType | undefined;
  soundThreshold: number | undefined;
}

function clampInt(value: number, min: number, max: number): number {
  return Math.max(min, Math.min(max, Math.round(value)));
}

export class SimSensors {
  distanceCm = 10;
  soundLevel = 0;
  private accel = { x: 0, y: 0, z: 0 };
  private held: { button: 1 | 2; until: number } | undefined;
  private subscription: SubscriptionType | undefined;
  private threshold = 0;
  private timer: TimerId | undefined;
  private readonly noise: { random: () => number; amplitude: number } | undefined;

  constructor(
    private readonly timers: SimTimers,
    /** Sends an event packet [value, 0] of `type` to the PC. */
    private readonly emit: (type: number, contents: Uint8Array) => void,
    noise?: AccelerometerNoise,
    /** Sound events come this often while the level meets the threshold. */
    private readonly soundIntervalMs = SOUND_EVENT_INTERVAL_MS,
  ) {
    this.noise = noise ? { random: seededRandom(noise.seed), amplitude: noise.amplitude } : undefined;
  }

  private get now(): number {
    return this.timers.clock.now();
  }

  get state(): SensorState {
    return {
      distanceCm: this.distanceCm,
      soundLevel: this.soundLevel,
      accelerometer: { ...this.accel },
      heldButton: this.held && this.held.until > this.now ? { ...this.held } : undefined,
      subscription: this.subscription,
      soundThreshold: this.subscription === SOUND_TYPE ? this.threshold : undefined,
    };
  }

  get activeSubscription(): SubscriptionType | undefined {
    return this.subscription;
  }

  /** Distance reading as the firmware reports it: whole cm clamped to 10..50. */
  distanceReading(): number {
    return clampInt(this.distanceCm, 10, 50);
  }

  setAccelerometer(x: number, y: number, z: number): void {
    this.accel = {
      x: clampInt(x, -32768, 32767),
      y: clampInt(y, -32768, 32767),
      z: clampInt(z, -32768, 32767),
    };
  }

  /** One accelerometer reading, with the optional seeded noise. */
  accelerometerReading(): { x: number; y: number; z: number } {
    const n = this.noise;
    if (!n) return { ...this.accel };
    const jitter = () => Math.round((n.random() * 2 - 1) * n.amplitude);
    return {
      x: clampInt(this.accel.x + jitter(), -32768, 32767),
      y: clampInt(this.accel.y + jitter(), -32768, 32767),
      z: clampInt(this.accel.z + jitter(), -32768, 32767),
    };
  }

  /**
   * The 0x1A reply: X, Y, Z signed 16-bit little-endian, with the firmware's checksum quirk (docs/protocol.md §2.1):
   * it covers only the three low bytes.
   */
  accelerometerPacket(platform: number): Uint8Array {
    const { x, y, z } = this.accelerometerReading();
    const c = Uint8Array.of(x & 0xff, (x >> 8) & 0xff, y & 0xff, (y >> 8) & 0xff, z & 0xff, (z >> 8) & 0xff);
    const bytes = encodePacket(ACCELEROMETER_TYPE, c, platform);
    bytes[bytes.length - 1] = c[0]! ^ c[2]! ^ c[4]!;
    return bytes;
  }

  setSoundLevel(level: number): void {
    this.soundLevel = clampInt(level, 0, 255);
  }

  /** Holds `button` for `holdMs`; while subscribed to 0x18 it is reported at once and every 200 ms. */
  pressButton(button: 1 | 2, holdMs: number): void {
    this.held = { button, until: this.now + Math.max(0, holdMs) };
    if (this.subscription === BUTTON_TYPE) {
      this.timers.cancel(this.timer);
      this.buttonTick();
    }
  }

  /** An IR key press: reported as [code, 0] while subscribed to 0x19 (otherwise nothing happens). */
  pressRemoteKey(code: number): void {
    if (this.subscription === REMOTE_TYPE) this.emit(REMOTE_TYPE, Uint8Array.of(code & 0xff, 0));
  }

  subscribe(type: SubscriptionType, threshold = 0): void {
    this.stop();
    this.subscription = type;
    if (type === SOUND_TYPE) {
      // Reported at once, then every 100 ms (or at the firmware's pace): a client that re-arms the
      // subscription often still hears it.
      this.threshold = threshold;
      this.soundTick();
    } else if (type === BUTTON_TYPE) {
      this.buttonTick();
    }
  }

  /** Ends the running subscription (a header arrived, direct mode, power cycle). */
  stop(): void {
    this.timers.cancel(this.timer);
    this.timer = undefined;
    this.subscription = undefined;
  }

  private soundTick(): void {
    if (this.soundLevel >= this.threshold) this.emit(SOUND_TYPE, Uint8Array.of(this.soundLevel, 0));
    this.timer = this.timers.after(this.soundIntervalMs, () => this.soundTick());
  }

  private buttonTick(): void {
    this.timer = undefined;
    const held = this.held;
    if (!held || held.until <= this.now) return;
    this.emit(BUTTON_TYPE, Uint8Array.of(held.button, 0));
    this.timer = this.timers.after(BUTTON_EVENT_INTERVAL_MS, () => this.buttonTick());
  }
}
