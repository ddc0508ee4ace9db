// GrCis studio page: the layout (theme, panels, keys), scene list, settings, render/stop with previews, zoom/pan, pixel
// read-out and probe, the scene in 3D, history and A/B, the script editor, animation. ES modules, one concern each, over one state object (state.js); the studio's state
// comes as pushed events (events.js). Every request carries the studio's cookie (set by the first load).
import { $, state } from "./state.js";
import { api } from "./api.js";
import { showError, initMessages } from "./messages.js";
import { initLayout } from "./layout.js";
import { showStatus } from "./status.js";
import { connect } from "./events.js";
import { initView } from "./view.js";
import { initHistory } from "./history.js";
import { initSettings, loadScenes, showChoices } from "./settings.js";
import { initEditor } from "./editor.js";
import { probe } from "./probe.js";
import { initPane3d } from "./pane3d.js";
import { initAnimation } from "./animation.js";

initLayout();
initMessages();
initView(probe);
initHistory();
initSettings();
initEditor();
initPane3d(probe);
initAnimation();
$("stop").addEventListener("click", () => {
  // A save being compiled ends too: it will not say that it compiles.
  state.compilingSave = null;
  api("stop", { method: "POST" }).catch(e => showError(e.message));
});

async function start() {
  await loadScenes();
  // The algorithm and preview choice the studio renders with, for a reloaded page; then the events keep the rest current.
  showChoices(await (await api("status")).json());
  showStatus();
  connect();
}
start().catch(e => showError(e.message));
