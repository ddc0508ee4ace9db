// The studio's state as it changes, pushed as Server-Sent Events (GET api/events) rather than asked for: each event
// names its render, and those of a render the page has seen replaced are ignored. On every (re)connection the stream
// starts with the whole status, so the page is never stale; the browser reconnects by itself.
import { state, freshRender } from "./state.js";
import { showStatus } from "./status.js";
import { wantImage } from "./view.js";
import { loadHistory } from "./history.js";
import { showAnimation } from "./animation.js";
import { showError } from "./messages.js";
import { refresh as refresh3d } from "./pane3d.js";

const studio = state.studio;

// An event of this render or a newer one (which starts afresh); false for a replaced render's.
function current(renderId) {
  if (renderId < studio.renderId) return false;
  if (renderId > studio.renderId) Object.assign(studio, freshRender(), { renderId });
  return true;
}

// The history once per finished image.
function finished(version) {
  if (version <= 0 || version === state.historyFor) return;
  state.historyFor = version;
  loadHistory().catch(e => showError(e.message));
  refresh3d();
}

const handlers = {
  // The whole status: on connecting, and again after each reconnection.
  status(s) {
    if (s.generation !== studio.generation) {
      // Another studio process answers (its supervisor restarted it, or says it is restarting it): its renders and images
      // are numbered afresh, so what the page knew of the old one's numbers is forgotten. The page's fields stay.
      Object.assign(studio, freshRender(), { renderId: s.renderId });
      Object.assign(state, { shownVersion: -1, wantedVersion: -1, historyFor: -1, viewsFor: -1, staleRender: -1 });
    } else if (s.renderId < studio.renderId) return;
    Object.assign(studio, s);
    if (s.version > 0) wantImage(s.version);
    if (!s.rendering) finished(s.version);
  },
  render(e) {
    if (!current(e.renderId)) return;
    studio.tab = e.tab;
  },
  errors(e) {
    if (!current(e.renderId)) return;
    studio.error = e.error;
    studio.diagnostics = e.diagnostics;
    studio.diagnosticsScene = e.scene;
  },
  progress(e) {
    if (!current(e.renderId)) return;
    Object.assign(studio, { fraction: e.fraction, seconds: e.seconds, samples: e.samples, noise: e.noise });
  },
  preview(e) {
    if (!current(e.renderId)) return;
    studio.version = e.version;
    wantImage(e.version);
  },
  done(e) {
    if (!current(e.renderId)) return;
    // A stopped render's bar stays where it stopped: its image is not complete.
    Object.assign(studio, { statistics: e.statistics, samples: e.samples, noise: e.noise, width: e.width, height: e.height,
      samplesPerPixel: e.samplesPerPixel, version: e.version, fraction: e.cancelled ? studio.fraction : 1, stopped: e.cancelled });
    wantImage(e.version);
    finished(e.version);
  },
  checked(e) {
    state.lastCheck = Math.max(state.lastCheck, e.check);
  },
  phase(e) {
    if (!current(e.renderId)) return;
    Object.assign(studio, { phase: e.phase, rendering: e.rendering, notes: e.notes });
  },
  animation(a) {
    showAnimation(a);
  },
};

export function connect() {
  const source = new EventSource("api/events");
  for (const [name, handle] of Object.entries(handlers))
    source.addEventListener(name, e => {
      state.events++;
      handle(JSON.parse(e.data));
      if (name !== "animation") showStatus();
    });
  // On a lost connection the browser tries again by itself (after the second the stream asked for).
  source.addEventListener("open", () => { state.connected = true; });
  source.addEventListener("error", () => { state.connected = false; });
  return source;
}
