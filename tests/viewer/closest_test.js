// SPDX-License-Identifier: MIT
// Closest points of recorded shapes (viewer/src/closest.js), the closest-feature lines'
// geometry, against distances worked out by hand for each kind of closest feature pair.
import assert from 'node:assert/strict';
import test from 'node:test';

import {ClosestPoints, ClosestSegmentSegment, ClosestOnTriangle, ShapeFeatures, ToWorld}
  from '../../viewer/src/closest.js';
import {kCube} from './make_recording.js';

const kRoundOff = 1e-12;
const kIdentity = [1, 0, 0, 0];
const cube = ShapeFeatures(kCube);
const ball = ShapeFeatures({type: 'sphere', radius: 0.5});
// 45 degrees about the x (or y, z) axis: (cos 22.5, sin 22.5 along the axis).
const c = Math.cos(Math.PI / 8);
const s = Math.sin(Math.PI / 8);

function Near(actual, expected, what) {
  assert.ok(Math.abs(actual - expected) < kRoundOff, `${what}: ${actual} vs ${expected}`);
}

test('a cube has 8 vertices, 12 triangles and 12 edges', () => {
  assert.equal(cube.vertices.length, 8);
  assert.equal(cube.triangles.length, 12);
  assert.equal(cube.edges.length, 12);
});

test('rotating (1, 0, 0) by 90 degrees about z gives (0, 1, 0)', () => {
  const q = [Math.SQRT1_2, 0, 0, Math.SQRT1_2];
  ToWorld(q, [0, 0, 0], [1, 0, 0]).forEach((x, k) => Near(x, [0, 1, 0][k], `k=${k}`));
});

test('closest points on a triangle: inside, on an edge, at a vertex', () => {
  const [a, b, cc] = [[0, 0, 0], [2, 0, 0], [0, 2, 0]];
  assert.deepEqual(ClosestOnTriangle([0.5, 0.5, 3], a, b, cc), [0.5, 0.5, 0]);
  assert.deepEqual(ClosestOnTriangle([1, -4, 1], a, b, cc), [1, 0, 0]);
  assert.deepEqual(ClosestOnTriangle([-1, -1, 0], a, b, cc), [0, 0, 0]);
});

test('crossing segments meet at their crossing; parallel ones at a clamped end', () => {
  const [x, y] = ClosestSegmentSegment([-1, 0, 0], [1, 0, 0], [0, -1, 2], [0, 1, 2]);
  assert.deepEqual(x, [0, 0, 0]);
  assert.deepEqual(y, [0, 0, 2]);
  const [p, q] = ClosestSegmentSegment([0, 0, 0], [1, 0, 0], [3, 1, 0], [4, 1, 0]);
  assert.deepEqual(p, [1, 0, 0]);
  assert.deepEqual(q, [3, 1, 0]);
});

test('face to face: unit cubes 3 apart along x are 2 apart', () => {
  const r = ClosestPoints(cube, kIdentity, [0, 0, 0], cube, kIdentity, [3, 0, 0]);
  Near(r.distance, 2, 'distance');
  Near(r.a[0], 0.5, 'a.x');
  Near(r.b[0], 2.5, 'b.x');
});

test('vertex to face: a cube turned 45 degrees about z points an edge at the other', () => {
  const r = ClosestPoints(cube, kIdentity, [0, 0, 0], cube, [c, 0, 0, s], [3, 0, 0]);
  Near(r.distance, 3 - Math.SQRT1_2 - 0.5, 'distance');
  Near(r.b[0], 3 - Math.SQRT1_2, 'b.x');
});

test('edge to edge: crossed edges of cubes turned about x and about y', () => {
  const r = ClosestPoints(cube, [c, s, 0, 0], [0, 0, 0], cube, [c, 0, s, 0], [0, 0, 3]);
  Near(r.distance, 3 - 2 * Math.SQRT1_2, 'distance');
  [0, 0, Math.SQRT1_2].forEach((x, k) => Near(r.a[k], x, `a[${k}]`));
  [0, 0, 3 - Math.SQRT1_2].forEach((x, k) => Near(r.b[k], x, `b[${k}]`));
});

test('sphere to cube and sphere to sphere: points on the sphere surface', () => {
  const r = ClosestPoints(ball, kIdentity, [0, 0, 0], cube, kIdentity, [2, 2, 0]);
  Near(r.distance, 1.5 * Math.SQRT2 - 0.5, 'distance');
  [0.5 * Math.SQRT1_2, 0.5 * Math.SQRT1_2, 0].forEach((x, k) => Near(r.a[k], x, `a[${k}]`));
  [1.5, 1.5, 0].forEach((x, k) => Near(r.b[k], x, `b[${k}]`));
  const two = ClosestPoints(ball, kIdentity, [0, 0, 0], ball, kIdentity, [0, 0, 2]);
  Near(two.distance, 1, 'distance');
  assert.deepEqual(two.a, [0, 0, 0.5]);
  assert.deepEqual(two.b, [0, 0, 1.5]);
});
