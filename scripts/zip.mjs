// Writes pkg/zip.js: fflate's zip writer and reader (npm "fflate", MIT), bundled by esbuild into
// one small ES module that the page, <ruled-view>'s package builders (www/course/) and Node import
// as a relative file — the unbundled page and the npm package have no bare module names to resolve.
// Its declarations (pkg/zip.d.ts) are fflate's own, re-exported.
// Usage: node scripts/zip.mjs
import { build } from 'esbuild';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
const NAMES = ['zipSync', 'unzipSync', 'strToU8', 'strFromU8'];
const { version } = JSON.parse(readFileSync(`${ROOT}node_modules/fflate/package.json`, 'utf8'));
const copyright = /Copyright[^\n]*/.exec(readFileSync(`${ROOT}node_modules/fflate/LICENSE`, 'utf8'))?.[0] ?? '';
const out = await build({
  stdin: { contents: `export { ${NAMES.join(', ')} } from 'fflate';`, resolveDir: ROOT, loader: 'js' },
  bundle: true,
  format: 'esm',
  platform: 'browser',
  minify: true,
  write: false,
  target: 'es2022',
  legalComments: 'none',
  logLevel: 'error',
});
const banner = `// fflate ${version} (https://github.com/101arrowz/fflate), MIT License, ${copyright}: ${NAMES.join(', ')}, bundled by scripts/zip.mjs\n`;
mkdirSync(`${ROOT}pkg`, { recursive: true });
writeFileSync(`${ROOT}pkg/zip.js`, banner + out.outputFiles[0].text);
// the types: fflate's declarations of these functions and of what they take
const types = readFileSync(`${ROOT}node_modules/fflate/esm/browser.d.ts`, 'utf8');
writeFileSync(
  `${ROOT}pkg/zip.d.ts`,
  `// fflate ${version}'s declarations (MIT), as scripts/zip.mjs found them\n${types}`,
);
console.log(`zip: pkg/zip.js ${(out.outputFiles[0].text.length / 1024).toFixed(0)} KiB (fflate ${version})`);
