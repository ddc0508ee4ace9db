// The 3D pane: the scene on show (its solids, lights and camera, api/scene/tessellation), the prepared scene's boxes, the
// probed pixel's rays and the render's hit points (api/scene/points), in one orbitable view (view3d.js) with a checkbox
// per layer (remembered in localStorage) and "View from camera"; hover and pick (pick3d.js). The scene is fetched once per
// render or animation frame on show, the points once per render while their layer is on; a probe replaces only the rays
// and the highlighted part (the one its primary ray hit). What each layer holds is written on the pane as data attributes
// (data-surfaces, data-lights, data-points, data-highlight, …), for a reader or a test.
import { $, state } from "./state.js";
import { api, problemText } from "./api.js";
import { showError } from "./messages.js";
import { View3d } from "./view3d.js";
import * as Scene3d from "./scene3d.js";
import { rays } from "./rays3d.js";
import { Picker } from "./pick3d.js";

const layerNames = ["surfaces", "boxes", "lights", "camera", "rays", "points"];
const defaults = { surfaces: true, boxes: false, lights: true, camera: true, rays: true, points: false };
// The points asked for: a 200 × 200 grid's worth, whatever the render's size.
const maxPoints = 40000;
const storeKey = "grcis-3d-layers";

// The pane's one state: the view (made when first opened) and its picker, the scene shown (its key and JSON), the scene
// whose points are shown, its size, the number of the newest request (an older answer arriving late is dropped), and how
// to probe a pixel (the image's click, given to initPane3d).
const pane = { view: null, picker: null, key: null, json: null, pointsKey: null, size: 10, asked: 0, probe: null };

function storedLayers() {
  try {
    return { ...defaults, ...JSON.parse(localStorage.getItem(storeKey) ?? "{}") };
  } catch {
    return { ...defaults };
  }
}

const isOpen = () => !$("rays3dPane").hidden;

// What is on show: an animation frame (its number) or the last still render.
function onShow() {
  const frame = $("animFrame").dataset.frame;
  return state.animation.onShow && frame !== undefined ? { key: `frame ${frame}`, query: `?frame=${frame}` }
    : { key: `render ${state.studio.generation}/${state.studio.renderId}`, query: "" };
}

function view() {
  if (!pane.view) {
    pane.view = new View3d($("rays3d"));
    pane.view.onCamera = on => $("fromCamera").setAttribute("aria-pressed", String(on));
    const shown = storedLayers();
    for (const name of layerNames) pane.view.visible[name] = shown[name];
    pane.picker = new Picker(pane.view, $("rays3dPane"), () => pane.json, p => pane.probe(p));
  }
  return pane.view;
}

function writeCounts() {
  const c = pane.view.counts(), p = $("rays3dPane");
  p.dataset.surfaces = c.surfaces;
  p.dataset.boxSolids = c.boxSolids;
  p.dataset.emitters = c.emitters;
  p.dataset.lights = c.lights;
  p.dataset.cameras = c.cameras;
  p.dataset.raySegments = c.raySegments;
  p.dataset.points = c.points;
  p.dataset.highlight = pane.view.highlighted?.mesh.userData.name ?? "";
  p.dataset.scene = pane.key ?? "";
}

// The probed pixel's rays, and the part its primary ray hit tinted (the previous probe's restored).
function showRays() {
  pane.view.setLayer("rays", rays(state.probe?.rays ?? null, pane.size));
  pane.view.highlight(state.probe?.part ?? null);
}

// The render's hit points, once per render while their layer is on; an animation frame has none (they are a still
// render's: the layer is empty then).
async function showPoints(want, asked) {
  if (!pane.view.visible.points || pane.pointsKey === want.key) return;
  let group = null;
  if (!want.query) {
    const r = await api(`scene/points?max=${maxPoints}`);
    if (!r.ok) throw new Error(await problemText(r));
    const json = await r.json();
    if (asked !== pane.asked) return;
    group = Scene3d.points(json);
  }
  pane.view.setLayer("points", group);
  pane.pointsKey = want.key;
}

// Fetches the scene on show (unless it is the one shown) and its boxes, and draws every layer.
export async function refresh() {
  if (!isOpen()) return;
  const v = view(), want = onShow(), asked = ++pane.asked;
  try {
    if (want.key !== pane.key) {
      const r = await api("scene/tessellation" + want.query);
      if (!r.ok) throw new Error(await problemText(r));
      const json = await r.json();
      const boxes = await (await api("scene/boxes")).json();
      if (asked !== pane.asked) return;
      const surfaces = Scene3d.surfaces(json);
      const box = Scene3d.bounds(surfaces, json, state.probe?.rays ? [state.probe.rays.origin] : []);
      pane.size = box ? box.getSize(new THREE.Vector3()).length() : 10;
      v.setLayer("surfaces", surfaces);
      v.setLayer("boxes", Array.isArray(boxes) ? Scene3d.boxes(boxes) : null);
      v.setLayer("lights", Scene3d.lights(json, pane.size));
      v.setLayer("camera", Scene3d.camera(json, pane.size * 0.12));
      v.sceneCamera = json.camera;
      Object.assign(pane, { key: want.key, json });
      // What is not drawn as it is (a mesh beyond the triangle budget as its box, a script's own solid as its box).
      const notes = $("notes3d");
      notes.textContent = (json.notes ?? []).join(" · ");
      notes.hidden = !notes.textContent;
      if (!v.fromCamera) v.frame(box);
      $("fromCamera").disabled = !json.camera;
    }
    if (asked !== pane.asked) return;
    await showPoints(want, asked);
    if (asked !== pane.asked) return;
    showRays();
    writeCounts();
    if (v.fromCamera) v.viewFromCamera(pane.json.width, pane.json.height);
    else v.draw();
  } catch (e) {
    showError(e.message);
  }
}

// A new probe: its rays among the scene shown.
export function probed() {
  if (!isOpen() || !pane.view || !pane.json) return refresh();
  showRays();
  writeCounts();
  pane.view.draw();
}

// The pane closed: every layer's GPU memory given back; the scene is fetched again when it opens.
function close() {
  pane.view?.clear();
  pane.key = pane.json = pane.pointsKey = null;
  pane.asked++;
  pane.picker?.hide();
  $("pick3d").hidden = true;
}

// What the renderer holds on the GPU now (null before the view is made), what each layer holds, and the canvas as PNG.
export const memory = () => pane.view?.memory() ?? null;
export const counts = () => pane.view?.counts() ?? null;
export const snapshot = () => pane.view?.snapshot() ?? null;
export const visibleLayers = () => layerNames.filter(n => pane.view?.layers[n]?.visible ?? false);

// Where part `name` (e.g. "Sphere 2") is drawn now: the client point of its middle, or null.
export function screenOf(name) {
  const mesh = pane.view?.layers.surfaces?.children.find(m => m.userData.name === name);
  if (!mesh) return null;
  mesh.geometry.boundingSphere ?? mesh.geometry.computeBoundingSphere();
  return pane.view.clientOf(mesh.geometry.boundingSphere.center.clone().applyMatrix4(mesh.matrixWorld));
}

// Picks point (GrCis's world) of part index `part`, as a click on it there does.
export const pickAt = (part, point) => pane.picker?.pick(part, point);

// probe(pixel): probes a pixel of the render, as a click on the image does (a click on a surface uses it).
export function initPane3d(probe) {
  pane.probe = probe;
  $("show3d").addEventListener("click", async () => {
    const p = $("rays3dPane");
    p.hidden = !p.hidden;
    $("show3d").setAttribute("aria-pressed", String(!p.hidden));
    if (p.hidden) close();
    else await refresh();
  });
  const shown = storedLayers();
  for (const box of document.querySelectorAll("#layers3d input[data-layer]")) {
    const name = box.dataset.layer;
    box.checked = shown[name];
    box.addEventListener("change", () => {
      const now = storedLayers();
      now[name] = box.checked;
      localStorage.setItem(storeKey, JSON.stringify(now));
      pane.view?.show(name, box.checked);
      if (name === "points" && box.checked) refresh();
    });
  }
  $("fromCamera").addEventListener("click", () => {
    if (pane.json) pane.view.viewFromCamera(pane.json.width, pane.json.height);
  });
  new ResizeObserver(() => { if (isOpen() && pane.view) pane.view.draw(); }).observe($("rays3dPane"));
}
