// SPDX-License-Identifier: MIT
// Evaluation of the recorded analytic paths (docs/recording-format.md "Segment"): the viewer
// computes every body's state itself and is interrupted only where a new segment starts
// (thesis §9.3). A cursor per body remembers its current segment, so a frame costs O(bodies)
// while the clock moves forward, and a jump (time slider) costs a binary search per body.

/**
 * Index of the segment of `body` in effect at time `t`: the last one with t0 <= t (the first
 * one if t is before it). Segments with equal t0 resolve to the last, which is the one that
 * holds after all events at that time.
 */
export function FindSegment(segments, body, t) {
  const t0 = segments.t0;
  let lo = segments.start[body];
  let hi = segments.start[body + 1]; // search (lo, hi): first index with t0 > t
  const first = lo;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (t0[mid] <= t) lo = mid + 1;
    else hi = mid;
  }
  return Math.max(first, lo - 1);
}

/** Per-body cursors into the segment tables, kept valid as the clock moves. */
export class SegmentCursors {
  constructor(segments) {
    this.segments = segments;
    const n = segments.start.length - 1;
    this.current = Uint32Array.from(segments.start.subarray(0, n));
  }

  /** Moves body `i`'s cursor to its segment at time `t` and returns the segment index. */
  Seek(i, t) {
    const {t0, start} = this.segments;
    let s = this.current[i];
    const end = start[i + 1];
    if (t0[s] > t && s > start[i]) {
      s = FindSegment(this.segments, i, t); // moved back: search
    } else {
      // Forward: usually zero or one step per frame; search when it is many.
      let steps = 0;
      while (s + 1 < end && t0[s + 1] <= t) {
        if (++steps > 8) {
          s = FindSegment(this.segments, i, t);
          break;
        }
        ++s;
      }
    }
    this.current[i] = s;
    return s;
  }

  /** Number of segments of body `i` that have started by time `t` (its version, 1-based). */
  CountSoFar(i, t) {
    const s = this.Seek(i, t);
    const {t0, start} = this.segments;
    return t0[s] <= t ? s - start[i] + 1 : 0;
  }
}

/** Position of segment `s` at time `t` into out[0..2]: p + v dt + a dt^2 / 2. */
export function EvalPosition(segments, s, t, out) {
  const dt = t - segments.t0[s];
  const p = segments.position;
  const v = segments.velocity;
  const a = segments.acceleration;
  for (let k = 0; k < 3; ++k) {
    const j = 3 * s + k;
    out[k] = p[j] + dt * (v[j] + 0.5 * dt * a[j]);
  }
  return out;
}

/** Velocity of segment `s` at time `t` into out[0..2]: v + a dt. */
export function EvalVelocity(segments, s, t, out) {
  const dt = t - segments.t0[s];
  for (let k = 0; k < 3; ++k) {
    const j = 3 * s + k;
    out[k] = segments.velocity[j] + dt * segments.acceleration[j];
  }
  return out;
}

/**
 * Orientation of segment `s` at time `t` into out[0..3] as (w, x, y, z):
 * q(t) = exp(w_W dt / 2) * q0, a rotation by |w| dt about w / |w| applied after q0.
 */
export function EvalOrientation(segments, s, t, out) {
  const dt = t - segments.t0[s];
  const w = segments.angular_velocity;
  const q = segments.orientation;
  const wx = w[3 * s];
  const wy = w[3 * s + 1];
  const wz = w[3 * s + 2];
  const speed = Math.sqrt(wx * wx + wy * wy + wz * wz);
  const half = 0.5 * speed * dt;
  // sin(half) / speed without dividing by zero: its series for small angles.
  const sinc = speed * dt === 0 ? 0.5 * dt
             : Math.abs(half) < 1e-4 ? 0.5 * dt * (1 - half * half / 6)
             : Math.sin(half) / speed;
  const rw = Math.cos(half);
  const rx = wx * sinc;
  const ry = wy * sinc;
  const rz = wz * sinc;
  const qw = q[4 * s];
  const qx = q[4 * s + 1];
  const qy = q[4 * s + 2];
  const qz = q[4 * s + 3];
  // Hamilton product r * q.
  out[0] = rw * qw - rx * qx - ry * qy - rz * qz;
  out[1] = rw * qx + rx * qw + ry * qz - rz * qy;
  out[2] = rw * qy - rx * qz + ry * qw + rz * qx;
  out[3] = rw * qz + rx * qy - ry * qx + rz * qw;
  return out;
}

/**
 * Wraps a position into a periodic container [lo, hi) in place (recorded positions are not
 * wrapped); other containers leave it as it is.
 */
export function WrapPosition(container, p) {
  if (container.kind !== 'periodic') return p;
  for (let k = 0; k < 3; ++k) {
    const lo = container.lo[k];
    const size = container.hi[k] - container.lo[k];
    let x = (p[k] - lo) % size;
    if (x < 0) x += size;
    p[k] = lo + x;
  }
  return p;
}

/** The full state of body `i` at time `t` (what the selection panel shows). */
export function BodyState(recording, cursors, i, t) {
  const s = cursors.Seek(i, t);
  const position = EvalPosition(recording.segments, s, t, [0, 0, 0]);
  const unwrapped = position.slice();
  WrapPosition(recording.header.container, position);
  const velocity = EvalVelocity(recording.segments, s, t, [0, 0, 0]);
  const orientation = EvalOrientation(recording.segments, s, t, [1, 0, 0, 0]);
  return {
    index: i,
    time: t,
    position,
    unwrapped,
    velocity,
    speed: Math.hypot(...velocity),
    orientation,
    mass: recording.bodies.mass[i],
    bounding_radius: recording.bodies.bounding_radius[i],
    shape: recording.bodies.shape[i],
    segments_so_far: cursors.CountSoFar(i, t),
    segments_total: recording.segments.start[i + 1] - recording.segments.start[i],
  };
}
