// The page around the image: the light or dark theme, the side panels' open or closed state (both kept by the browser
// for the next visit), and the keys that work everywhere: F5 or Ctrl+Enter renders, Esc stops, [ and ] step through
// the history. The view's own keys (F, 1, r) are in view.js, Ctrl+S in editor.js.
import { $ } from "./state.js";

function setTheme(theme) {
  document.documentElement.dataset.theme = theme;
  $("theme").setAttribute("aria-pressed", String(theme === "light"));
  localStorage.setItem("grcis-theme", theme);
}

// A button acts as clicked, unless it is disabled or hidden.
function press(id) {
  const b = $(id);
  if (!b.disabled && !b.hidden) b.click();
}

const typing = e => e.target.closest?.("input, textarea, select, .CodeMirror");

export function initLayout() {
  // The editor's text area is named for screen readers (every CodeMirror the page makes gets it).
  CodeMirror.defaults.screenReaderLabel = "Script source";
  setTheme(localStorage.getItem("grcis-theme") ?? "dark");
  $("theme").addEventListener("click", () => setTheme(document.documentElement.dataset.theme === "dark" ? "light" : "dark"));
  for (const d of document.querySelectorAll("aside details")) {
    const key = "grcis-panel-" + d.id, kept = localStorage.getItem(key);
    if (kept !== null) d.open = kept === "open";
    d.addEventListener("toggle", () => localStorage.setItem(key, d.open ? "open" : "closed"));
  }
  window.addEventListener("keydown", e => {
    if (e.defaultPrevented) return;   // handled where it was typed (the editor's own keys, its completion list's Esc)
    if (e.key === "F5" && !e.ctrlKey && !e.metaKey || e.key === "Enter" && (e.ctrlKey || e.metaKey)) {
      e.preventDefault();
      press("render");
    } else if (e.key === "Escape") {
      if (!$("picker").hidden) { $("picker").hidden = true; return; }
      press("stop");
    } else if ((e.key === "[" || e.key === "]") && !e.ctrlKey && !e.metaKey && !e.altKey && !typing(e)) {
      press(e.key === "[" ? "back" : "forward");
    }
  });
}
