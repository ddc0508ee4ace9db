// The studio's state on the page: progress bar, time, statistics, phase, messages, diagnostics, the Stop button.
import { $, state, freshRender } from "./state.js";
import { showMessages } from "./messages.js";
import { showDiagnostics } from "./diagnostics.js";

const phaseText = { compiling: "compiling the script…", rendering: "rendering…", stopping: "stopping…", restarting: "restarting the render process…", idle: "" };
const ownsRender = s => { if (s.tab === state.tab) state.ownedRender = true; };

export function showStatus() {
  const s = state.studio;
  ownsRender(s);
  $("bar").style.width = (100 * s.fraction).toFixed(1) + "%";
  $("progress").setAttribute("aria-valuenow", (100 * s.fraction).toFixed(0));
  $("elapsed").textContent = s.seconds.toFixed(1) + " s";
  // While passes run: the samples so far and the estimated noise, so a user sees when the image has converged.
  $("stats").textContent = s.statistics || (s.samples != null
    ? `${s.samples} spp so far` + (s.noise != null ? `, noise ${s.noise.toPrecision(3)} RMSE` : "")
    : "");
  if (state.animation.onShow) $("stats").textContent = state.animation.onShow;
  $("stats").title = $("stats").textContent;   // in full, where the status bar cuts it
  // The first compile of a script takes seconds: say so, not a still page.
  $("phase").textContent = s.phase === "idle" && s.stopped ? "stopped" : phaseText[s.phase] ?? s.phase;
  $("phase").dataset.phase = s.phase;
  noteCheck();
  showMessages();
  showDiagnostics(s.diagnostics, s.diagnosticsScene);
  $("stop").disabled = s.phase === "idle" || s.phase === "restarting";
  // The 3D view shows the scene of a render: from the first image on.
  $("show3d").hidden = !(s.version > 0);
  // The downloads are links: without an image (version 0, before the first preview) they lead nowhere, so they have no href.
  for (const id of ["png", "pfm", "glb"]) {
    const link = $(id);
    if (s.version > 0) link.setAttribute("href", link.dataset.href);
    else link.removeAttribute("href");
    link.setAttribute("aria-disabled", String(!(s.version > 0)));
  }
}

// A saved script that is not the one rendered: once its check has ended without errors, the page says it compiles.
export function noteCheck() {
  const save = state.compilingSave;
  if (!save || state.lastCheck < save.check) return;
  const s = state.studio;
  if (!s.error && s.diagnostics.length === 0) state.pageNote = `${save.name} compiles; Render shows it`;
  state.compilingSave = null;
}

// The page's own new render (its number from the answer to Render): from now on older renders' events, still on their
// way, are ignored (events.js). Its own events say how it goes, the phase first among them.
export function adopt(renderId) {
  const studio = state.studio;
  if (renderId <= studio.renderId) return;   // its events came first
  state.animation.onShow = "";   // the status bar is about this render from now on
  Object.assign(studio, freshRender(), { renderId, phase: "compiling", rendering: true, tab: state.tab });
  showStatus();
}
