// The pixel probe: a clicked pixel's colour, hash and ray tree as text, and its rays in the 3D view (pane3d.js).
import { $, state } from "./state.js";
import { api } from "./api.js";
import { showError } from "./messages.js";
import { probed } from "./pane3d.js";

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
    await probed();
  } catch (e) {
    showError(e.message);
  }
}
