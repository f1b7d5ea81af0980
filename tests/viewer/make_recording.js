// SPDX-License-Identifier: MIT
// An independent writer of .sdrec recordings (docs/recording-format.md, version 1) for the
// viewer's tests: it builds small deterministic fixture runs as plain objects and encodes them
// field by field from the format's tables, so it also checks the format document.
// The motion is not physics: bodies move on straight lines (one falls, some spin) and at chosen
// times a pair swaps velocities, which gives new segments and a collision record.
//
//   node tests/viewer/make_recording.js OUT.sdrec [--kind mixed|gas|walled] [--n N]
//        [--events E] [--seed S] [--until T] [--truncate BYTES]
import {writeFileSync} from 'node:fs';
import {fileURLToPath} from 'node:url';

const kMagic = Buffer.from([0x53, 0x44, 0x52, 0x45, 0x43, 0x0d, 0x0a, 0x1a]);

// A cube and a tetrahedron, centroid at the origin, faces counter-clockwise seen from outside.
export const kCube = {
  type: 'polyhedron',
  vertices: [[-0.5, -0.5, -0.5], [0.5, -0.5, -0.5], [0.5, 0.5, -0.5], [-0.5, 0.5, -0.5],
             [-0.5, -0.5, 0.5], [0.5, -0.5, 0.5], [0.5, 0.5, 0.5], [-0.5, 0.5, 0.5]],
  faces: [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [1, 2, 6, 5], [0, 4, 7, 3]],
};
const kTetra = {
  type: 'polyhedron',
  vertices: [[0.5, 0.5, 0.5], [-0.5, -0.5, 0.5], [-0.5, 0.5, -0.5], [0.5, -0.5, -0.5]],
  faces: [[0, 1, 3], [0, 2, 1], [0, 3, 2], [1, 2, 3]],
};

// Park-Miller minimal standard generator: the fixtures must not depend on Math.random.
function Lcg(seed) {
  let state = (seed % 2147483646) + 1;
  return () => {
    state = (state * 48271) % 2147483647;
    return (state - 1) / 2147483646;
  };
}

/** Position of a plain segment object at time t (the formula of the format document). */
export function SegmentPosition(seg, t) {
  const dt = t - seg.t0;
  const a = seg.acceleration ?? [0, 0, 0];
  return [0, 1, 2].map((k) => seg.position[k] + seg.velocity[k] * dt + 0.5 * a[k] * dt * dt);
}

/** Velocity of a plain segment object at time t. */
export function SegmentVelocity(seg, t) {
  const a = seg.acceleration ?? [0, 0, 0];
  return [0, 1, 2].map((k) => seg.velocity[k] + a[k] * (t - seg.t0));
}

/** Orientation (w, x, y, z) of a plain segment at time t: exp(w dt / 2) * q0. */
export function SegmentOrientation(seg, t) {
  const q = seg.orientation ?? [1, 0, 0, 0];
  const w = seg.angular_velocity ?? [0, 0, 0];
  const angle = Math.hypot(...w) * (t - seg.t0);
  const axis = Normalize(w);
  const r = [Math.cos(angle / 2), ...axis.map((x) => x * Math.sin(angle / 2))];
  return [r[0] * q[0] - r[1] * q[1] - r[2] * q[2] - r[3] * q[3],
          r[0] * q[1] + r[1] * q[0] + r[2] * q[3] - r[3] * q[2],
          r[0] * q[2] - r[1] * q[3] + r[2] * q[0] + r[3] * q[1],
          r[0] * q[3] + r[1] * q[2] - r[2] * q[1] + r[3] * q[0]];
}

function Normalize(v) {
  const n = Math.hypot(...v) || 1;
  return v.map((x) => x / n);
}

function ContainerFor(kind, n, radius) {
  // Box edge for a bounding-sphere packing fraction of 0.2 (gas) or 0.05, at least 8 radii.
  const fraction = kind === 'gas' ? 0.2 : 0.05;
  const edge = Math.max(8 * radius, Math.cbrt((n * 4 / 3 * Math.PI * radius ** 3) / fraction));
  return {kind: kind === 'walled' ? 'walled' : 'periodic', lo: [0, 0, 0], hi: [edge, edge, edge]};
}

function InitialBodies(kind, n, random, container) {
  const shapes = kind === 'gas' ? [{type: 'sphere', radius: 0.5}]
                                : [{type: 'sphere', radius: 0.5}, kCube, kTetra];
  const edge = container.hi[0];
  const per_side = Math.ceil(Math.cbrt(n));
  const spacing = edge / per_side;
  const bodies = [];
  const segments = [];
  for (let i = 0; i < n; ++i) {
    const shape = kind === 'gas' ? 0 : i % shapes.length;
    const cell = [i % per_side, Math.floor(i / per_side) % per_side,
                  Math.floor(i / per_side / per_side)];
    const seg = {
      body: i, t0: 0,
      position: cell.map((c) => (c + 0.5) * spacing),
      velocity: [0, 1, 2].map(() => 2 * random() - 1),
    };
    if (kind === 'walled' && i === 0) seg.acceleration = [0, 0, -0.5];
    if (shape !== 0) {
      seg.orientation = Normalize([1, random() - 0.5, random() - 0.5, random() - 0.5]);
      seg.angular_velocity = [0, 1, 2].map(() => 2 * random() - 1);
    }
    bodies.push({shape, mass: 1 + i % 3, bounding_radius: shape === 0 ? 0.5 : Math.sqrt(0.75)});
    segments.push(seg);
  }
  return {shapes, bodies, segments};
}

/**
 * A deterministic fixture run: {header, bodies, segments, collisions, end_time}, every segment
 * a plain object {body, t0, position, velocity, acceleration?, orientation?, angular_velocity?}
 * in file order.
 */
export function MakeFixture({kind = 'mixed', n = 24, events = 12, seed = 1, until = 10} = {}) {
  const random = Lcg(seed);
  const container = ContainerFor(kind, n, 0.5);
  const {shapes, bodies, segments} = InitialBodies(kind, n, random, container);
  const current = segments.slice();
  const collisions = [];
  // Events at increasing times; each swaps the velocities of a pair of distinct bodies.
  for (let e = 0; e < events && n >= 2; ++e) {
    const t = until * (e + 1) / (events + 1);
    const a = Math.floor(random() * n);
    const b = (a + 1 + Math.floor(random() * (n - 1))) % n;
    const pa = SegmentPosition(current[a], t);
    const pb = SegmentPosition(current[b], t);
    const va = SegmentVelocity(current[a], t);
    const vb = SegmentVelocity(current[b], t);
    for (const [body, p, v] of [[a, pa, vb], [b, pb, va]]) {
      const seg = {...current[body], body, t0: t, position: p, velocity: v};
      if (seg.orientation) seg.orientation = SegmentOrientation(current[body], t);
      current[body] = seg;
      segments.push(seg);
    }
    collisions.push({a, b, wall: false, time: t, point: pa.map((x, k) => (x + pb[k]) / 2),
                     normal: Normalize(pb.map((x, k) => x - pa[k])), impulse: 0.25 + e});
  }
  const header = {
    generator: 'tests/viewer/make_recording.js', scene: `fixture-${kind}`, seed, bodies: n,
    container, gravity: kind === 'walled' ? [0, 0, -0.5] : [0, 0, 0], shapes,
    start_time: 0, end_time: until,
  };
  return {header, bodies, segments, collisions, end_time: until};
}

// Little-endian field writer into a growing list of buffers.
class Writer {
  constructor() {
    this.parts = [];
  }
  bytes(b) {
    this.parts.push(Buffer.from(b));
  }
  u8(v) {
    const b = Buffer.alloc(1);
    b.writeUInt8(v);
    this.parts.push(b);
  }
  u32(v) {
    const b = Buffer.alloc(4);
    b.writeUInt32LE(v);
    this.parts.push(b);
  }
  f64(...values) {
    for (const v of values) {
      const b = Buffer.alloc(8);
      b.writeDoubleLE(v);
      this.parts.push(b);
    }
  }
  buffer() {
    return Buffer.concat(this.parts);
  }
}

/** Encodes a fixture (MakeFixture's shape) as .sdrec bytes, field by field. */
export function EncodeRecording(fixture, {version = 1, end = true} = {}) {
  const w = new Writer();
  const header = Buffer.from(JSON.stringify(fixture.header), 'utf8');
  w.bytes(kMagic);
  w.u32(version);
  w.u32(header.length);
  w.bytes(header);
  for (const body of fixture.bodies) {
    w.u32(body.shape);
    w.u32(body.flags ?? 0);
    w.f64(body.mass, body.bounding_radius);
  }
  // Segments and collisions merged by time; segments first at equal times (format rule).
  const records = [...fixture.segments.map((s) => ({time: s.t0, order: 0, s})),
                   ...fixture.collisions.map((c) => ({time: c.time, order: 1, c}))];
  records.sort((x, y) => x.time - y.time || x.order - y.order);
  for (const r of records) {
    if (r.s) {
      const s = r.s;
      const flags = (s.acceleration ? 1 : 0) | (s.orientation ? 2 : 0);
      w.u8(1);
      w.u8(flags);
      w.u32(s.body);
      w.f64(s.t0, ...s.position, ...s.velocity);
      if (s.acceleration) w.f64(...s.acceleration);
      if (s.orientation) w.f64(...s.orientation, ...s.angular_velocity);
    } else {
      const c = r.c;
      w.u8(2);
      w.u8(c.wall ? 1 : 0);
      w.u32(c.a);
      w.u32(c.b);
      w.f64(c.time, ...c.point, ...c.normal, c.impulse);
    }
  }
  if (end) {
    w.u8(3);
    w.f64(fixture.end_time);
  }
  return w.buffer();
}

function ParseArgs(argv) {
  const options = {};
  const out = argv[0];
  for (let i = 1; i < argv.length; i += 2) {
    const key = argv[i].replace(/^--/, '');
    const value = argv[i + 1];
    options[key] = key === 'kind' ? value : Number(value);
  }
  return {out, options};
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const {out, options} = ParseArgs(process.argv.slice(2));
  if (!out) {
    console.error('usage: make_recording.js OUT.sdrec [--kind K] [--n N] [--events E] ...');
    process.exit(2);
  }
  let bytes = EncodeRecording(MakeFixture(options));
  if (options.truncate !== undefined) bytes = bytes.subarray(0, options.truncate);
  writeFileSync(out, bytes);
  console.log(`${out}: ${bytes.length} bytes`);
}
