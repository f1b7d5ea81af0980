// SPDX-License-Identifier: MIT
// Optional overlays drawn over the bodies: bounding spheres (the elements of the sparse phase),
// engaged pairs, closest-feature lines of the engaged pairs (closest.js), collision points and
// the selected body's marker.
//
// Engaged pairs: recording format v1 does not carry engagements, so the viewer derives them
// from their definition (DESIGN.md glossary): two elements are engaged while their bounding
// spheres overlap. A uniform grid of cell size = the largest bounding diameter finds them in
// O(bodies) per frame; in a periodic box distances use the nearest image.
import * as THREE from 'three';

import {ClosestPoints, PairCost, ShapeFeatures} from './closest.js';

/** Lines beyond this many engaged pairs are not drawn (the count is still reported). */
export const kMaxPairLines = 50000;
/** Feature tests per frame for closest-feature lines (a 600-face pair is ~4e6). */
export const kFeatureBudget = 4e6;

function BoundingSpheres(recording) {
  const n = recording.bodies.count;
  const geometry = new THREE.SphereGeometry(1, 12, 8);
  const material = new THREE.MeshBasicMaterial({color: 0x99bbff, wireframe: true,
                                                transparent: true, opacity: 0.18,
                                                depthWrite: false});
  const mesh = new THREE.InstancedMesh(geometry, material, Math.max(n, 1));
  mesh.count = n;
  mesh.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
  mesh.frustumCulled = false;
  mesh.visible = false;
  return mesh;
}

function LineSet(capacity, color) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6 * capacity), 3));
  geometry.setDrawRange(0, 0);
  // Drawn over the bodies: an engaged pair's centre line is mostly inside them.
  const material = new THREE.LineBasicMaterial({color, depthTest: false, transparent: true,
                                                opacity: 0.85});
  const lines = new THREE.LineSegments(geometry, material);
  lines.renderOrder = 1;
  lines.frustumCulled = false;
  return lines;
}

function CollisionPoints(capacity) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * capacity), 3));
  geometry.setDrawRange(0, 0);
  const material = new THREE.PointsMaterial({color: 0xffee88, size: 6, sizeAttenuation: false});
  const points = new THREE.Points(geometry, material);
  points.frustumCulled = false;
  return points;
}

// A magenta cage drawn through everything, so the selected body is found in a crowd.
function SelectionMarker() {
  const material = new THREE.MeshBasicMaterial({color: 0xff40f0, wireframe: true,
                                                depthTest: false, transparent: true,
                                                opacity: 0.9});
  const marker = new THREE.Mesh(new THREE.SphereGeometry(1, 16, 10), material);
  marker.visible = false;
  marker.renderOrder = 2;
  return marker;
}

/** Minimum-image difference b - a along one axis of a periodic box of edge `size`. */
function Nearest(d, size) {
  return size > 0 ? d - size * Math.round(d / size) : d;
}

// Uniform grid over the bodies: cell edge >= the largest bounding diameter, cells numbered
// x-fastest, bodies bucketed by a counting sort. In a periodic box cells wrap around.
function BuildGrid(position, radius, container) {
  const n = radius.length;
  let max_r = 0;
  for (let i = 0; i < n; ++i) max_r = Math.max(max_r, radius[i]);
  const periodic = container.kind === 'periodic';
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < n; ++i) {
    for (let k = 0; k < 3; ++k) {
      lo[k] = Math.min(lo[k], position[3 * i + k]);
      hi[k] = Math.max(hi[k], position[3 * i + k]);
    }
  }
  const extent = periodic ? container.hi.map((h, k) => h - container.lo[k])
                          : hi.map((h, k) => h - lo[k]);
  if (periodic) lo.splice(0, 3, ...container.lo);
  // Never more than ~8 cells per body, whatever the spread.
  const cell = Math.max(2 * max_r, 1e-9, Math.cbrt((extent[0] * extent[1] * extent[2]) / (8 * n)));
  const dims = extent.map((e) => Math.max(1, Math.floor(e / cell)));
  if (!periodic) dims.forEach((d, k) => (dims[k] = d + 1));
  const cell_of = new Uint32Array(n);
  const start = new Uint32Array(dims[0] * dims[1] * dims[2] + 1);
  for (let i = 0; i < n; ++i) {
    let id = 0;
    for (let k = 2; k >= 0; --k) {
      let c = Math.floor((position[3 * i + k] - lo[k]) / (periodic ? extent[k] / dims[k] : cell));
      c = periodic ? ((c % dims[k]) + dims[k]) % dims[k] : Math.min(c, dims[k] - 1);
      id = id * dims[k] + c;
    }
    cell_of[i] = id;
    start[id + 1]++;
  }
  for (let c = 1; c < start.length; ++c) start[c] += start[c - 1];
  const fill = start.slice(0, start.length - 1);
  const members = new Uint32Array(n);
  for (let i = 0; i < n; ++i) members[fill[cell_of[i]]++] = i;
  const size = periodic ? extent : [0, 0, 0];
  return {dims, start, members, cell_of, periodic, size};
}

// Ids of the (up to 27, distinct) cells around cell `id`.
function NeighbourCells(grid, id, out) {
  const [nx, ny, nz] = grid.dims;
  const c = [id % nx, Math.floor(id / nx) % ny, Math.floor(id / (nx * ny))];
  out.length = 0;
  for (let dz = -1; dz <= 1; ++dz) for (let dy = -1; dy <= 1; ++dy) for (let dx = -1; dx <= 1; ++dx) {
    const d = [dx, dy, dz];
    let nid = 0;
    let inside = true;
    for (let k = 2; k >= 0; --k) {
      let x = c[k] + d[k];
      if (grid.periodic) x = (x + grid.dims[k]) % grid.dims[k];
      else if (x < 0 || x >= grid.dims[k]) inside = false;
      nid = nid * grid.dims[k] + x;
    }
    if (inside && !out.includes(nid)) out.push(nid);
  }
  return out;
}

/**
 * Pairs of bodies whose bounding spheres overlap, from centres `position` (3 per body) and
 * radii `radius`; `container` gives the periodic images. Returns a flat array [a0, b0, a1, ...].
 */
export function OverlappingPairs(position, radius, container) {
  const grid = BuildGrid(position, radius, container);
  const pairs = [];
  const around = [];
  for (let i = 0; i < radius.length; ++i) {
    for (const cell of NeighbourCells(grid, grid.cell_of[i], around)) {
      for (let m = grid.start[cell]; m < grid.start[cell + 1]; ++m) {
        const j = grid.members[m];
        if (j <= i) continue;
        let dist2 = 0;
        for (let k = 0; k < 3; ++k) {
          const d = Nearest(position[3 * j + k] - position[3 * i + k], grid.size[k]);
          dist2 += d * d;
        }
        const reach = radius[i] + radius[j];
        if (dist2 < reach * reach) pairs.push(i, j);
      }
    }
  }
  return pairs;
}

export class Overlays {
  constructor(recording, scene) {
    this.recording = recording;
    this.spheres = BoundingSpheres(recording);
    this.pairs = LineSet(kMaxPairLines, 0xff66cc);
    this.closest = LineSet(kMaxPairLines, 0x7dffb0);
    this.features = recording.header.shapes.map(ShapeFeatures);
    this.feature_lines = 0;
    this.points = CollisionPoints(4096);
    this.marker = SelectionMarker();
    this.pair_count = 0;
    this.show = {spheres: false, pairs: false, features: false};
    for (const object of [this.spheres, this.pairs, this.closest, this.points, this.marker]) {
      scene.add(object);
    }
  }

  /** Redraws the overlays for the player's current body positions. */
  Update(player, selected) {
    const radius = this.recording.bodies.bounding_radius;
    this.spheres.visible = this.show.spheres;
    if (this.show.spheres) this.UpdateSpheres(player.position, radius);
    this.pairs.visible = this.show.pairs;
    this.closest.visible = this.show.features;
    if (this.show.pairs || this.show.features) {
      const pairs = OverlappingPairs(player.position, radius, this.recording.header.container);
      this.pair_count = pairs.length / 2;
      if (this.show.pairs) this.UpdatePairs(player.position, pairs);
      if (this.show.features) this.UpdateClosest(player, pairs);
    }
    this.UpdatePoints(player.flashing);
    this.marker.visible = selected !== null;
    if (selected !== null) {
      this.marker.position.fromArray(player.position, 3 * selected);
      this.marker.scale.setScalar(1.25 * radius[selected]);
    }
  }

  UpdateSpheres(position, radius) {
    const m = this.spheres.instanceMatrix.array;
    for (let i = 0; i < radius.length; ++i) {
      const r = radius[i];
      m.fill(0, 16 * i, 16 * i + 16);
      m[16 * i] = r;
      m[16 * i + 5] = r;
      m[16 * i + 10] = r;
      m[16 * i + 12] = position[3 * i];
      m[16 * i + 13] = position[3 * i + 1];
      m[16 * i + 14] = position[3 * i + 2];
      m[16 * i + 15] = 1;
    }
    this.spheres.instanceMatrix.needsUpdate = true;
  }

  UpdatePairs(position, pairs) {
    const container = this.recording.header.container;
    const out = this.pairs.geometry.attributes.position;
    const lines = Math.min(this.pair_count, kMaxPairLines);
    const periodic = container.kind === 'periodic';
    for (let l = 0; l < lines; ++l) {
      const a = pairs[2 * l];
      const b = pairs[2 * l + 1];
      for (let k = 0; k < 3; ++k) {
        const pa = position[3 * a + k];
        const size = periodic ? container.hi[k] - container.lo[k] : 0;
        out.array[6 * l + k] = pa;
        out.array[6 * l + 3 + k] = pa + Nearest(position[3 * b + k] - pa, size);
      }
    }
    out.needsUpdate = true;
    this.pairs.geometry.setDrawRange(0, 2 * lines);
  }

  // A line between the closest points of each engaged pair, within the frame's budget; in a
  // periodic box B is taken at its image nearest to A.
  UpdateClosest(player, pairs) {
    const container = this.recording.header.container;
    const shape_of = this.recording.bodies.shape;
    const out = this.closest.geometry.attributes.position;
    let lines = 0;
    let spent = 0;
    for (let l = 0; l < pairs.length / 2 && lines < kMaxPairLines; ++l) {
      const a = pairs[2 * l];
      const b = pairs[2 * l + 1];
      const fa = this.features[shape_of[a]];
      const fb = this.features[shape_of[b]];
      spent += PairCost(fa, fb);
      if (spent > kFeatureBudget) break;
      const pa = Array.from(player.position.subarray(3 * a, 3 * a + 3));
      const pb = [0, 1, 2].map((k) => pa[k] + Nearest(player.position[3 * b + k] - pa[k],
          container.kind === 'periodic' ? container.hi[k] - container.lo[k] : 0));
      const qa = Array.from(player.orientation.subarray(4 * a, 4 * a + 4));
      const qb = Array.from(player.orientation.subarray(4 * b, 4 * b + 4));
      const {a: xa, b: xb} = ClosestPoints(fa, qa, pa, fb, qb, pb);
      out.array.set(xa, 6 * lines);
      out.array.set(xb, 6 * lines + 3);
      lines++;
    }
    this.feature_lines = lines;
    out.needsUpdate = true;
    this.closest.geometry.setDrawRange(0, 2 * lines);
  }

  UpdatePoints(flashing) {
    const c = this.recording.collisions;
    const container = this.recording.header.container;
    const out = this.points.geometry.attributes.position;
    const count = Math.min(flashing.length, out.count);
    for (let f = 0; f < count; ++f) {
      for (let k = 0; k < 3; ++k) {
        let x = c.point[3 * flashing[f] + k];
        if (container.kind === 'periodic') {
          const size = container.hi[k] - container.lo[k];
          x = container.lo[k] + ((((x - container.lo[k]) % size) + size) % size);
        }
        out.array[3 * f + k] = x;
      }
    }
    out.needsUpdate = true;
    this.points.geometry.setDrawRange(0, count);
  }
}
