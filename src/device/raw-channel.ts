// Over 400 lines: one set of rules for the raw link (download acknowledgements and the servo bus share the wire-
// time and late-reply guards), kept together so that they cannot drift apart.
import type { Clock } from "../shared/clock.ts";
import { type Wait, Waitress } from "../shared/waitress.ts";
import { RbcStillPlayingError } from "./direct-mode-errors.ts";
import { RbcCancelledError, RbcError, RbcTimeoutError } from "./errors.ts";

/** One byte at 115200 baud, 8N1 (10 bits), in ms: 86.8 µs (docs/protocol.md §1). */
export const WIRE_BYTE_MS = 10_000 / 115_200;
/** Slack for the clock's grain (`performance.now()` is coarsened to 0.1 ms in some browsers). */
const CLOCK_SLACK_MS = 0.1;

/** What an exchange waits for. The channel counts the bytes itself (`receive`) and then ends the wait. */
interface RawMatcher {
  need: number;
  accept?: (byte: number) => boolean;
  /** Acknowledgement exchanges only: a matching byte before this clock time is early, not the answer. */
  notBefore?: number;
  /** A listening servo command (`servoListen`): every byte goes here, none is counted. */
  listen?: (byte: number) => void;
}

/** How `servoListen`'s wait ends at its cap (a line that never went quiet): not an error, an outcome. */
const LISTEN_CAP = Symbol("cap");

/**
 * An acknowledgement byte that the conversation did not call for: a second one for the same part, one with no
 * part in flight, or one sooner than its part could have crossed the wire. It is a fault of the line or of
 * the robot, and the protocol has no sequence numbers to tell which part it belongs to.
 */
export class RbcUnexpectedAckError extends RbcError {
  override name = "RbcUnexpectedAckError";
  constructor(
    /** `extra`: no acknowledgement was due; `early`: it came before its part could have reached the robot. */
    readonly kind: "extra" | "early",
    /** The part the conversation was at ("chunk 4 (64 bytes)"), or after. */
    readonly where: string,
  ) {
    // A technical line: the upload that meets it says it for a person (`RbcUploadError`, stop extra-ack/early-ack).
    super("bad-reply", `unexpected acknowledgement (${kind}) ${where}`);
  }
}

/** What the servo bus's rules need from direct mode (see `RawChannel.guardServoBus`). */
export interface ServoBusHost {
  /**
   * The link takes wire time (a real 115200-baud line always does; an unpaced simulator delivers at once):
   * only then is a reply sooner than its bytes take on the wire refused as early.
   */
  paced: boolean;
  /** Bytes nobody asked for arrived: leave direct mode (the leave sequence). Called once, at once. */
  leave: (fault: RbcStillPlayingError) => void;
  /**
   * A reply may still arrive for a command whose wait ended: make sure it has arrived or never will before the
   * next command is written (leave direct mode, a packet request answered, enter again). Rejects when the bus
   * cannot be made quiet; the next command is then not sent.
   */
  fence: () => Promise<void>;
  /**
   * The settle time after entering (docs/protocol.md §3.6): bytes that come meanwhile, before the first servo
   * command, are old servo replies the controller's buffer relayed as direct mode began. They are drained, not
   * judged (the entry waits it out: `drainStale`).
   */
  settleMs: number;
}

/** The servo bus's state in direct mode (see `RawChannel.guardServoBus`). */
interface ServoBusGuard {
  host: ServoBusHost;
  /** A command's wait ended without its whole reply: a late reply may still come. */
  unsettled: boolean;
  /** Bytes that came after their command's wait ended, discarded. */
  late: number;
  /** The first bytes nobody asked for; every later servo exchange fails with it until direct mode is new. */
  fault: RbcStillPlayingError | undefined;
  /** The command in flight or last written, for the messages. */
  last: string;
  /** Until this clock time (and the first command), unasked bytes are drained (`ServoBusHost.settleMs`). */
  drainUntil: number;
}

/** The strict count of acknowledgements during a download (see `RawChannel.guardAcks`). */
interface AckGuard {
  byte: number;
  onUnexpected: (() => void) | undefined;
  /** The first unexpected acknowledgement, kept until the upload asks (it then stops sending). */
  fault: RbcUnexpectedAckError | undefined;
  unexpected: number;
  /** The last part written, for the messages. */
  last: string;
}

/**
 * The byte-level conversation used outside RBC packets: download acknowledgements (one `40` per part) and
 * servo-bus replies (two bytes per wCK command). One exchange at a time; bytes that arrive with no exchange
 * waiting are dropped, except during a guarded download (`guardAcks`), where they are faults.
 */
export class RawChannel {
  private buffer: number[] = [];
  /** The exchange's wait, one at a time. */
  private readonly waits: Waitress<Uint8Array, RawMatcher>;
  private guard: AckGuard | undefined;
  private bus: ServoBusGuard | undefined;
  /** The fault that ended the last servo-bus session, kept until direct mode is entered again. */
  private busFault: RbcError | undefined;

  constructor(
    private readonly clock: Clock,
    private readonly write: (bytes: Uint8Array, note: string) => Promise<void>,
  ) {
    this.waits = new Waitress(clock);
  }

  /** The exchange waiting for its reply, if any. */
  private get waiter(): Wait<Uint8Array, RawMatcher> | undefined {
    return this.waits.pending[0];
  }

  receive(bytes: Uint8Array): void {
    if (this.guard) {
      this.receiveAcks(this.guard, bytes);
      return;
    }
    if (this.bus) {
      this.receiveServo(this.bus, bytes);
      return;
    }
    const waiter = this.waiter;
    if (!waiter) return;
    const { accept, need } = waiter.matcher;
    for (const b of bytes) {
      if (accept && !accept(b)) continue;
      this.buffer.push(b);
    }
    if (this.buffer.length >= need) waiter.resolve(Uint8Array.from(this.buffer.splice(0, need)));
  }

  /**
   * The servo bus's rules in direct mode until `endServoBus()` (docs/protocol.md §3.6 [decision]; issue 20,
   * items 3 and 4). The wCK protocol has no sequence numbers, so:
   * - A reply is accepted only while its command is the one in flight, and no sooner than the command's bytes
   *   and the reply's take on the wire (on a paced link). Bytes with no command in flight, more bytes than the
   *   reply, or bytes sooner than that are nobody's answer: the robot is still playing something (its motion
   *   drives the bus). Direct mode is left at once (`host.leave`) and the exchange fails with
   *   `RbcStillPlayingError`, as does every later one until direct mode is entered again.
   * - A command whose wait ended without its whole reply (timeout, cancel) may still be answered: the bus is
   *   unsettled. Bytes that arrive meanwhile are late and discarded, and before the next command is written the
   *   bus is fenced (`host.fence`: leave direct mode, one packet request answered, enter again). The link keeps
   *   order, so once the fence's packet reply has come, every servo byte sent before it has come too (the
   *   parser discarded it) or never will: a reply can never answer a command sent after it, the same guarantee
   *   as packet mode's fences. A fence that fails fails the command, unsent.
   * - Bytes within the settle time after entering, before the first command, are stale (`host.settleMs`,
   *   §3.6 [decision, turn 4]): drained and logged, not judged. "Still playing" is only what comes after.
   */
  guardServoBus(host: ServoBusHost): void {
    const drainUntil = this.clock.now() + host.settleMs;
    this.bus = {
      host,
      unsettled: false,
      late: 0,
      fault: undefined,
      last: "direct mode",
      drainUntil,
    };
    this.busFault = undefined;
    this.buffer = [];
  }

  /** Ends the servo bus's rules (direct mode left); returns how many late bytes were discarded. */
  endServoBus(): { late: number } {
    const late = this.bus?.late ?? 0;
    this.bus = undefined;
    return { late };
  }

  /** Whether bytes arriving now are drained: the settle time after entering, no command yet (`guardServoBus`). */
  get draining(): boolean {
    const bus = this.bus;
    return bus !== undefined && !bus.fault && !this.waiter && this.clock.now() < bus.drainUntil;
  }

  /** What is left of the settle time after entering, before the first command (0 after it; `guardServoBus`). */
  get settleLeftMs(): number {
    return this.bus ? Math.max(0, this.bus.drainUntil - this.clock.now()) : 0;
  }

  /** Whether the servo bus's rules are on (direct mode, see `guardServoBus`). */
  get servoBus(): boolean {
    return this.bus !== undefined;
  }

  /**
   * Counts the acknowledgement byte `byte` strictly until `endAckGuard()` (a download, docs/protocol.md §6.2: one
   * `40` per part written). [decision] The design, and why:
   * - Exactly one acknowledgement is owed per part written, and only from the moment its write was issued
   *   until it arrives. Any other one is a fault detected the moment it arrives: a second `40` in the same
   *   read, one with no part in flight (after a part's `40`, before the next part is written), or one sooner
   *   after its part's write than the part's bytes take on the wire (`notBeforeMs` of `ackExchange`; a genuine
   *   answer cannot precede the last byte it answers). It is never kept for the next part: a `40` counts only
   *   while its part's exchange is open, so an extra byte cannot become the next part's acknowledgement.
   * - The fault rejects the open exchange at once, or, with none open, the next `ackExchange` before it
   *   writes anything: the upload stops sending and can abandon the download.
   * - Other bytes are line noise and are skipped (they cannot be a `40`).
   * What cannot be told apart is a stray `40` that arrives later than its part's wire time and before the
   * robot's own answer: it is taken as that answer, and the robot's answer then arrives one part early. The
   * upload therefore confirms every result by the robot's own memory accounting, never by the count of `40`s.
   */
  guardAcks(byte: number, onUnexpected?: () => void): void {
    this.guard = { byte, onUnexpected, fault: undefined, unexpected: 0, last: "the start" };
    this.buffer = [];
  }

  /** Throws the first unexpected acknowledgement seen so far, if any (before the next part is written). */
  checkAcks(): void {
    if (this.guard?.fault) throw this.guard.fault;
  }

  /** Ends the strict count; returns the first unexpected acknowledgement seen, if any, and how many there were. */
  endAckGuard(): { fault: RbcUnexpectedAckError | undefined; unexpected: number } {
    const g = this.guard;
    this.guard = undefined;
    return { fault: g?.fault, unexpected: g?.unexpected ?? 0 };
  }

  /**
   * Writes one part of a guarded download and waits for its acknowledgement (see `guardAcks`). `notBeforeMs`:
   * the least time after the write at which a genuine acknowledgement can arrive (0: no timing rule).
   */
  ackExchange(
    bytes: Uint8Array,
    options: { timeoutMs: number; note: string; notBeforeMs: number; signal?: AbortSignal },
  ): Promise<void> {
    const guard = this.guard;
    if (!guard) return Promise.reject(new Error("ackExchange outside guardAcks"));
    if (guard.fault) return Promise.reject(guard.fault);
    guard.last = options.note;
    return this.plainExchange(bytes, {
      need: 1,
      timeoutMs: options.timeoutMs,
      note: options.note,
      signal: options.signal,
      notBefore: this.clock.now() + options.notBeforeMs,
    }).then(() => undefined);
  }

  /**
   * A servo command in direct mode (see `guardServoBus`): writes `bytes` and waits for `need` reply bytes
   * (`need` 0 writes without waiting). Outside direct mode it is refused (`wrong-mode`), nothing written;
   * only a write that wants no reply goes out then (abandoning a download).
   */
  exchange(
    bytes: Uint8Array,
    options: {
      need: number;
      timeoutMs: number;
      note: string;
      signal?: AbortSignal;
      accept?: (b: number) => boolean;
      notBefore?: number;
    },
  ): Promise<Uint8Array> {
    // A write that wants no reply outside a servo session (abandoning a download) is only a write.
    if (options.need === 0 && !this.bus && !this.busFault) return this.plainExchange(bytes, options);
    return this.servoExchange(bytes, options);
  }

  /** What ended the last servo session early (bytes nobody asked for, a failed fence), until direct mode is new. */
  get servoFault(): RbcError | undefined {
    return this.busFault;
  }

  /**
   * A servo command that listens instead of counting (the servo doctor, docs/protocol.md §5): writes `bytes`,
   * hands every byte the bus sends back to `onByte` with no count and no timing rule (the listener records
   * arrival times itself), and ends when the listener closes `close` because the line has gone quiet. Such an
   * exchange leaves the bus settled only when `expect` bytes or more came: an unanswered (or half-answered)
   * read does not, as its reply may still be on its way (docs/protocol.md §5 "Servo doctor"), so the next
   * command is fenced first. At `capMs` (a line that never goes quiet) it resolves `"cap"` and the bus is
   * unsettled too. The other servo-bus rules hold: bytes between commands are nobody's answer
   * (`RbcStillPlayingError`).
   */
  async servoListen(
    bytes: Uint8Array,
    options: {
      note: string;
      capMs: number;
      /** How many bytes make a whole answer: with fewer, the bus is left unsettled. */
      expect: number;
      /**
       * Called just before `bytes` are handed to the link (after any fence; never when the command ends unsent):
       * the listener's clock starts there.
       */
      onWrite: () => void;
      close: AbortSignal;
      onByte: (byte: number) => void;
      signal?: AbortSignal;
    },
  ): Promise<"closed" | "cap"> {
    const bus = await this.readyBus(options.signal);
    bus.last = options.note;
    const { note, capMs, close, signal } = options;
    // Aborted while the bus was fenced: nothing is written, and the bus stays as settled as it was.
    if (signal?.aborted) throw new RbcCancelledError();
    let heard = 0;
    const listen = (b: number) => {
      heard++;
      options.onByte(b);
    };
    const matcher = { need: Number.POSITIVE_INFINITY, listen };
    options.onWrite();
    const wait = this.open(bytes, note, matcher, { ms: capMs, error: () => LISTEN_CAP }, signal);
    const onClose = () => wait.resolve(Uint8Array.of());
    close.addEventListener("abort", onClose);
    if (close.aborted) onClose();
    try {
      await wait.promise;
      if (heard < options.expect) bus.unsettled = true;
      return "closed";
    } catch (e) {
      // A cap or a cancel leaves the bus unsettled: the next command is fenced first.
      if (e === LISTEN_CAP || e instanceof RbcCancelledError) bus.unsettled = true;
      if (e === LISTEN_CAP) return "cap";
      throw e;
    } finally {
      close.removeEventListener("abort", onClose);
    }
  }

  /** The servo bus, fenced first if a reply may still be on its way; throws when there is none to use. */
  private async readyBus(signal: AbortSignal | undefined): Promise<ServoBusGuard> {
    const bus = this.bus;
    if (!bus || bus.fault) {
      throw (
        bus?.fault ??
        this.busFault ??
        new RbcError("wrong-mode", undefined, { situation: { kind: "direct-mode-needed" } })
      );
    }
    if (signal?.aborted) throw new RbcCancelledError();
    // The first command ends the drain: what comes from now on is judged.
    bus.drainUntil = 0;
    if (bus.unsettled) {
      try {
        await bus.host.fence();
      } catch (e) {
        // Direct mode is over (the host left it): every later servo command fails the same way, unsent.
        if (this.bus === bus) this.bus = undefined;
        const error = e instanceof RbcError ? e : new RbcError("timeout", String(e), { cause: e });
        this.busFault = error;
        throw error;
      }
      if (this.bus !== bus || bus.fault) throw bus.fault ?? this.busFault ?? new RbcCancelledError();
      bus.unsettled = false;
    }
    return bus;
  }

  /** A servo command under the servo bus's rules (see `guardServoBus`). */
  private async servoExchange(
    bytes: Uint8Array,
    options: { need: number; timeoutMs: number; note: string; signal?: AbortSignal },
  ): Promise<Uint8Array> {
    const bus = await this.readyBus(options.signal);
    bus.last = options.note;
    const wireMs = (bytes.length + options.need) * WIRE_BYTE_MS - CLOCK_SLACK_MS;
    const notBefore = this.clock.now() + (bus.host.paced ? Math.max(0, wireMs) : 0);
    try {
      return await this.plainExchange(bytes, { ...options, notBefore });
    } catch (e) {
      // Its reply may still be on its way: the next command waits for the bus to be fenced.
      if (e instanceof RbcTimeoutError || e instanceof RbcCancelledError) bus.unsettled = true;
      throw e;
    }
  }

  private plainExchange(
    bytes: Uint8Array,
    options: {
      need: number;
      timeoutMs: number;
      note: string;
      signal?: AbortSignal;
      accept?: (b: number) => boolean;
      notBefore?: number;
    },
  ): Promise<Uint8Array> {
    const { need, timeoutMs, note, signal } = options;
    if (need === 0) return this.write(bytes, note).then(() => new Uint8Array(0));
    const matcher = { need, accept: options.accept, notBefore: options.notBefore };
    const timeout = () => new RbcTimeoutError(note, timeoutMs);
    return this.open(bytes, note, matcher, { ms: timeoutMs, error: timeout }, signal).promise;
  }

  /**
   * Registers an exchange's wait (before the write), then writes `bytes`: a failed write ends the wait. A
   * `signal` already aborted rejects the wait and writes nothing.
   */
  private open(
    bytes: Uint8Array,
    note: string,
    matcher: RawMatcher,
    deadline: { ms: number; error: () => unknown },
    signal: AbortSignal | undefined,
  ): Wait<Uint8Array, RawMatcher> {
    const cancel = { signal, error: () => new RbcCancelledError() };
    const wait = this.waits.wait(matcher, { cancel, deadline });
    if (signal?.aborted) return wait; // rejected at once, nothing written
    this.buffer = [];
    this.write(bytes, note).catch((e) => wait.reject(e));
    return wait;
  }

  /** Rejects the waiting exchange, if any. */
  fail(error: RbcError): void {
    this.waits.reject(error);
    this.buffer = [];
  }

  private receiveServo(bus: ServoBusGuard, bytes: Uint8Array): void {
    const waiter = this.waiter;
    if (bus.fault) return;
    if (!waiter) {
      // Drained (the connection logged them as such): old servo replies relayed as direct mode began.
      if (this.clock.now() < bus.drainUntil) return;
      if (bus.unsettled) bus.late += bytes.length;
      else this.unasked(bus, "unasked");
      return;
    }
    const { listen, notBefore, need } = waiter.matcher;
    if (listen) {
      for (const b of bytes) listen(b);
      return;
    }
    if (notBefore !== undefined && this.clock.now() < notBefore) {
      this.unasked(bus, "early");
      return;
    }
    this.buffer.push(...bytes);
    if (this.buffer.length > need) {
      this.unasked(bus, "unasked");
      return;
    }
    if (this.buffer.length === need) waiter.resolve(Uint8Array.from(this.buffer.splice(0)));
  }

  /** Bytes nobody asked for on the servo bus: direct mode ends and the exchange fails (see `guardServoBus`). */
  private unasked(bus: ServoBusGuard, kind: RbcStillPlayingError["kind"]): void {
    const fault = new RbcStillPlayingError(kind, bus.last);
    bus.fault = fault;
    this.busFault = fault;
    this.bus = undefined;
    this.buffer = [];
    this.waiter?.reject(fault);
    bus.host.leave(fault);
  }

  private receiveAcks(guard: AckGuard, bytes: Uint8Array): void {
    const now = this.clock.now();
    for (const b of bytes) {
      if (b !== guard.byte) continue;
      const waiter = this.waiter;
      const notBefore = waiter?.matcher.notBefore;
      if (waiter && (notBefore === undefined || now >= notBefore)) {
        waiter.resolve(Uint8Array.of(b));
        continue;
      }
      const fault = waiter
        ? new RbcUnexpectedAckError("early", guard.last)
        : new RbcUnexpectedAckError("extra", `after ${guard.last}`);
      guard.unexpected++;
      guard.fault ??= fault;
      guard.onUnexpected?.();
      waiter?.reject(guard.fault);
    }
  }
}
