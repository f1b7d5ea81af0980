// SPDX-License-Identifier: MIT
// Frame cost of the viewer for fixture runs of N bodies (not a test: timings are never
// asserted; docs/viewer.md quotes its output):
// 1. the per-frame update alone (every path evaluated into the instance buffers) in node, for a
//    sphere gas and for spinning polyhedra;
// 2. whole frames in headless Chromium, where SwiftShader rasterizes on the CPU.
//   SPARSEDYN_CLI=build/release/apps/cli/sparsedyn node tests/viewer/measure_frames.js 10000 100000
import {spawn} from 'node:child_process';
import {mkdtempSync, writeFileSync} from 'node:fs';
import {createRequire} from 'node:module';
import {tmpdir} from 'node:os';
import {dirname, join} from 'node:path';
import {fileURLToPath} from 'node:url';

import {Player} from '../../viewer/src/player.js';
import {ParseRecording} from '../../viewer/src/recording.js';
import {EncodeRecording, MakeFixture} from './make_recording.js';

// Player.Update on stand-ins for the instanced meshes (it only writes their arrays).
function UpdateMilliseconds(kind, n) {
  const recording = ParseRecording(EncodeRecording(MakeFixture({kind, n, events: n})));
  const members = recording.header.shapes.map(() => []);
  for (let i = 0; i < n; ++i) members[recording.bodies.shape[i]].push(i);
  const view = {groups: [], group_of: new Uint16Array(n), slot_of: new Uint32Array(n)};
  members.forEach((bodies, shape) => {
    bodies.forEach((i, slot) => {
      view.group_of[i] = view.groups.length;
      view.slot_of[i] = slot;
    });
    view.groups.push({shape, bodies: Uint32Array.from(bodies),
                      mesh: {instanceMatrix: {array: new Float32Array(16 * bodies.length)},
                             instanceColor: {array: new Float32Array(3 * bodies.length)}}});
  });
  const player = new Player(recording, view);
  const frames = 200;
  const begin = performance.now();
  for (let f = 1; f <= frames; ++f) player.Update((10 * f) / frames, 0.35);
  return (performance.now() - begin) / frames;
}

const counts = process.argv.slice(2).map(Number);
for (const n of counts) {
  console.log(`update, ${n} bodies: sphere gas ${UpdateMilliseconds('gas', n).toFixed(1)} ms, ` +
              `spinning polyhedra and spheres ${UpdateMilliseconds('mixed', n).toFixed(1)} ms`);
}

const here = dirname(fileURLToPath(import.meta.url));
const {chromium} = createRequire(join(here, '../../viewer/package.json'))('playwright-core');
const dir = mkdtempSync(join(tmpdir(), 'sparsedyn-frames-'));
const browser = await chromium.launch({
  executablePath: process.env.SPARSEDYN_CHROMIUM || '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking',
         '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
for (const n of counts) {
  const file = join(dir, `gas-${n}.sdrec`);
  writeFileSync(file, EncodeRecording(MakeFixture({kind: 'gas', n, events: n})));
  const server = spawn(process.env.SPARSEDYN_CLI, ['view', file, '--port', '0']);
  const url = await new Promise((resolve) => server.stdout.on('data', (d) => {
    const m = String(d).match(/http:\/\/127\.0\.0\.1:\d+\//);
    if (m) resolve(m[0]);
  }));
  const page = await browser.newPage({viewport: {width: 1280, height: 800}});
  const begin = Date.now();
  await page.goto(url);
  await page.waitForFunction(() => window.sparsedynViewer?.ready, null, {timeout: 120000});
  const loaded = (Date.now() - begin) / 1000;
  await page.waitForTimeout(8000);
  const stats = await page.evaluate(() => window.sparsedynViewer.stats());
  console.log(`chromium, ${n}-sphere gas: loaded in ${loaded.toFixed(1)} s, update ${stats.update_ms.toFixed(1)} ms,` +
              ` frame ${stats.frame_ms.toFixed(0)} ms (${stats.frames} frames in 8 s)`);
  await page.close();
  server.kill();
}
await browser.close();
