// SPDX-License-Identifier: MIT
// Puts every body where its path says it is at the clock's time: per frame, one segment lookup
// (a cursor step), one polynomial evaluation and one quaternion per body, written straight into
// the instance buffers. Collisions near the current time flash their two bodies.
import {KindColor, SpeedColor, SpeedScale} from './colormap.js';
import {SegmentCursors, EvalVelocity, EvalOrientation, WrapPosition} from './paths.js';

/** At most this many recent collisions flash at once (a dense gas has many per frame). */
export const kMaxFlashes = 4096;

// Column-major 4x4 rigid transform from a unit quaternion (w, x, y, z) and a translation.
function WriteMatrix(m, at, q, p) {
  const n = 1 / Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const w = q[0] * n;
  const x = q[1] * n;
  const y = q[2] * n;
  const z = q[3] * n;
  const x2 = x + x;
  const y2 = y + y;
  const z2 = z + z;
  const xx = x * x2, xy = x * y2, xz = x * z2;
  const yy = y * y2, yz = y * z2, zz = z * z2;
  const wx = w * x2, wy = w * y2, wz = w * z2;
  m[at] = 1 - (yy + zz); m[at + 1] = xy + wz; m[at + 2] = xz - wy; m[at + 3] = 0;
  m[at + 4] = xy - wz; m[at + 5] = 1 - (xx + zz); m[at + 6] = yz + wx; m[at + 7] = 0;
  m[at + 8] = xz + wy; m[at + 9] = yz - wx; m[at + 10] = 1 - (xx + yy); m[at + 11] = 0;
  m[at + 12] = p[0]; m[at + 13] = p[1]; m[at + 14] = p[2]; m[at + 15] = 1;
}

// First index in the sorted array `times` whose value is > t.
function UpperBound(times, t) {
  let lo = 0;
  let hi = times.length;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (times[mid] <= t) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

export class Player {
  /** `view` is BuildScene's result; the player writes its instance buffers. */
  constructor(recording, view) {
    this.recording = recording;
    this.view = view;
    this.cursors = new SegmentCursors(recording.segments);
    const n = recording.bodies.count;
    this.position = new Float64Array(3 * n); // drawn (wrapped) centres, for the overlays
    this.orientation = new Float64Array(4 * n); // (w, x, y, z); identity for spheres
    this.speed = new Float64Array(n);
    this.speed_scale = SpeedScale(this.InitialSpeeds());
    this.flashing = []; // indices of the collisions flashing at the last update
  }

  InitialSpeeds() {
    const {segments, bodies} = this.recording;
    const v = [0, 0, 0];
    const speeds = new Float64Array(bodies.count);
    for (let i = 0; i < bodies.count; ++i) {
      speeds[i] = Math.hypot(...EvalVelocity(segments, segments.start[i], 0, v));
    }
    return speeds;
  }

  /** Evaluates every body at time `t`; collisions within (t - flash_window, t] flash. */
  Update(t, flash_window) {
    for (const group of this.view.groups) {
      const round = this.recording.header.shapes[group.shape].type === 'sphere';
      this.UpdateGroup(group, t, round);
      group.mesh.instanceMatrix.needsUpdate = true;
      group.mesh.instanceColor.needsUpdate = true;
      group.mesh.boundingSphere = null; // recomputed on demand (picking)
    }
    this.Flash(t, flash_window);
  }

  // The hot loop (10^5 bodies per frame): the path polynomial written out, no allocation, and
  // no orientation for spheres (a turning sphere looks the same) or non-spinning segments.
  UpdateGroup(group, t, round) {
    const {t0, position, velocity, acceleration, angular_velocity} = this.recording.segments;
    const container = this.recording.header.container;
    const wrap = container.kind === 'periodic';
    const matrices = group.mesh.instanceMatrix.array;
    const colors = group.mesh.instanceColor.array;
    const bodies = group.bodies;
    const p = [0, 0, 0];
    const q = [1, 0, 0, 0];
    for (let slot = 0; slot < bodies.length; ++slot) {
      const i = bodies[slot];
      const s = this.cursors.Seek(i, t);
      const dt = t - t0[s];
      const j = 3 * s;
      const vx = velocity[j] + dt * acceleration[j];
      const vy = velocity[j + 1] + dt * acceleration[j + 1];
      const vz = velocity[j + 2] + dt * acceleration[j + 2];
      p[0] = position[j] + dt * (velocity[j] + 0.5 * dt * acceleration[j]);
      p[1] = position[j + 1] + dt * (velocity[j + 1] + 0.5 * dt * acceleration[j + 1]);
      p[2] = position[j + 2] + dt * (velocity[j + 2] + 0.5 * dt * acceleration[j + 2]);
      if (wrap) WrapPosition(container, p);
      if (round) {
        q[0] = 1;
        q[1] = q[2] = q[3] = 0;
      } else if (angular_velocity[j] === 0 && angular_velocity[j + 1] === 0 &&
                 angular_velocity[j + 2] === 0) {
        EvalOrientation(this.recording.segments, s, t0[s], q);
      } else {
        EvalOrientation(this.recording.segments, s, t, q);
      }
      const speed = Math.sqrt(vx * vx + vy * vy + vz * vz);
      this.speed[i] = speed;
      this.position[3 * i] = p[0];
      this.position[3 * i + 1] = p[1];
      this.position[3 * i + 2] = p[2];
      for (let k = 0; k < 4; ++k) this.orientation[4 * i + k] = q[k];
      WriteMatrix(matrices, 16 * slot, q, p);
      if (!KindColor(this.recording.bodies.flags[i], colors, 3 * slot)) {
        SpeedColor(speed, this.speed_scale, colors, 3 * slot);
      }
    }
  }

  // Brightens both bodies of each recent collision towards white, fading over the window.
  Flash(t, flash_window) {
    const c = this.recording.collisions;
    const end = UpperBound(c.time, t);
    const begin = Math.max(UpperBound(c.time, t - flash_window), end - kMaxFlashes);
    this.flashing.length = 0;
    for (let k = begin; k < end; ++k) {
      this.flashing.push(k);
      const glow = 1 - (t - c.time[k]) / flash_window;
      this.Brighten(c.a[k], glow);
      if (!c.wall[k]) this.Brighten(c.b[k], glow);
    }
  }

  Brighten(body, glow) {
    const group = this.view.groups[this.view.group_of[body]];
    const colors = group.mesh.instanceColor.array;
    const at = 3 * this.view.slot_of[body];
    for (let k = 0; k < 3; ++k) colors[at + k] += glow * (1.6 - colors[at + k]);
  }
}
