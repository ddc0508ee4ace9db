// The scene in three.js objects, from the studio's tessellation (GET api/scene/tessellation) and boxes (api/scene/boxes):
// one group per layer of the 3D view (surfaces, boxes, lights, camera). Everything is in GrCis's own world; the view
// mirrors z once at its root (GrCis's world is left-handed, three.js's right-handed), so nothing here converts.
// Each group owns its geometries and materials: the view disposes them when it replaces the group.

const unit = v => new THREE.Vector3(...v);

// The twelve edges of a box as segments (pairs of corners), into a flat list of coordinates.
export function boxEdges(min, max, into) {
  const c = i => [i & 1 ? max[0] : min[0], i & 2 ? max[1] : min[1], i & 4 ? max[2] : min[2]];
  for (const [a, b] of [[0, 1], [2, 3], [4, 5], [6, 7], [0, 2], [1, 3], [4, 6], [5, 7], [0, 4], [1, 5], [2, 6], [3, 7]])
    into.push(...c(a), ...c(b));
}

function lines(points, color, opacity = 1) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.Float32BufferAttribute(points, 3));
  return new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color, transparent: opacity < 1, opacity }));
}

// Every solid as its triangles in its material's colour, placed by its matrix. Solids of one shape share one geometry; a
// script's own solid (kind BoundingBox) is its box, drawn see-through; a CSG operand is named with its operation; an
// emissive surface (a light of the path tracers) glows in its emission's colour, unshaded.
export function surfaces(json) {
  const group = new THREE.Group();
  group.name = "surfaces";
  const geometries = json.shapes.map(s => {
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.Float32BufferAttribute(s.positions, 3));
    g.setIndex(s.indices);
    g.computeVertexNormals();
    return g;
  });
  const materials = new Map();
  const material = (color, flat, box) => {
    const key = `${color}|${flat}|${box}`;
    if (!materials.has(key))
      materials.set(key, new THREE.MeshLambertMaterial({ color: new THREE.Color(...color.map(c => Math.min(1, c))), side: THREE.DoubleSide,
        flatShading: flat, transparent: box, opacity: box ? 0.35 : 1, depthWrite: !box }));
    return materials.get(key);
  };
  // What hover and pick read of a part: its index in json.parts (the probe's numbering), name, class, operation, colour.
  const about = (p, index, kind) => ({ part: index, name: p.name, type: p.type, kind, csg: p.csg, color: p.color, emission: p.emission });
  json.parts.forEach((p, index) => {
    const box = p.kind === "BoundingBox";
    if (p.emission) {
      const mesh = new THREE.Mesh(geometries[p.shape], new THREE.MeshBasicMaterial({ color: lightColour(p.emission), side: THREE.DoubleSide }));
      mesh.name = `${p.name} (emissive)`;
      mesh.userData = about(p, index, "Emitter");
      mesh.matrixAutoUpdate = false;
      mesh.matrix.fromArray(p.matrix);
      group.add(mesh);
      return;
    }
    // Corners shared by faces at right angles (cubes, boxes) need flat shading; curved solids are smooth.
    const mesh = new THREE.Mesh(geometries[p.shape], material(p.color, box || p.type === "Cube", box));
    mesh.name = p.csg ? `${p.name} (${p.csg} operand)` : box ? `${p.name} (its box)` : p.name;
    mesh.userData = about(p, index, p.kind);
    mesh.matrixAutoUpdate = false;
    mesh.matrix.fromArray(p.matrix);
    group.add(mesh);
  });
  return group;
}

// The render's primary-ray hits (api/scene/points) as dots of their pixels' colours, a few screen pixels wide whatever
// their distance, so a CSG result or a script's own solid shows its real shape. The group's userData.points counts them.
export function points(json) {
  const group = new THREE.Group();
  group.name = "points";
  group.userData.points = json.count;
  if (json.count === 0) return group;
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.Float32BufferAttribute(json.positions, 3));
  // The colours the render's image shows (its gamma applied; three.js shows them as given); a light's pixel may exceed 1.
  const shown = c => Math.pow(Math.min(1, Math.max(0, c)), 1 / (json.gamma || 1));
  geometry.setAttribute("color", new THREE.Float32BufferAttribute(json.colors.map(shown), 3));
  group.add(new THREE.Points(geometry, new THREE.PointsMaterial({ size: 3, sizeAttenuation: false, vertexColors: true })));
  return group;
}

// The prepared scene's world boxes, dark grey.
export function boxes(list) {
  const points = [];
  for (const b of list) boxEdges(b.min, b.max, points);
  const group = new THREE.Group();
  group.name = "boxes";
  if (points.length > 0) group.add(lines(points, 0x777777));
  return group;
}

// A light's colour: its intensity per band over its largest (GrCis's intensities may exceed 1).
function lightColour(intensity) {
  const top = Math.max(...intensity, 1e-9);
  return new THREE.Color(...intensity.map(c => Math.max(0, c) / top));
}

// Point lights as small balls, rectangle lights as their rectangle, sphere lights as their sphere (wire), each in its
// colour; size is the scene's size, for the balls' radius.
export function lights(json, size) {
  const group = new THREE.Group();
  group.name = "lights";
  for (const l of json.lights) {
    const colour = lightColour(l.intensity);
    const light = new THREE.Group();
    light.name = `${l.kind} light`;
    if (l.kind === "Rectangle") {
      const c = unit(l.position), u = unit(l.edgeU).multiplyScalar(0.5), v = unit(l.edgeV).multiplyScalar(0.5);
      const corner = (a, b) => c.clone().addScaledVector(u, a).addScaledVector(v, b).toArray();
      const [p0, p1, p2, p3] = [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)];
      const face = new THREE.BufferGeometry();
      face.setAttribute("position", new THREE.Float32BufferAttribute([...p0, ...p1, ...p2, ...p0, ...p2, ...p3], 3));
      light.add(new THREE.Mesh(face, new THREE.MeshBasicMaterial({ color: colour, side: THREE.DoubleSide, transparent: true, opacity: 0.6 })));
      light.add(lines([...p0, ...p1, ...p1, ...p2, ...p2, ...p3, ...p3, ...p0], colour));
    } else {
      const sphere = l.kind === "Sphere";
      const ball = new THREE.Mesh(new THREE.SphereGeometry(sphere ? l.radius : size * 0.012, sphere ? 16 : 12, sphere ? 12 : 8),
        new THREE.MeshBasicMaterial({ color: colour, wireframe: sphere }));
      ball.position.copy(unit(l.position));
      light.add(ball);
    }
    group.add(light);
  }
  return group;
}

// The camera as its frustum from the eye to an image plane of the render's aspect ratio, the plane see-through, and a
// small triangle above the plane's top edge saying which way is up. depth: the plane's distance from the eye.
export function camera(json, depth) {
  const group = new THREE.Group();
  group.name = "camera";
  const c = json.camera;
  if (!c) return group;
  const eye = unit(c.position), dir = unit(c.direction).normalize(), up = unit(c.up).normalize();
  // GrCis's left-handed world: up × direction points to the image's right.
  const right = new THREE.Vector3().crossVectors(up, dir).normalize();
  const h = depth * Math.tan(c.verticalFov / 2), w = h * c.aspect;
  const centre = eye.clone().addScaledVector(dir, depth);
  const corner = (a, b) => centre.clone().addScaledVector(right, a * w).addScaledVector(up, b * h).toArray();
  const [p0, p1, p2, p3] = [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)];
  const e = eye.toArray(), top = centre.clone().addScaledVector(up, h * 1.35).toArray();
  group.add(lines([...e, ...p0, ...e, ...p1, ...e, ...p2, ...e, ...p3, ...p0, ...p1, ...p1, ...p2, ...p2, ...p3, ...p3, ...p0,
    ...p3, ...top, ...top, ...p2], 0xffffff));
  const plane = new THREE.BufferGeometry();
  plane.setAttribute("position", new THREE.Float32BufferAttribute([...p0, ...p1, ...p2, ...p0, ...p2, ...p3], 3));
  group.add(new THREE.Mesh(plane, new THREE.MeshBasicMaterial({ color: 0x88aaff, side: THREE.DoubleSide, transparent: true, opacity: 0.15,
    depthWrite: false })));
  return group;
}

// The size of what the view should frame: the solids other than planes (an infinite plane is a patch far larger than the
// scene), the camera, the lights and the given points; null when there is nothing.
export function bounds(surfaceGroup, json, points = []) {
  const all = new THREE.Box3(), planes = new THREE.Box3();
  surfaceGroup?.updateMatrixWorld(true);
  for (const m of surfaceGroup?.children ?? []) {
    m.geometry.computeBoundingBox();
    const b = m.geometry.boundingBox.clone().applyMatrix4(m.matrix);
    (m.userData.type === "Plane" ? planes : all).union(b);
  }
  if (all.isEmpty()) all.union(planes);
  if (json?.camera) all.expandByPoint(unit(json.camera.position));
  for (const l of json?.lights ?? []) all.expandByPoint(unit(l.position));
  for (const p of points) all.expandByPoint(unit(p));
  return all.isEmpty() ? null : all;
}
