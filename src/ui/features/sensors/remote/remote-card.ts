import "../../../styles/remote.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { translator } from "../../../../i18n/translate.ts";
import { formatFirmware } from "../../../../shared/format.ts";
import { formatTime } from "../../../format.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { builtInMotionName } from "../events.ts";
import { sensorsMessages } from "../messages.ts";
import { sensorsOf } from "../state.ts";
import {
  isUserFirmware,
  type KeyPlays,
  keyPlays,
  REMOTE_KEYS,
  type RemoteKey,
  type RemoteKeyGroup,
  type RobotFacts,
  remoteKeyOf,
} from "./key-map.ts";
import { type RemoteTranslator, remoteMessages } from "./messages.ts";

/**
 * The Remote card (issue 23 item 3), in the Sensors view, where the IR remote is listened to: the key map of
 * docs/protocol.md §3.1, what each key plays on this robot (key-map.ts), the hazards named, and, while the remote
 * subscription is on, the last key pressed lit.
 */

const GROUPS: readonly RemoteKeyGroup[] = ["builtin", "number", "star", "hash"];

/** What the robot reported that decides what the keys play. */
function robotFacts(ctx: ViewContext): RobotFacts {
  const book = ctx.state.motions?.motionBook;
  const names = new Map<number, string>();
  for (const e of book?.entries ?? []) if (e.slot !== undefined) names.set(e.slot, e.name);
  // What this browser recorded uploading to this robot earlier (the shelf, kept while its memory allows it).
  for (const s of ctx.state.shelf?.slots ?? []) if (!names.has(s.slot)) names.set(s.slot, s.name);
  return {
    ...(ctx.state.connection.firmware ? { firmware: ctx.state.connection.firmware } : {}),
    ...(ctx.state.device.freeMotion === undefined ? {} : { freeMotion: ctx.state.device.freeMotion }),
    ...(book?.count === undefined ? {} : { downloads: book.count }),
    names,
  };
}

function groupTitle(t: RemoteTranslator, group: RemoteKeyGroup): string {
  switch (group) {
    case "builtin":
      return t("sensors.remote.group.builtin");
    case "number":
      return t("sensors.remote.group.number");
    case "star":
      return t("sensors.remote.group.star");
    case "hash":
      return t("sensors.remote.group.hash");
  }
}

/** The key as it is named: "key 1", "* + 1", "# + A", or a built-in's code. */
function keyName(t: RemoteTranslator, key: RemoteKey): string {
  switch (key.group) {
    case "builtin":
      return t("sensors.remote.face.builtin", { code: String(key.code) });
    case "number":
      return t("sensors.remote.face.number", { face: key.face });
    case "star":
      return t("sensors.remote.face.star", { face: key.face });
    case "hash":
      return t("sensors.remote.face.hash", { face: key.face });
  }
}

function playsText(t: RemoteTranslator, plays: KeyPlays): string {
  switch (plays.kind) {
    case "builtin": {
      const st = translator(sensorsMessages, t.locale);
      return builtInMotionName(st, plays.code) ?? String(plays.code);
    }
    case "hazard":
      return plays.hazard === "charging"
        ? t("sensors.remote.plays.charging")
        : t("sensors.remote.plays.zeroPose");
    case "download":
      return t("sensors.remote.plays.download", { name: plays.name });
    case "download-unknown":
      return t("sensors.remote.plays.unknown");
    case "empty":
      return t("sensors.remote.plays.empty");
    case "user-nothing":
      return t("sensors.remote.plays.userNothing");
    case "user-flash-demo":
      return t("sensors.remote.plays.userFlashDemo");
    case "user-endless-walk":
      return t("sensors.remote.plays.userEndlessWalk");
  }
}

/** A hazard on this robot: a `#` key, or key 9 on the official "user" build. */
function isHazard(plays: KeyPlays): boolean {
  return plays.kind === "hazard" || plays.kind === "user-endless-walk";
}

function keyTile(t: RemoteTranslator, key: RemoteKey, facts: RobotFacts, lit: boolean): TemplateResult {
  const plays = keyPlays(key, facts);
  const hazard = isHazard(plays);
  // Key 9 on another build: what it plays here, and the user build's walk named beside it.
  const elsewhere = !hazard && key.hazard === "endless-walk";
  const quiet = plays.kind === "empty" || plays.kind === "user-nothing";
  return html`<li
    class="remote-key remote-key--${key.group} ${lit ? "is-lit" : ""} ${hazard ? "is-hazard" : ""} ${quiet ? "is-quiet" : ""}"
    data-testid="remote-key"
    data-code=${key.code}
    aria-current=${lit ? "true" : nothing}
  >
    ${key.group === "builtin" ? nothing : html`<span class="remote-key-face">${key.face}</span>`}
    <span class="remote-key-text">
      <span class="remote-key-name small muted">${keyName(t, key)}${key.group === "builtin" ? nothing : html` · ${t("sensors.remote.code", { code: String(key.code) })}`}</span>
      <span class="remote-key-plays">${hazard ? html`<strong class="text-warning">${t("sensors.remote.hazard")}:</strong> ` : nothing}${playsText(t, plays)}</span>
      ${elsewhere ? html`<span class="small text-warning">${t("sensors.remote.userKey9")}</span>` : nothing}
      ${lit ? html`<span class="sr-only">(${t("sensors.remote.pressed")})</span>` : nothing}
    </span>
  </li>`;
}

function firmwareNote(t: RemoteTranslator, facts: RobotFacts): string {
  if (!facts.firmware) return t("sensors.remote.firmwareUnknown");
  if (isUserFirmware(facts)) return t("sensors.remote.firmwareUser");
  return t("sensors.remote.firmwareOther", { version: formatFirmware(facts.firmware) });
}

/** The last key the remote sent, while the remote subscription is on. */
function lastKey(ctx: ViewContext): { code: number; at: number } | undefined {
  if (ctx.state.connection.subscription !== "remote") return undefined;
  const event = sensorsOf(ctx.state).events.find((e) => e.kind === "remote");
  return event ? { code: event.value, at: event.at } : undefined;
}

function lastKeyText(t: RemoteTranslator, last: { code: number; at: number } | undefined): string {
  if (!last) return t("sensors.remote.noKeyYet");
  const time = formatTime(last.at, t.locale);
  const key = remoteKeyOf(last.code);
  const name =
    key?.group === "builtin"
      ? (builtInMotionName(translator(sensorsMessages, t.locale), key.code) ?? keyName(t, key))
      : key && keyName(t, key);
  return name
    ? t("sensors.remote.lastKey", { key: name, code: String(last.code), time })
    : t("sensors.remote.lastUnknown", { code: String(last.code), time });
}

function keyGroup(
  t: RemoteTranslator,
  group: RemoteKeyGroup,
  facts: RobotFacts,
  litCode: number | undefined,
): TemplateResult {
  const keys = REMOTE_KEYS.filter((k) => k.group === group);
  return html`<section class="remote-group remote-group--${group}" aria-labelledby=${`remote-${group}`}>
    <h3 id=${`remote-${group}`} class="remote-group-title">${groupTitle(t, group)}</h3>
    <ul class="remote-keys" role="list">
      ${keys.map((k) => keyTile(t, k, facts, litCode === k.code))}
    </ul>
  </section>`;
}

export function remoteCard(ctx: ViewContext): TemplateResult {
  const t = translator(remoteMessages, ctx.state.locale);
  const facts = robotFacts(ctx);
  const listening = ctx.state.connection.subscription === "remote";
  const last = lastKey(ctx);
  return html`
    <section class="card remote-card" aria-labelledby="remote-title" data-testid="remote-card">
      <h2 id="remote-title" class="card-title">${t("sensors.remote.title")}</h2>
      <p class="muted small">${t("sensors.remote.intro")}</p>
      <p class="small" data-testid="remote-firmware">${firmwareNote(t, facts)}</p>
      <div role="status" aria-live="polite" aria-label=${t("sensors.remote.title")}>
        <p class="small" data-testid="remote-listen">
          ${listening ? t("sensors.remote.listening") : t("sensors.remote.listenHint")}
        </p>
        ${listening ? html`<p class="small num" data-testid="remote-last">${lastKeyText(t, last)}</p>` : nothing}
      </div>
      <details class="remote-fold" data-testid="remote-fold" ?open=${listening}>
        <summary>${t("sensors.remote.keysFold", { count: REMOTE_KEYS.length })}</summary>
        ${GROUPS.map((group) => keyGroup(t, group, facts, last?.code))}
      </details>
    </section>
  `;
}
