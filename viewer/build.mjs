// Bundles the viewer into ONE self-contained IIFE script (three.js, uPlot, the
// viewer's code and its CSS inlined as text), so that a report opens from disk.
// Usage: node build.mjs --outfile <path/viewer.js>
import * as esbuild from 'esbuild';

const i = process.argv.indexOf('--outfile');
const outfile = i > 0 ? process.argv[i + 1] : 'dist/viewer.js';

await esbuild.build({
  entryPoints: ['src/main.js'],
  bundle: true,
  format: 'iife',
  minify: true,
  target: ['es2020'],
  loader: { '.css': 'text' },
  legalComments: 'eof',
  logLevel: 'warning',
  outfile,
});
console.log(`viewer bundle written to ${outfile}`);
