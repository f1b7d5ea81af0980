// SPDX-License-Identifier: MIT
// Makes the README's picture of the viewer (docs/figures/viewer.png), reproducibly:
//   SPARSEDYN_CLI=build/release/apps/cli/sparsedyn \
//     node tests/viewer/screenshot.js RUN.sdrec OUT.png [TIME] [BODY]
// It opens the recording in headless Chromium, pauses at TIME, selects the visible body nearest
// to BODY's index (or none) and saves a 1280x800 screenshot. The figure in the README:
//   sparsedyn run --record run.sdrec   (the default scene: 1000 polyhedra of the thesis)
//   node tests/viewer/screenshot.js run.sdrec docs/figures/viewer.png 6.2 0
import {spawnSync} from 'node:child_process';
import {mkdtempSync} from 'node:fs';
import {createRequire} from 'node:module';
import {tmpdir} from 'node:os';
import {dirname, join} from 'node:path';
import {fileURLToPath, pathToFileURL} from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const {chromium} = createRequire(join(here, '../../viewer/package.json'))('playwright-core');
const [recording, out, time, body] = process.argv.slice(2);
const html = join(mkdtempSync(join(tmpdir(), 'sparsedyn-shot-')), 'page.html');
const made = spawnSync(process.env.SPARSEDYN_CLI, ['view', recording, '--html', html]);
if (made.status !== 0) throw new Error(String(made.stderr));

const browser = await chromium.launch({
  executablePath: process.env.SPARSEDYN_CHROMIUM || '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking',
         '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
const page = await browser.newPage({viewport: {width: 1280, height: 800}, deviceScaleFactor: 1});
await page.goto(pathToFileURL(html).href);
await page.waitForFunction(() => window.sparsedynViewer?.ready);
await page.evaluate((t) => {
  window.sparsedynViewer.pause();
  window.sparsedynViewer.seek(t);
}, Number(time ?? 1));
if (body !== undefined) {
  // The first body from BODY on whose centre is visible and picks itself.
  await page.evaluate((first) => {
    const v = window.sparsedynViewer;
    for (let i = first; ; ++i) {
      const at = v.screenPoint(i);
      if (at && at.x > 300 && at.x < 900 && at.y > 150 && at.y < 650 && v.pickAt(at.x, at.y) === i) {
        v.select(i);
        return;
      }
    }
  }, Number(body));
}
await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
// The status line's frame time is SwiftShader's CPU rendering, not what a browser shows.
await page.evaluate(() => (document.getElementById('status').style.visibility = 'hidden'));
await page.screenshot({path: out});
await browser.close();
console.log(`${out}: written`);
