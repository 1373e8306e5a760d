/**
 * The simulated RBC and its Web Serial look-alikes (docs/protocol.md §9, docs/architecture.md `src/sim/`).
 *
 * SimulatedRbc decisions where the protocol is silent:
 * - Quick replies are sent synchronously from `receive`; the mock port adds wire time and latency.
 * - Requests whose contents should be `01` are dropped with anything else; only the low size byte is checked.
 * - While a motion plays, the interrupt-answered requests are answered at once; 0x16 and the subscriptions wait
 *   for its end (at most 64 of them wait; more are dropped). A Run replaces the key the motion's 0x14 reply
 *   carries (the new motion does not play); a 7 also ends the motion within STOP_SCENE_MS, at the end of its
 *   scene, with one reply and no basic posture (`sim-run-keys.ts`). While a sound plays everything is
 *   dropped. Run Motion numbers other than 1-11, 12-21 and 33-42 (0, 0x2B, 0x31, ...) get no reply.
 * - A motion started from the remote (`playFromRemote`, `busyMotion`) sends no 0x14 reply at its end unless a
 *   Run arrived meanwhile. With silent servos only built-in motions hold error 11; the "user" build's flash
 *   demo (21) plays built-in motion 9's frames.
 * - An accepted zero write, download first part or motion start resets the error code to FF.
 * - Any header from the PC ends the running subscription, 0x19 included.
 * - A download abandons after 1 s of silence (no error code); downloaded files survive 0x1F and a power
 *   cycle (EEPROM) until a later download into the same slot replaces them.
 * - A playing motion moves the servos frame by frame (docs/protocol.md §10; `sim-motion-playback.ts`): downloaded
 *   motions from their image, built-in motions 1-11 from a few keyframes each (`sim-builtin-motions.ts`). Wire
 *   commands (wCK moves, synchronised moves) move servos at once. A passive servo can be posed by hand
 *   (`poseByHand`); `onServos` tells watchers of every change. See docs/architecture.md, "The simulated robot
 *   moves".
 *
 * - The servo bus (`sim-servos.ts`) routes every wCK command by bus id: a motion's frames too, so a replacement
 *   servo at id 0 follows servo 0. Two servos answering one command collide (`collide`): each starts a byte
 *   after the other and overlapping bytes carry their AND, so two pairs arrive as 3 bytes, never a clean pair.
 *   A loaded servo reports load LOADED_SERVO_LOAD while it holds and makes 40% of each move. Moves stop at the
 *   servo's bounds. Factory values of gains, speed and overload are not documented: DEFAULT_SERVO_PARAMETERS.
 *   Id sets, stored gains and overload last through a power cycle (the servo's EEPROM); bounds of ids 0-15 go
 *   back to 1..254 and power-up-only sets fall back. A servo set to another baud rate answers nothing.
 *
 * MockSerialPort follows Chrome: open() rejects InvalidStateError when open, TypeError on bad options,
 * NetworkError while unplugged; close() rejects TypeError while a stream is locked and InvalidStateError when
 * the port is not open (also after a cable pull, which closes the port by itself).
 */
export {
  createDemoRbc,
  DEMO_ACCELEROMETER,
  DEMO_ACCELEROMETER_NOISE,
  demoWorldOptions,
} from "./demo-world.ts";
export { FakeSerial } from "./fake-serial.ts";
export {
  BYTE_TIME_MS,
  bluetoothLinkOptions,
  DEFAULT_BUFFER_SIZE,
  type MockSerialPortOptions,
  type MockSerialPortStats,
  type OpenedOptions,
  type PortInfo,
  RBC_BAUD_RATE,
  SPP_SERVICE_CLASS_ID,
} from "./mock-serial-options.ts";
export { MockSerialPort, type SimEndpoint } from "./mock-serial-port.ts";
export { type FaultedReply, PortFaults, type ReplyFault } from "./port-faults.ts";
export {
  type BootloaderFaults,
  type BootloaderMode,
  BootloaderRbc,
  type BootloaderRbcOptions,
  type BootloaderStats,
  demoFirmwareHex,
  firmwareMarker,
} from "./sim-bootloader.ts";
export { BUILT_IN_KEYFRAMES, builtInPlayback } from "./sim-builtin-motions.ts";
export type { DownloadProgress } from "./sim-downloader.ts";
export type { StoredFile } from "./sim-downloads.ts";
export {
  checkLastingMemory,
  type SimAreaMemory,
  type SimLastingMemory,
  type SimServoMemory,
  servoBusFromMemory,
} from "./sim-memory.ts";
export {
  buildPlayback,
  imagePlayback,
  type PlaybackInput,
  type SimFrame,
  type SimPlayback,
  type SimScene,
} from "./sim-motion-playback.ts";
export { DEFAULT_DOWNLOADED_MOTION_MS, STOP_SCENE_MS } from "./sim-player.ts";
export type { DropReason } from "./sim-receiver.ts";
export {
  ERROR_SERVO_SILENT,
  SERVOS_SILENT_RUN_MS,
  USER_ENDLESS_WALK,
  USER_FLASH_DEMO,
} from "./sim-run-keys.ts";
export {
  type AccelerometerNoise,
  FIRMWARE_SOUND_EVENT_INTERVAL_MS,
  type SensorState,
  type SubscriptionType,
} from "./sim-sensors.ts";
export {
  collide,
  LOADED_SERVO_FOLLOW,
  LOADED_SERVO_LOAD,
  type ServoFaults,
} from "./sim-servo-faults.ts";
export { DEFAULT_SERVO_PARAMETERS } from "./sim-servo-parameters.ts";
export type { ServoListener } from "./sim-servo-watch.ts";
export { ServoBus, type ServoState } from "./sim-servos.ts";
export {
  DEFAULT_SERIAL_NUMBER,
  type SimulatedRbcOptions,
  type SimulatedRbcState,
  type SimulatedRbcStats,
} from "./sim-types.ts";
export { SimulatedRbc } from "./simulated-rbc.ts";
