import type { RbcClient } from "../../../device/rbc-client.ts";
import { said } from "../../../i18n/said.ts";
import type { SerialPortLike } from "../../../link/web-serial-transport.ts";
import type { Clock } from "../../../shared/clock.ts";
import { type AppState, noticeOf, type RobotStop } from "../../app-state.ts";
import { failureNotice } from "../../failure-notice.ts";
import { createRbcClient } from "../../robot-link.ts";
import type { Controller } from "../../scope.ts";
import type { Store } from "../../store.ts";
import { panelShelfKey, type StoredUpload } from "../shelf/index.ts";
import { type BackupStorage, keptBackups } from "../zeros/index.ts";
import { type ClassDemoRobot, createClassDemo } from "./demo-robots.ts";
import { classMessages } from "./messages.ts";
import type { NameStorage } from "./names.ts";
import { tidyName } from "./names.ts";
import { checkPack, type PackCheck } from "./pack-check.ts";
import { uploadPackTo } from "./pack-upload.ts";
import { uploadSummary } from "./result-words.ts";
import { robotTask } from "./robot-task.ts";
import { type ClassRobot, classOf, type PackFile, patchClass, patchRobot } from "./state.ts";
import { limpEach, runOnEach, stopEach } from "./together.ts";

/**
 * The Class view's robots, each on a connection of its own: its own RbcClient over its own port, independent
 * of the session's robot (nothing in the rest of the panel changes when a class robot connects, fails or is
 * lost). Operations on several robots run in parallel, each awaited on its own, so one robot's failure (a
 * pulled cable, a busy robot) never stops or misreports the others. Lives in the page's scope
 * (`CLASS_SLOT`): the robots stay connected while the person looks at other views.
 */

/** A connected (or connecting) class robot: its row id, its client and port; a demo robot's simulator. */
export interface RobotLink {
  id: number;
  client: RbcClient;
  port: SerialPortLike;
  /** Cancels the pack's upload to this robot ("Cancel" in its row, or "Cancel all"). */
  abort?: AbortController;
  detach: Array<() => void>;
  /** A demo robot's memory keeper: saves what is pending when the robot is put away. */
  keeper?: { stop(): void };
}

export interface ClassRoomOptions {
  /** The clock demo robots run on (tests: a virtual clock); real time by default. */
  demoClock?: Clock;
  names: () => Promise<NameStorage>;
  backups: () => Promise<BackupStorage>;
  /** Wall-clock ms for the skew of "Run on all" (performance.now in the page). */
  now: () => number;
  /** Told of every demo robot made (tests pull its cable). */
  onDemo?: (demo: ClassDemoRobot) => void;
  /** Records a motion stored into a known slot on the robot's shelf (issue 23 item 2; `recordOnRobotShelf`). */
  shelf?: (key: string, stored: StoredUpload) => Promise<unknown>;
}

export class ClassRoom implements Controller {
  private readonly links = new Map<number, RobotLink>();
  private demoCount = 0;
  private checked: { pack: readonly PackFile[]; check: PackCheck } | undefined;
  private disposed = false;

  constructor(
    readonly store: Store<AppState>,
    private readonly options: ClassRoomOptions,
  ) {}

  /** The link of row `id` while it is connected. */
  link(id: number): RobotLink | undefined {
    return this.links.get(id);
  }

  /** The rows' links that group actions go to: selected, connected and not busy with something else. */
  chosenLinks(): RobotLink[] {
    return classOf(this.store.get())
      .robots.filter((r) => r.selected && r.phase === "connected" && robotTask(r) === undefined)
      .flatMap((r) => {
        const link = this.links.get(r.id);
        return link ? [link] : [];
      });
  }

  /** The pack checked once: checked again only when the pack changed. */
  checkedPack(pack: readonly PackFile[]): PackCheck {
    if (this.checked?.pack !== pack) this.checked = { pack, check: checkPack(pack) };
    return this.checked.check;
  }

  /** Reads the kept names and zero backups into the state (once, when the view first opens). */
  async loadKept(): Promise<void> {
    const [names, backups] = await Promise.all([
      this.options
        .names()
        .then((s) => s.entries())
        .catch(() => []),
      this.options
        .backups()
        .then((s) => keptBackups(s))
        .catch(() => []),
    ]);
    patchClass(this.store, (c) => ({
      names: { ...Object.fromEntries(names), ...c.names },
      backups: backups.map(({ id, backup }) => ({
        id,
        serialNumber: backup.serialNumber,
        savedAt: backup.savedAt,
        zeros: backup.zeros,
      })),
      backupId: c.backupId ?? backups[0]?.id,
    }));
  }

  /** "Add demo robot": a new simulated robot with its own serial number, connected at once. */
  async addDemo(): Promise<void> {
    const n = ++this.demoCount;
    const demo = await createClassDemo(n, this.options.demoClock);
    this.options.onDemo?.(demo);
    await this.connect(
      demo.port,
      { demo: true, portLabel: `demo ${n}`, demoNumber: n },
      demo.clock,
      demo.keeper,
    );
  }

  /** A port the person chose (or one the browser remembers): connected unless it is in the class already. */
  addPort(port: SerialPortLike, portLabel: string): Promise<void> {
    for (const link of this.links.values()) {
      if (link.port === port) {
        patchClass(this.store, {
          summary: noticeOf("info", this.store.get().locale, [said(classMessages, "class.portTwice")]),
        });
        return Promise.resolve();
      }
    }
    return this.connect(port, { demo: false, portLabel });
  }

  private async connect(
    port: SerialPortLike,
    label: Pick<ClassRobot, "demo" | "portLabel" | "demoNumber">,
    clock?: Clock,
    keeper?: { stop(): void },
  ): Promise<void> {
    const c = classOf(this.store.get());
    const id = c.nextId;
    patchClass(this.store, {
      nextId: id + 1,
      robots: [...c.robots, { id, ...label, phase: "connecting", selected: true }],
    });
    const client = createRbcClient(port, clock);
    const link: RobotLink = { id, client, port, detach: [], ...(keeper ? { keeper } : {}) };
    this.links.set(id, link);
    link.detach.push(
      client.stateChanges.on((s) => {
        if (s.mode === "disconnected" && s.reason && this.links.get(id) === link) this.lost(link, s.reason);
        else if (this.links.get(id) === link) this.mirrorPosture(id, s.basicPostureConfirmed);
      }),
      client.activityChanges.on((activity) => patchRobot(this.store, id, { activity })),
    );
    try {
      const identity = await client.identify(await client.connect());
      if (this.links.get(id) !== link) return;
      patchRobot(this.store, id, {
        phase: "connected",
        serialNumber: identity.serialNumber,
        firmware: identity.firmware,
        platform: identity.platform,
        activity: client.activity,
        postureConfirmed: client.state.basicPostureConfirmed,
      });
      await this.readFacts(id);
    } catch (e) {
      if (this.links.get(id) !== link) return;
      this.forget(link);
      await client.close().catch(() => {});
      patchRobot(this.store, id, {
        phase: "failed",
        problem: failureNotice(said(classMessages, "class.connectFailed"), e, this.store.get().locale),
      });
    }
  }

  /** The robot's client learned (or forgot) that motion 7 answered: the row follows, changed only when it differs. */
  private mirrorPosture(id: number, confirmed: boolean): void {
    const row = classOf(this.store.get()).robots.find((r) => r.id === id);
    if (row && row.phase === "connected" && (row.postureConfirmed ?? false) !== confirmed) {
      patchRobot(this.store, id, { postureConfirmed: confirmed });
    }
  }

  /** Reads the error code, the free motion memory and the zeros of one robot (each on its own: one may fail). */
  async readFacts(id: number): Promise<void> {
    const link = this.links.get(id);
    if (!link) return;
    const { client } = link;
    patchRobot(this.store, id, { task: "reading" });
    const [errorCode, freeMotion, zeros] = await Promise.all([
      client.readErrorCode().catch(() => undefined),
      client.readFreeMemory("motion").then(
        (free) => (free === undefined ? null : free),
        () => undefined,
      ),
      client.readZeros().catch(() => undefined),
    ]);
    if (this.links.get(id) !== link) return;
    patchRobot(this.store, id, (r) => ({
      task: r.task === "reading" ? undefined : r.task,
      errorCode: errorCode ?? r.errorCode,
      freeMotion: freeMotion === undefined ? r.freeMotion : freeMotion,
      zeros: zeros ?? r.zeros,
    }));
  }

  private lost(link: RobotLink, reason: string): void {
    this.forget(link);
    patchRobot(this.store, link.id, (r) => ({
      phase: "lost",
      activity: undefined,
      selected: r.selected,
      problem: noticeOf("danger", this.store.get().locale, [said(classMessages, "class.lost")], reason),
    }));
  }

  private forget(link: RobotLink): void {
    link.keeper?.stop();
    delete link.keeper;
    for (const detach of link.detach) detach();
    link.detach = [];
    if (this.links.get(link.id) === link) this.links.delete(link.id);
  }

  /** Closes a robot's connection (if any) and takes its row away. */
  async remove(id: number): Promise<void> {
    const link = this.links.get(id);
    patchClass(this.store, (c) => ({ robots: c.robots.filter((r) => r.id !== id) }));
    if (!link) return;
    this.forget(link);
    link.abort?.abort();
    await link.client.close().catch(() => {});
  }

  /** Keeps the name a teacher gave the robot with this serial number (empty: forgets it). */
  async setName(serialNumber: string, typed: string): Promise<void> {
    const name = tidyName(typed);
    patchClass(this.store, (c) => {
      const names = { ...c.names };
      if (name) names[serialNumber] = name;
      else delete names[serialNumber];
      return { names, naming: undefined };
    });
    try {
      const storage = await this.options.names();
      await (name ? storage.set(serialNumber, name) : storage.remove(serialNumber));
    } catch {
      // Kept for this page; the browser refused to keep it longer (private window, storage full).
    }
  }

  /**
   * A motion stored into download slot `stored.slot` of robot `id`: recorded on that robot's shelf (by serial
   * number, else by port). The upload stands whatever happens here.
   */
  async recordOnShelf(id: number, stored: StoredUpload): Promise<void> {
    const robot = classOf(this.store.get()).robots.find((r) => r.id === id);
    if (!robot || !this.options.shelf) return;
    await this.options
      .shelf(panelShelfKey(robot.serialNumber, { name: robot.portLabel }), stored)
      .catch(() => {});
  }

  /** Uploads the checked pack to every chosen robot at once; each robot's result in its row. */
  async uploadPack(check: PackCheck): Promise<void> {
    const links = this.chosenLinks();
    const outcomes = await Promise.all(links.map((link) => uploadPackTo(this, link, check)));
    patchClass(this.store, { summary: uploadSummary(outcomes, this.store.get().locale) });
  }

  cancel(id: number): void {
    const link = this.links.get(id);
    if (!link?.abort) return;
    // The robot's activity machine marks its upload `cancelling` (the row reads it there) until it ends.
    link.abort.abort();
  }

  cancelAll(): void {
    for (const link of this.links.values()) this.cancel(link.id);
  }

  /** "Run on all": motion `number` to every chosen robot, all Runs started in the same tick. */
  async runOnAll(number: number): Promise<void> {
    await runOnEach(this, this.chosenLinks(), number, this.options.now);
  }

  /**
   * Stop for every connected robot (7 to each one playing a motion); never Limp. The page's Stop wins over a
   * question the view is asking (Run on all, Upload, Limp all): it closes unanswered, so nothing starts after Stop.
   */
  async stopAll(): Promise<RobotStop[]> {
    if (classOf(this.store.get()).asking) patchClass(this.store, { asking: undefined });
    return stopEach(this, [...this.links.values()]);
  }

  /** Limp for every connected robot, after the view asked once (they fall unless held). */
  async limpAll(): Promise<void> {
    await limpEach(this, [...this.links.values()]);
  }

  /** The port is one of the class's connected (or connecting) robots. */
  hasPort(port: SerialPortLike): boolean {
    return [...this.links.values()].some((link) => link.port === port);
  }

  /** How many robots Limp all would make passive (the question names it). */
  connectedCount(): number {
    return this.links.size;
  }

  get ended(): boolean {
    return this.disposed;
  }

  dispose(): void {
    this.disposed = true;
    for (const link of [...this.links.values()]) {
      this.forget(link);
      link.abort?.abort();
      void link.client.close().catch(() => {});
    }
  }
}
