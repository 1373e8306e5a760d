import { DOWNLOAD_ACK, NO_ERROR } from "../protocol/catalog.ts";
import { WRITE_MOTION_TYPE } from "../protocol/commands.ts";
import type { TimerId } from "../shared/clock.ts";
import { createActionArea, createMotionArea, DownloadSession, type MemoryArea } from "./sim-downloads.ts";
import type { DropReason, SimReceiver } from "./sim-receiver.ts";
import type { SimTimers } from "./sim-timers.ts";

/** Error code of a download chunk with a wrong checksum (docs/protocol.md §3.2). */
const ERROR_CHECKSUM = 2;

export interface DownloaderHost {
  send(bytes: Uint8Array): void;
  setError(code: number): void;
  drop(reason: DropReason): void;
}

export interface DownloadProgress {
  area: "motion" | "action";
  size: number;
  received: number;
}

/**
 * The download sequence of docs/protocol.md §6.2 as the simulated RBC runs it: the first part is answered `40`
 * (or refused with error 3 / 4), then every chunk is answered `40` after a simulated page write; a bad chunk
 * checksum sets error 2 and abandons the download. While a download runs, the receiver is in raw mode.
 */
export class SimDownloader {
  readonly motionArea = createMotionArea();
  readonly actionArea = createActionArea();
  private session: DownloadSession | undefined;
  private idleTimer: TimerId | undefined;
  private pageWriteUntil = 0;

  constructor(
    private readonly timers: SimTimers,
    private readonly receiver: SimReceiver,
    private readonly host: DownloaderHost,
    private readonly pageWriteMs: number,
    /** [decision] Silence mid-download after which it is abandoned without an error code. */
    private readonly idleTimeoutMs: number,
  ) {}

  get progress(): DownloadProgress | undefined {
    const s = this.session;
    return s ? { area: s.area.kind, size: s.size, received: s.received } : undefined;
  }

  /** A 14-byte first part of type 0x01 (motion) or 0x02 (action) arrived. */
  start(type: number, size: number): void {
    const area = type === WRITE_MOTION_TYPE ? this.motionArea : this.actionArea;
    if (!area.accepts(size)) {
      if (size > 0) this.host.setError(area.fullError);
      this.host.drop("download-refused");
      return;
    }
    this.host.setError(NO_ERROR);
    this.session = new DownloadSession(area, size);
    this.receiver.rawMode((b) => this.byte(b));
    this.armIdleTimer();
    this.host.send(Uint8Array.of(DOWNLOAD_ACK));
  }

  /** Power-up: counts and pointers reset (files stay), any download in progress is forgotten. */
  powerCycle(): void {
    this.session = undefined;
    this.idleTimer = undefined;
    this.pageWriteUntil = 0;
    this.motionArea.resetPointer();
    this.actionArea.resetPointer();
  }

  private byte(byte: number): void {
    const session = this.session;
    if (!session) return;
    this.armIdleTimer();
    const result = session.push(byte);
    if (result === "more") return;
    if (result === "chunk-ok") {
      this.ackAfterPageWrite(session.area);
      return;
    }
    this.endSession();
    if (result === "bad-checksum") {
      this.host.setError(ERROR_CHECKSUM);
      this.host.drop("download-chunk-checksum");
    } else {
      this.ackAfterPageWrite(session.area, session.payload);
    }
  }

  /** `40` after the simulated EEPROM page write; the last chunk also records the file. */
  private ackAfterPageWrite(area: MemoryArea, completed?: Uint8Array): void {
    const now = this.timers.clock.now();
    this.pageWriteUntil = Math.max(now, this.pageWriteUntil) + this.pageWriteMs;
    this.timers.after(this.pageWriteUntil - now, () => {
      if (completed) area.record(completed);
      this.host.send(Uint8Array.of(DOWNLOAD_ACK));
    });
  }

  private armIdleTimer(): void {
    this.timers.cancel(this.idleTimer);
    if (!Number.isFinite(this.idleTimeoutMs)) return;
    this.idleTimer = this.timers.after(this.idleTimeoutMs, () => {
      this.idleTimer = undefined;
      this.endSession();
      this.host.drop("download-timeout");
    });
  }

  private endSession(): void {
    this.timers.cancel(this.idleTimer);
    this.idleTimer = undefined;
    this.session = undefined;
    this.receiver.packetMode();
  }
}
