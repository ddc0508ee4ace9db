// One probed pixel's ray tree as line segments, a group the 3D view shows among the scene (layer "rays"). Colours: primary
// white, shadow yellow (red when blocked), reflected cyan, refracted magenta, others grey, normals green. One geometry
// per kind of line, holding all its segments; the view disposes them when the next probe replaces the group.

export const colours = { Primary: 0xffffff, Shadow: 0xffdd33, Blocked: 0xff3333, Reflected: 0x33ddff, Refracted: 0xff55ff, Other: 0x999999,
  Normal: 0x44ff44 };

// The tree of root (a probe's rays, or null) as a group; size is the scene's size (a ray that hits nothing is drawn that
// long, a normal 3 % of it). The group's userData.segments counts the segments drawn.
export function rays(root, size) {
  const group = new THREE.Group();
  group.name = "rays";
  // Per kind of line, its segments' end points (x, y, z, x, y, z, …).
  const segments = {};
  const add = (kind, from, to) => (segments[kind] ??= []).push(...from, ...to);
  const walk = n => {
    const end = n.hit ?? n.origin.map((o, i) => o + n.direction[i] * size / Math.hypot(...n.direction));
    add(n.kind === "Shadow" && n.blocked ? "Blocked" : n.kind in colours ? n.kind : "Other", n.origin, end);
    if (n.hit && n.normal) add("Normal", n.hit, n.hit.map((p, i) => p + n.normal[i] * size * 0.03));
    n.children.forEach(walk);
  };
  if (root) walk(root);
  let count = 0;
  for (const [kind, points] of Object.entries(segments)) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.Float32BufferAttribute(points, 3));
    group.add(new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: colours[kind] })));
    count += points.length / 6;
  }
  group.userData.segments = count;
  return group;
}
