// SPDX-License-Identifier: MIT
// Builds the three.js scene of a recording: renderer, camera, lights, the container box and one
// InstancedMesh per shape (so 10^5 bodies are a handful of draw calls).
import * as THREE from 'three';

/** Sphere tessellation by body count: fewer triangles when there are many bodies. */
function SphereDetail(count) {
  if (count <= 1000) return [20, 14];
  if (count <= 20000) return [12, 8];
  return [8, 6];
}

/** Geometry of one recorded shape (docs/recording-format.md "Header JSON"), in the body frame. */
export function ShapeGeometry(shape, count) {
  if (shape.type === 'sphere') {
    const [w, h] = SphereDetail(count);
    return new THREE.SphereGeometry(shape.radius, w, h);
  }
  // Polyhedron: triangulate each (convex, counter-clockwise) face as a fan; no index, so that
  // computed normals are face normals (flat shading).
  const positions = [];
  for (const face of shape.faces) {
    for (let k = 1; k + 1 < face.length; ++k) {
      for (const v of [face[0], face[k], face[k + 1]]) positions.push(...shape.vertices[v]);
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  geometry.computeVertexNormals();
  return geometry;
}

/** Axis-aligned box the scene lives in: the container, or the initial positions if open. */
export function SceneBounds(recording) {
  const c = recording.header.container;
  if (c.kind !== 'open' && c.lo && c.hi) {
    return new THREE.Box3(new THREE.Vector3(...c.lo), new THREE.Vector3(...c.hi));
  }
  const box = new THREE.Box3();
  const {segments, bodies} = recording;
  const p = new THREE.Vector3();
  for (let i = 0; i < bodies.count; ++i) {
    const s = segments.start[i];
    p.fromArray(segments.position, 3 * s);
    box.expandByPoint(p);
  }
  if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
  return box.expandByScalar(2);
}

function ContainerLines(recording, bounds) {
  const kind = recording.header.container.kind;
  if (kind === 'open') return null;
  const helper = new THREE.Box3Helper(bounds, kind === 'periodic' ? 0x6688aa : 0xaaaaaa);
  helper.material.transparent = true;
  helper.material.opacity = kind === 'periodic' ? 0.5 : 0.9;
  return helper;
}

// Bodies grouped by shape; each group is drawn by one InstancedMesh. group_of/slot_of map a body
// to its group and its instance in that group.
function BodyGroups(recording) {
  const {count, shape} = recording.bodies;
  const shapes = recording.header.shapes;
  const members = shapes.map(() => []);
  for (let i = 0; i < count; ++i) members[shape[i]].push(i);
  const group_of = new Uint16Array(count);
  const slot_of = new Uint32Array(count);
  const groups = [];
  members.forEach((bodies, s) => {
    if (bodies.length === 0) return;
    const material = new THREE.MeshLambertMaterial({color: 0xffffff});
    const mesh = new THREE.InstancedMesh(ShapeGeometry(shapes[s], count), material, bodies.length);
    mesh.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
    mesh.instanceColor = new THREE.InstancedBufferAttribute(new Float32Array(3 * bodies.length), 3);
    mesh.instanceColor.setUsage(THREE.DynamicDrawUsage);
    mesh.frustumCulled = false; // instances move every frame; the mesh bound would be stale
    bodies.forEach((body, slot) => {
      group_of[body] = groups.length;
      slot_of[body] = slot;
    });
    groups.push({shape: s, mesh, bodies: Uint32Array.from(bodies)});
  });
  return {groups, group_of, slot_of};
}

/** The page's one renderer (a new recording reuses it). */
export function CreateRenderer(canvas) {
  const renderer = new THREE.WebGLRenderer({canvas, antialias: false});
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  return renderer;
}

/**
 * Creates camera, lights, container and body meshes for `recording`.
 * Returns {scene, camera, bounds, center, groups, group_of, slot_of}.
 */
export function BuildScene(recording) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x12161c);
  scene.add(new THREE.HemisphereLight(0xdde8ff, 0x303038, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(0.5, 0.8, 1.0);
  scene.add(sun);

  const bounds = SceneBounds(recording);
  const container = ContainerLines(recording, bounds);
  if (container) scene.add(container);

  const size = bounds.getSize(new THREE.Vector3()).length();
  const center = bounds.getCenter(new THREE.Vector3());
  const camera = new THREE.PerspectiveCamera(45, 1, size / 1000, size * 20);
  camera.position.copy(center).add(new THREE.Vector3(0.5, 0.35, 0.75).multiplyScalar(size));

  const {groups, group_of, slot_of} = BodyGroups(recording);
  for (const g of groups) scene.add(g.mesh);
  return {scene, camera, bounds, center, groups, group_of, slot_of};
}
