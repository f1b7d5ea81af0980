// SPDX-License-Identifier: MIT
// The viewer in headless Chromium (playwright-core driving Debian's chromium; three.js renders
// on the CPU through SwiftShader): the page loads a recording with no console errors, the clock
// advances, clicking a body shows the state the recording gives for it, and the screenshot has
// bodies in it. Run by ctest (tests/viewer/CMakeLists.txt) with
//   SPARSEDYN_CLI      the sparsedyn binary (its `view` serves or writes the page)
//   SPARSEDYN_CHROMIUM chromium's path (default: found on PATH)
//   SPARSEDYN_TEST_OUT where screenshots go (default: a temporary folder)
import assert from 'node:assert/strict';
import {spawn, spawnSync} from 'node:child_process';
import {existsSync, mkdirSync, mkdtempSync, writeFileSync} from 'node:fs';
import {createRequire} from 'node:module';
import {tmpdir} from 'node:os';
import {dirname, join} from 'node:path';
import {after, before, test} from 'node:test';
import {fileURLToPath, pathToFileURL} from 'node:url';

import {EncodeRecording, MakeFixture, SegmentPosition, SegmentVelocity} from './make_recording.js';

const here = dirname(fileURLToPath(import.meta.url));
const require = createRequire(join(here, '../../viewer/package.json'));
const {chromium} = require('playwright-core');

/** The state panel prints 9 decimals; the brief's tolerance for "the same number". */
const kShownTolerance = 1e-6;
const kBackground = [0x12, 0x16, 0x1c];
const kViewport = {width: 1000, height: 700};

const cli = process.env.SPARSEDYN_CLI;
const out_dir = process.env.SPARSEDYN_TEST_OUT || mkdtempSync(join(tmpdir(), 'sparsedyn-viewer-'));
mkdirSync(out_dir, {recursive: true});

function FindChromium() {
  if (process.env.SPARSEDYN_CHROMIUM) return process.env.SPARSEDYN_CHROMIUM;
  for (const dir of (process.env.PATH ?? '').split(':')) {
    for (const name of ['chromium', 'chromium-browser']) {
      if (existsSync(join(dir, name))) return join(dir, name);
    }
  }
  throw new Error('chromium not found: scripts/deps.sh installs it (Debian package chromium)');
}

let browser;
before(async () => {
  assert.ok(cli && existsSync(cli), `SPARSEDYN_CLI must name the sparsedyn binary (got ${cli})`);
  browser = await chromium.launch({
    executablePath: FindChromium(),
    args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking',
           '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
});
after(async () => browser?.close());

// A page that records console errors and uncaught exceptions.
async function OpenPage(url) {
  const page = await browser.newPage({viewport: kViewport, deviceScaleFactor: 1});
  const errors = [];
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(url);
  await page.waitForFunction(() => window.sparsedynViewer?.ready, null, {timeout: 30000});
  assert.equal(await page.evaluate(() => window.sparsedynViewer.error), null);
  return {page, errors};
}

const NextFrames = (page) => page.evaluate(() => new Promise(
    (done) => requestAnimationFrame(() => requestAnimationFrame(() => requestAnimationFrame(done)))));

// The clock moves on its own (SwiftShader frames can take a second on a busy machine, hence
// waiting for the change rather than for a fixed time).
async function CheckClockAdvances(page) {
  await page.evaluate(() => window.sparsedynViewer.play());
  const t0 = await page.evaluate(() => window.sparsedynViewer.time());
  await page.waitForFunction((t) => window.sparsedynViewer.time() > t, t0, {timeout: 30000});
  await NextFrames(page);
  const shown = Number(await page.locator('#clock').getAttribute('data-time'));
  const t1 = await page.evaluate(() => window.sparsedynViewer.time());
  assert.ok(shown > t0 && shown <= t1, `clock shows ${shown}, started at ${t0}`);
}

// Finds a candidate body whose centre is on screen, clear of the panels and not hidden by
// another body (asking the page's picker), clicks it and returns the panel's fields as text.
async function ClickABody(page, candidates) {
  const margins = {left: 230, right: kViewport.width - 280, top: 20,
                   bottom: kViewport.height - 100};
  const target = await page.evaluate(({bodies, box}) => {
    for (const body of bodies) {
      const at = window.sparsedynViewer.screenPoint(body);
      if (!at || at.x < box.left || at.x > box.right || at.y < box.top || at.y > box.bottom) {
        continue;
      }
      if (window.sparsedynViewer.pickAt(at.x, at.y) === body) return {body, ...at};
    }
    return null;
  }, {bodies: candidates, box: margins});
  assert.ok(target, 'no candidate body is visible');
  await page.mouse.click(target.x, target.y);
  const fields = {};
  for (const name of ['index', 'time', 'position', 'velocity', 'speed', 'mass', 'segments']) {
    fields[name] = await page.locator(`[data-field="${name}"]`).textContent();
  }
  assert.equal(Number(fields.index), target.body, 'the clicked body is the one shown');
  return fields;
}

function Numbers(text) {
  return text.trim().split(/\s+/).map(Number);
}

function Wrap(container, p) {
  if (container.kind !== 'periodic') return p;
  return p.map((x, k) => {
    const size = container.hi[k] - container.lo[k];
    return container.lo[k] + ((((x - container.lo[k]) % size) + size) % size);
  });
}

function AssertClose(shown, expected, what) {
  shown.forEach((x, k) => assert.ok(Math.abs(x - expected[k]) <= kShownTolerance,
                                    `${what}[${k}]: shown ${x}, expected ${expected[k]}`));
}

// Pauses just after a recorded collision, picks one of its bodies and checks every number in
// the panel against `segments` (plain {body, t0, position, velocity, acceleration?} objects).
async function CheckPickedState(page, {segments, collisions, container, masses}) {
  const c = collisions[Math.floor(collisions.length / 2)];
  const t = c.time + 0.0137;
  await page.evaluate((time) => {
    window.sparsedynViewer.pause();
    window.sparsedynViewer.seek(time);
  }, t);
  await NextFrames(page);
  const order = [c.a, c.b, ...masses.map((_, i) => i)];
  const fields = await ClickABody(page, order);
  const body = Number(fields.index);
  const shown_t = Number(fields.time);
  assert.ok(Math.abs(shown_t - t) < 1e-9, `panel time ${shown_t}, clock ${t}`);
  const mine = segments.filter((s) => s.body === body && s.t0 <= shown_t);
  const seg = mine[mine.length - 1];
  AssertClose(Numbers(fields.position), Wrap(container, SegmentPosition(seg, shown_t)), 'position');
  const v = SegmentVelocity(seg, shown_t);
  AssertClose(Numbers(fields.velocity), v, 'velocity');
  AssertClose([Number(fields.speed)], [Math.hypot(...v)], 'speed');
  assert.equal(Number(fields.mass), masses[body]);
  assert.equal(Number(fields.segments.split(' ')[0]), mine.length);
  return body;
}

// Colourful pixels in the middle of the screenshot (bodies are coloured by speed; background,
// panels and container lines are grey). The page itself decodes the PNG.
async function ColouredFraction(page, png) {
  return page.evaluate(async ({b64, bg}) => {
    const image = new Image();
    image.src = `data:image/png;base64,${b64}`;
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = image.width;
    canvas.height = image.height;
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0);
    const {data} = context.getImageData(0, 0, image.width, image.height);
    let coloured = 0;
    let changed = 0;
    for (let p = 0; p < data.length; p += 4) {
      const [r, g, b] = [data[p], data[p + 1], data[p + 2]];
      if (Math.max(r, g, b) - Math.min(r, g, b) > 40) coloured++;
      if (Math.abs(r - bg[0]) + Math.abs(g - bg[1]) + Math.abs(b - bg[2]) > 30) changed++;
    }
    return {coloured: coloured / (data.length / 4), changed: changed / (data.length / 4)};
  }, {b64: png.toString('base64'), bg: kBackground});
}

async function CheckBodiesDrawn(page, name) {
  await page.evaluate(() => window.sparsedynViewer.select(null));
  await NextFrames(page);
  await page.screenshot({path: join(out_dir, `${name}.png`)});
  const middle = await page.screenshot({clip: {x: 230, y: 20, width: kViewport.width - 510,
                                               height: kViewport.height - 120}});
  const {coloured, changed} = await ColouredFraction(page, middle);
  assert.ok(coloured > 0.02 && changed > 0.02,
            `${name}: only ${(100 * coloured).toFixed(2)}% coloured pixels: bodies not drawn?`);
}

// Turns on every overlay; each engaged pair gets its closest-feature line (small shapes: the
// per-frame budget is not reached).
async function CheckOverlays(page) {
  // DOM clicks: playwright's check() waits for animation-stable frames, slow on SwiftShader.
  await page.evaluate(() => ['show-pairs', 'show-spheres', 'show-features'].forEach(
      (id) => document.getElementById(id).click()));
  await NextFrames(page);
  const counts = await page.evaluate(() => window.sparsedynViewer.overlayCounts());
  assert.equal(counts.feature_lines, counts.pairs);
  assert.equal(await page.locator('#pair-count').textContent(), `(${counts.pairs})`);
}

function FixtureFacts(fixture) {
  return {segments: fixture.segments, collisions: fixture.collisions,
          container: fixture.header.container, masses: fixture.bodies.map((b) => b.mass)};
}

function WriteFixture(name, options) {
  const fixture = MakeFixture(options);
  const file = join(out_dir, `${name}.sdrec`);
  writeFileSync(file, EncodeRecording(fixture));
  return {fixture, file};
}

test('the self-contained page (view --html) plays a recording, picks and draws bodies',
     async () => {
  const {fixture, file} = WriteFixture('fixture-mixed', {kind: 'mixed', n: 40, events: 30});
  const html = join(out_dir, 'fixture-mixed.html');
  const made = spawnSync(cli, ['view', file, '--html', html], {encoding: 'utf8'});
  assert.equal(made.status, 0, made.stderr);
  const {page, errors} = await OpenPage(pathToFileURL(html).href);
  await CheckClockAdvances(page);
  await CheckPickedState(page, FixtureFacts(fixture));
  await CheckOverlays(page);
  await CheckBodiesDrawn(page, 'viewer-fixture-mixed');
  assert.deepEqual(errors, []);
  await page.close();
});

test('a truncated recording plays what it has and says it is incomplete', async () => {
  const fixture = MakeFixture({kind: 'mixed', n: 12, events: 8});
  const whole = EncodeRecording(fixture);
  const file = join(out_dir, 'fixture-truncated.sdrec');
  writeFileSync(file, whole.subarray(0, whole.length - 40));
  const html = join(out_dir, 'fixture-truncated.html');
  const made = spawnSync(cli, ['view', file, '--html', html], {encoding: 'utf8'});
  assert.equal(made.status, 0, made.stderr);
  const {page, errors} = await OpenPage(pathToFileURL(html).href);
  assert.match(await page.locator('#message').textContent(), /Incomplete recording .*truncated/);
  await CheckClockAdvances(page);
  assert.deepEqual(errors, []);
  await page.close();
});

// Starts `sparsedyn view FILE --port 0` and resolves with its address once it prints it.
function StartServer(file) {
  const server = spawn(cli, ['view', file, '--port', '0'], {stdio: ['ignore', 'pipe', 'pipe']});
  return new Promise((resolve, reject) => {
    let out = '';
    server.stdout.on('data', (chunk) => {
      out += chunk;
      const match = out.match(/http:\/\/127\.0\.0\.1:\d+\//);
      if (match) resolve({server, url: match[0]});
    });
    server.on('exit', (code) => reject(new Error(`sparsedyn view exited with ${code}: ${out}`)));
  });
}

test('the served page (view --port 0) plays a periodic gas and derives engaged pairs',
     async () => {
  const {fixture, file} = WriteFixture('fixture-gas', {kind: 'gas', n: 200, events: 150});
  const {server, url} = await StartServer(file);
  try {
    const {page, errors} = await OpenPage(url);
    await CheckClockAdvances(page);
    await CheckPickedState(page, FixtureFacts(fixture));
    await CheckOverlays(page);
    await CheckBodiesDrawn(page, 'viewer-fixture-gas');
    assert.deepEqual(errors, []);
    await page.close();
  } finally {
    server.kill();
  }
});

// The facts CheckPickedState needs, from `sparsedyn export-jsonl` (the C++ reader's view of the
// file: an independent decoding of the same bytes).
function ExportedFacts(file) {
  const exported = spawnSync(cli, ['export-jsonl', file], {encoding: 'utf8',
                                                           maxBuffer: 1 << 28});
  assert.equal(exported.status, 0, exported.stderr);
  const facts = {segments: [], collisions: [], container: null, masses: []};
  for (const line of exported.stdout.split('\n')) {
    if (!line) continue;
    const r = JSON.parse(line);
    if (r.record === 'header') facts.container = r.container;
    if (r.record === 'body') facts.masses[r.index] = r.mass;
    if (r.record === 'segment') facts.segments.push(r);
    if (r.record === 'collision' && !(r.flags & 1)) facts.collisions.push(r);
  }
  return facts;
}

test('a recording made by sparsedyn run --record plays, and a picked body shows its state',
     async () => {
  const file = join(out_dir, 'cli-gas.sdrec');
  const run = spawnSync(cli, ['run', '--preset', 'gas', '--n', '300', '--until', '3',
                              '--record', file], {encoding: 'utf8'});
  assert.equal(run.status, 0, run.stderr);
  const facts = ExportedFacts(file);
  const {server, url} = await StartServer(file);
  try {
    const {page, errors} = await OpenPage(url);
    await CheckClockAdvances(page);
    await CheckPickedState(page, facts);
    await CheckBodiesDrawn(page, 'viewer-cli-gas');
    assert.deepEqual(errors, []);
    await page.close();
  } finally {
    server.kill();
  }
});
