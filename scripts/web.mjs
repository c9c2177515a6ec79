// Builds the production page into dist/web/ (after scripts/build.sh has built pkg/ and
// scripts/onefile.mjs the one-file builds), the site `npm start` serves:
//   index.html              the page, its references rewritten to the hashed files, its body the
//                           page's shell (www/page/shell.js: header, stage, the linked scene's
//                           heading) and its head the few inline lines that choose that heading
//                           before the first paint (allowed by their hash in the page's policy)
//   assets/                 every file named by its content's hash (cached for a year):
//     main-<hash>.js          the page's entry, bundled and minified with esbuild, and the
//     chunk-<hash>.js         chunks it shares with what loads on demand (split at the page's
//                             dynamic imports: the other language, the Share dialog, the
//                             figure exports, the exercise author); boot-<hash>.js the
//                             classic start-up message
//     worker-<hash>.js        the refinement worker, one module
//     ruledlab_bg-<hash>.wasm the core (fetched and compiled by WebAssembly.instantiateStreaming)
//     style-, noscript-, favicon-<hash>.*  (style: the page's and the view's, ui/css.js)
//   dist/                   the one-file page, its embed script and manifest, at the paths the
//                           page asks for them (the Share dialog), not hashed: they are handed out
// and beside every file its gzip (.gz) and brotli (.br) compression, which scripts/serve.mjs
// sends to browsers that accept it. What the first scene needs and what loads later is written
// to dist/web-manifest.json (the build's test reads it). A file whose hashed name and
// compressions are already there is not compressed again; files of older builds are removed.
import { build, transform } from 'esbuild';
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { basename, dirname, extname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { brotliCompressSync, constants, gzipSync } from 'node:zlib';
import { shellHtml, firstScript } from '../www/page/shell.js';
import { CSS } from '../www/ui/css.js';

const ROOT = resolve(fileURLToPath(new URL('..', import.meta.url)));
const OUT = join(ROOT, 'dist/web');
const ASSETS = join(OUT, 'assets');
/** The modules loaded on demand (by a dynamic import), by what they are: the test checks that
 * the first scene requests none of them. */
const LAZY = {
  'the other language': ['www/i18n/de/index.js'],
  'the Share dialog': ['www/page/share.js'],
  'the figure exports': ['www/export/svg.js', 'www/export/tikz.js', 'www/export/png.js'],
  'the exercise author': ['www/page/author.js'],
  'the course packages and a package page': ['www/page/packages.js', 'www/page/course.js'],
  // the second wasm module and its glue: tool paths, machines, G-code (cam.js)
  'the CAM module': ['pkg/cam/ruledlab_cam.js'],
};
/** `new URL(…, import.meta.url)` targets the bundles may keep as they are, and why. */
const UNUSED = {
  // share.js's snippet script when no manifest is served; the site serves dist/manifest.json
  'www/index.js': 'the site serves dist/manifest.json',
};
/** Files (of the site) not worth compressing. */
const BINARY = new Set(['.png', '.jpg', '.ico', '.gz', '.br']);

/** The first 8 hex digits of the SHA-256 of `bytes` (content hash of a file name). */
const hash = (/** @type {Uint8Array | string} */ bytes) =>
  createHash('sha256').update(bytes).digest('hex').slice(0, 8).toUpperCase();

mkdirSync(ASSETS, { recursive: true });
/** Paths (under dist/web/) this build wrote. */
const written = new Set();

/** Writes `bytes` to `path` under dist/web/ unless the same bytes are there. */
function put(/** @type {string} */ path, /** @type {Uint8Array | string} */ bytes) {
  const file = join(OUT, path);
  mkdirSync(dirname(file), { recursive: true });
  const data = typeof bytes === 'string' ? Buffer.from(bytes) : Buffer.from(bytes);
  if (!existsSync(file) || !readFileSync(file).equals(data)) {
    writeFileSync(file, data);
    rmSync(`${file}.gz`, { force: true });
    rmSync(`${file}.br`, { force: true });
  }
  written.add(path);
}

/** Copies a repository file into assets/ under its hashed name; returns the path under dist/web/. */
function hashed(
  /** @type {string} */ source,
  /** @type {Uint8Array | string} */ bytes = readFileSync(join(ROOT, source)),
) {
  const ext = extname(source);
  const path = `assets/${basename(source, ext)}-${hash(bytes)}${ext}`;
  put(path, bytes);
  return path;
}

// the core's two modules, then the worker (it names their files), then the page (it names all)
const wasm = hashed('pkg/ruledlab_bg.wasm');
const camWasm = hashed('pkg/cam/ruledlab_cam_bg.wasm');
/** Where each `new URL(…, import.meta.url)` target of the sources is in the site, from assets/. */
const urls = new Map([
  [join(ROOT, 'pkg/ruledlab_bg.wasm'), `./${basename(wasm)}`],
  [join(ROOT, 'pkg/cam/ruledlab_cam_bg.wasm'), `./${basename(camWasm)}`],
  [join(ROOT, 'dist/manifest.json'), '../dist/manifest.json'],
  [join(ROOT, 'dist/ruledlab.html'), '../dist/ruledlab.html'],
  [join(ROOT, 'dist/ruledlab-embed.js'), '../dist/ruledlab-embed.js'],
]);

/**
 * Rewrites the `new URL('…', import.meta.url)` of every bundled source to where its target is
 * in the site (every chunk is in assets/); a target the site does not have fails the build.
 * @type {import('esbuild').Plugin}
 */
const siteUrls = {
  name: 'ruledlab-site-urls',
  setup(b) {
    b.onLoad({ filter: /\.js$/ }, ({ path }) => {
      const source = readFileSync(path, 'utf8');
      // (comments before the target, such as core.js's /* @vite-ignore */, are dropped)
      const contents = source.replace(
        /new URL\((?:\/\*[^*]*\*\/\s*)*(['"])([^'"]+)\1,\s*import\.meta\.url\)/g,
        (/** @type {string} */ whole, /** @type {string} */ quote, /** @type {string} */ target) => {
          const absolute = resolve(dirname(path), target);
          const mapped = urls.get(absolute);
          if (mapped) return `new URL(${quote}${mapped}${quote}, import.meta.url)`;
          if (relative(ROOT, absolute) in UNUSED) return whole;
          throw new Error(`${relative(ROOT, path)}: new URL('${target}') is not in the site (scripts/web.mjs)`);
        },
      );
      return { contents, loader: 'js' };
    });
  },
};

/** esbuild options every bundle of the site shares. @type {import('esbuild').BuildOptions} */
const common = {
  bundle: true,
  format: 'esm',
  minify: true,
  target: 'es2022',
  legalComments: 'none',
  logLevel: 'error',
  write: false,
  metafile: true,
  plugins: [siteUrls],
};

/** The files a build wrote in memory (write: false). */
const outputs = (/** @type {import('esbuild').BuildResult} */ result) =>
  /** @type {import('esbuild').OutputFile[]} */ (result.outputFiles);

const worker = await build({ ...common, entryPoints: [join(ROOT, 'www/worker.js')], outfile: join(ASSETS, 'w.js') });
const workerFile = `assets/worker-${hash(outputs(worker)[0].contents)}.js`;
put(workerFile, outputs(worker)[0].contents);
urls.set(join(ROOT, 'www/worker.js'), `./${basename(workerFile)}`);

const page = await build({
  ...common,
  entryPoints: { main: join(ROOT, 'www/page/main.js') },
  splitting: true,
  outdir: ASSETS,
  entryNames: '[name]-[hash]',
  chunkNames: '[name]-[hash]',
});
for (const file of outputs(page)) put(relative(OUT, file.path), file.contents);
const meta = /** @type {import('esbuild').Metafile} */ (page.metafile);
const chunks = Object.fromEntries(Object.entries(meta.outputs).map(([p, o]) => [relative(OUT, resolve(ROOT, p)), o]));
// (a chunk that is imported on demand has an entryPoint too: the page's is main.js)
const entry = /** @type {string} */ (
  Object.keys(chunks).find((p) => chunks[p].entryPoint === relative(ROOT, join(ROOT, 'www/page/main.js')))
);
/** The files a chunk imports statically, itself included (what loads with it). */
const closure = (/** @type {string} */ start) => {
  const seen = new Set([start]);
  for (const file of seen)
    for (const i of chunks[file].imports)
      if (i.kind === 'import-statement' && !i.external) seen.add(relative(OUT, resolve(ROOT, i.path)));
  return [...seen];
};
const initial = closure(entry);
/** The output chunk holding the source module `source`. */
const chunkOf = (/** @type {string} */ source) =>
  Object.keys(chunks).find((p) => Object.keys(chunks[p].inputs).includes(source));

const boot = await build({ ...common, entryPoints: [join(ROOT, 'www/page/boot.js')], format: 'iife', outfile: 'b.js' });
const bootFile = `assets/boot-${hash(outputs(boot)[0].contents)}.js`;
put(bootFile, outputs(boot)[0].contents);

// the page: the repository's index.html with every reference to a file of www/ made hashed,
// and the chunks the entry imports announced at once (modulepreload: fetched in parallel
// instead of one import level after the other)
const references = {
  // the page's styles and the view's (ui/css.js, which the page then need not adopt): the shell
  // is painted styled before any script runs
  'www/page/style.css': hashed('www/page/style.css', `${readFileSync(join(ROOT, 'www/page/style.css'), 'utf8')}${CSS}`),
  'www/page/noscript.css': hashed('www/page/noscript.css'),
  'www/favicon.svg': hashed('www/favicon.svg'),
  'www/page/boot.js': bootFile,
  'www/page/main.js': entry,
};
let html = readFileSync(join(ROOT, 'index.html'), 'utf8');
for (const [from, to] of Object.entries(references)) {
  if (!html.includes(`"${from}"`)) throw new Error(`index.html does not name ${from}`);
  html = html.replaceAll(`"${from}"`, `"${to}"`);
}
// the page's shell (www/page/shell.js) in its body, and in its head the few lines that choose what
// the link asks for before the first paint, inline (allowed by their hash). Those lines also
// start the page's module, its chunks (modulepreload: fetched in parallel instead of one import
// level after the other) and the core (preloaded: compiled while it downloads) — once the shell
// is painted, so that on a slow line these 440 KiB do not share it with the stylesheet the first
// paint waits for
const module = `<script type="module" src="${entry}"></script>`;
if (!html.includes(module)) throw new Error('index.html does not load the page module');
html = html.replace(new RegExp(`\\n\\s*${module.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}`), '');
const firstLines = (
  await transform(firstScript({ wasm, entry, chunks: initial.filter((p) => p !== entry) }), {
    minify: true,
    target: 'es2020',
    legalComments: 'none',
  })
).code.trim();
const body = /<body>[\s\S]*<\/body>/;
if (!body.test(html)) throw new Error('index.html has no <body>');
html = html
  .replace(body, `<body>\n${shellHtml()}\n</body>`)
  // before the stylesheet: a script after it would wait for it (and the shell could be painted first)
  .replace(/(\n\s*<link rel="stylesheet")/, `\n  <script>${firstLines}</script>$1`)
  .replace(/<html lang="en">/, '<html lang="en" data-shell>')
  .replace(
    "script-src 'self'",
    `script-src 'self' 'sha256-${createHash('sha256').update(firstLines).digest('base64')}'`,
  );
if (!html.includes('data-shell') || !html.includes("'sha256-")) throw new Error('index.html: the shell was not put in');
if (/\bwww\//.test(html)) throw new Error('dist/web/index.html still names a file of www/');
put('index.html', html);

// the one-file builds, where the page looks for them
for (const name of ['ruledlab.html', 'ruledlab-embed.js', 'manifest.json'])
  put(`dist/${name}`, readFileSync(join(ROOT, 'dist', name)));

// gzip and brotli beside every file that compresses
let compressed = 0;
for (const path of written) {
  if (BINARY.has(extname(path))) continue;
  const file = join(OUT, path);
  if (existsSync(`${file}.gz`) && existsSync(`${file}.br`) && statSync(file).mtimeMs <= statSync(`${file}.br`).mtimeMs)
    continue;
  const bytes = readFileSync(file);
  const gz = gzipSync(bytes, { level: 9 });
  const br = brotliCompressSync(bytes, {
    params: {
      [constants.BROTLI_PARAM_QUALITY]: 11,
      [constants.BROTLI_PARAM_LGWIN]: 24,
      [constants.BROTLI_PARAM_SIZE_HINT]: bytes.length,
    },
  });
  // (a file too small to gain goes as it is)
  if (gz.length < bytes.length) writeFileSync(`${file}.gz`, gz);
  if (br.length < bytes.length) writeFileSync(`${file}.br`, br);
  compressed++;
}
// what older builds left
for (const dir of [ASSETS, join(OUT, 'dist')])
  for (const name of readdirSync(dir)) {
    const path = relative(OUT, join(dir, name)).replace(/\.(gz|br)$/, '');
    if (!written.has(path)) rmSync(join(dir, name), { force: true });
  }

/** Sizes of a file under dist/web/: raw and brotli. */
const size = (/** @type {string} */ path) => ({
  bytes: statSync(join(OUT, path)).size,
  brotli: existsSync(join(OUT, `${path}.br`)) ? statSync(join(OUT, `${path}.br`)).size : null,
});
const manifest = {
  entry,
  initial,
  wasm,
  camWasm,
  worker: workerFile,
  lazy: Object.fromEntries(
    Object.entries(LAZY).map(([what, sources]) => [
      what,
      [...new Set(sources.map((s) => chunkOf(s) ?? `(not bundled: ${s})`))],
    ]),
  ),
  sizes: Object.fromEntries([...written].sort().map((p) => [p, size(p)])),
};
writeFileSync(join(ROOT, 'dist/web-manifest.json'), `${JSON.stringify(manifest, null, 2)}\n`);
const kib = (/** @type {number} */ n) => `${(n / 1024).toFixed(0)} KiB`;
const first = [...initial, wasm, references['www/page/style.css']].map(size);
console.log(
  `build: dist/web/ (${written.size} files, ${compressed} compressed now): the first scene loads ${kib(first.reduce((s, f) => s + f.bytes, 0))}, ${kib(first.reduce((s, f) => s + (f.brotli ?? f.bytes), 0))} with brotli (JavaScript ${kib(initial.map(size).reduce((s, f) => s + (f.brotli ?? f.bytes), 0))})`,
);
