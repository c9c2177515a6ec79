// The sizes of what the build makes, measured one way for the build's guard, the book and its
// test: each wasm module raw and gzipped, the one-file page and the embed script, what the
// production page's first scene loads. `node scripts/sizes.mjs` (build.sh runs it) prints them
// and fails where a module is over its limit; `--write` also writes them into the book's `sizes`
// block (docs/src/internals/sizes.md), which tests/node/sizes.test.mjs holds to the build within
// 1 KiB. The limits are here and nowhere else.
import { readFileSync } from 'node:fs';
import { brotliCompressSync, constants, gzipSync } from 'node:zlib';
import { rewriteBlock } from './doc-block.mjs';

const ROOT = new URL('../', import.meta.url);

/** The most each module may weigh gzipped, in KiB. */
export const LIMITS_KIB = /** @type {const} */ ({ teaching: 300, cam: 300 });

/**
 * One measured thing: its name in the book, the file (or files) and its bytes raw, gzipped
 * (level 9) and with brotli (quality 11).
 * @typedef {{key: string, what: string, file: string, raw: number, gzip: number, brotli: number}} Size
 */

/** @param {string} file */
const bytes = (file) => readFileSync(new URL(file, ROOT));

/** @param {string} key @param {string} what @param {string[]} files @returns {Size} */
function measure(key, what, files) {
  const parts = files.map(bytes);
  const sum = (/** @type {(b: Buffer) => number} */ f) => parts.reduce((s, b) => s + f(b), 0);
  return {
    key,
    what,
    file: files.length === 1 ? files[0] : `${files.length} files of dist/web/`,
    raw: sum((b) => b.length),
    gzip: sum((b) => gzipSync(b, { level: 9 }).length),
    brotli: sum(
      (b) =>
        brotliCompressSync(b, {
          params: { [constants.BROTLI_PARAM_QUALITY]: 11, [constants.BROTLI_PARAM_SIZE_HINT]: b.length },
        }).length,
    ),
  };
}

/** Measures the build in `pkg/` and `dist/`. @returns {Size[]} */
export function measureBuild() {
  const manifest = JSON.parse(bytes('dist/web-manifest.json').toString());
  // its entry and the chunks it imports, the teaching module and the page's stylesheet
  const style = Object.keys(manifest.sizes).filter((f) => /^assets\/style-[\w-]+\.css$/.test(f));
  const first = [...manifest.initial, manifest.wasm, ...style].map((/** @type {string} */ f) => `dist/web/${f}`);
  return [
    measure('teaching', 'the teaching module (wasm)', ['pkg/ruledlab_bg.wasm']),
    measure('cam', 'the CAM module (wasm), loaded when first asked for', ['pkg/cam/ruledlab_cam_bg.wasm']),
    measure('first-scene', "the production page's first scene: its scripts, stylesheet and the teaching module", first),
    measure('onefile', 'the one-file page', ['dist/ruledlab.html']),
    measure('embed', 'the embed script', ['dist/ruledlab-embed.js']),
  ];
}

const kib = (/** @type {number} */ n) => Math.round(n / 1024);

/** The book's table of `sizes`. @param {Size[]} sizes */
export function table(sizes) {
  return [
    '| what | file | raw | gzipped | brotli |',
    '|---|---|---:|---:|---:|',
    ...sizes.map(
      (s) => `| ${s.what} | \`${s.file}\` | ${kib(s.raw)} KiB | ${kib(s.gzip)} KiB | ${kib(s.brotli)} KiB |`,
    ),
  ].join('\n');
}

/** The numbers of the book's table, by row, in KiB: [raw, gzip, brotli]. @param {string} text */
export function readTable(text) {
  return [...text.matchAll(/^\| (.+?) \| `[^`]+` \| (\d+) KiB \| (\d+) KiB \| (\d+) KiB \|$/gm)].map((m) => ({
    what: m[1],
    kib: [Number(m[2]), Number(m[3]), Number(m[4])],
  }));
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const sizes = measureBuild();
  for (const s of sizes)
    console.log(`sizes: ${s.what}: ${kib(s.raw)} KiB, ${kib(s.gzip)} KiB gzipped, ${kib(s.brotli)} KiB with brotli`);
  if (process.argv.includes('--write') && rewriteBlock('sizes', table(sizes)))
    console.log('sizes: the book’s table rewritten (docs/src/internals/sizes.md)');
  const over = sizes.filter(
    (s) => s.key in LIMITS_KIB && s.gzip > LIMITS_KIB[/** @type {keyof typeof LIMITS_KIB} */ (s.key)] * 1024,
  );
  for (const s of over)
    console.error(
      `sizes: ${s.what} is ${kib(s.gzip)} KiB gzipped, over its limit of ${LIMITS_KIB[/** @type {keyof typeof LIMITS_KIB} */ (s.key)]} KiB`,
    );
  if (over.length) process.exit(1);
}
