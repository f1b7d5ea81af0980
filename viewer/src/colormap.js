// SPDX-License-Identifier: MIT
// Speed to colour, as in the thesis's pictures: slow bodies cool (blue), fast ones hot (red).

// Control points of the ramp at 0, 1/4, 1/2, 3/4, 1 (linear RGB for three's colour buffers).
const kStops = [
  [0.05, 0.10, 0.60],
  [0.05, 0.55, 0.85],
  [0.20, 0.75, 0.25],
  [0.95, 0.75, 0.10],
  [0.85, 0.08, 0.05],
];

/** Writes the colour of `speed` on the ramp [0, max_speed] into out[at .. at+2]. */
export function SpeedColor(speed, max_speed, out, at) {
  let u = max_speed > 0 ? speed / max_speed : 0;
  u = Math.min(Math.max(u, 0), 1) * (kStops.length - 1);
  const k = Math.min(Math.floor(u), kStops.length - 2);
  const f = u - k;
  const a = kStops[k];
  const b = kStops[k + 1];
  out[at] = a[0] + f * (b[0] - a[0]);
  out[at + 1] = a[1] + f * (b[1] - a[1]);
  out[at + 2] = a[2] + f * (b[2] - a[2]);
}

// Bodies that are not coloured by speed: statics stay grey, god objects (driven from outside)
// a pink that the ramp never takes.
const kStaticColor = [0.30, 0.30, 0.34];
const kGodColor = [1.00, 0.25, 0.65];

/**
 * Writes the colour of a static body or god object (RecordedBody flags: bit 0 static, bit 1
 * god) into out[at .. at+2] and returns true; false for any other body.
 */
export function KindColor(flags, out, at) {
  const c = (flags & 2) !== 0 ? kGodColor : (flags & 1) !== 0 ? kStaticColor : null;
  if (c === null) return false;
  out[at] = c[0];
  out[at + 1] = c[1];
  out[at + 2] = c[2];
  return true;
}

/** CSS gradient of the same ramp, for the legend. */
export function RampCss() {
  const srgb = (c) => Math.round(255 * Math.pow(c, 1 / 2.2));
  const stops = kStops.map((c, i) =>
    `rgb(${srgb(c[0])},${srgb(c[1])},${srgb(c[2])}) ${(100 * i) / (kStops.length - 1)}%`);
  return `linear-gradient(to right, ${stops.join(', ')})`;
}

/**
 * The top of the ramp: a high quantile of the bodies' initial speeds, so that a few fast
 * bodies do not wash the rest out.
 */
export function SpeedScale(speeds) {
  if (speeds.length === 0) return 1;
  const sorted = Float64Array.from(speeds).sort();
  const top = sorted[Math.min(sorted.length - 1, Math.floor(0.98 * sorted.length))];
  return top > 0 ? 1.25 * top : 1;
}
