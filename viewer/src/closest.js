// SPDX-License-Identifier: MIT
// Closest points of two recorded bodies (spheres or convex polyhedra) for the viewer's
// closest-feature lines. Recording format v1 does not carry the narrow phase's features, so the
// viewer finds them by brute force over feature pairs: every vertex against every triangle of
// the other body, and every edge against every edge. That is exact for convex bodies that do
// not overlap (the closest pair of points is always one of these pairs), and cheap for the
// few engaged pairs a frame has; a per-frame budget bounds the cost for big hulls.

/** Cost of one body pair in feature tests; `ClosestFeatureLines` stops at its budget. */
export function PairCost(a, b) {
  return a.vertices.length * b.triangles.length + b.vertices.length * a.triangles.length +
         a.edges.length * b.edges.length;
}

/**
 * Features of a recorded shape in its body frame: vertices, triangles (fans of the faces) and
 * unique edges, or a sphere's radius.
 */
export function ShapeFeatures(shape) {
  if (shape.type === 'sphere') {
    return {radius: shape.radius, vertices: [[0, 0, 0]], triangles: [], edges: []};
  }
  const triangles = [];
  const edges = new Map();
  for (const face of shape.faces) {
    for (let k = 1; k + 1 < face.length; ++k) triangles.push([face[0], face[k], face[k + 1]]);
    face.forEach((v, k) => {
      const w = face[(k + 1) % face.length];
      edges.set(v < w ? `${v},${w}` : `${w},${v}`, [Math.min(v, w), Math.max(v, w)]);
    });
  }
  return {radius: 0, vertices: shape.vertices, triangles, edges: [...edges.values()]};
}

const Sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const Dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const Along = (a, d, s) => [a[0] + s * d[0], a[1] + s * d[1], a[2] + s * d[2]];
const Dist2 = (a, b) => Dot(Sub(a, b), Sub(a, b));
const Clamp01 = (x) => Math.min(1, Math.max(0, x));

/** Rotates body-frame point v by unit quaternion q = (w, x, y, z) and adds p. */
export function ToWorld(q, p, v) {
  const [w, x, y, z] = q;
  // v' = v + 2w (u x v) + 2 u x (u x v), u = (x, y, z)
  const cx = y * v[2] - z * v[1];
  const cy = z * v[0] - x * v[2];
  const cz = x * v[1] - y * v[0];
  return [v[0] + 2 * (w * cx + y * cz - z * cy) + p[0],
          v[1] + 2 * (w * cy + z * cx - x * cz) + p[1],
          v[2] + 2 * (w * cz + x * cy - y * cx) + p[2]];
}

/**
 * Closest point to `p` on triangle (a, b, c): the minimum over the triangle's plane when the
 * projection falls inside, else over its three edges.
 */
export function ClosestOnTriangle(p, a, b, c) {
  const ab = Sub(b, a);
  const ac = Sub(c, a);
  const ap = Sub(p, a);
  // Barycentric coordinates of the projection: solve [ab.ab ab.ac; ab.ac ac.ac] [s t] = [ab.ap ac.ap].
  const d00 = Dot(ab, ab);
  const d01 = Dot(ab, ac);
  const d11 = Dot(ac, ac);
  const det = d00 * d11 - d01 * d01;
  if (det > 1e-300) {
    const s = (d11 * Dot(ab, ap) - d01 * Dot(ac, ap)) / det;
    const t = (d00 * Dot(ac, ap) - d01 * Dot(ab, ap)) / det;
    if (s >= 0 && t >= 0 && s + t <= 1) return Along(Along(a, ab, s), ac, t);
  }
  let best = null;
  for (const [u, v] of [[a, b], [b, c], [c, a]]) {
    const q = ClosestOnSegment(p, u, v);
    if (best === null || Dist2(p, q) < Dist2(p, best)) best = q;
  }
  return best;
}

/** Closest point to `p` on segment (a, b). */
export function ClosestOnSegment(p, a, b) {
  const d = Sub(b, a);
  const len2 = Dot(d, d);
  return len2 > 0 ? Along(a, d, Clamp01(Dot(Sub(p, a), d) / len2)) : a;
}

/**
 * Closest points of segments (p1, q1) and (p2, q2): minimise |p1 + s d1 - p2 - t d2|^2 over
 * s, t in [0, 1]; the unconstrained optimum clamped, then each parameter re-optimised for the
 * other clamped one.
 */
export function ClosestSegmentSegment(p1, q1, p2, q2) {
  const d1 = Sub(q1, p1);
  const d2 = Sub(q2, p2);
  const r = Sub(p1, p2);
  const a = Dot(d1, d1);
  const e = Dot(d2, d2);
  const f = Dot(d2, r);
  const c = Dot(d1, r);
  const b = Dot(d1, d2);
  const denom = a * e - b * b;
  let s = denom > 1e-300 * a * e && denom > 0 ? Clamp01((b * f - c * e) / denom) : 0;
  let t = e > 0 ? (b * s + f) / e : 0;
  if (t < 0 || t > 1) {
    t = Clamp01(t);
    s = a > 0 ? Clamp01((b * t - c) / a) : 0;
  }
  return [Along(p1, d1, s), Along(p2, d2, t)];
}

function Closer(best, pa, pb) {
  const d2 = Dist2(pa, pb);
  if (best.d2 > d2) {
    best.d2 = d2;
    best.a = pa;
    best.b = pb;
  }
}

/**
 * Closest points of body A (features `fa`, orientation `qa`, position `pa`) and body B, in the
 * world frame: {a, b, distance}. A sphere's point is on its surface, towards the other body.
 */
export function ClosestPoints(fa, qa, pa, fb, qb, pb) {
  const va = fa.vertices.map((v) => ToWorld(qa, pa, v));
  const vb = fb.vertices.map((v) => ToWorld(qb, pb, v));
  const best = {d2: Infinity, a: null, b: null};
  // Vertex of one against triangles of the other (a sphere is its centre, a "vertex").
  for (const v of va) for (const [i, j, k] of fb.triangles) Closer(best, v, ClosestOnTriangle(v, vb[i], vb[j], vb[k]));
  for (const v of vb) for (const [i, j, k] of fa.triangles) Closer(best, ClosestOnTriangle(v, va[i], va[j], va[k]), v);
  for (const [i, j] of fa.edges) {
    for (const [k, l] of fb.edges) {
      const [x, y] = ClosestSegmentSegment(va[i], va[j], vb[k], vb[l]);
      Closer(best, x, y);
    }
  }
  if (best.a === null) Closer(best, va[0], vb[0]); // two spheres: centre to centre
  // Spheres: move from the centre to the surface along the line.
  const gap = Math.sqrt(best.d2);
  const dir = gap > 0 ? Sub(best.b, best.a).map((x) => x / gap) : [0, 0, 0];
  const a = Along(best.a, dir, fa.radius);
  const b = Along(best.b, dir, -fb.radius);
  return {a, b, distance: gap - fa.radius - fb.radius};
}
