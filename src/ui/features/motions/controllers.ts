import type { RbmValidation } from "../../../protocol/rbm-validate.ts";
import type { AppContext } from "../../context.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { Ticker } from "./ticker.ts";

/**
 * The Motions feature's controllers. Per connection: the upload in flight (its AbortController), the motion
 * the panel is waiting on, and the redraw ticker. Per page: the checks of opened files against the connected
 * robot (the files stay open across connections).
 */

export interface MotionRun {
  number: number;
  /**
   * "Stop motion" was pressed for this run: which of the two actions says how it ended (the Stop's). The panel's
   * own bookkeeping between its actions, never drawn: views ask the device's machine (`isStopping`).
   */
  stopRequested: boolean;
}

export class MotionsController implements Controller {
  /** Aborts the upload in flight ("Cancel upload"). */
  upload: AbortController | undefined;
  run: MotionRun | undefined;
  readonly ticker: Ticker;

  constructor(ctx: AppContext) {
    this.ticker = new Ticker(ctx.store);
  }

  dispose(): void {
    // An upload in flight ends with the link (the client rejects it as disconnected); only the timer is ours.
    this.upload = undefined;
    this.run = undefined;
    this.ticker.dispose();
  }
}

export const MOTIONS = controllerKey("motions", (ctx: AppContext) => new MotionsController(ctx));

/** The motions controller of the connection. */
export function motionsController(ctx: AppContext): MotionsController {
  return ctx.session.connectionScope.get(MOTIONS);
}

const MAX_CACHED_CHECKS = 200;

/** Checks of opened files, by file id and the connected robot's serial number ("made for another robot"). */
export class FileChecks implements Controller {
  private readonly checks = new Map<string, RbmValidation>();

  get(id: number, serialNumber: string | undefined, check: () => RbmValidation): RbmValidation {
    const key = `${id}:${serialNumber ?? ""}`;
    let v = this.checks.get(key);
    if (!v) {
      v = check();
      if (this.checks.size >= MAX_CACHED_CHECKS) this.checks.clear();
      this.checks.set(key, v);
    }
    return v;
  }

  dispose(): void {
    this.checks.clear();
  }
}

export const FILE_CHECKS = controllerKey("motion file checks", () => new FileChecks());
