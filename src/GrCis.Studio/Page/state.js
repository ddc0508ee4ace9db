// The page's one state object: what the studio said last (its status, kept current by the event stream, events.js)
// and what the page holds itself (the view, the fields the user changed, the editor's file, the animation shown).

export const $ = id => document.getElementById(id);

// A render's own part of the studio's status: what a new render starts from.
export const freshRender = () => ({
  fraction: 0, seconds: 0, statistics: "", samples: null, noise: null, error: null, diagnostics: [], diagnosticsScene: null, stopped: false,
});

// This page's id: the studio has one render at a time, so a page tells when another tab's request replaced its own.
// Kept per tab across reloads (sessionStorage), so a reloaded page still knows its own render.
function tabId() {
  const id = sessionStorage.getItem("grcis-tab") ??
    Array.from(crypto.getRandomValues(new Uint8Array(8)), b => b.toString(16).padStart(2, "0")).join("");
  sessionStorage.setItem("grcis-tab", id);
  return id;
}

export const state = {
  tab: tabId(),
  // The studio's status as /api/status answers it; renderId is the newest render the page knows of (older ones' events are ignored).
  studio: { generation: 0, renderId: 0, phase: "idle", rendering: false, version: 0, notes: [], tab: null, ...freshRender() },
  // The event stream is open (false while the browser reconnects); the events applied so far.
  connected: false,
  events: 0,
  scenes: [],
  // The image on show (its version) and the newest one announced; the render whose history and extra views are loaded.
  shownVersion: -1,
  wantedVersion: -1,
  historyFor: -1,
  viewsFor: -1,
  // Zoom and pan of the image (fitted: fitted again to each new image and view size, until the user zooms or pans); a drag
  // in progress; enlarge: fitting may scale the image above 1:1 (smoothly).
  view: { zoom: 1, panX: 0, panY: 0, fitted: true, enlarge: false, drag: null, hoverTimer: null },
  // Settings the user changed since the scene was chosen: they win over the script's own values (as command-line
  // options do); the other fields show the script's values, marked, and are sent as not given.
  given: new Set(),
  rangeGiven: new Set(),
  // This tab has had a render of its own (only then is another tab's render a takeover); the render whose error and
  // notes are about a scene no longer chosen (not shown).
  ownedRender: false,
  staleRender: -1,
  // The page's own last error (a refused request) and note: shown beside the studio's until the next action.
  pageError: "",
  pageNote: "",
  // A saved script that is not the one rendered, being compiled: its name and the check's number; the last check ended.
  compilingSave: null,
  lastCheck: 0,
  // The script editor: CodeMirror, the scene it shows, its marks; the version (ETag) of the file its text started from, and a
  // newer one found on disk while it has unsaved edits; the wait for the language services to load (once per page).
  editor: { cm: null, scene: null, marks: [], tag: null, diskTag: null, diskText: null, epoch: 0, checking: false, timer: null, ready: null },
  // The last pixel probed (its ray tree, for the 3D view).
  probe: null,
  // Animation: the run's frames per second and whether Play steps through its frames.
  // onShow: what the status bar and History say while a frame, not a still render, is on show ("" = a still).
  animation: { fps: 25, playing: false, timer: null, showing: Promise.resolve(), onShow: "" },
};
