// The pixel probe: a clicked pixel's colour, hash and ray tree as text, and the rays among the scene's boxes in 3D.
import { $, state } from "./state.js";
import { api } from "./api.js";
import { showError } from "./messages.js";
import * as RayView from "./rays3d.js";

export async function probe(p) {
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
    state.probe = r;
    $("show3d").hidden = !r.rays;
    if (!$("rays3dPane").hidden) await show3d();
  } catch (e) {
    showError(e.message);
  }
}

async function show3d() {
  try {
    const boxes = await (await api("scene/boxes")).json();
    RayView.show($("rays3d"), boxes, state.probe?.rays);
  } catch (e) {
    showError(e.message);
  }
}

export function initProbe() {
  $("show3d").addEventListener("click", async () => {
    const pane = $("rays3dPane");
    pane.hidden = !pane.hidden;
    $("show3d").setAttribute("aria-pressed", String(!pane.hidden));
    if (pane.hidden) RayView.close();
    else await show3d();
  });
}
