// The image: drawn on a canvas, fitted and centred (the default, kept while the view changes size), zoomed about the
// cursor and panned, or 1:1; the pixel read-out under the cursor; the extra views (depth, normals, rays per pixel, noise)
// in its place.
import { $, state } from "./state.js";
import { api } from "./api.js";
import { showError, say } from "./messages.js";
import { showStatus } from "./status.js";

const canvas = $("canvas"), ctx = canvas.getContext("2d");
const view = state.view;

export function place() {
  canvas.style.transform = $("canvasB").style.transform = `translate(${view.panX}px, ${view.panY}px) scale(${view.zoom})`;
  // Pixels stay sharp squares when zoomed in (to inspect them); only a fitted image enlarged on request is smoothed.
  const smooth = view.fitted && view.enlarge && view.zoom > 1;
  canvas.classList.toggle("smooth", smooth);
  $("canvasB").classList.toggle("smooth", smooth);
  // The probed pixel's ring, at the pixel's middle.
  const p = state.probe, mark = $("probeMark");
  mark.hidden = !p || p.x >= canvas.width || p.y >= canvas.height;
  if (p) {
    mark.style.left = `${view.panX + (p.x + 0.5) * view.zoom}px`;
    mark.style.top = `${view.panY + (p.y + 0.5) * view.zoom}px`;
  }
}

export async function draw(response) {
  const bitmap = await createImageBitmap(await response.blob());
  if (canvas.width !== bitmap.width || canvas.height !== bitmap.height) {
    canvas.width = bitmap.width;
    canvas.height = bitmap.height;
  }
  ctx.drawImage(bitmap, 0, 0);
  canvas.classList.add("drawn");
  if (view.fitted) fit();
  else place();
}

export async function showImage(version) {
  if ($("view-kind").value !== "") return showView();
  const r = await api("image.png?v=" + version);
  if (r.status === 404) return;
  state.shownVersion = Number(r.headers.get("X-Image-Version"));
  await draw(r);
  // A still render on show again after animation frames: the status bar is about it again, and History once it ends.
  if (state.animation.onShow) {
    state.animation.onShow = "";
    state.historyFor = -1;
    showStatus();
  }
}

// A newer image was announced: fetched once the one being fetched is drawn, so previews never pile up or arrive out of order.
let fetching = false;
export async function wantImage(version) {
  state.wantedVersion = Math.max(state.wantedVersion, version);
  if (fetching) return;
  fetching = true;
  try {
    while (state.wantedVersion > state.shownVersion) {
      const wanted = state.wantedVersion;
      await showImage(wanted);
      if (state.shownVersion < wanted) break;   // nothing newer to show (an extra view on show, or no image)
    }
  } catch (e) {
    showError(e.message);
  } finally {
    fetching = false;
  }
}

export async function showView() {
  const kind = $("view-kind").value;
  $("viewDownloads").hidden = kind === "";
  if (kind === "") return showImage(-1);
  try {
    if (state.viewsFor !== state.shownVersion) {
      say("computing the extra views…");
      await api("views", { method: "POST" });
      state.viewsFor = state.shownVersion;
      say("");
    }
    $("viewPng").href = `api/views/${kind}.png`;
    $("viewPng").download = kind.toLowerCase() + ".png";
    $("viewCsv").href = `api/views/${kind}.csv`;
    $("viewCsv").download = kind.toLowerCase() + ".csv";
    await draw(await api(`views/${kind}.png?v=${state.viewsFor}`));
  } catch (e) {
    showError(e.message);
  }
}

// The whole image in the view, as large as it fits (within the zoom's 1/8 to 64), centred; it stays fitted (each new
// image, a view that changes size) until the user zooms or pans. Never above 1:1 unless the user asks (Enlarge): a small
// image blown up looks worse than it is.
const margin = 8;   // px of the view's grey around a fitted image, so its edges show
export function fit() {
  view.fitted = true;
  const w = $("view").clientWidth, h = $("view").clientHeight;
  view.zoom = Math.min(view.enlarge ? 64 : 1, Math.max(1 / 8, Math.min((w - 2 * margin) / canvas.width, (h - 2 * margin) / canvas.height)));
  view.panX = (w - canvas.width * view.zoom) / 2;
  view.panY = (h - canvas.height * view.zoom) / 2;
  place();
}

// 1:1 about the view's centre: the pixel in the middle stays there.
function actualSize() {
  view.fitted = false;
  const cx = $("view").clientWidth / 2, cy = $("view").clientHeight / 2;
  view.panX = cx - (cx - view.panX) / view.zoom;
  view.panY = cy - (cy - view.panY) / view.zoom;
  view.zoom = 1;
  place();
}

function pixelAt(e) {
  const box = $("view").getBoundingClientRect();
  return { x: Math.floor((e.clientX - box.left - view.panX) / view.zoom), y: Math.floor((e.clientY - box.top - view.panY) / view.zoom) };
}

const inside = p => p.x >= 0 && p.y >= 0 && p.x < canvas.width && p.y < canvas.height;

// Zoom, pan and read-out with the mouse, keys F, 1 and r; a click (a press without a drag) on a pixel calls onClick with it.
export function initView(onClick) {
  $("view").addEventListener("wheel", e => {
    // Zoom about the cursor, 1/8 to 64.
    e.preventDefault();
    const box = $("view").getBoundingClientRect(), cx = e.clientX - box.left, cy = e.clientY - box.top;
    view.fitted = false;
    const next = Math.min(64, Math.max(1 / 8, view.zoom * (e.deltaY < 0 ? 1.25 : 0.8)));
    view.panX = cx - (cx - view.panX) * next / view.zoom;
    view.panY = cy - (cy - view.panY) * next / view.zoom;
    view.zoom = next;
    place();
  }, { passive: false });
  $("view").addEventListener("mousedown", e => { view.drag = { x: e.clientX, y: e.clientY, moved: false }; });
  window.addEventListener("mouseup", e => {
    if (view.drag && !view.drag.moved) {
      const p = pixelAt(e);
      if (inside(p)) onClick(p);
    }
    view.drag = null;
  });
  $("view").addEventListener("mousemove", e => {
    const drag = view.drag;
    if (drag) {
      if (Math.abs(e.clientX - drag.x) + Math.abs(e.clientY - drag.y) > 2) { drag.moved = true; view.fitted = false; }
      view.panX += e.clientX - drag.x;
      view.panY += e.clientY - drag.y;
      drag.x = e.clientX;
      drag.y = e.clientY;
      place();
      return;
    }
    const p = pixelAt(e);
    if (!inside(p)) return;
    const kind = $("view-kind").value;
    if (kind !== "") {
      // The view's value under the cursor comes from the server, at most every 100 ms.
      clearTimeout(view.hoverTimer);
      view.hoverTimer = setTimeout(async () => {
        const r = await api(`views/value?kind=${kind}&x=${p.x}&y=${p.y}`);
        if (r.ok) $("readout").textContent = `[${p.x}, ${p.y}] ${(await r.json()).text}`;
      }, 100);
      return;
    }
    const d = ctx.getImageData(p.x, p.y, 1, 1).data;
    $("readout").textContent = `[${p.x}, ${p.y}] = (${d[0]}, ${d[1]}, ${d[2]})`;
  });
  window.addEventListener("keydown", e => {
    // Keys for the view, except while typing (a field, the editor) or with a modifier (Ctrl+S and the like).
    if (e.ctrlKey || e.metaKey || e.altKey || e.target.closest?.("input, textarea, select, .CodeMirror")) return;
    if (e.key === "r") { view.fitted = false; view.zoom = 1; view.panX = view.panY = 0; place(); }
    else if (e.key === "f" || e.key === "F") fit();
    else if (e.key === "1") actualSize();
  });
  $("fit").addEventListener("click", fit);
  // Enlarge (kept by the browser): a fitted image smaller than the view fills it, smoothly scaled.
  view.enlarge = $("enlarge").checked = localStorage.getItem("grcis-enlarge") === "true";
  $("enlarge").addEventListener("change", () => {
    view.enlarge = $("enlarge").checked;
    localStorage.setItem("grcis-enlarge", String(view.enlarge));
    if (view.fitted && canvas.classList.contains("drawn")) fit();
  });
  $("actual").addEventListener("click", actualSize);
  // The panes beside it open and close, the window changes size: a fitted image is fitted again.
  new ResizeObserver(() => { if (view.fitted && canvas.classList.contains("drawn")) fit(); }).observe($("view"));
  $("view-kind").addEventListener("change", showView);
}
