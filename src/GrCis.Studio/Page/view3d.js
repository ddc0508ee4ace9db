// The 3D view: a three.js renderer over named layers (groups of objects: surfaces, boxes, lights, camera, rays, points), an
// orbit of our own (drag orbits, wheel zooms) and "view from the camera", which looks through the render's camera at the
// render's size so the view lines up with the image. three.js is the vendored classic script (global THREE).
//
// GPU memory: a layer replaced or the view closed disposes its geometries and materials, so showing scene after scene
// holds no more than one scene's worth.

// Everything of the scene hangs under one root that mirrors z: GrCis's world is left-handed (a camera looking along +z has
// +x on its right), three.js's right-handed; mirrored, the render's camera sees what the render shows, not its mirror image.
const mirror = v => new THREE.Vector3(v[0], v[1], -v[2]);

export class View3d {
  constructor(canvas) {
    this.canvas = canvas;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
    this.renderer.setClearColor(0x111111);
    this.camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1e5);
    this.scene = new THREE.Scene();
    // Shading light: a soft sky-and-ground fill, and a lamp at the eye so what faces the viewer is lit.
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x333333, 0.55));
    const lamp = new THREE.DirectionalLight(0xffffff, 0.6);
    lamp.position.set(0, 0, 1);
    this.camera.add(lamp);
    this.scene.add(this.camera);
    this.root = new THREE.Group();
    this.root.scale.z = -1;
    this.scene.add(this.root);
    this.layers = {};
    this.visible = {};
    // The orbit: the point looked at, the distance to it and two angles; sceneCamera, the render's camera (null = none);
    // fromCamera: the view looks through it at the render's size (width, height).
    this.orbit = { target: new THREE.Vector3(), radius: 10, theta: 0.6, phi: 1.1 };
    this.sceneCamera = null;
    this.fromCamera = null;
    // Told whether the view looks through the render's camera (the page marks its button pressed).
    this.onCamera = null;
    this.dragging = null;
    // The part shown highlighted (the probed pixel's): its mesh and the material its tinted copy replaced.
    this.highlighted = null;
    canvas.addEventListener("pointerdown", e => {
      this.dragging = { x: e.clientX, y: e.clientY, moved: false };
      canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener("pointerup", () => { this.dragging = null; });
    canvas.addEventListener("pointermove", e => this.drag(e));
    canvas.addEventListener("wheel", e => {
      e.preventDefault();
      this.leaveCamera();
      this.orbit.radius *= e.deltaY < 0 ? 0.85 : 1.18;
      this.draw();
    }, { passive: false });
  }

  drag(e) {
    if (!this.dragging) return;
    // A press that has not moved a few pixels is a click (a pick), not yet an orbit.
    if (!this.dragging.moved && Math.abs(e.clientX - this.dragging.x) + Math.abs(e.clientY - this.dragging.y) < 4) return;
    this.dragging.moved = true;
    this.leaveCamera();
    const o = this.orbit;
    o.theta -= (e.clientX - this.dragging.x) * 0.01;
    o.phi = Math.min(Math.PI - 0.01, Math.max(0.01, o.phi - (e.clientY - this.dragging.y) * 0.01));
    this.dragging = { x: e.clientX, y: e.clientY };
    this.draw();
  }

  // Replaces layer name's group (disposing the old one's GPU buffers), shown as its checkbox says.
  setLayer(name, group) {
    const old = this.layers[name];
    if (name === "surfaces") this.highlight(null);
    if (old) {
      this.root.remove(old);
      dispose(old);
    }
    this.layers[name] = group;
    if (!group) return;
    group.visible = this.visible[name] ?? true;
    this.root.add(group);
  }

  show(name, visible) {
    this.visible[name] = visible;
    if (this.layers[name]) this.layers[name].visible = visible;
    this.draw();
  }

  // Orbits around the middle of box (GrCis's coordinates), far enough to see all of it; from beside the render's camera
  // when there is one (the scene as the render shows it, turned a little so the camera's frustum shows too).
  frame(box) {
    const size = box ? box.getSize(new THREE.Vector3()).length() : 10;
    const centre = box ? box.getCenter(new THREE.Vector3()) : new THREE.Vector3();
    const o = this.orbit;
    o.target = mirror(centre.toArray());
    // Far enough that a ball of the box's diagonal fits the narrower of the view's two angles.
    const aspect = this.canvas.clientWidth / Math.max(1, this.canvas.clientHeight), half = Math.PI / 8;
    const narrower = Math.min(half, Math.atan(Math.tan(half) * aspect));
    o.radius = Math.max(1e-3, size / 2 / Math.sin(narrower));
    if (this.sceneCamera) {
      const offset = mirror(this.sceneCamera.position).sub(o.target);
      if (offset.lengthSq() > 0) {
        o.theta = Math.atan2(offset.x, offset.z) + 0.5;
        o.phi = Math.min(Math.PI - 0.01, Math.max(0.01, Math.acos(offset.y / offset.length()) - 0.35));
      }
    }
    this.camera.near = Math.max(1e-4, size * 1e-3);
    this.camera.far = size * 100 + 1;
  }

  // Looks through the render's camera (GrCis's position, direction, up, vertical fov) at the render's size in pixels;
  // false when the scene has no camera.
  viewFromCamera(width, height) {
    if (!this.sceneCamera) return false;
    this.fromCamera = { width, height };
    this.canvas.classList.add("from-camera");
    this.onCamera?.(true);
    this.draw();
    return true;
  }

  // Orbiting again from where the camera stood, around the point the orbit looked at, at the same distance.
  leaveCamera() {
    if (!this.fromCamera) return;
    this.fromCamera = null;
    this.canvas.classList.remove("from-camera");
    this.onCamera?.(false);
    const o = this.orbit, eye = this.camera.position.clone();
    o.target = eye.clone().add(this.camera.getWorldDirection(new THREE.Vector3()).multiplyScalar(o.radius));
    const offset = eye.sub(o.target);
    o.phi = Math.acos(Math.max(-1, Math.min(1, offset.y / offset.length())));
    o.theta = Math.atan2(offset.x, offset.z);
  }

  draw() {
    const r = this.renderer, cam = this.camera;
    if (this.fromCamera && this.sceneCamera) {
      const c = this.sceneCamera, { width, height } = this.fromCamera;
      r.setSize(width, height, false);
      cam.fov = c.verticalFov * 180 / Math.PI;
      cam.aspect = width / height;
      cam.position.copy(mirror(c.position));
      cam.up.copy(mirror(c.up));
      cam.lookAt(cam.position.clone().add(mirror(c.direction)));
    } else {
      const w = this.canvas.clientWidth, h = this.canvas.clientHeight, o = this.orbit;
      r.setSize(w, h, false);
      cam.fov = 45;
      cam.aspect = w / Math.max(1, h);
      cam.up.set(0, 1, 0);
      cam.position.set(
        o.target.x + o.radius * Math.sin(o.phi) * Math.sin(o.theta),
        o.target.y + o.radius * Math.cos(o.phi),
        o.target.z + o.radius * Math.sin(o.phi) * Math.cos(o.theta));
      cam.lookAt(o.target);
    }
    cam.updateProjectionMatrix();
    r.render(this.scene, cam);
  }

  // Where the drawing is on screen (client pixels): the whole canvas, or through the render's camera the render's size
  // fitted into it unstretched (object-fit: contain).
  drawnBox() {
    let { left, top, width, height } = this.canvas.getBoundingClientRect();
    if (this.fromCamera) {
      const { width: w, height: h } = this.fromCamera, scale = Math.min(width / w, height / h);
      left += (width - w * scale) / 2;
      top += (height - h * scale) / 2;
      width = w * scale;
      height = h * scale;
    }
    return { left, top, width, height };
  }

  // The client point (x, y) in three.js's device coordinates (−1 to 1 across the drawing).
  deviceAt(x, y) {
    const b = this.drawnBox();
    return new THREE.Vector2((x - b.left) / b.width * 2 - 1, 1 - (y - b.top) / b.height * 2);
  }

  // The inverse: the client point where a point of three.js's world is drawn.
  clientOf(world) {
    const d = world.clone().project(this.camera), b = this.drawnBox();
    return { x: b.left + (d.x + 1) / 2 * b.width, y: b.top + (1 - d.y) / 2 * b.height };
  }

  // The surface under the client point (x, y), from the surfaces layer only (none while it is hidden): its mesh and the
  // point hit in GrCis's world; null when there is none.
  surfaceAt(x, y) {
    const layer = this.layers.surfaces;
    if (!layer?.visible) return null;
    const ray = new THREE.Raycaster();
    ray.setFromCamera(this.deviceAt(x, y), this.camera);
    const hit = ray.intersectObjects(layer.children, false)[0];
    if (!hit) return null;
    return { mesh: hit.object, point: [hit.point.x, hit.point.y, -hit.point.z] };
  }

  // Marks part index `part` of the surfaces layer: tinted (a copy of its material, so solids sharing it stay as they are)
  // and its triangles' edges drawn over it, orange, whatever its own colour. The part marked before is restored. null:
  // none. Returns the mesh marked, or null.
  highlight(part) {
    const h = this.highlighted;
    if (h && h.mesh.userData.part === part) return h.mesh;
    if (h) {
      h.mesh.material.dispose();
      h.mesh.material = h.original;
      h.mesh.remove(h.edges);
      h.edges.material.dispose();
      this.highlighted = null;
    }
    const mesh = part == null ? null : this.layers.surfaces?.children.find(m => m.userData.part === part);
    if (!mesh) return null;
    const tinted = mesh.material.clone(), orange = new THREE.Color(1, 0.55, 0);
    if (tinted.emissive) tinted.emissive.copy(orange).multiplyScalar(0.35);
    else tinted.color.lerp(orange, 0.35);
    if (tinted.transparent) tinted.opacity = Math.max(tinted.opacity, 0.6);
    // The edges share the part's geometry (nothing more on the GPU but the wireframe's index).
    const edges = new THREE.Mesh(mesh.geometry, new THREE.MeshBasicMaterial({ color: orange, wireframe: true, transparent: true, opacity: 0.45 }));
    mesh.add(edges);
    this.highlighted = { mesh, original: mesh.material, edges };
    mesh.material = tinted;
    return mesh;
  }

  // The canvas as a PNG data URL, drawn just now (the drawing buffer is not kept between frames).
  snapshot() {
    this.draw();
    return this.canvas.toDataURL("image/png");
  }

  // What each layer holds: solids drawn as surfaces, as boxes and glowing (emissive), lights, camera frusta, ray segments,
  // hit points.
  counts() {
    const parts = this.layers.surfaces?.children ?? [];
    return {
      surfaces: parts.filter(m => m.userData.kind === "Surface").length,
      boxSolids: parts.filter(m => m.userData.kind === "BoundingBox").length,
      emitters: parts.filter(m => m.userData.kind === "Emitter").length,
      lights: this.layers.lights?.children.length ?? 0,
      cameras: this.layers.camera?.children.length ? 1 : 0,
      raySegments: this.layers.rays?.userData.segments ?? 0,
      points: this.layers.points?.userData.points ?? 0,
    };
  }

  // Every layer given back (the pane closed).
  clear() {
    for (const name of Object.keys(this.layers)) this.setLayer(name, null);
  }

  // What the renderer holds on the GPU now (three.js's own count of geometries and textures, and its shader programs).
  memory() {
    return { ...this.renderer.info.memory, programs: this.renderer.info.programs?.length ?? 0 };
  }
}

// A group's geometries and materials, each once (solids of one shape share a geometry, of one colour a material).
function dispose(group) {
  const done = new Set();
  group.traverse(o => {
    for (const thing of [o.geometry, ...(Array.isArray(o.material) ? o.material : [o.material])])
      if (thing && !done.has(thing)) {
        done.add(thing);
        thing.dispose();
      }
  });
}
