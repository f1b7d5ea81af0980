// SPDX-License-Identifier: MIT
// Unit tests of the viewer's recording parser and path evaluation (node --test), against
// hand-computed values and against the independent fixture writer's own evaluation.
import assert from 'node:assert/strict';
import test from 'node:test';

import {FindSegment, SegmentCursors, EvalPosition, EvalOrientation, WrapPosition, BodyState}
  from '../../viewer/src/paths.js';
import {KindColor} from '../../viewer/src/colormap.js';
import {ParseRecording, RecordingError, kBodyGod, kBodyStatic} from '../../viewer/src/recording.js';
import {EncodeRecording, MakeFixture, SegmentOrientation, SegmentPosition}
  from './make_recording.js';

// Positions are sums of a few products of O(10) numbers: round-off is ~1e-14.
const kRoundOff = 1e-12;

function OneBody(segment, extra = {}) {
  return {
    header: {bodies: 1, container: {kind: 'open'}, shapes: [{type: 'sphere', radius: 1}],
             start_time: 0, end_time: 5, ...extra},
    bodies: [{shape: 0, mass: 2, bounding_radius: 1}],
    segments: [segment], collisions: [], end_time: 5,
  };
}

// The independent evaluation: scan a body's plain segments for the last one started by t.
function ExpectedSegment(fixture, body, t) {
  const mine = fixture.segments.filter((s) => s.body === body);
  let seg = mine[0];
  for (const s of mine) if (s.t0 <= t) seg = s;
  return seg;
}

test('an accelerated segment evaluates to the hand-computed position', () => {
  const rec = ParseRecording(EncodeRecording(OneBody(
      {body: 0, t0: 1, position: [1, 2, 3], velocity: [0.5, 0, -1], acceleration: [0, 0, -2]})));
  // dt = 2: (1 + 0.5*2, 2, 3 - 2 - 0.5*2*4) = (2, 2, -3)
  assert.deepEqual(EvalPosition(rec.segments, 0, 3, [0, 0, 0]), [2, 2, -3]);
  assert.equal(rec.bodies.mass[0], 2);
  assert.equal(rec.end_time, 5);
  assert.equal(rec.truncated, null);
});

test('static bodies and god objects are read from the body flags and drawn in their colours', () => {
  const fixture = OneBody({body: 0, t0: 0, position: [0, 0, 0], velocity: [1, 0, 0]});
  fixture.header.bodies = 3;
  fixture.bodies = [{shape: 0, mass: 1, bounding_radius: 1, flags: kBodyGod},
                    {shape: 0, mass: 1, bounding_radius: 1, flags: kBodyStatic},
                    {shape: 0, mass: 1, bounding_radius: 1}];
  fixture.segments = [0, 1, 2].map((body) =>
    ({body, t0: 0, position: [3 * body, 0, 0], velocity: [0, 0, 0]}));
  const rec = ParseRecording(EncodeRecording(fixture));
  assert.deepEqual(Array.from(rec.bodies.flags), [kBodyGod, kBodyStatic, 0]);
  const god = [0, 0, 0];
  const fixed = [0, 0, 0];
  assert.equal(KindColor(rec.bodies.flags[0], god, 0), true);
  assert.equal(KindColor(rec.bodies.flags[1], fixed, 0), true);
  assert.equal(KindColor(rec.bodies.flags[2], [0, 0, 0], 0), false);
  assert.notDeepEqual(god, fixed);
});

test('a spin of pi about z for one second turns identity into (0, 0, 0, 1)', () => {
  const rec = ParseRecording(EncodeRecording(OneBody(
      {body: 0, t0: 0, position: [0, 0, 0], velocity: [0, 0, 0], orientation: [1, 0, 0, 0],
       angular_velocity: [0, 0, Math.PI]})));
  const q = EvalOrientation(rec.segments, 0, 1, [0, 0, 0, 0]);
  [0, 0, 0, 1].forEach((x, k) => assert.ok(Math.abs(q[k] - x) < kRoundOff, `q=${q}`));
});

test('positions in a periodic box wrap into [lo, hi)', () => {
  const box = {kind: 'periodic', lo: [-1, 0, 0], hi: [3, 4, 4]};
  assert.deepEqual(WrapPosition(box, [3.5, -0.5, 8]), [-0.5, 3.5, 0]);
  assert.deepEqual(WrapPosition({kind: 'walled'}, [9, 9, 9]), [9, 9, 9]);
});

test('parsed segments and collisions match the fixture, state by state', () => {
  const fixture = MakeFixture({kind: 'mixed', n: 30, events: 40, seed: 7});
  const rec = ParseRecording(EncodeRecording(fixture));
  assert.equal(rec.bodies.count, 30);
  assert.equal(rec.collisions.count, 40);
  assert.equal(rec.segments.t0.length, fixture.segments.length);
  const cursors = new SegmentCursors(rec.segments);
  // Times forward (cursor steps), then backward (cursor searches), including event times.
  const times = [];
  for (let k = 0; k <= 200; ++k) times.push(10 * k / 200);
  for (const c of fixture.collisions) times.push(c.time);
  times.sort((a, b) => a - b);
  for (const t of [...times, ...times.slice().reverse()]) {
    for (let i = 0; i < 30; ++i) {
      const s = cursors.Seek(i, t);
      assert.equal(s, FindSegment(rec.segments, i, t));
      const seg = ExpectedSegment(fixture, i, t);
      const p = EvalPosition(rec.segments, s, t, [0, 0, 0]);
      SegmentPosition(seg, t).forEach((x, k) => assert.ok(Math.abs(p[k] - x) < kRoundOff));
      const q = EvalOrientation(rec.segments, s, t, [0, 0, 0, 0]);
      SegmentOrientation(seg, t).forEach((x, k) => assert.ok(Math.abs(q[k] - x) < kRoundOff));
    }
  }
  const c = fixture.collisions[3];
  assert.equal(rec.collisions.a[3], c.a);
  assert.equal(rec.collisions.time[3], c.time);
  assert.equal(rec.collisions.impulse[3], c.impulse);
});

test('BodyState counts the segments started so far and wraps the position', () => {
  const fixture = MakeFixture({kind: 'gas', n: 8, events: 6, seed: 3});
  const rec = ParseRecording(EncodeRecording(fixture));
  const cursors = new SegmentCursors(rec.segments);
  const body = fixture.collisions[2].a;
  const t = fixture.collisions[2].time + 0.01;
  const state = BodyState(rec, cursors, body, t);
  const expected_count = fixture.segments.filter((s) => s.body === body && s.t0 <= t).length;
  assert.equal(state.segments_so_far, expected_count);
  const unwrapped = SegmentPosition(ExpectedSegment(fixture, body, t), t);
  const edge = fixture.header.container.hi[0];
  unwrapped.forEach((x, k) => {
    assert.ok(Math.abs(state.unwrapped[k] - x) < kRoundOff);
    assert.ok(Math.abs(state.position[k] - (((x % edge) + edge) % edge)) < kRoundOff);
  });
});

test('bad files are refused with a message that says why', () => {
  const good = EncodeRecording(MakeFixture({n: 4, events: 2}));
  const bad_magic = Buffer.from(good);
  bad_magic[0] = 0x50;
  assert.throws(() => ParseRecording(bad_magic), /not a sparsedyn recording/);
  const v2 = Buffer.from(good);
  v2.writeUInt32LE(2, 8);
  assert.throws(() => ParseRecording(v2), /version 2 .*version 1/);
  assert.throws(() => ParseRecording(good.subarray(0, 30)), RecordingError);
});

test('a truncated file is reported as such and keeps what it has', () => {
  const fixture = MakeFixture({n: 4, events: 4});
  const whole = EncodeRecording(fixture);
  const rec = ParseRecording(whole.subarray(0, whole.length - 20));
  assert.match(rec.truncated, /truncated/);
  assert.equal(rec.bodies.count, 4);
  const no_end = ParseRecording(EncodeRecording(fixture, {end: false}));
  assert.equal(no_end.truncated, 'no end record');
  assert.equal(no_end.collisions.count, 4);
});
