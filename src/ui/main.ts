import "./styles.css";
import { render } from "lit-html";
import { initialState } from "./app-state.ts";
import { LOG_CAPACITY, PacketLog } from "./packet-log.ts";
import { routeFromHash, ViewLoader } from "./router.ts";
import { webSerial } from "./serial-ports.ts";
import { Session } from "./session.ts";
import { createStore, frameScheduler } from "./store.ts";
import { appView } from "./views/app-view.ts";
import { DEFAULT_VIEW, VIEWS } from "./views/registry.ts";
import type { AppView, ViewContext } from "./views/view-types.ts";

const serial = webSerial();
const store = createStore(
  initialState({
    serialSupported: serial !== undefined,
    secureContext: window.isSecureContext,
    route: routeFromHash(location.hash, VIEWS) ?? DEFAULT_VIEW,
  }),
);
const packetLog = new PacketLog(LOG_CAPACITY, (clockMs) => performance.timeOrigin + clockMs);
const session = new Session(store, packetLog);
const loader = new ViewLoader(VIEWS, () => store.update((s) => ({ viewsLoaded: s.viewsLoaded + 1 })));

const root = document.getElementById("app");
if (!root) throw new Error("index.html has no #app element");
root.textContent = "";

/** Counts connections, so that each view is activated once per showing and connection. */
let connectionCount = 0;
let lastPhase = store.get().connection.phase;
/** The view activated last, until it is deactivated (another view, or no robot). */
let active: { key: string; view: AppView } | undefined;
let renderedPhase = lastPhase;

function renderNow(): void {
  const state = store.get();
  const ctx: ViewContext = { state, store, session, packetLog };
  render(appView(ctx, loader), root as HTMLElement);
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
}

const scheduleRender = frameScheduler(renderNow);
store.subscribe((state) => {
  if (state.connection.phase === "connected" && lastPhase !== "connected") connectionCount++;
  lastPhase = state.connection.phase;
  scheduleRender();
});

window.addEventListener("hashchange", () => {
  const route = routeFromHash(location.hash, VIEWS);
  if (route && route !== store.get().route) store.update({ route });
});

// Escape = Stop (limp) while a robot is connected, wherever the focus is.
document.addEventListener("keydown", (e) => {
  if (e.key !== "Escape" || e.repeat || store.get().connection.phase !== "connected") return;
  e.preventDefault();
  void session.stop();
});

// Release the port when the page goes away, so the next page (or program) can open it.
window.addEventListener("pagehide", () => void session.disconnect());

if (serial) {
  serial.addEventListener("connect", () => void session.refreshKnownPorts());
  serial.addEventListener("disconnect", () => void session.refreshKnownPorts());
  void session.refreshKnownPorts();
}

renderNow();
