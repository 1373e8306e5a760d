import { html, nothing, render, type TemplateResult } from "lit-html";
import type { RegisterSWOptions } from "vite-plugin-pwa/types";
import { isLocale, type Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import { whatIsBusy } from "./busy.ts";
import { uiMessages } from "./messages.ts";

/**
 * The hosted panel's service worker updates only when the owner says so. A new version is downloaded in the
 * background and then waits; this notice says it is ready and offers "Reload". Nothing reloads the page by
 * itself: a reload in the middle of an upload would cut it short and leave the robot's download half done.
 * Even when another tab of the panel takes the new version (its own "Reload"), this tab only says so.
 *
 * Started once from index.html (vite.config.ts adds a module script that Vite bundles into the entry chunk);
 * the one-file panel has no service worker and no notice. It speaks the page's language: the app sets `lang`
 * on the page (English until then), and the notice is drawn again when it changes.
 */

/** `registerSW` of vite-plugin-pwa's `virtual:pwa-register` (passed in, so this module has no virtual import). */
export type RegisterServiceWorker = (options: RegisterSWOptions) => (reloadPage?: boolean) => Promise<void>;

export type UpdatePhase =
  /** Nothing to say. */
  | "idle"
  /** A new version is installed and waits for "Reload". */
  | "ready"
  /** "Reload" was pressed: the new version is taking over, then the page reloads. */
  | "reloading"
  /** Another tab of the panel took the new version; this page still runs the old one. */
  | "elsewhere";

export interface UpdatePromptState {
  phase: UpdatePhase;
  /** Why reloading now would interrupt something (from `busy`), shown instead of reloading. */
  blockedBy?: string;
}

export interface UpdatePromptOptions {
  /**
   * Says what a reload would interrupt right now (e.g. "Still running: Uploading wave.rbm."), or undefined
   * when reloading is safe. Asked when "Reload" is pressed. By default, what the app answers (`busy.ts`).
   */
  busy?: () => string | undefined;
  /** Where the notice is drawn (default: a live region inserted before #app). */
  host?: HTMLElement;
  /** The language to speak (default: the page's `lang`, which the app sets). */
  locale?: () => Locale;
}

export interface UpdatePromptActions {
  reload(): void;
  later(): void;
}

/** The notice for a state: empty when idle, so the live region stays in place and announces what appears. */
export function updatePromptView(
  state: UpdatePromptState,
  actions: UpdatePromptActions,
  locale: Locale = "en",
): TemplateResult {
  if (state.phase === "idle") return html``;
  const t = translator(uiMessages, locale);
  const text =
    state.phase === "elsewhere"
      ? t("update.elsewhere")
      : state.phase === "reloading"
        ? t("update.reloading")
        : t("update.ready");
  return html`
    <div class="notice notice--info banner-notice" data-testid="update-prompt">
      <div class="banner-text">
        <p>${text}</p>
        ${state.blockedBy ? html`<p>${t("update.blocked", { busy: state.blockedBy })}</p>` : nothing}
      </div>
      ${
        state.phase === "reloading"
          ? nothing
          : html`
            <button type="button" class="btn" @click=${actions.reload}>${t("update.reload")}</button>
            <button type="button" class="btn btn--quiet" @click=${actions.later}>${t("update.later")}</button>
          `
      }
    </div>
  `;
}

/** The page's language as the app set it on `<html lang>`; English before the app runs. */
function pageLocale(): Locale {
  const lang = document.documentElement.lang;
  return isLocale(lang) ? lang : "en";
}

function defaultHost(): HTMLElement {
  const host = document.createElement("div");
  host.className = "stop-banner update-prompt";
  host.setAttribute("role", "status");
  host.setAttribute("aria-live", "polite");
  const app = document.getElementById("app");
  document.body.insertBefore(host, app);
  return host;
}

/**
 * Registers the service worker and shows the notice when a new version waits. Does nothing in a browser
 * without service workers (the panel then simply loads from the network each time).
 */
export function startUpdatePrompt(
  registerSW: RegisterServiceWorker,
  options: UpdatePromptOptions = {},
): void {
  if (!("serviceWorker" in navigator)) return;
  const host = options.host ?? defaultHost();
  const state: UpdatePromptState = { phase: "idle" };
  /** True once this page pressed "Reload": only then may the new version's arrival reload it. */
  let requested = false;
  let reloaded = false;
  let registration: ServiceWorkerRegistration | undefined;
  const reloadOnce = (): void => {
    if (reloaded) return;
    reloaded = true;
    location.reload();
  };

  const actions: UpdatePromptActions = {
    reload() {
      const blockedBy = options.busy ? options.busy() : whatIsBusy();
      if (blockedBy) {
        state.blockedBy = blockedBy;
        show();
        return;
      }
      state.blockedBy = undefined;
      if (state.phase === "elsewhere") {
        location.reload();
        return;
      }
      if (!registration?.waiting) {
        // Nothing waits any more (another tab took it over): a plain reload brings the new version.
        location.reload();
        return;
      }
      requested = true;
      state.phase = "reloading";
      show();
      // The page reloads once the new worker controls it (asked for here, so this is the owner's reload).
      navigator.serviceWorker.addEventListener("controllerchange", reloadOnce, { once: true });
      // Tells the waiting worker to take over.
      void applyUpdate(true);
    },
    later() {
      state.phase = "idle";
      state.blockedBy = undefined;
      show();
    },
  };
  const locale = options.locale ?? pageLocale;
  const show = (): void => {
    render(updatePromptView(state, actions, locale()), host);
  };
  // The language switch sets `lang` on the page: say the notice again in the new language.
  new MutationObserver(show).observe(document.documentElement, {
    attributes: true,
    attributeFilter: ["lang"],
  });

  const applyUpdate = registerSW({
    immediate: true,
    onNeedRefresh() {
      if (state.phase === "reloading") return;
      state.phase = "ready";
      show();
    },
    onNeedReload() {
      if (requested) {
        reloadOnce();
        return;
      }
      state.phase = "elsewhere";
      show();
    },
    onRegisteredSW(_url, found) {
      registration = found;
    },
    onRegisterError() {
      // No offline copy (e.g. storage disabled): the panel still works online, so there is nothing to say.
    },
  });
  show();
}
