/*
 * Longer than the project's ~400 lines on purpose: one conversation (the waiter, the queue, the fences of late
 * replies, the parser and the link's life) shares private state whose invariants hold only together; the
 * operations on top of it live in their own files (motion-run.ts, stop.ts, limp.ts, …), its options in
 * connection-options.ts.
 */
import { LinkError, type Transport, type TransportStatusEvent } from "../link/transport.ts";
import { concatBytes } from "../protocol/bytes.ts";
import { ABANDON_DOWNLOAD } from "../protocol/catalog.ts";
import {
  COMMAND_BY_TYPE,
  COMMANDS,
  type CommandSpec,
  commandName,
  EVENT_TYPES,
  MAX_REPLY_CONTENT,
} from "../protocol/commands.ts";
import { ProtocolError } from "../protocol/errors.ts";
import { encodePacket, type Packet } from "../protocol/packet.ts";
import { PacketParser } from "../protocol/packet-parser.ts";
import { EXIT_DIRECT_MODE } from "../protocol/wck.ts";
import { type Clock, realClock } from "../shared/clock.ts";
import { Emitter } from "../shared/emitter.ts";
import { Waitress, withDeadline } from "../shared/waitress.ts";
import { BootloaderPromptWatch, RbcInBootloaderError } from "./bootloader-prompt.ts";
import {
  DEFAULT_TIMEOUTS,
  type RbcClientOptions,
  type RbcTimeouts,
  type RequestOptions,
} from "./connection-options.ts";
import {
  RbcBadReplyError,
  RbcCancelledError,
  RbcDisconnectedError,
  RbcError,
  RbcInvalidArgumentError,
  RbcNotConnectedError,
  RbcPortError,
  RbcTimeoutError,
} from "./errors.ts";
import { RawChannel } from "./raw-channel.ts";
import { type LinkTiming, RoundTripEstimator } from "./round-trip.ts";

export type { RbcClientOptions, RbcTimeouts, RequestOptions } from "./connection-options.ts";

import type { ClientMode, ClientState, LogEntry, RbcEvent, SubscriptionKind } from "./types.ts";

/** What answers a request's wait: a reply of its type. */
interface ReplyMatcher {
  type: number;
  /** Replies of the right type that this returns false for are ignored (e.g. a stopped motion's reply). */
  accept?: (p: Packet) => boolean;
  /** A quick request's write: its reply measures the link's round trip from then. */
  roundTripFrom?: number;
}

export const SUBSCRIPTIONS = {
  sound: COMMANDS.subscribeSound,
  buttons: COMMANDS.subscribeButtons,
  remote: COMMANDS.subscribeRemote,
} as const;

/** Quick requests the RBC answers from its main loop, so only once a playing motion ends (§3.6). */
export const MAIN_LOOP_REPLY_TYPES: ReadonlySet<number> = new Set([COMMANDS.readDistance.type]);

/** `ClientState.reason` of a link lost without a word from the link (technical; the error is worded by code). */
const LINK_LOST = "link lost (no reason given)";
/** The log's note for servo bytes drained as direct mode began (docs/protocol.md §3.6). */
const DRAINED_NOTE = "drained: old servo replies relayed as direct mode began";

const SUBSCRIPTION_BY_TYPE = new Map<number, SubscriptionKind>(
  Object.entries(SUBSCRIPTIONS).map(([kind, spec]) => [spec.type, kind as SubscriptionKind]),
);

/**
 * The conversation with an RBC under the typed operations of `RbcClient`: the link's life (connect, loss,
 * close), one request in flight at a time with its waiter registered before its bytes are written, a timeout
 * on every request (from the command table's timeout class), retries for idempotent reads, routing of
 * unsolicited event packets to `events`, the raw byte channel for downloads and the servo bus, the packet log
 * and the client state. A lost link rejects whatever is pending with `RbcDisconnectedError`.
 *
 * Internal to `device/`: `RbcClient` holds one in a private field and is the only public way in, so no caller
 * can send a request that skipped the client's validation (a zero table, a motion number, a servo position).
 */
export class RbcConnection {
  readonly clock: Clock;
  /** The timeouts as configured (the fixed values); `timeouts` gives those in force. */
  readonly baseTimeouts: Readonly<RbcTimeouts>;
  /** The measured round trip of the link and the quick timeout it gives. */
  readonly roundTrip: RoundTripEstimator;
  readonly retries: number;
  /** Every packet and raw chunk in and out, for the packet log. */
  readonly log = new Emitter<LogEntry>();
  readonly stateChanges = new Emitter<ClientState>();
  readonly events = new Emitter<RbcEvent>();
  readonly parser: PacketParser;
  readonly raw: RawChannel;
  /** The request in flight's wait for its reply (one at a time: `exclusive`). */
  private readonly replies: Waitress<Packet, ReplyMatcher>;
  private queue: Promise<unknown> = Promise.resolve();
  /** Bumped by Stop and Limp (`cancelQueued`): queued operations from an older epoch are cancelled. */
  epoch = 0;
  /** Which of Stop or Limp began each epoch after the first, so a cancelled turn can say which one it was. */
  private readonly epochBy = new Map<number, "stop" | "limp">();
  private _state: ClientState = { mode: "disconnected", basicPostureConfirmed: false };
  subscription: { kind: SubscriptionKind; request: Uint8Array } | undefined;
  /**
   * Told about a reply no waiter takes (used to notice an ignored motion early). It returns true when the reply
   * answers a request it sent beside the queue (a probe): that reply was asked for, so it is not counted as
   * unanswered and does not make its type suspect.
   */
  unsolicited: ((packet: Packet) => boolean | undefined) | undefined;
  private unlisten: Array<() => void> = [];
  /**
   * Types of quick requests whose reply may still arrive (the request timed out or was cancelled, or a reply
   * of that type came unasked). The next request of such a type is fenced first (see `fence`), so that a late
   * reply can never answer a request sent after it: the protocol has no sequence numbers.
   */
  private readonly suspect = new Set<number>();
  /**
   * Replies owed by the RBC's main loop (docs/protocol.md §3.6): every request of a main-loop type (0x16) that
   * went unanswered owes one reply, which comes when the main loop is free (a motion ended). The next replies of
   * that type pay those debts first, so a late one never answers a later request; a fence of an
   * interrupt-answered type proves nothing about them. `paidAt` is when the last debt was paid.
   */
  private readonly owed = new Map<number, { count: number; since: number; paidAt?: number }>();
  /** When the parser last discarded bytes (a garbled frame): something answered, damaged. */
  private lastDiscardAt = Number.NEGATIVE_INFINITY;
  /** When a request's wait last ended with bytes of a partial or garbled frame. */
  private garbledAt = Number.NEGATIVE_INFINITY;
  /** Told about every reply the RBC's main loop sent (0x14, 0x16): the main loop is free at that moment. */
  mainLoopAnswered: ((type: number) => void) | undefined;
  /** Replies no request took: late ones (discarded after a fence or a timeout) and unasked repeats. */
  /**
   * `unansweredReplies`: replies no request in flight took, a late one paying an abandoned request's debt
   * included; `unaskedReplies`: only those nothing ever asked for (no debt paid), such as a firmware that repeats
   * its reply (docs/protocol.md §3.5).
   */
  readonly stats = { unansweredReplies: 0, unaskedReplies: 0, fences: 0, timeouts: 0 };

  constructor(
    readonly transport: Transport,
    options: RbcClientOptions = {},
  ) {
    this.clock = options.clock ?? realClock;
    const base = { ...DEFAULT_TIMEOUTS, ...options.timeouts };
    this.baseTimeouts = base;
    this.roundTrip = new RoundTripEstimator(
      options.link ?? "wired",
      {
        floorMs: base.quickMs,
        ceilingMs: Math.max(base.quickMs, base.quickCeilingMs),
        firstMs: Math.max(base.quickMs, base.firstQuickMs),
      },
      options.adaptiveTimeouts ?? true,
    );
    this.retries = options.retries ?? 2;
    this.parser = new PacketParser({
      onDiscard: (reason, bytes) => {
        this.lastDiscardAt = this.clock.now();
        this.emitLog({ direction: "in", kind: "discard", name: reason, bytes, note: `discarded: ${reason}` });
      },
      // No reply carries more than its type can (docs/protocol.md §3.5): a corrupted size byte costs one reply.
      maxContent: (type) => COMMAND_BY_TYPE.get(type)?.replySize ?? MAX_REPLY_CONTENT,
    });
    this.raw = new RawChannel(this.clock, (bytes, note) => this.writeRaw(bytes, note));
    this.replies = new Waitress(this.clock, (p, m) => m.type === p.type && (m.accept?.(p) ?? true));
  }

  get state(): Readonly<ClientState> {
    return this._state;
  }

  /**
   * The timeouts in force: the quick one from the measured round trip (never below the configured value), the
   * motion/sound margin and the settle wait grown by what the link adds above it. On a wired link, exactly
   * the configured values.
   */
  get timeouts(): Readonly<RbcTimeouts> {
    const base = this.baseTimeouts;
    const extra = this.roundTrip.extraMs;
    return {
      ...base,
      quickMs: base.quickMs + extra,
      marginMs: base.marginMs + extra,
      settleMs: base.settleMs + Math.round(extra / 2),
    };
  }

  /** The link's measured timing (`RbcClient.link`). */
  get link(): LinkTiming {
    return this.roundTrip.snapshot();
  }

  get mode(): ClientMode {
    return this._state.mode;
  }

  /**
   * Opens the transport (115200 8N1), abandons any half-done download, leaves direct mode blindly, then runs
   * `handshake` (the client reads the firmware version there). Link failures come out as `RbcPortError`, and a
   * port that opens but where nothing answers as `RbcError("no-robot")`, so callers handle one error family.
   */
  async connect<T>(handshake: () => Promise<T>): Promise<T> {
    if (this.mode !== "disconnected") {
      throw new RbcError("wrong-mode", undefined, { situation: { kind: "already-connected" } });
    }
    this.setState({
      mode: "connecting",
      reason: undefined,
      lostCause: undefined,
      basicPostureConfirmed: false,
      subscription: undefined,
    });
    // A robot waiting in its bootloader sends `^` and answers nothing (docs/protocol.md §11).
    const prompt = new BootloaderPromptWatch(this.clock);
    const stopWatching = this.transport.onData((bytes) => prompt.receive(bytes));
    this.unlisten = [
      this.transport.onData((bytes) => this.onBytes(bytes)),
      this.transport.onStatus((e) => this.onTransportStatus(e)),
    ];
    try {
      try {
        await this.transport.open();
      } catch (e) {
        throw e instanceof LinkError ? RbcPortError.fromLink(e) : e;
      }
      // In case the RBC was left in the middle of a download (by an earlier program that died) or in direct
      // mode (docs/protocol.md §5): neither gets a reply, and each is harmless garbage in the other states.
      await this.withTimeout(
        this.writeRaw(
          concatBytes(ABANDON_DOWNLOAD, EXIT_DIRECT_MODE),
          "abandon any download, leave direct mode",
        ),
        this.timeouts.quickMs,
        "leave direct mode",
      );
      await this.sleep(this.timeouts.settleMs);
      this.parser.reset();
      this.owed.clear();
      this.setState({ mode: "packet" });
      return await handshake();
    } catch (e) {
      const inBootloader = e instanceof RbcTimeoutError ? await prompt.confirm() : undefined;
      await this.close();
      if (inBootloader) throw new RbcInBootloaderError(inBootloader, e);
      if (e instanceof RbcTimeoutError) {
        throw new RbcError("no-robot", undefined, { cause: e });
      }
      if (e instanceof LinkError) throw RbcPortError.fromLink(e);
      throw e;
    } finally {
      stopWatching();
    }
  }

  /** Closes the link. Pending requests are rejected. */
  async close(): Promise<void> {
    // Leave the robot reading packets: end a download under way, or direct mode.
    const farewell =
      this.mode === "download" ? ABANDON_DOWNLOAD : this.mode === "direct" ? EXIT_DIRECT_MODE : undefined;
    if (farewell && this.transport.status === "open") {
      const name = farewell === ABANDON_DOWNLOAD ? "abandon the download" : "leave direct mode";
      this.emitLog({ direction: "out", kind: "raw", name, bytes: farewell });
      await this.withTimeout(this.transport.write(farewell), this.timeouts.quickMs, "close").catch(() => {});
    }
    this.failPending(new RbcDisconnectedError(undefined, undefined, { kind: "connection-closed" }));
    for (const u of this.unlisten) u();
    this.unlisten = [];
    await this.transport.close();
    this.setState({ mode: "disconnected", playing: undefined, sounding: undefined, subscription: undefined });
    this.subscription = undefined;
  }

  // ---- Internals ---------------------------------------------------------------------------------------

  /**
   * Runs `fn` after everything queued before it; one operation at a time. Any packet `fn` sent ended the RBC's
   * subscription, so it is armed again afterwards (unless `fn` is the subscribe itself).
   */
  exclusive<T>(fn: () => Promise<T>, epoch = this.epoch, { rearm = true } = {}): Promise<T> {
    const run = this.queue.then(async () => {
      if (epoch !== this.epoch) throw this.cancelledSince(epoch);
      try {
        return await fn();
      } finally {
        if (rearm) await this.rearmSubscription();
      }
    });
    this.queue = run.catch(() => {});
    return run;
  }

  /** Starts a new epoch for Stop or Limp: every turn queued under an older one is cancelled when it comes up. */
  cancelQueued(by: "stop" | "limp"): number {
    this.epoch++;
    this.epochBy.set(this.epoch, by);
    return this.epoch;
  }

  /** The error for a turn of `epoch` that Stop or Limp overtook: names the first of them after it. */
  cancelledSince(epoch: number): RbcCancelledError {
    const by = this.epochBy.get(epoch + 1) ?? "stop";
    return new RbcCancelledError(undefined, by, { kind: "cancelled-by", by });
  }

  /** Which of Stop or Limp began the first epoch after `epoch` (for a sentence of the operation it overtook). */
  cancelledBy(epoch: number): "stop" | "limp" {
    return this.epochBy.get(epoch + 1) ?? "stop";
  }

  /** One request of the table, queued behind everything before it (`exclusive`), with its reply decoded. */
  command<A, R>(spec: CommandSpec<A, R>, args: A, options: RequestOptions = {}): Promise<R> {
    return this.exclusive(() => this.request(spec, args, options));
  }

  /** How long to wait for a reply to `spec`, from its timeout class (docs/protocol.md §3 "reply arrives"). */
  timeoutFor<A>(spec: CommandSpec<A, unknown>, args: A, expectedMs?: number): number {
    switch (spec.timeout) {
      case "quick":
        return this.timeouts.quickMs;
      case "motion":
        return (
          (expectedMs ?? spec.expectedMs?.(args) ?? this.timeouts.unknownMotionMs) + this.timeouts.marginMs
        );
      case "sound":
        return (expectedMs ?? spec.expectedMs?.(args) ?? 0) + this.timeouts.marginMs;
      case "subscribe":
        throw new RbcError("invalid-argument", `"${spec.name}" starts events and has no reply to wait for.`);
    }
  }

  /**
   * One request/reply of the table: builds the contents (a refused argument sends nothing), waits as long as
   * the row's timeout class says, decodes the reply, and retries idempotent reads. Must run inside `exclusive`.
   */
  async request<A, R>(spec: CommandSpec<A, R>, args: A, options: RequestOptions = {}): Promise<R> {
    this.requirePacketMode(spec.name);
    let contents: Uint8Array;
    try {
      contents = spec.request(args);
    } catch (e) {
      throw e instanceof ProtocolError
        ? new RbcInvalidArgumentError(undefined, { kind: "not-encoded" }, e)
        : e;
    }
    const timeoutFor = () => options.timeoutMs ?? this.timeoutFor(spec, args, options.expectedMs);
    timeoutFor(); // a row without a reply is refused before anything is sent
    const retries = options.retries ?? (spec.idempotent ? this.retries : 0);
    for (let attempt = 0; ; attempt++) {
      try {
        if (this.suspect.has(spec.type)) await this.fence(spec.type, spec.name);
        // Per attempt: a timeout before it has backed the quick timeout off (round-trip.ts).
        const timeoutMs = timeoutFor();
        const packet = await this.transact(spec.type, contents, spec.name, timeoutMs, options);
        try {
          return spec.decode(packet.contents);
        } catch (e) {
          throw new RbcBadReplyError(e instanceof Error ? e.message : String(e), e);
        }
      } catch (e) {
        const retryable = e instanceof RbcTimeoutError || e instanceof RbcBadReplyError;
        if (!retryable || attempt >= retries) throw e;
        this.parser.reset();
      }
    }
  }

  /**
   * Makes sure no late reply of `stale` is still on its way before a new request of that type is sent. The RBC
   * answers quick requests in the order it gets them and the link keeps that order, so once the reply to a
   * quick read of another, unsuspected type has arrived, every reply to a request sent before it has arrived
   * too (and was discarded as unasked) or never will. If that read goes unanswered as well, the new request is
   * not sent: it fails with the timeout, and both types stay suspect.
   */
  private async fence(stale: number, name: string): Promise<void> {
    const fences = [COMMANDS.readFirmwareVersion, COMMANDS.readErrorCode, COMMANDS.readZeros];
    const spec = fences.find((f) => f.type !== stale && !this.suspect.has(f.type));
    this.stats.fences++;
    if (!spec) {
      // Every fence type is suspect: wait out a quick reply's time instead; what arrives meanwhile is discarded.
      await this.sleep(this.timeouts.quickMs);
      this.suspect.clear();
      return;
    }
    try {
      await this.transact(spec.type, spec.request(undefined), spec.name, this.timeouts.quickMs, {});
    } catch (e) {
      if (e instanceof RbcTimeoutError) throw new RbcTimeoutError(name, e.waitedMs);
      throw e;
    }
    this.suspect.clear();
  }

  /** Waits for a reply of `type` (sending `contents` first unless `send` is false). */
  transact(
    type: number,
    contents: Uint8Array,
    name: string,
    timeoutMs: number,
    {
      signal,
      accept,
      send = true,
      measure = true,
    }: { signal?: AbortSignal; accept?: (p: Packet) => boolean; send?: boolean; measure?: boolean },
  ) {
    // Only a quick reply measures the link: the others wait for the robot (a motion, a sound) as well.
    const quick = COMMAND_BY_TYPE.get(type)?.timeout === "quick";
    if (signal?.aborted) return Promise.reject(new RbcCancelledError());
    const sentAt = send ? this.clock.now() : undefined;
    const roundTripFrom = quick && measure ? sentAt : undefined;
    const wait = this.replies.wait(
      { type, accept, roundTripFrom }, // registered before the write
      {
        cancel: {
          signal,
          error: () => {
            if (send) this.expectLate(type);
            return new RbcCancelledError(undefined, undefined, { kind: "stopped-waiting", command: name });
          },
        },
        deadline: {
          ms: timeoutMs,
          error: () => {
            this.stats.timeouts++;
            if (quick) this.roundTrip.timedOut();
            // Bytes came but no whole reply (a partial or garbled frame): the reply came damaged, it is not late.
            const garbled = sentAt !== undefined && (this.parser.pending > 0 || this.lastDiscardAt >= sentAt);
            // A partial frame is not this reply's any more; the reply itself may still come later.
            this.parser.reset();
            if (send && !(garbled && MAIN_LOOP_REPLY_TYPES.has(type))) this.expectLate(type, sentAt);
            if (garbled && sentAt !== undefined) this.garbledAt = this.clock.now();
            return new RbcTimeoutError(name, timeoutMs);
          },
        },
      },
    );
    if (send) this.writePacket(encodePacket(type, contents), type).catch((e) => wait.reject(e));
    return wait.promise;
  }

  /**
   * A reply of `type` may still arrive for a request that no one waits for any more (quick types only). A
   * main-loop type owes one more reply, unless its main loop answered after `sentAt` (the request's write):
   * then the main loop is free, everything it owed has come, and this request's reply was lost.
   */
  expectLate(type: number, sentAt?: number): void {
    if (MAIN_LOOP_REPLY_TYPES.has(type)) {
      const debt = this.currentDebt(type);
      if (sentAt !== undefined && debt?.paidAt !== undefined && debt.paidAt >= sentAt) {
        this.owed.delete(type);
        return;
      }
      this.owed.set(type, {
        count: (debt?.count ?? 0) + 1,
        since: debt && debt.count > 0 ? debt.since : this.clock.now(),
        paidAt: debt?.paidAt,
      });
      return;
    }
    if (COMMAND_BY_TYPE.get(type)?.timeout === "quick") this.suspect.add(type);
  }

  /**
   * Whether an answer to a request of `type` written at `since` came, but not whole or not as this request's:
   * the main loop sent a reply of `type` after it (a debt paid: it was free then), or a frame arrived garbled
   * before its timeout. Either way the robot is not busy: the reply was damaged or lost.
   */
  mainLoopAnsweredSince(type: number, since: number): boolean {
    const paidAt = this.owed.get(type)?.paidAt;
    return (paidAt !== undefined && paidAt >= since) || this.garbledAt >= since;
  }

  /** How many replies of main-loop type `type` are owed to requests no one waits for (docs/protocol.md §3.6). */
  owedReplies(type: number): number {
    return this.currentDebt(type)?.count ?? 0;
  }

  /**
   * The debt of `type`, forgotten once older than the longest wait for a motion (a reply owed that long was
   * lost: no motion keeps the main loop busy longer, and one that never ends sends nothing more anyway).
   */
  private currentDebt(type: number): { count: number; since: number; paidAt?: number } | undefined {
    const debt = this.owed.get(type);
    if (!debt) return undefined;
    const limit = this.timeouts.unknownMotionMs + this.timeouts.marginMs;
    if (debt.count > 0 && this.clock.now() - debt.since > limit) {
      this.owed.delete(type);
      return undefined;
    }
    return debt;
  }

  /** A reply of a main-loop type pays its oldest debt, if any: discarded, as it answers an abandoned request. */
  private payOwed(packet: Packet): boolean {
    const debt = this.currentDebt(packet.type);
    if (!debt || debt.count === 0) return false;
    const now = this.clock.now();
    this.owed.set(packet.type, { count: debt.count - 1, since: debt.since, paidAt: now });
    this.stats.unansweredReplies++;
    return true;
  }

  requirePacketMode(what: string): void {
    if (this.mode === "disconnected") {
      const lost = this._state.reason;
      if (!lost) throw new RbcNotConnectedError();
      throw new RbcDisconnectedError(
        undefined,
        undefined,
        lost === LINK_LOST
          ? undefined
          : { kind: "link-lost", reported: lost, cause: this._state.lostCause, advice: "connect-again" },
      );
    }
    if (this.mode === "direct") {
      throw new RbcError("wrong-mode", undefined, {
        situation: { kind: "needs-normal-mode", command: what },
      });
    }
  }

  private async rearmSubscription(): Promise<void> {
    if (this.subscription && this.mode === "packet") {
      await this.writePacket(this.subscription.request, this.subscription.request[8]!).catch(() => {});
    }
  }

  async writePacket(bytes: Uint8Array, type: number): Promise<void> {
    this.emitLog({ direction: "out", kind: "packet", type, name: commandName(type), bytes });
    await this.send(bytes);
  }

  async writeRaw(bytes: Uint8Array, note: string): Promise<void> {
    this.emitLog({ direction: "out", kind: "raw", name: note, bytes });
    await this.send(bytes);
  }

  private async send(bytes: Uint8Array): Promise<void> {
    try {
      await this.transport.write(bytes);
    } catch (e) {
      throw new RbcDisconnectedError(e instanceof Error ? e.message : undefined, e);
    }
  }

  private onBytes(bytes: Uint8Array): void {
    if (this.mode === "direct" && this.raw.draining) {
      // Old servo replies relayed as direct mode began (docs/protocol.md §3.6): drained, not judged.
      this.emitLog({ direction: "in", kind: "discard", name: "drained", bytes, note: DRAINED_NOTE });
      this.raw.receive(bytes);
      return;
    }
    if (this.mode === "download" || this.mode === "direct") {
      this.emitLog({
        direction: "in",
        kind: "raw",
        name: this.mode === "direct" ? "servo bus" : "download",
        bytes,
      });
      this.raw.receive(bytes);
      return;
    }
    for (const packet of this.parser.push(bytes)) this.route(packet);
  }

  private route(packet: Packet): void {
    this.emitLog({
      direction: "in",
      kind: "packet",
      type: packet.type,
      name: commandName(packet.type),
      bytes: packet.raw ?? encodePacket(packet.type, packet.contents, packet.platform),
    });
    if (packet.platform !== this._state.platform) this.setState({ platform: packet.platform });
    const kind = SUBSCRIPTION_BY_TYPE.get(packet.type);
    if (kind && EVENT_TYPES.has(packet.type) && packet.contents.length === 2) {
      this.events.emit({ kind, value: packet.contents[0]!, time: this.clock.now() });
      return;
    }
    if (MAIN_LOOP_REPLY_TYPES.has(packet.type) || packet.type === COMMANDS.runMotion.type) {
      this.mainLoopAnswered?.(packet.type);
    }
    // A late main-loop reply pays its debt before any waiter sees it (docs/protocol.md §3.6: matched by count).
    if (this.payOwed(packet)) return;
    const answered = this.replies.resolve(packet);
    if (answered) {
      // Request written → its own reply complete. The fences guarantee that a reply of this type is this
      // request's (no late one is outstanding), so the sample is never a retried or late reply's.
      const from = answered.matcher.roundTripFrom;
      if (from !== undefined) this.roundTrip.sample(this.clock.now() - from);
      return;
    }
    // Anything else is a late, unexpected or side-channel reply: logged above, offered to `unsolicited`, and
    // unless that claims it, counted and its type fenced before its next request (a repeat may follow).
    if (this.unsolicited?.(packet) === true) return;
    this.stats.unansweredReplies++;
    this.stats.unaskedReplies++;
    // An unasked main-loop reply with nothing owed (a firmware that repeats it): fenced as before.
    if (MAIN_LOOP_REPLY_TYPES.has(packet.type)) this.suspect.add(packet.type);
    else this.expectLate(packet.type);
  }

  private onTransportStatus(event: TransportStatusEvent): void {
    if (event.status !== "lost") return;
    // The link says what happened (a technical line, and its facts for the catalogue); without it, the error is
    // worded by its code (a lost link).
    const reason = event.reason ?? LINK_LOST;
    const situation =
      event.reason === undefined
        ? undefined
        : ({ kind: "link-lost", reported: reason, cause: event.cause, advice: "check-cable" } as const);
    this.failPending(new RbcDisconnectedError(undefined, event.error, situation));
    this.subscription = undefined;
    this.setState({
      mode: "disconnected",
      reason,
      lostCause: event.cause,
      playing: undefined,
      sounding: undefined,
      subscription: undefined,
    });
    for (const u of this.unlisten) u();
    this.unlisten = [];
    void this.transport.close();
  }

  failPending(error: RbcError): void {
    for (const { type } of this.replies.reject(error)) this.expectLate(type);
    this.raw.fail(error);
  }

  /** Sets the client mode for the download and servo-bus phases. */
  setMode(mode: ClientMode): void {
    if (mode === "packet") this.parser.reset();
    this.setState({ mode });
  }

  /** Rejects with RbcTimeoutError if `p` has not settled within `ms` (for writes that expect no reply). */
  withTimeout<T>(p: Promise<T>, ms: number, name: string): Promise<T> {
    return withDeadline(this.clock, p, { ms, error: () => new RbcTimeoutError(name, ms) });
  }

  sleep(ms: number): Promise<void> {
    return new Promise((r) => this.clock.setTimeout(r, ms));
  }

  setState(patch: Partial<ClientState>): void {
    this._state = { ...this._state, ...patch };
    this.stateChanges.emit(this._state);
  }

  private emitLog(entry: Omit<LogEntry, "time">): void {
    if (this.log.active) this.log.emit({ time: this.clock.now(), ...entry });
  }
}
