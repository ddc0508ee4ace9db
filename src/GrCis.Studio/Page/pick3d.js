// Hover and pick in the 3D view. Hovering a surface names its part in a small label beside the pointer (name, class, the
// CSG operation it is an operand of, its colour); a click on a surface probes the pixel of the render that sees that
// point, and says so when no pixel does (the point lies outside the camera's view or behind something). Both ask three.js
// about the surfaces layer only; hover at most once per animation frame. The script line that made a solid is not
// shown: the scene graph does not record it.
import { state } from "./state.js";

const v3 = a => new THREE.Vector3(...a);

// Where the render's pinhole camera c (the tessellation's camera) sees GrCis point p: the pixel coordinates (continuous,
// 0 at the image's left and top edges) and the point's depth along the view direction; null behind the camera. GrCis's
// world is left-handed: up × direction points to the image's right.
export function pixelOf(c, width, height, p) {
  const dir = v3(c.direction).normalize(), up = v3(c.up).normalize(), right = new THREE.Vector3().crossVectors(up, dir).normalize();
  const d = v3(p).sub(v3(c.position)), depth = d.dot(dir);
  if (!(depth > 0)) return null;
  const t = Math.tan(c.verticalFov / 2);
  return { x: (1 + d.dot(right) / (depth * t * c.aspect)) * width / 2, y: (1 - d.dot(up) / (depth * t)) * height / 2, depth };
}

const f2 = c => c.map(v => v.toFixed(2)).join(", ");

// The label's lines for a part (its mesh's userData).
function describe(u) {
  const lines = [u.name, u.csg ? `${u.type} · ${u.csg} operand` : u.type];
  if (u.kind === "BoundingBox") lines.push("its bounding box (a solid of the script's own class)");
  lines.push(u.emission ? `emits (${f2(u.emission)})` : `colour (${f2(u.color)})`);
  return lines;
}

export class Picker {
  // view: the View3d; pane: the 3D pane (the label and status are its children); scene(): the tessellation shown;
  // probe(pixel): probes a pixel of the render as a click on the image does (state.probe holds the answer).
  constructor(view, pane, scene, probe) {
    Object.assign(this, { view, pane, scene, probe });
    this.label = pane.querySelector("#hover3d");
    this.status = pane.querySelector("#pick3d");
    this.pending = null;
    this.frame = 0;
    this.down = null;
    const canvas = view.canvas;
    canvas.addEventListener("pointermove", e => {
      this.pending = e;
      this.frame ||= requestAnimationFrame(() => this.hover());
    });
    canvas.addEventListener("pointerleave", () => this.hide());
    canvas.addEventListener("pointerdown", e => { this.down = { x: e.clientX, y: e.clientY }; });
    canvas.addEventListener("pointerup", e => {
      const d = this.down;
      this.down = null;
      if (d && Math.abs(e.clientX - d.x) + Math.abs(e.clientY - d.y) < 4) this.click(e.clientX, e.clientY);
    });
  }

  hide() {
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.pending = null;
    this.label.hidden = true;
    delete this.label.dataset.part;
  }

  // The part under the pointer, named beside it: below and right of the pointer, flipped left or up at the pane's
  // edges, never under it (and it lets the pointer through).
  hover() {
    this.frame = 0;
    const e = this.pending;
    if (!e) return;
    const hit = this.view.dragging?.moved ? null : this.view.surfaceAt(e.clientX, e.clientY);
    if (!hit) {
      this.label.hidden = true;
      delete this.label.dataset.part;
      return;
    }
    const u = hit.mesh.userData, label = this.label;
    if (label.dataset.part !== u.name) {
      label.replaceChildren(...describe(u).map(t => Object.assign(document.createElement("div"), { textContent: t })));
      label.dataset.part = u.name;
    }
    label.hidden = false;
    const box = this.pane.getBoundingClientRect(), gap = 14;
    let x = e.clientX - box.left + gap, y = e.clientY - box.top + gap;
    if (x + label.offsetWidth > box.width) x = e.clientX - box.left - gap - label.offsetWidth;
    if (y + label.offsetHeight > box.height) y = e.clientY - box.top - gap - label.offsetHeight;
    label.style.left = `${Math.max(0, x)}px`;
    label.style.top = `${Math.max(0, y)}px`;
  }

  click(x, y) {
    const hit = this.view.surfaceAt(x, y);
    if (hit) return this.pick(hit.mesh.userData.part, hit.point);
  }

  // Probes the pixel that sees `point` (GrCis's world) of part index `part`, and says whether that pixel's primary ray
  // hits this point, another part or the same part elsewhere (the point is hidden), or no pixel sees it at all. What it
  // found is on the pane as data-pick-part, data-pick-pixel ("x,y", empty when none) and data-pick-visible.
  async pick(part, point) {
    const json = this.scene(), mesh = this.view.layers.surfaces?.children.find(m => m.userData.part === part);
    if (!json || !mesh) return;
    const name = mesh.userData.name, c = json.camera;
    const at = c ? pixelOf(c, json.width, json.height, point) : null;
    if (!at || at.x < 0 || at.y < 0 || at.x >= json.width || at.y >= json.height)
      return this.report(name, null, false, `${name} here is not visible from the camera: ${c ? "outside its view" : "the scene has no camera"}`);
    const pixel = { x: Math.floor(at.x), y: Math.floor(at.y) };
    await this.probe(pixel);
    const r = state.probe;
    if (r?.x !== pixel.x || r?.y !== pixel.y) return;
    // Near enough: a few pixels' width at that depth, and the tessellation's error (a fiftieth of the solid's size).
    mesh.geometry.boundingSphere ?? mesh.geometry.computeBoundingSphere();
    const tolerance = 6 * at.depth * Math.tan(c.verticalFov / 2) / json.height +
      0.02 * mesh.geometry.boundingSphere.radius * mesh.matrix.getMaxScaleOnAxis();
    const hit = r.rays?.kind === "Primary" ? r.rays.hit : null;
    const visible = r.part === part && hit != null && v3(hit).distanceTo(v3(point)) <= tolerance;
    const sees = r.part === part ? `${name} in front of this point` : r.partName ?? (hit ? "a solid the view does not show" : "the background");
    this.report(name, pixel, visible, visible ? `${name}: seen at pixel [${pixel.x}, ${pixel.y}]`
      : `${name} here is not visible from the camera: pixel [${pixel.x}, ${pixel.y}] sees ${sees}`);
  }

  report(name, pixel, visible, text) {
    Object.assign(this.pane.dataset, { pickPart: name, pickPixel: pixel ? `${pixel.x},${pixel.y}` : "", pickVisible: String(visible) });
    this.status.textContent = text;
    this.status.hidden = false;
  }
}
