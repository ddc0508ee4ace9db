// The ray visualiser: the scene's bounding boxes and one pixel's rays in an orbitable three.js view.
// Drag to orbit, wheel to zoom. Colours: primary white, shadow yellow (red when blocked), reflected cyan,
// refracted magenta, others grey.
"use strict";

const RayView = (() => {
  const colours = { Primary: 0xffffff, Shadow: 0xffdd33, Reflected: 0x33ddff, Refracted: 0xff55ff };
  let renderer = null, scene = null, camera = null, target = null;
  let radius = 10, theta = 0.6, phi = 1.1, dragging = null;

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

  function segment(from, to, colour) {
    const g = new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(...from), new THREE.Vector3(...to)]);
    return new THREE.Line(g, new THREE.LineBasicMaterial({ color: colour }));
  }

  // Shows the ray tree of a probe (root node) among the scene's boxes.
  function show(canvas, boxes, root) {
    if (!renderer) init(canvas);
    scene = new THREE.Scene();
    const all = new THREE.Box3();
    for (const b of boxes) {
      const box = new THREE.Box3(new THREE.Vector3(...b.min), new THREE.Vector3(...b.max));
      scene.add(new THREE.Box3Helper(box, 0x777777));
      all.union(box);
    }
    if (root) all.expandByPoint(new THREE.Vector3(...root.origin));
    const size = all.isEmpty() ? 10 : all.getSize(new THREE.Vector3()).length();
    const walk = n => {
      // A ray that hits nothing is drawn as far as the scene is large.
      const end = n.hit ?? n.origin.map((o, i) => o + n.direction[i] * size / Math.hypot(...n.direction));
      const colour = n.kind === "Shadow" && n.blocked ? 0xff3333 : colours[n.kind] ?? 0x999999;
      scene.add(segment(n.origin, end, colour));
      if (n.hit && n.normal)
        scene.add(segment(n.hit, n.hit.map((p, i) => p + n.normal[i] * size * 0.03), 0x44ff44));
      n.children.forEach(walk);
    };
    if (root) walk(root);
    target = all.isEmpty() ? new THREE.Vector3() : all.getCenter(new THREE.Vector3());
    radius = Math.max(1, size * 1.2);
    draw();
    return scene.children.length;
  }

  return { show };
})();
