// SPDX-License-Identifier: MIT
// Which body is under a point of the canvas: a ray against the instanced meshes (exact shapes,
// nearest hit wins), and the reverse, where a body's centre is on screen (for tests).
import * as THREE from 'three';

const raycaster = new THREE.Raycaster();

function NormalizedDevice(canvas, client_x, client_y) {
  const rect = canvas.getBoundingClientRect();
  return new THREE.Vector2(((client_x - rect.left) / rect.width) * 2 - 1,
                           -((client_y - rect.top) / rect.height) * 2 + 1);
}

/** Body index drawn at client coordinates (client_x, client_y), or null. */
export function PickBody(view, canvas, client_x, client_y) {
  raycaster.setFromCamera(NormalizedDevice(canvas, client_x, client_y), view.camera);
  const meshes = view.groups.map((g) => g.mesh);
  for (const mesh of meshes) mesh.computeBoundingSphere(); // instances have moved
  const hits = raycaster.intersectObjects(meshes, false);
  if (hits.length === 0) return null;
  const group = view.groups.find((g) => g.mesh === hits[0].object);
  return group.bodies[hits[0].instanceId];
}

/** Client coordinates of a world point, or null when it is behind the camera. */
export function ScreenPoint(view, canvas, p) {
  const v = new THREE.Vector3(p[0], p[1], p[2]).project(view.camera);
  if (v.z > 1) return null;
  const rect = canvas.getBoundingClientRect();
  return {x: rect.left + (v.x + 1) / 2 * rect.width, y: rect.top + (1 - v.y) / 2 * rect.height};
}

/** Calls on_click(x, y) for a click that was not a drag of the orbit camera. */
export function OnClickNotDrag(canvas, on_click) {
  let down = null;
  canvas.addEventListener('pointerdown', (e) => (down = {x: e.clientX, y: e.clientY}));
  canvas.addEventListener('pointerup', (e) => {
    if (down && Math.hypot(e.clientX - down.x, e.clientY - down.y) < 5) {
      on_click(e.clientX, e.clientY);
    }
    down = null;
  });
}
