// The pixel probe: a clicked pixel's colour, hash and ray tree as text, a ring around it on the image, and its rays and
// the part it hit in the 3D view (pane3d.js).
import { $, state } from "./state.js";
import { api } from "./api.js";
import { showError } from "./messages.js";
import { probed } from "./pane3d.js";
import { place } from "./view.js";

export async function probe(p) {
  try {
    const r = await (await api(`probe?x=${p.x}&y=${p.y}`)).json();
    const f = v => v ? "(" + v.map(c => c.toFixed(3)).join(", ") + ")" : "-";
    const lines = [`pixel [${r.x}, ${r.y}] ${f(r.pixel)}, hash ${r.hash}${r.partName ? `, hits ${r.partName}` : ""}`];
    const walk = (n, indent) => {
      lines.push(`${indent}${n.kind} ${n.solid ?? (n.blocked ? "blocked" : "miss")} at ${f(n.hit)}`);
      for (const c of n.children) walk(c, indent + "  ");
    };
    if (r.rays) walk(r.rays, "");
    $("rays").textContent = lines.join("\n");
    state.probe = r;
    place();
    await probed();
  } catch (e) {
    showError(e.message);
  }
}
