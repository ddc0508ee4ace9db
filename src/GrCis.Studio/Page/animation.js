// Animation: render a time range's frames, follow them as they come (the studio announces each), scrub through
// them, play them in a loop at the run's rate; the frame on show as PNG.
import { $, state } from "./state.js";
import { refresh as refresh3d } from "./pane3d.js";
import { api } from "./api.js";
import { showError } from "./messages.js";
import { draw } from "./view.js";
import { showStatus } from "./status.js";
import { settings, rangeValue } from "./settings.js";

const anim = state.animation;

async function renderFrames() {
  showError("");
  try {
    await api("animation", {
      method: "POST", headers: { "Content-Type": "application/json" },
      body: JSON.stringify({
        scene: $("scene").value, param: $("param").value, settings: settings(), algorithm: $("algorithm").value, given: [...state.given],
        start: rangeValue("animStart"), end: rangeValue("animEnd"), fps: rangeValue("animFps"),
        folder: $("animFolder").value.trim() || null,
      }),
    });
  } catch (e) {
    showError(e.message);
    return;
  }
  $("animStop").disabled = false;
}

// The run as the studio announces it: progress, and the newest frame on show while the scrubber is at the end.
export function showAnimation(a) {
  if (a.fps > 0) anim.fps = a.fps;
  $("animStatus").textContent = `${a.framesDone}/${a.framesTotal} frames, ${a.seconds.toFixed(1)} s` +
    (a.running ? `, ETA ${a.etaSeconds.toFixed(1)} s` : "") + (a.folder ? ` → ${a.folder}` : "") + (a.error ? ` (${a.error})` : "");
  const scrub = $("animScrub");
  const follow = !anim.playing && Number(scrub.value) >= Number(scrub.max);
  scrub.max = Math.max(0, a.framesDone - 1);
  scrub.disabled = a.framesDone === 0;
  $("animPlay").disabled = a.framesDone === 0;
  $("animStop").disabled = !a.running;
  if (a.framesDone > 0 && follow) {
    scrub.value = a.framesDone - 1;
    showFrameInTurn(a.framesDone - 1);
  }
}

// Frames are drawn one after another, in the order asked.
function showFrameInTurn(k) {
  anim.showing = anim.showing.then(() => showFrame(k)).catch(() => { });
  return anim.showing;
}

async function showFrame(k) {
  const r = await api(`animation/frame/${k}.png`);
  if (!r.ok) return;
  $("view-kind").value = "";
  await draw(r);
  // The shown frame: its number and its PNG, the bytes served (the file written, when frames go to a folder).
  $("animFrame").textContent = `frame ${k + 1}/${Number($("animScrub").max) + 1}`;
  // The status bar and History describe the frame, not the still render shown before it.
  anim.onShow = `animation ${$("animFrame").textContent}: ${$("animStatus").textContent}`;
  $("historyLabel").textContent = $("historyLabel").title = "an animation frame (frames are not kept in History)";
  showStatus();
  $("animFrame").dataset.frame = k;
  $("framePng").href = `api/animation/frame/${k}.png`;
  $("framePng").download = `out${String(k).padStart(4, "0")}.png`;
  $("framePng").hidden = false;
  $("frameGlb").href = `api/animation/frame/${k}.glb`;
  $("frameGlb").download = `out${String(k).padStart(4, "0")}.glb`;
  $("frameGlb").hidden = false;
  refresh3d();
}

function togglePlay() {
  anim.playing = !anim.playing;
  $("animPlay").textContent = anim.playing ? "Pause" : "Play";
  clearTimeout(anim.timer);
  if (anim.playing) playStep();
}

// Play: the finished frames one after another at the animation's rate, from the first again after the last.
async function playStep() {
  const scrub = $("animScrub"), started = performance.now();
  const next = Number(scrub.value) >= Number(scrub.max) ? 0 : Number(scrub.value) + 1;
  scrub.value = next;
  await showFrameInTurn(next);
  // The frame's time less the time it took to fetch and draw, so the rate holds when it can.
  if (anim.playing) anim.timer = setTimeout(playStep, Math.max(0, 1000 / anim.fps - (performance.now() - started)));
}

export function initAnimation() {
  $("animRender").addEventListener("click", renderFrames);
  $("animStop").addEventListener("click", () => api("animation/stop", { method: "POST" }).catch(e => showError(e.message)));
  $("animScrub").addEventListener("input", () => showFrameInTurn(Number($("animScrub").value)));
  $("animPlay").addEventListener("click", togglePlay);
}
