// GrCis studio page: scene list, settings, render/stop with previews, zoom/pan, pixel read-out and probe.
// Plain browser JavaScript, no libraries: every request carries the studio's cookie (set by the first load).
"use strict";

const $ = id => document.getElementById(id);
const canvas = $("canvas"), ctx = canvas.getContext("2d");
let scenes = [], shownVersion = -1, polling = null;
let zoom = 1, panX = 0, panY = 0, drag = null;
let viewsFor = -1, hoverTimer = null, historyFor = -1;
let editor = null, editedScene = null, marks = [], lastProbe = null;
// The version (ETag) of the file the editor's text started from, and a newer one found on disk while it has unsaved edits.
let editorTag = null, diskTag = null, diskText = null, sourceEpoch = 0, checkingSource = false;
// Settings the user changed since the scene was chosen: they win over the script's own values (as command-line
// options do); the other fields show the script's values, marked, and are sent as not given.
const given = new Set();
const givenFlag = { width: "Size", height: "Size", spp: "SamplesPerPixel", jitter: "Jitter",
  shadows: "Shadows", reflections: "Reflections", refractions: "Refractions" };
const rangeFields = ["animStart", "animEnd", "animFps"];
const rangeGiven = new Set();

// The page's own last error (a refused request): shown beside the studio's until the next action.
let pageError = "";
function showError(message) {
  pageError = message;
  pageNote = "";
  $("messages").textContent = message;
}
// A saved script that is not the one rendered is compiled by the studio: its name until the result is known, then a note.
let compilingSave = null, pageNote = "";
const phaseText = { compiling: "compiling the script…", rendering: "rendering…", idle: "" };

// This page's id: the studio has one render at a time, so a page tells when another tab's request replaced its own.
// Kept per tab across reloads (sessionStorage), so a reloaded page still knows its own render.
const tab = sessionStorage.getItem("grcis-tab") ??
  Array.from(crypto.getRandomValues(new Uint8Array(8)), b => b.toString(16).padStart(2, "0")).join("");
sessionStorage.setItem("grcis-tab", tab);
const tookOver = "Another tab or window of this studio started what is on show (one render at a time; Render here to take it back).";

async function api(path, options) {
  const r = await fetch("api/" + path, { ...options, headers: { ...options?.headers, "X-GrCis-Tab": tab } });
  if (!r.ok && r.status !== 404) {
    let text = await r.text();
    try { text = JSON.parse(text).error ?? text; } catch { }
    throw new Error(text || r.statusText);
  }
  return r;
}

async function loadScenes() {
  const list = await (await api("scenes")).json();
  scenes = list.scenes;
  const select = $("scene");
  select.innerHTML = "";
  for (const s of scenes) {
    const o = document.createElement("option");
    o.value = o.textContent = s.name;
    select.appendChild(o);
  }
  if (list.selected) select.value = list.selected;
  sceneChanged();
}

function sceneChanged() {
  const s = scenes.find(x => x.name === $("scene").value);
  $("edit").hidden = !s?.file;
  $("param").value = s?.param ?? "";
  $("param").title = s?.tooltip ?? "";
  $("param").placeholder = s?.tooltip ?? "";
  return loadScriptValues();
}

// Shows a value of the script in its field, marked as the script's (until the user changes it).
function showScriptValue(id, value) {
  const field = $(id);
  // A range the previous script set, and this one does not, is the scene's again (an empty field).
  if (value == null && field.classList.contains("script") && rangeFields.includes(id)) field.value = "";
  field.classList.toggle("script", value != null);
  field.title = value != null ? "the script's value; change it to use your own" : "";
  if (value == null) return false;
  field.value = value;
  return true;
}

// The chosen scene's own values (built, not rendered): size, samples per pixel, algorithm, animation range.
async function loadScriptValues() {
  const name = $("scene").value;
  showError("");
  let v = {};
  try {
    v = await (await api("scene/values", {
      method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify({ scene: name, param: $("param").value }),
    })).json();
  } catch (e) {
    showError(e.message);
  }
  if ($("scene").value !== name) return;   // another scene was chosen meanwhile
  const size = v.width != null || v.height != null;
  if (showScriptValue("width", size ? (v.width ?? $("width").value) : null) | showScriptValue("height", size ? (v.height ?? $("height").value) : null))
    given.delete("Size");
  if (showScriptValue("spp", v.samplesPerPixel)) given.delete("SamplesPerPixel");
  $("algorithm").options[0].textContent = `scene's choice (${v.algorithm ?? "ray tracing"})`;
  for (const [id, value] of [["animStart", v.start], ["animEnd", v.end], ["animFps", v.fps]])
    if (showScriptValue(id, value)) rangeGiven.delete(id);
  if (v.tooltip) { $("param").title = $("param").placeholder = v.tooltip; }
}

// A field the user changes is given: it wins over the script's value.
function fieldChanged(e) {
  const id = e.target.id;
  if (givenFlag[id]) given.add(givenFlag[id]);
  if (rangeFields.includes(id)) rangeGiven.add(id);
  for (const f of id === "width" || id === "height" ? ["width", "height"] : [id]) {
    $(f).classList.remove("script");
    $(f).title = "";
  }
}

// An animation field as sent: the user's value, or null for the script's (else the scene's, else 0 to 10 s at 25 fps).
function rangeValue(id) {
  return rangeGiven.has(id) || !$(id).classList.contains("script") && $(id).value !== "" ? Number($(id).value) : null;
}

function settings() {
  const num = id => Number($(id).value);
  const time = $("time").value.trim();
  return {
    width: num("width"), height: num("height"), samplesPerPixel: num("spp"), jitter: num("jitter"),
    shadows: $("shadows").checked, reflections: $("reflections").checked, refractions: $("refractions").checked,
    threads: num("threads"), seed: num("seed"), time: time === "" ? null : Number(time),
  };
}

// The algorithm the studio renders with now ("" = the scene's choice), shown after a reload of the page.
async function loadAlgorithm() {
  const s = await (await api("status")).json();
  $("algorithm").value = s.algorithm ?? "";
  $("progressive").value = s.progressive == null ? "" : String(s.progressive);
}

// The preview choice as the API takes it: true, false or null (automatic).
function progressive() {
  const v = $("progressive").value;
  return v === "" ? null : v === "true";
}

async function render() {
  showError("");
  $("view-kind").value = "";
  $("viewDownloads").hidden = true;
  try {
    await api("render", {
      method: "POST", headers: { "Content-Type": "application/json" },
      body: JSON.stringify({
        scene: $("scene").value, param: $("param").value, settings: settings(), algorithm: $("algorithm").value, progressive: progressive(),
        given: [...given],
      }),
    });
  } catch (e) {
    showError(e.message);
    return;
  }
  $("stop").disabled = false;
  pollSoon(0);
}

// One polling loop: five times a second while something runs, once a second otherwise (a script saved by
// another editor re-renders on the server, and the page follows).
function pollSoon(ms) {
  clearTimeout(polling);
  polling = setTimeout(async () => {
    let busy = false;
    try { busy = await poll(); } catch { }
    pollSoon(busy ? 200 : 1000);
  }, ms);
}

async function poll() {
  const s = await (await api("status")).json();
  $("bar").style.width = (100 * s.fraction).toFixed(1) + "%";
  $("elapsed").textContent = s.seconds.toFixed(1) + " s";
  // While passes run: the samples so far and the estimated noise, so a user sees when the image has converged.
  $("stats").textContent = s.statistics || (s.samples != null
    ? `${s.samples} spp so far` + (s.noise != null ? `, noise ${s.noise.toPrecision(3)} RMSE` : "")
    : "");
  // The first compile of a script takes seconds: say so, not a still page.
  $("phase").textContent = phaseText[s.phase] ?? s.phase;
  $("phase").dataset.phase = s.phase;
  if (compilingSave && s.phase === "idle") {
    if (!s.error && s.diagnostics.length === 0) pageNote = `${compilingSave} compiles; Render shows it`;
    compilingSave = null;
  }
  const other = s.tab && s.tab !== tab ? tookOver : "";
  $("messages").textContent = [other, ...s.notes, s.error, pageError, pageNote].filter(Boolean).join("\n");
  showDiagnostics(s.diagnostics);
  $("stop").disabled = s.phase === "idle";
  await checkSource();
  if (s.version !== shownVersion && s.version > 0) await showImage(s.version);
  // The history once per finished image (the image fetched may already be newer than the status that asked for it).
  if (!s.rendering && s.version > 0 && s.version !== historyFor) {
    historyFor = s.version;
    await loadHistory();
  }
  return s.phase !== "idle";
}

function showDiagnostics(list) {
  if (!editor) return;
  for (const m of marks) m.clear ? m.clear() : editor.removeLineClass(m, "background", "line-error");
  marks = [];
  const ul = $("diagnostics");
  ul.innerHTML = "";
  for (const d of list) {
    const line = d.line - 1, ch = Math.max(0, d.column - 1);
    marks.push(editor.addLineClass(line, "background", "line-error"));
    marks.push(editor.markText({ line, ch }, { line, ch: ch + 1 }, { className: "cm-diagnostic", title: d.message }));
    const li = document.createElement("li");
    li.textContent = `${d.line}:${d.column} ${d.severity} ${d.id}: ${d.message}`;
    li.dataset.line = d.line;
    li.dataset.column = d.column;
    li.addEventListener("click", () => { editor.setCursor({ line, ch }); editor.focus(); });
    ul.appendChild(li);
  }
}

async function show3d() {
  try {
    const boxes = await (await api("scene/boxes")).json();
    RayView.show($("rays3d"), boxes, lastProbe?.rays);
  } catch (e) {
    showError(e.message);
  }
}

async function renderFrames() {
  showError("");
  try {
    await api("animation", {
      method: "POST", headers: { "Content-Type": "application/json" },
      body: JSON.stringify({
        scene: $("scene").value, param: $("param").value, settings: settings(), algorithm: $("algorithm").value, given: [...given],
        start: rangeValue("animStart"), end: rangeValue("animEnd"), fps: rangeValue("animFps"),
        folder: $("animFolder").value.trim() || null,
      }),
    });
  } catch (e) {
    showError(e.message);
    return;
  }
  $("animStop").disabled = false;
  followFrames();
}

// Play: the finished frames one after another at the animation's rate, from the first again after the last.
let playing = false, playTimer = null, animFps = 25;

async function followFrames() {
  const a = await (await api("animation")).json();
  if (a.fps > 0) animFps = a.fps;
  $("animStatus").textContent = `${a.framesDone}/${a.framesTotal} frames, ${a.seconds.toFixed(1)} s` +
    (a.running ? `, ETA ${a.etaSeconds.toFixed(1)} s` : "") + (a.folder ? ` → ${a.folder}` : "") + (a.error ? ` (${a.error})` : "");
  const scrub = $("animScrub");
  const follow = !playing && Number(scrub.value) >= Number(scrub.max);
  scrub.max = Math.max(0, a.framesDone - 1);
  scrub.disabled = a.framesDone === 0;
  $("animPlay").disabled = a.framesDone === 0;
  if (a.framesDone > 0 && follow) { scrub.value = a.framesDone - 1; await showFrame(a.framesDone - 1); }
  if (a.running) setTimeout(followFrames, 250);
  else $("animStop").disabled = true;
}

async function showFrame(k) {
  const r = await api(`animation/frame/${k}.png`);
  if (!r.ok) return;
  $("view-kind").value = "";
  await draw(r);
  // The shown frame: its number and its PNG, the bytes served (the file written, when frames go to a folder).
  $("animFrame").textContent = `frame ${k + 1}/${Number($("animScrub").max) + 1}`;
  $("animFrame").dataset.frame = k;
  $("framePng").href = `api/animation/frame/${k}.png`;
  $("framePng").download = `out${String(k).padStart(4, "0")}.png`;
  $("framePng").hidden = false;
}

function togglePlay() {
  playing = !playing;
  $("animPlay").textContent = playing ? "Pause" : "Play";
  clearTimeout(playTimer);
  if (playing) playStep();
}

async function playStep() {
  const scrub = $("animScrub"), started = performance.now();
  const next = Number(scrub.value) >= Number(scrub.max) ? 0 : Number(scrub.value) + 1;
  scrub.value = next;
  try { await showFrame(next); } catch { }
  // The frame's time less the time it took to fetch and draw, so the rate holds when it can.
  if (playing) playTimer = setTimeout(playStep, Math.max(0, 1000 / animFps - (performance.now() - started)));
}

async function openEditor() {
  const name = $("scene").value;
  const r = await api("source?scene=" + encodeURIComponent(name));
  if (!r.ok) { showError(`${name} is not a script file`); return; }
  const text = await r.text();
  $("editorPane").hidden = false;
  $("editorName").textContent = scenes.find(x => x.name === name)?.file ?? name;
  if (!editor) {
    editor = CodeMirror($("editor"), { value: text, mode: "text/x-csharp", lineNumbers: true, indentUnit: 2, tabSize: 2 });
    editor.setOption("extraKeys", { "Ctrl-S": save, "Cmd-S": save });
  }
  editedScene = name;
  loadSource(text, r.headers.get("ETag"));
}

// The editor shows the file's text as it is on disk, with no unsaved edits.
function loadSource(text, tag) {
  sourceEpoch++;
  const cursor = editor.getCursor();
  if (editor.getValue() !== text) editor.setValue(text);
  editor.setCursor(cursor);
  editor.markClean();
  editorTag = tag;
  diskTag = diskText = null;
  $("sourceChanged").hidden = true;
}

// Another editor changed the open script: the text is reloaded, or, over unsaved edits, the user is asked.
async function checkSource() {
  if (!editor || !editedScene || $("editorPane").hidden || checkingSource) return;
  checkingSource = true;
  const epoch = sourceEpoch;
  try {
    const r = await fetch("api/source?scene=" + encodeURIComponent(editedScene), {
      cache: "no-store", headers: editorTag ? { "If-None-Match": editorTag } : {},
    });
    const tag = r.headers.get("ETag");
    if (r.status !== 200 || epoch !== sourceEpoch || tag === editorTag || tag === diskTag) return;
    const text = await r.text();
    if (epoch !== sourceEpoch) return;   // saved or reloaded meanwhile
    if (editor.isClean() || editor.getValue() === text) {
      loadSource(text, tag);
      pageNote = `${$("editorName").textContent} changed on disk: reloaded`;
    } else {
      diskTag = tag;
      diskText = text;
      $("sourceChanged").hidden = false;
    }
  } catch { } finally {
    checkingSource = false;
  }
}

async function save() {
  if (!editor || !editedScene) return;
  sourceEpoch++;
  const text = editor.getValue(), headers = { "Content-Type": "text/plain; charset=utf-8", "X-GrCis-Tab": tab };
  // Only over the text it was loaded from (or the disk's, once the user chose to keep theirs): never over a newer file unseen.
  if (editorTag) headers["If-Match"] = editorTag;
  try {
    const r = await fetch("api/source?scene=" + encodeURIComponent(editedScene), { method: "PUT", headers, body: text });
    if (r.status === 412) {
      await checkSource();   // asks, showing the bar (or reloads, when nothing was edited)
      return;
    }
    if (!r.ok) {
      let message = await r.text();
      try { message = JSON.parse(message).error ?? message; } catch { }
      throw new Error(message || r.statusText);
    }
    sourceEpoch++;
    editorTag = r.headers.get("ETag");
    if (editor.getValue() === text) editor.markClean();
    showError("");
    // 204: the rendered script, which the studio re-renders; 202: another script, which it compiles.
    if (r.status === 202) compilingSave = $("editorName").textContent;
    $("messages").textContent = "saved; compiling…";
  } catch (e) {
    showError(e.message);
  }
  pollSoon(150);
}

async function loadHistory(list) {
  const h = list ?? await (await api("history")).json();
  $("back").disabled = !h.canGoBack;
  $("forward").disabled = !h.canGoForward;
  $("historyLabel").textContent = h.position >= 0 ? `${h.position + 1}/${h.items.length}: ${h.items[h.position].label}` : "";
  // The B choices: every kept render; a choice whose render is no longer the same one is dropped.
  const select = $("abWith"), chosen = select.value, chosenLabel = select.selectedOptions[0]?.textContent;
  select.length = 1;
  h.items.forEach((item, i) => select.add(new Option(`${i + 1}: ${item.label}`, String(i))));
  select.value = chosen !== "" && select.options[Number(chosen) + 1]?.textContent === chosenLabel ? chosen : "";
  if (select.value !== chosen) await compareWith();
}

async function moveHistory(direction) {
  try {
    const h = await (await api("history/" + direction, { method: "POST" })).json();
    await loadHistory(h);
    viewsFor = -1;
    const s = await (await api("status")).json();
    await showImage(s.version);
  } catch (e) {
    showError(e.message);
  }
}

async function showView() {
  const kind = $("view-kind").value;
  $("viewDownloads").hidden = kind === "";
  if (kind === "") return showImage(-1);
  try {
    if (viewsFor !== shownVersion) {
      $("messages").textContent = "computing the extra views…";
      await api("views", { method: "POST" });
      viewsFor = shownVersion;
      $("messages").textContent = "";
    }
    $("viewPng").href = `api/views/${kind}.png`;
    $("viewPng").download = kind.toLowerCase() + ".png";
    $("viewCsv").href = `api/views/${kind}.csv`;
    $("viewCsv").download = kind.toLowerCase() + ".csv";
    await draw(await api(`views/${kind}.png?v=${viewsFor}`));
  } catch (e) {
    showError(e.message);
  }
}

async function showImage(version) {
  if ($("view-kind").value !== "") return showView();
  const r = await api("image.png?v=" + version);
  if (r.status === 404) return;
  shownVersion = Number(r.headers.get("X-Image-Version"));
  await draw(r);
}

async function draw(response) {
  const bitmap = await createImageBitmap(await response.blob());
  if (canvas.width !== bitmap.width || canvas.height !== bitmap.height) {
    canvas.width = bitmap.width;
    canvas.height = bitmap.height;
  }
  ctx.drawImage(bitmap, 0, 0);
  place();
}

function place() {
  canvas.style.transform = $("canvasB").style.transform = `translate(${panX}px, ${panY}px) scale(${zoom})`;
}

// A/B: a kept render (B) drawn over the image on show (A), placed as it is and cut at the split: A left of it, B right.
async function compareWith() {
  const i = $("abWith").value, b = $("canvasB");
  $("abSplit").hidden = b.hidden = i === "";
  if (i === "") return;
  try {
    const bitmap = await createImageBitmap(await (await api(`history/${i}.png`)).blob());
    b.width = bitmap.width;
    b.height = bitmap.height;
    b.getContext("2d").drawImage(bitmap, 0, 0);
    b.dataset.item = i;
    split();
    place();
  } catch (e) {
    showError(e.message);
  }
}

function split() { $("canvasB").style.clipPath = `inset(0 0 0 ${$("abSplit").value}%)`; }

// The whole image in the view, as large as it fits (within the zoom's 1/8 to 64), centred.
function fit() {
  const w = $("view").clientWidth, h = $("view").clientHeight;
  zoom = Math.min(64, Math.max(1 / 8, Math.min(w / canvas.width, h / canvas.height)));
  panX = (w - canvas.width * zoom) / 2;
  panY = (h - canvas.height * zoom) / 2;
  place();
}

// 1:1 about the view's centre: the pixel in the middle stays there.
function actualSize() {
  const cx = $("view").clientWidth / 2, cy = $("view").clientHeight / 2;
  panX = cx - (cx - panX) / zoom;
  panY = cy - (cy - panY) / zoom;
  zoom = 1;
  place();
}

function pixelAt(e) {
  const box = $("view").getBoundingClientRect();
  return { x: Math.floor((e.clientX - box.left - panX) / zoom), y: Math.floor((e.clientY - box.top - panY) / zoom) };
}

$("view").addEventListener("wheel", e => {
  // Zoom about the cursor, 1/8 to 64.
  e.preventDefault();
  const box = $("view").getBoundingClientRect(), cx = e.clientX - box.left, cy = e.clientY - box.top;
  const next = Math.min(64, Math.max(1 / 8, zoom * (e.deltaY < 0 ? 1.25 : 0.8)));
  panX = cx - (cx - panX) * next / zoom;
  panY = cy - (cy - panY) * next / zoom;
  zoom = next;
  place();
}, { passive: false });
$("view").addEventListener("mousedown", e => { drag = { x: e.clientX, y: e.clientY, moved: false }; });
window.addEventListener("mouseup", e => {
  if (drag && !drag.moved) probe(pixelAt(e));
  drag = null;
});
$("view").addEventListener("mousemove", e => {
  if (drag) {
    if (Math.abs(e.clientX - drag.x) + Math.abs(e.clientY - drag.y) > 2) drag.moved = true;
    panX += e.clientX - drag.x;
    panY += e.clientY - drag.y;
    drag.x = e.clientX;
    drag.y = e.clientY;
    place();
    return;
  }
  const p = pixelAt(e);
  if (p.x < 0 || p.y < 0 || p.x >= canvas.width || p.y >= canvas.height) return;
  const kind = $("view-kind").value;
  if (kind !== "") {
    // The view's value under the cursor comes from the server, at most every 100 ms.
    clearTimeout(hoverTimer);
    hoverTimer = setTimeout(async () => {
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
  if (e.key === "r") { zoom = 1; panX = panY = 0; place(); }
  else if (e.key === "f" || e.key === "F") fit();
  else if (e.key === "1") actualSize();
});

async function probe(p) {
  if (p.x < 0 || p.y < 0 || p.x >= canvas.width || p.y >= canvas.height) return;
  try {
    const r = await (await api(`probe?x=${p.x}&y=${p.y}`)).json();
    const f = v => v ? "(" + v.map(c => c.toFixed(3)).join(", ") + ")" : "-";
    const lines = [`pixel [${r.x}, ${r.y}] ${f(r.pixel)}, hash ${r.hash}`];
    const walk = (n, indent) => {
      lines.push(`${indent}${n.kind} ${n.solid ?? (n.blocked ? "blocked" : "miss")} at ${f(n.hit)}`);
      for (const c of n.children) walk(c, indent + "  ");
    };
    if (r.rays) walk(r.rays, "");
    $("rays").textContent = lines.join("\n");
    lastProbe = r;
    $("show3d").hidden = !r.rays;
    if (!$("rays3dPane").hidden) await show3d();
  } catch (e) {
    showError(e.message);
  }
}

$("scene").addEventListener("change", sceneChanged);
$("param").addEventListener("change", loadScriptValues);
for (const id of [...Object.keys(givenFlag), ...rangeFields]) {
  $(id).addEventListener("input", fieldChanged);
  $(id).addEventListener("change", fieldChanged);
}
$("view-kind").addEventListener("change", showView);
$("edit").addEventListener("click", openEditor);
$("open").addEventListener("click", async () => {
  const files = await (await api("files")).json();
  const select = $("files");
  select.innerHTML = "";
  for (const f of files) {
    const o = document.createElement("option");
    o.value = o.textContent = f;
    select.appendChild(o);
  }
  $("picker").hidden = files.length === 0;
  if (files.length === 0) showError("no scripts in the folders given to grcis studio");
});
$("add").addEventListener("click", async () => {
  try {
    const added = await (await api("scenes/add", {
      method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify({ path: $("files").value }),
    })).json();
    await loadScenes();
    $("scene").value = added.name;
    sceneChanged();
    $("picker").hidden = true;
  } catch (e) {
    showError(e.message);
  }
});
$("animRender").addEventListener("click", renderFrames);
$("animStop").addEventListener("click", () => api("animation/stop", { method: "POST" }));
$("animScrub").addEventListener("input", () => showFrame(Number($("animScrub").value)));
$("animPlay").addEventListener("click", togglePlay);
$("fit").addEventListener("click", fit);
$("abWith").addEventListener("change", compareWith);
$("abSplit").addEventListener("input", split);
$("show3d").addEventListener("click", async () => { $("rays3dPane").hidden = !$("rays3dPane").hidden; if (!$("rays3dPane").hidden) await show3d(); });
$("save").addEventListener("click", save);
$("closeEditor").addEventListener("click", () => { $("editorPane").hidden = true; });
$("reloadSource").addEventListener("click", () => { if (diskText !== null) loadSource(diskText, diskTag); });
$("keepMine").addEventListener("click", () => {
  // The next save replaces the file on disk with the editor's text.
  editorTag = diskTag ?? editorTag;
  diskTag = diskText = null;
  $("sourceChanged").hidden = true;
});
document.addEventListener("keydown", e => {
  // In the editor CodeMirror's own Ctrl+S has saved already (and prevented the default): one save per key press.
  if ((e.ctrlKey || e.metaKey) && e.key === "s" && !e.defaultPrevented) { e.preventDefault(); save(); }
});
$("back").addEventListener("click", () => moveHistory("back"));
$("forward").addEventListener("click", () => moveHistory("forward"));
$("render").addEventListener("click", render);
$("stop").addEventListener("click", () => api("stop", { method: "POST" }));
loadScenes().then(loadAlgorithm).then(() => pollSoon(0)).catch(e => { showError(e.message); });
