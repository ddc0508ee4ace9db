// The scene, its parameters and the settings: the script's own values shown marked, the user's winning once changed;
// Render sends them.
import { $, state } from "./state.js";
import { api } from "./api.js";
import { showError } from "./messages.js";
import { adopt } from "./status.js";

const givenFlag = { width: "Size", height: "Size", spp: "SamplesPerPixel", jitter: "Jitter",
  shadows: "Shadows", reflections: "Reflections", refractions: "Refractions" };
const rangeFields = ["animStart", "animEnd", "animFps"];

export async function loadScenes() {
  const list = await (await api("scenes")).json();
  state.scenes = list.scenes;
  const select = $("scene");
  select.innerHTML = "";
  // Scripts and built-in scenes in groups of their own (a script shows its file name: "FiveBalls.cs", not "Five balls").
  const groups = {};
  for (const s of state.scenes) {
    const group = groups[s.kind] ??= select.appendChild(Object.assign(document.createElement("optgroup"),
      { label: s.kind === "Script" ? "Scripts" : "Built-in scenes" }));
    const o = document.createElement("option");
    o.value = s.name;
    o.textContent = s.label ?? s.name;
    group.appendChild(o);
  }
  if (list.selected) select.value = list.selected;
  return sceneChanged();
}

export function sceneChanged(e) {
  // Chosen by the user: the shown render's error and notes are another scene's.
  if (e) state.staleRender = state.studio.renderId;
  const s = state.scenes.find(x => x.name === $("scene").value);
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
    state.given.delete("Size");
  if (showScriptValue("spp", v.samplesPerPixel)) state.given.delete("SamplesPerPixel");
  $("algorithm").options[0].textContent = `scene's (${v.algorithm ?? "ray tracing"})`;
  for (const [id, value] of [["animStart", v.start], ["animEnd", v.end], ["animFps", v.fps]])
    if (showScriptValue(id, value)) state.rangeGiven.delete(id);
  if (v.tooltip) { $("param").title = $("param").placeholder = v.tooltip; }
}

// A field the user changes is given: it wins over the script's value.
function fieldChanged(e) {
  const id = e.target.id;
  if (givenFlag[id]) state.given.add(givenFlag[id]);
  if (rangeFields.includes(id)) state.rangeGiven.add(id);
  for (const f of id === "width" || id === "height" ? ["width", "height"] : [id]) {
    $(f).classList.remove("script");
    $(f).title = "";
  }
}

// An animation field as sent: the user's value, or null for the script's (else the scene's, else 0 to 10 s at 25 fps).
export function rangeValue(id) {
  return state.rangeGiven.has(id) || !$(id).classList.contains("script") && $(id).value !== "" ? Number($(id).value) : null;
}

export function settings() {
  const num = id => Number($(id).value);
  const time = $("time").value.trim();
  return {
    width: num("width"), height: num("height"), samplesPerPixel: num("spp"), jitter: num("jitter"),
    shadows: $("shadows").checked, reflections: $("reflections").checked, refractions: $("refractions").checked,
    threads: num("threads"), seed: num("seed"), time: time === "" ? null : Number(time),
  };
}

// The algorithm and preview choice the studio renders with now ("" = the scene's choice), shown after a reload of the page;
// so are the size and samples per pixel of the render on show (a reload mid-render must not offer another size).
export function showChoices(status) {
  if (status.width != null && status.height != null &&
      (Number($("width").value) !== status.width || Number($("height").value) !== status.height)) {
    $("width").value = status.width;
    $("height").value = status.height;
    for (const f of ["width", "height"]) { $(f).classList.remove("script"); $(f).title = ""; }
    state.given.add("Size");
  }
  if (status.samplesPerPixel != null && Number($("spp").value) !== status.samplesPerPixel) {
    $("spp").value = status.samplesPerPixel;
    $("spp").classList.remove("script");
    $("spp").title = "";
    state.given.add("SamplesPerPixel");
  }
  $("algorithm").value = status.algorithm ?? "";
  $("progressive").value = status.progressive == null ? "" : String(status.progressive);
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
    const r = await api("render", {
      method: "POST", headers: { "Content-Type": "application/json" },
      body: JSON.stringify({
        scene: $("scene").value, param: $("param").value, settings: settings(), algorithm: $("algorithm").value, progressive: progressive(),
        given: [...state.given],
      }),
    });
    if (r.ok) adopt((await r.json()).renderId);
  } catch (e) {
    showError(e.message);
  }
}

export function initSettings() {
  $("scene").addEventListener("change", sceneChanged);
  $("param").addEventListener("change", loadScriptValues);
  // Enter in Parameters renders, as the Render button does (the new text reaches the script's values too, through "change").
  $("param").addEventListener("keydown", e => {
    if (e.key !== "Enter" || e.isComposing) return;
    e.preventDefault();
    render();
  });
  for (const id of [...Object.keys(givenFlag), ...rangeFields]) {
    $(id).addEventListener("input", fieldChanged);
    $(id).addEventListener("change", fieldChanged);
  }
  $("render").addEventListener("click", render);
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
}
