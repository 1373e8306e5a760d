import "./styles.css";
import { render } from "lit-html";
import type { Locale } from "../i18n/locale.ts";
import { keepLanguage, loadLanguage } from "../i18n/split-catalogue.ts";
import type { Clock } from "../shared/clock.ts";
import { initialState, runningWords } from "./app-state.ts";
import { answerBusyQueries, busySentence } from "./busy.ts";
import type { AppContext } from "./context.ts";
import type { DemoRobotOptions } from "./demo-robot.ts";
import { robotTask } from "./features/class/index.ts";
import { refreshKnownPorts } from "./features/connection/index.ts";
import { routeFromHash, ViewLoader } from "./router.ts";
import { webSerial } from "./serial-ports.ts";
import { Session } from "./session.ts";
import { showRoute, viewArrived } from "./shell/actions.ts";
import { appView, pageTitle } from "./shell/app-view.ts";
import { escapeTakenElsewhere } from "./shell/escape.ts";
import { pageStartLocale } from "./shell/locale-choice.ts";
import { DEFAULT_VIEW, VIEWS } from "./shell/registry.ts";
import { watchTopBarHeight } from "./shell/top-bar-height.ts";
import type { AppView, ViewContext } from "./shell/view-types.ts";
import { anyRobotConnected, stopAll } from "./stop-all.ts";
import { createStore, frameScheduler } from "./store.ts";

/**
 * Browser tests run the demo robot on the clock of their fake serial port (`window.__rbcTest.clock`, a virtual
 * clock set by tests/e2e/fake-serial-entry.ts before the page loads). Nothing else sets it, so people always
 * get a demo robot on real time, and a robot on a cable is never affected.
 */
function demoOptionsForTests(): DemoRobotOptions {
  const clock = (window as unknown as { __rbcTest?: { clock?: Partial<Clock> } }).__rbcTest?.clock;
  const isClock =
    typeof clock?.now === "function" &&
    typeof clock.setTimeout === "function" &&
    typeof clock.clearTimeout === "function";
  return isClock ? { clock: clock as Clock } : {};
}

/** Builds the panel into #app and wires it to the page: rendering, routes, Escape (Stop), the port list. */
function startApp(root: HTMLElement, locale: Locale): void {
  const serial = webSerial();
  const store = createStore(
    initialState({
      serialSupported: serial !== undefined,
      secureContext: window.isSecureContext,
      route: routeFromHash(location.hash, VIEWS) ?? DEFAULT_VIEW,
      // The saved choice of the language switch, else the browser's languages (index.html says "en" until now).
      locale,
    }),
  );
  // The packet log is made by the session with the first connection (its code is not in the first load).
  const session = new Session(store, undefined, { demo: demoOptionsForTests() });
  const app: AppContext = {
    store,
    session,
    get packetLog() {
      return session.packetLog;
    },
  };
  const loader = new ViewLoader(VIEWS, () => viewArrived(store));

  /** Counts connections, so that each view is activated once per showing and connection. */
  let connectionCount = 0;
  let lastPhase = store.get().connection.phase;
  /** The view activated last, until it is deactivated (another view, or no robot). */
  let active: { key: string; view: AppView } | undefined;
  let renderedPhase = lastPhase;
  let barWatched = false;

  const renderNow = (): void => {
    const state = store.get();
    const ctx: ViewContext = { ...app, state };
    render(appView(ctx, loader), root);
    if (!barWatched) {
      barWatched = true;
      watchTopBarHeight(root);
    }
    const title = pageTitle(ctx);
    if (document.title !== title) document.title = title;
    if (document.documentElement.lang !== state.locale) document.documentElement.lang = state.locale;
    // When connecting or a lost link replaces the focused control, keep keyboard users in the main area.
    if (state.connection.phase !== renderedPhase) {
      renderedPhase = state.connection.phase;
      const focused = document.activeElement;
      if (!focused || focused === document.body)
        document.getElementById("main")?.focus({ preventScroll: true });
    }
    const view = loader.get(state.route);
    const key = state.connection.phase === "connected" && view ? `${state.route}#${connectionCount}` : "";
    if (key !== (active?.key ?? "")) {
      const previous = active;
      active = key && view ? { key, view } : undefined;
      previous?.view.deactivate?.(ctx);
      if (active) active.view.activate?.(ctx);
    }
  };

  const scheduleRender = frameScheduler(renderNow);
  store.subscribe((state) => {
    if (state.connection.phase === "connected" && lastPhase !== "connected") connectionCount++;
    lastPhase = state.connection.phase;
    scheduleRender();
  });

  window.addEventListener("hashchange", () => {
    const route = routeFromHash(location.hash, VIEWS);
    if (route) showRoute(store, route);
  });

  // Escape = Stop for every robot of the page (each ends what runs and holds its pose) while one is connected,
  // the top-bar robot or a Class view robot, unless a field, a dialog, a menu or an open popup takes it. Never
  // Limp.
  document.addEventListener("keydown", (e) => {
    if (e.key !== "Escape" || e.repeat || e.defaultPrevented) return;
    if (!anyRobotConnected(store.get()) || escapeTakenElsewhere(e.target, document)) return;
    e.preventDefault();
    void stopAll(app);
  });

  // A reload (the update prompt's, or the browser's) or a closed tab would cut short what runs on the robot: an
  // upload would leave its download half done. The update prompt asks this before reloading; the browser asks
  // the person ("Leave site?") while something runs.
  answerBusyQueries(() =>
    busySentence(runningWords(store.get().running, store.get().locale), store.get().locale),
  );
  window.addEventListener("beforeunload", (e) => {
    const state = store.get();
    // The Class view's robots run their own work (an upload, a Run) beside the top bar's robot.
    const classBusy = state.classRoom?.robots.some((r) => robotTask(r) !== undefined) ?? false;
    if (state.running.length > 0 || classBusy) e.preventDefault();
  });

  // Release the port when the page goes away, so the next page (or program) can open it.
  window.addEventListener("pagehide", () => void session.disconnect());

  if (serial) {
    serial.addEventListener("connect", () => void refreshKnownPorts(store));
    serial.addEventListener("disconnect", () => void refreshKnownPorts(store));
    void refreshKnownPorts(store);
  }

  renderNow();
  // The browser tests' start option (a robot connected at start, src/ui/test-start.ts) is only in their build
  // (mode "e2e"): in any other, this condition is false when the code is built, and the module is left out.
  if (import.meta.env.MODE === "e2e") void import("./test-start.ts").then((m) => m.applyTestStart(app));
}

const root = document.getElementById("app");
if (!root) throw new Error("index.html has no #app element");
// The hosted build loads each catalogue's languages one at a time (docs/i18n.md, "One language at a time"):
// nothing is drawn before the words of the page's language are there; English follows in the background
// (the technical detail's language). Elsewhere (the dev server, the one-file panel) there is nothing to wait for.
const locale = pageStartLocale();
void loadLanguage(locale).then(() => {
  root.textContent = "";
  startApp(root, locale);
  if (locale !== "en") void keepLanguage("en").catch(() => undefined);
});
