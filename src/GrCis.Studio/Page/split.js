// The split between the image and the script editor: dragged, or moved with the arrow keys, it sets the editor's width,
// which the browser keeps for the next visit; a double click goes back to the default share. The image keeps at least
// 320 px and the editor 240 px (app.css), so no drag and no window size pushes either away.
import { $ } from "./state.js";

const key = "grcis-editor-width", minEditor = 240, minImage = 320, step = 24;

const pane = () => $("editorPane");

// The editor's share of the width it splits with the image, for screen readers (the separator's value).
function announce() {
  const editor = pane().offsetWidth, image = $("viewer").offsetWidth;
  $("editorSplit").setAttribute("aria-valuenow", String(Math.round(100 * editor / Math.max(1, editor + image))));
}

function setWidth(px, keep) {
  // The widest the editor may be: all the image's width above its minimum, besides its own.
  const widest = pane().offsetWidth + $("viewer").offsetWidth - minImage;
  const width = Math.round(Math.max(minEditor, Math.min(widest, px)));
  pane().style.setProperty("--editor-width", width + "px");
  if (keep) localStorage.setItem(key, String(width));
  announce();
}

// When the editor opens: the width kept from an earlier drag (the window may be smaller now: the CSS keeps the image's minimum).
export function applySplit() {
  const kept = Number(localStorage.getItem(key));
  if (kept > 0) pane().style.setProperty("--editor-width", kept + "px");
  else pane().style.removeProperty("--editor-width");
  announce();
}

export function initSplit() {
  const split = $("editorSplit");
  split.addEventListener("pointerdown", e => {
    if (e.button !== 0) return;
    e.preventDefault();
    split.setPointerCapture(e.pointerId);
    split.classList.add("dragging");
  });
  split.addEventListener("pointermove", e => {
    if (split.classList.contains("dragging")) setWidth(pane().getBoundingClientRect().right - e.clientX, false);
  });
  const end = e => {
    if (!split.classList.contains("dragging")) return;
    split.classList.remove("dragging");
    split.releasePointerCapture(e.pointerId);
    setWidth(pane().offsetWidth, true);
  };
  split.addEventListener("pointerup", end);
  split.addEventListener("pointercancel", end);
  split.addEventListener("keydown", e => {
    // The split is on the editor's left: Left widens the editor, Right widens the image.
    if (e.key !== "ArrowLeft" && e.key !== "ArrowRight") return;
    e.preventDefault();
    setWidth(pane().offsetWidth + (e.key === "ArrowLeft" ? step : -step), true);
  });
  split.addEventListener("dblclick", () => {
    localStorage.removeItem(key);
    applySplit();
  });
}
