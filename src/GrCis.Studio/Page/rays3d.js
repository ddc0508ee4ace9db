// The ray visualiser: the scene's bounding boxes and one pixel's rays in an orbitable three.js view (three.js is the
// vendored classic script, global THREE). Drag to orbit, wheel to zoom. Colours: primary white, shadow yellow (red when
// blocked), reflected cyan, refracted magenta, others grey, normals green, boxes dark grey.
//
// One line material per kind of line, made once and shared by every view; one geometry per kind per view, holding all
// its segments. A new probe disposes the previous view's geometries, and closing the pane disposes the materials too
// (three.js makes them again when next drawn), so probing again and again holds no more GPU memory than one view.

const colours = { Primary: 0xffffff, Shadow: 0xffdd33, Blocked: 0xff3333, Reflected: 0x33ddff, Refracted: 0xff55ff, Other: 0x999999,
  Normal: 0x44ff44, Box: 0x777777 };
const materials = {};
let renderer = null, scene = null, camera = null, target = null;
let radius = 10, theta = 0.6, phi = 1.1, dragging = null;

function material(kind) {
  return materials[kind] ??= new THREE.LineBasicMaterial({ color: colours[kind] });
}

function init(canvas) {
  renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
  camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1e5);
  canvas.addEventListener("pointerdown", e => { dragging = { x: e.clientX, y: e.clientY }; canvas.setPointerCapture(e.pointerId); });
  canvas.addEventListener("pointerup", () => { dragging = null; });
  canvas.addEventListener("pointermove", e => {
    if (!dragging) return;
    theta -= (e.clientX - dragging.x) * 0.01;
    phi = Math.min(Math.PI - 0.01, Math.max(0.01, phi - (e.clientY - dragging.y) * 0.01));
    dragging = { x: e.clientX, y: e.clientY };
    draw();
  });
  canvas.addEventListener("wheel", e => { e.preventDefault(); radius *= e.deltaY < 0 ? 0.85 : 1.18; draw(); }, { passive: false });
}

function draw() {
  const w = renderer.domElement.clientWidth, h = renderer.domElement.clientHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / Math.max(1, h);
  camera.updateProjectionMatrix();
  camera.position.set(
    target.x + radius * Math.sin(phi) * Math.sin(theta),
    target.y + radius * Math.cos(phi),
    target.z + radius * Math.sin(phi) * Math.cos(theta));
  camera.lookAt(target);
  renderer.render(scene, camera);
}

// The view's geometries: each holds GPU buffers until disposed.
function disposeScene() {
  scene?.traverse(o => o.geometry?.dispose());
  scene = null;
}

// The twelve edges of a box as segments (pairs of corners).
function boxEdges(min, max, into) {
  const c = i => [i & 1 ? max[0] : min[0], i & 2 ? max[1] : min[1], i & 4 ? max[2] : min[2]];
  for (const [a, b] of [[0, 1], [2, 3], [4, 5], [6, 7], [0, 2], [1, 3], [4, 6], [5, 7], [0, 4], [1, 5], [2, 6], [3, 7]])
    into.push(...c(a), ...c(b));
}

// Shows the ray tree of a probe (root node) among the scene's boxes; returns the number of segments drawn.
export function show(canvas, boxes, root) {
  if (!renderer) init(canvas);
  disposeScene();
  scene = new THREE.Scene();
  // Per kind of line, its segments' end points (x, y, z, x, y, z, …).
  const segments = { Box: [] };
  const all = new THREE.Box3();
  for (const b of boxes) {
    boxEdges(b.min, b.max, segments.Box);
    all.union(new THREE.Box3(new THREE.Vector3(...b.min), new THREE.Vector3(...b.max)));
  }
  if (root) all.expandByPoint(new THREE.Vector3(...root.origin));
  const size = all.isEmpty() ? 10 : all.getSize(new THREE.Vector3()).length();
  const add = (kind, from, to) => (segments[kind] ??= []).push(...from, ...to);
  const walk = n => {
    // A ray that hits nothing is drawn as far as the scene is large.
    const end = n.hit ?? n.origin.map((o, i) => o + n.direction[i] * size / Math.hypot(...n.direction));
    add(n.kind === "Shadow" && n.blocked ? "Blocked" : n.kind in colours ? n.kind : "Other", n.origin, end);
    if (n.hit && n.normal) add("Normal", n.hit, n.hit.map((p, i) => p + n.normal[i] * size * 0.03));
    n.children.forEach(walk);
  };
  if (root) walk(root);
  let count = 0;
  for (const [kind, points] of Object.entries(segments)) {
    if (points.length === 0) continue;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.Float32BufferAttribute(points, 3));
    scene.add(new THREE.LineSegments(geometry, material(kind)));
    count += points.length / 6;
  }
  target = all.isEmpty() ? new THREE.Vector3() : all.getCenter(new THREE.Vector3());
  radius = Math.max(1, size * 1.2);
  draw();
  return count;
}

// The pane closed: the view's geometries and the shared materials are given back.
export function close() {
  disposeScene();
  for (const m of Object.values(materials)) m.dispose();
}

// What the renderer holds on the GPU now (three.js's own count of geometries and textures, and its shader programs).
export function memory() {
  return renderer ? { ...renderer.info.memory, programs: renderer.info.programs?.length ?? 0 } : null;
}
