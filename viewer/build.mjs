// SPDX-License-Identifier: MIT
// Bundles the viewer with esbuild into OUT_DIR/viewer.html + OUT_DIR/viewer.js (three.js
// included, no network needed at run time). Run by the CMake target `viewer`:
//   node viewer/build.mjs OUT_DIR
import {build} from 'esbuild';
import {copyFileSync, mkdirSync} from 'node:fs';
import {dirname, join} from 'node:path';
import {fileURLToPath} from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const out_dir = process.argv[2];
if (!out_dir) {
  console.error('usage: node build.mjs OUT_DIR');
  process.exit(2);
}
mkdirSync(out_dir, {recursive: true});
await build({
  entryPoints: [join(here, 'src/main.js')],
  outfile: join(out_dir, 'viewer.js'),
  bundle: true,
  format: 'iife',
  minify: true,
  target: ['es2020'],
  legalComments: 'eof', // three.js's MIT notice stays in the bundle
  logLevel: 'warning',
});
copyFileSync(join(here, 'src/index.html'), join(out_dir, 'viewer.html'));
