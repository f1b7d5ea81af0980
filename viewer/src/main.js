// SPDX-License-Identifier: MIT
// The viewer page: finds the recording (embedded in the page, or served next to it), builds the
// scene and plays it. The clock is the only state that moves; every frame the bodies are
// evaluated from their analytic paths at the clock's time.
import {OrbitControls} from 'three/addons/controls/OrbitControls.js';

import {Overlays} from './overlays.js';
import {BodyState} from './paths.js';
import {OnClickNotDrag, PickBody, ScreenPoint} from './picking.js';
import {Player} from './player.js';
import {ParseRecording} from './recording.js';
import {BuildScene, CreateRenderer} from './scene.js';
import {Ui} from './ui.js';

/** A collision flashes for this long in wall-clock seconds, whatever the playback speed... */
const kFlashSeconds = 0.15;
/** ...unless that would light up more than this fraction of the bodies on average. */
const kFlashFraction = 0.03;

const canvas = document.getElementById('view');
const renderer = CreateRenderer(canvas);
const state = {
  session: null, // {recording, view, player, overlays, controls}
  t: 0,
  playing: true,
  speed: 1,
  selected: null,
  show: {spheres: false, pairs: false, features: false},
  frame_ms: 0,
  update_ms: 0,
  frames: 0,
  last_frame: null,
};

const ui = new Ui(document, {
  toggle: () => {
    if (!state.session) return;
    if (!state.playing && state.t >= state.session.recording.end_time) {
      state.t = state.session.recording.start_time; // play again from the start
    }
    state.playing = !state.playing;
  },
  speed: (x) => (state.speed = x),
  seek: (t) => (state.t = t),
  open: (file) => file.arrayBuffer().then((bytes) => Load(bytes, file.name)).catch(ShowError),
  overlay: (name, on) => (state.show[name] = on),
});

function ShowError(e) {
  ui.ShowMessage(`Cannot show this recording: ${e.message}`);
  console.warn('sparsedyn viewer:', e);
}

function Dispose(session) {
  session.controls.dispose();
  session.view.scene.traverse((object) => {
    object.geometry?.dispose();
    object.material?.dispose();
  });
}

/** Replaces the current recording by the one in `bytes` (ArrayBuffer or Uint8Array). */
function Load(bytes, name) {
  const recording = ParseRecording(bytes);
  if (state.session) Dispose(state.session);
  const view = BuildScene(recording);
  const player = new Player(recording, view);
  const overlays = new Overlays(recording, view.scene);
  const controls = new OrbitControls(view.camera, canvas);
  controls.target.copy(view.center);
  controls.update();
  state.session = {recording, view, player, overlays, controls};
  state.t = recording.start_time;
  state.playing = true;
  state.selected = null;
  ui.SetRecording(recording, player.speed_scale, recording.header.scene ?? name);
  ui.ShowState(null);
  ui.ShowMessage(recording.truncated ? `Incomplete recording (${recording.truncated}); ` +
                 'showing what it has.' : '');
  if (recording.truncated) console.warn(`sparsedyn viewer: ${recording.truncated}`);
}

function ResizeIfNeeded(camera) {
  const width = canvas.clientWidth;
  const height = canvas.clientHeight;
  if (canvas.width !== Math.floor(width * renderer.getPixelRatio()) ||
      canvas.height !== Math.floor(height * renderer.getPixelRatio())) {
    renderer.setSize(width, height, false);
    camera.aspect = width / Math.max(height, 1);
    camera.updateProjectionMatrix();
  }
}

function Frame(now) {
  requestAnimationFrame(Frame);
  const session = state.session;
  const wall_dt = state.last_frame === null ? 0 : (now - state.last_frame) / 1000;
  state.last_frame = now;
  if (!session) return;
  const {recording, view, player, overlays} = session;
  const before = state.t;
  if (state.playing) {
    state.t += Math.min(wall_dt, 0.1) * state.speed;
    if (state.t >= recording.end_time) {
      state.t = recording.end_time;
      state.playing = false;
    }
  }
  const begin = performance.now();
  player.Update(state.t, FlashWindow(recording, Math.abs(state.t - before)));
  overlays.show = state.show;
  overlays.Update(player, state.selected);
  const updated = performance.now();
  ResizeIfNeeded(view.camera);
  renderer.render(view.scene, view.camera);
  const k = state.frames === 0 ? 1 : 0.1; // moving averages
  state.update_ms += k * (updated - begin - state.update_ms);
  state.frame_ms += k * (wall_dt * 1000 - state.frame_ms);
  state.frames++;
  ui.SetClock(state.t, state.playing);
  ui.SetPairCount(state.show.pairs || state.show.features ? overlays.pair_count : null);
  ui.SetFeatureLineCount(state.show.features ? overlays.feature_lines : null);
  if (state.selected !== null) ui.ShowState(Inspect(state.selected), recording.header.shapes);
  ui.SetStatus(`${recording.bodies.count} bodies, ${recording.segments.t0.length} segments, ` +
               `${recording.collisions.count} collisions · update ${state.update_ms.toFixed(1)} ms` +
               ` · frame ${state.frame_ms.toFixed(1)} ms`);
}

// Simulated time a collision stays lit: kFlashSeconds of wall time, shortened in busy runs so
// that about kFlashFraction of the bodies flash at once (2 bodies per collision), and never
// shorter than this frame's step of the clock (every collision is seen).
function FlashWindow(recording, step) {
  const span = recording.end_time - recording.start_time;
  const rate = span > 0 ? recording.collisions.count / span : 0;
  const busy = rate > 0 ? (kFlashFraction * recording.bodies.count) / (2 * rate) : Infinity;
  return Math.max(Math.min(kFlashSeconds * state.speed, busy), step);
}

function Inspect(i) {
  const {recording, player} = state.session;
  return BodyState(recording, player.cursors, i, state.t);
}

OnClickNotDrag(canvas, (x, y) => {
  if (!state.session) return;
  state.selected = PickBody(state.session.view, canvas, x, y);
  ui.ShowState(state.selected === null ? null : Inspect(state.selected),
               state.session.recording.header.shapes);
});

// Where the recording comes from: embedded in the page (sparsedyn view --html), else the URL in
// ?recording=, else recording.sdrec next to the page (sparsedyn view's server).
async function RecordingBytes() {
  const embedded = document.getElementById('sdrec-data');
  if (embedded) {
    const text = atob(embedded.textContent.trim());
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
    return {bytes, name: embedded.dataset.name ?? 'recording'};
  }
  const url = new URLSearchParams(location.search).get('recording') ?? 'recording.sdrec';
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return {bytes: await response.arrayBuffer(), name: url};
}

// A small interface for tests and the browser console.
window.sparsedynViewer = {
  ready: false,
  error: null,
  time: () => state.t,
  playing: () => state.playing,
  play: () => (state.playing = true),
  pause: () => (state.playing = false),
  seek: (t) => (state.t = t),
  select: (i) => (state.selected = i),
  selected: () => state.selected,
  state: (i) => Inspect(i),
  pickAt: (x, y) => PickBody(state.session.view, canvas, x, y),
  screenPoint: (i) => ScreenPoint(state.session.view, canvas,
                                  Array.from(state.session.player.position.subarray(3 * i, 3 * i + 3))),
  overlayCounts: () => ({pairs: state.session.overlays.pair_count,
                         feature_lines: state.session.overlays.feature_lines}),
  stats: () => ({update_ms: state.update_ms, frame_ms: state.frame_ms, frames: state.frames}),
};

RecordingBytes()
    .then(({bytes, name}) => Load(bytes, name))
    .catch((e) => {
      window.sparsedynViewer.error = e.message;
      ui.ShowMessage(`No recording loaded (${e.message}). Open a .sdrec file below, or run ` +
                     '`sparsedyn view FILE.sdrec`.');
    })
    .finally(() => (window.sparsedynViewer.ready = true));
requestAnimationFrame(Frame);
