// SPDX-License-Identifier: MIT
// The page's controls and panels (the DOM is in index.html): play/pause, speed, time slider,
// overlay toggles, the speed legend and the selected body's state.
import {RampCss} from './colormap.js';

const kSliderSteps = 10000;

/** Formats a number for the state panel: 9 decimals, enough to compare at 1e-6. */
export function FormatNumber(x) {
  return x.toFixed(9);
}

function FormatVector(v) {
  return v.map(FormatNumber).join('  ');
}

function ShapeName(shape) {
  if (shape.type === 'sphere') return `sphere r=${shape.radius}`;
  return `polyhedron, ${shape.faces.length} faces`;
}

export class Ui {
  /** `on` holds the callbacks: toggle(), speed(x), seek(t), open(file), overlay(name, on). */
  constructor(doc, on) {
    this.doc = doc;
    this.$ = (id) => doc.getElementById(id);
    this.start = 0;
    this.end = 1;
    this.dragging = false;
    this.$('play').addEventListener('click', () => on.toggle());
    doc.addEventListener('keydown', (e) => {
      // Not when a control has the focus: space is its own key there (a button would toggle twice).
      if (e.code === 'Space' && !['INPUT', 'BUTTON', 'SELECT'].includes(e.target.tagName)) {
        e.preventDefault();
        on.toggle();
      }
    });
    this.$('speed').addEventListener('change', (e) => on.speed(Number(e.target.value)));
    const slider = this.$('time');
    slider.max = String(kSliderSteps);
    slider.addEventListener('input', () => on.seek(this.SliderTime()));
    slider.addEventListener('pointerdown', () => (this.dragging = true));
    slider.addEventListener('pointerup', () => (this.dragging = false));
    this.$('open').addEventListener('change', (e) => {
      if (e.target.files.length > 0) on.open(e.target.files[0]);
    });
    this.$('show-spheres').addEventListener('change', (e) => on.overlay('spheres', e.target.checked));
    this.$('show-pairs').addEventListener('change', (e) => on.overlay('pairs', e.target.checked));
    this.$('show-features').addEventListener('change',
                                             (e) => on.overlay('features', e.target.checked));
    this.$('legend-bar').style.background = RampCss();
  }

  SliderTime() {
    return this.start + (this.end - this.start) * Number(this.$('time').value) / kSliderSteps;
  }

  /** Shows a recording's name, time range and the top of the speed scale. */
  SetRecording(recording, speed_scale, name) {
    this.start = recording.start_time;
    this.end = recording.end_time;
    this.$('scene-name').textContent = name;
    this.$('legend-max').textContent = speed_scale.toPrecision(3);
  }

  SetClock(t, playing) {
    this.$('clock').textContent = `t = ${t.toFixed(3)} / ${this.end.toFixed(3)}`;
    this.$('clock').dataset.time = String(t);
    this.$('play').textContent = playing ? 'Pause' : 'Play';
    if (!this.dragging) {
      const span = this.end - this.start;
      const u = span > 0 ? (t - this.start) / span : 0;
      this.$('time').value = String(Math.round(u * kSliderSteps));
    }
  }

  SetPairCount(count) {
    this.$('pair-count').textContent = count === null ? '' : `(${count})`;
  }

  SetFeatureLineCount(count) {
    this.$('feature-count').textContent = count === null ? '' : `(${count})`;
  }

  SetStatus(text) {
    this.$('status').textContent = text;
  }

  /** Fills the state panel from BodyState's result, or empties it for null. */
  ShowState(state, shapes) {
    this.$('info-empty').hidden = state !== null;
    this.$('info-table').hidden = state === null;
    if (state === null) return;
    const field = (name, text) => {
      this.doc.querySelector(`[data-field="${name}"]`).textContent = text;
    };
    field('index', String(state.index));
    field('shape', ShapeName(shapes[state.shape]));
    field('time', FormatNumber(state.time));
    field('position', FormatVector(state.position));
    field('velocity', FormatVector(state.velocity));
    field('speed', FormatNumber(state.speed));
    field('mass', String(state.mass));
    field('segments', `${state.segments_so_far} of ${state.segments_total}`);
  }

  ShowMessage(text) {
    this.$('message').textContent = text;
    this.$('message').style.display = text ? 'block' : 'none';
  }
}
