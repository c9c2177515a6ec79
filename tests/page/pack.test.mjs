// The package as a web developer gets it: `npm pack`, installed into a fresh app outside the
// repo, served as static files, <ruled-view scene="striction" controls> from 'ruledlab/view'
// draws with its controls; a Vite app built from the tarball runs; and in the production builds
// of Vite and of webpack 5, with no configuration, the large model refines in the worker (seen in
// the worker's own timeline), and where a policy forbids workers the page says so once.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';
import webpack from 'webpack';
import { startServer } from '../../scripts/serve.mjs';
import { launch, watch, ARTIFACTS } from './browser.mjs';
import { decodePng, countDifferent } from './png.mjs';
import { everyElementCold } from './cold.mjs';

const REPO = fileURLToPath(new URL('../..', import.meta.url));
const BACKGROUND = [251, 250, 247];
let browser, tarball;

before(async () => {
  browser = await launch();
  const dir = mkdtempSync(join(tmpdir(), 'ruledlab-pack-'));
  const out = JSON.parse(
    execFileSync('npm', ['pack', '--json', '--pack-destination', dir], { cwd: REPO, encoding: 'utf8' }),
  );
  tarball = join(dir, out[0].filename);
  const files = out[0].files.map((f) => f.path);
  for (const need of [
    'www/index.js',
    'www/view.js',
    'pkg/view/www/index.d.ts',
    'pkg/ruledlab.d.ts',
    'www/ruled-view.js',
    'www/worker.js',
    'pkg/ruledlab_bg.wasm',
    'dist/ruledlab.html',
    'dist/ruledlab-embed.js',
    'www/course/index.js',
    'pkg/zip.js',
  ]) {
    assert.ok(files.includes(need), `the package lacks ${need}`);
  }
  assert.ok(
    !files.some((f) => f.startsWith('src/') || f.startsWith('tests/') || f.startsWith('target/')),
    'the package ships sources or tests',
  );
  // the element and what it needs, not the page's shell (its header, Share, the author, the app)
  assert.deepEqual(
    files.filter((f) => f.startsWith('www/page/') || f === 'index.html'),
    [],
    'the package ships the page',
  );
});
after(async () => browser?.close());

/** A fresh app directory with the tarball installed (no network: the package has no dependencies). */
function app() {
  const dir = mkdtempSync(join(tmpdir(), 'ruledlab-app-'));
  writeFileSync(join(dir, 'package.json'), JSON.stringify({ name: 'app', private: true, type: 'module' }));
  execFileSync('npm', ['install', '--no-audit', '--no-fund', '--offline', tarball], { cwd: dir, stdio: 'ignore' });
  return dir;
}

async function check(url, name) {
  const page = await browser.newPage();
  const problems = watch(page);
  const requests = [];
  page.on('request', (r) => requests.push(r.url()));
  await page.goto(url);
  await page.waitForFunction(() => document.querySelector('ruled-view')?.dataset.ready === '1', null, {
    timeout: 30000,
  });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const png = await page.locator('ruled-view').screenshot({ path: join(ARTIFACTS, `${name}.png`) });
  const image = decodePng(png);
  assert.ok(countDifferent(image, BACKGROUND) > 0.02 * image.width * image.height, 'nothing drawn');
  const controls = await page
    .locator('ruled-view')
    .evaluate((v) => v.shadowRoot.querySelectorAll('.rl-controls input, .rl-controls select').length);
  assert.ok(controls >= 5, `only ${controls} controls`);
  assert.deepEqual(problems, []);
  return { page, requests };
}

/**
 * Type-checks `file` of the app in `dir` under tsc --strict, as a user's TypeScript project would
 * (the package's own types, no @types), with `options` added to the compiler's.
 * @param {string} dir @param {string} file @param {Record<string, unknown>} options
 */
function typeCheck(dir, file, options) {
  const compilerOptions = {
    strict: true,
    noEmit: true,
    target: 'es2022',
    module: 'esnext',
    moduleResolution: 'bundler',
    types: [],
    ...options,
  };
  writeFileSync(join(dir, 'tsconfig.json'), JSON.stringify({ compilerOptions, files: [file] }));
  execFileSync(join(REPO, 'node_modules/.bin/tsc'), ['-p', join(dir, 'tsconfig.json')], { cwd: dir, stdio: 'inherit' });
}

test('npm pack → installed in a fresh app → <ruled-view controls> from ruledlab/view draws', async () => {
  const dir = app();
  writeFileSync(
    join(dir, 'index.html'),
    `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>app</title>
<script type="importmap">{ "imports": { "ruledlab/view": "./node_modules/ruledlab/www/index.js" } }</script>
<script type="module">import 'ruledlab/view';</script>
<style>ruled-view { height: 520px; }</style></head>
<body><ruled-view scene="striction" controls></ruled-view></body></html>`,
  );
  const { server, url } = await startServer({ root: dir });
  try {
    const { page, requests } = await check(url, 'pack-static');
    assert.deepEqual(
      requests.filter((u) => !u.startsWith(url) && !u.startsWith('data:') && !u.startsWith('blob:')),
      [],
      'read from outside the app',
    );
    await page.close();
  } finally {
    server.close();
  }
});

test('a Vite app built from the tarball: the core by name and the viewer from ruledlab/view', async () => {
  const dir = app();
  writeFileSync(
    join(dir, 'index.html'),
    '<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>vite app</title><style>ruled-view { height: 520px; }</style></head><body><ruled-view scene="striction" controls></ruled-view><script type="module" src="./main.js"></script></body></html>',
  );
  writeFileSync(
    join(dir, 'main.js'),
    `import init, { AnalyticSurface } from 'ruledlab';
import 'ruledlab/view';
await init();
const helicoid = AnalyticSurface.byName('helicoid');
try {
  const s = helicoid.sample(40);
  try { document.body.dataset.delta = String(s.invariants().distribution[0]); } finally { s.free(); }
} finally { helicoid.free(); }
`,
  );
  await build({ root: dir, logLevel: 'silent', build: { outDir: join(dir, 'dist'), target: 'es2022' } });
  const assets = readdirSync(join(dir, 'dist', 'assets'));
  assert.ok(
    assets.some((f) => f.endsWith('.wasm')),
    `no wasm in ${assets}`,
  );
  const { server, url } = await startServer({ root: join(dir, 'dist') });
  try {
    const { page } = await check(url, 'pack-vite');
    assert.ok(Math.abs(Number(await page.evaluate(() => document.body.dataset.delta)) - 0.5) < 1e-12);
    await page.close();
  } finally {
    server.close();
  }
});

/**
 * A production build of the app in `dir` (its main.js) with webpack 5, no configuration beyond
 * entry and output, into `dir/dist-webpack/` with a page that loads the bundle.
 */
async function webpackBuild(/** @type {string} */ dir) {
  const out = join(dir, 'dist-webpack');
  const stats = await new Promise((resolve, reject) =>
    webpack({ mode: 'production', context: dir, entry: './main.js', output: { path: out } }, (err, s) =>
      err ? reject(err) : resolve(s),
    ),
  );
  assert.ok(!stats.hasErrors(), stats.toString({ all: false, errors: true }));
  writeFileSync(
    join(out, 'index.html'),
    `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>webpack app</title><style>ruled-view { height: 520px; }</style></head><body>${LARGE}<script src="main.js"></script></body></html>`,
  );
  return out;
}

/** A model above the worker's threshold: 10 000 rulings refined three times (79 993 rulings). */
const LARGE = '<ruled-view scene="large" params="n=10000&steps=3" controls></ruled-view>';
const SUBDIVIDE = 'ruledlab:core:RuledSurface.subdivide';

/**
 * Opens the built app at `url` (served with `headers`) and waits for the refined model; returns
 * where the core subdivided (its User Timing measure is set in the timeline of the thread that
 * called it: the page's, or a worker's), the workers that started and what the console said.
 */
async function refineIn(/** @type {string} */ root, /** @type {Record<string, string>} */ headers = {}) {
  const { server, url } = await startServer({ root, headers });
  const page = await browser.newPage();
  const problems = watch(page);
  /** @type {string[]} */
  const warnings = [];
  page.on('console', (m) => m.type() === 'warning' && /ruledlab/.test(m.text()) && warnings.push(m.text()));
  /** @type {import('playwright-core').Worker[]} */
  const workers = [];
  page.on('worker', (w) => workers.push(w));
  try {
    await page.goto(url);
    await page.waitForFunction(
      () =>
        /79[\s,.]?993/.test(
          document.querySelector('ruled-view')?.shadowRoot?.querySelector('.rl-readout')?.textContent ?? '',
        ),
      null,
      { timeout: 120000 },
    );
    const inWorkers = await Promise.all(
      workers.map((w) => w.evaluate((name) => performance.getEntriesByName(name).length, SUBDIVIDE).catch(() => 0)),
    );
    return {
      page: await page.evaluate((name) => performance.getEntriesByName(name).length, SUBDIVIDE),
      worker: inWorkers.reduce((a, b) => a + b, 0),
      workers: workers.map((w) => w.url()),
      warnings,
      problems,
    };
  } finally {
    await page.close();
    server.close();
  }
}

test('the worker in every bundle: Vite 8 and webpack 5 production builds of the tarball refine in the worker; where none may start, the page says so once', async () => {
  const dir = app();
  writeFileSync(
    join(dir, 'index.html'),
    `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>vite app</title><style>ruled-view { height: 520px; }</style></head><body>${LARGE}<script type="module" src="./main.js"></script></body></html>`,
  );
  writeFileSync(join(dir, 'main.js'), "import 'ruledlab/view';\n");
  const vite = join(dir, 'dist-vite');
  mkdirSync(vite);
  await build({ root: dir, logLevel: 'silent', build: { outDir: vite, target: 'es2022' } });
  const builds = { vite, webpack: await webpackBuild(dir) };
  for (const [bundler, root] of Object.entries(builds)) {
    const got = await refineIn(root);
    assert.equal(got.workers.length, 1, `${bundler}: workers ${got.workers}`);
    assert.ok(
      !got.workers[0].startsWith('data:') && !got.workers[0].startsWith('blob:'),
      `${bundler}: ${got.workers[0]}`,
    );
    assert.ok(got.worker > 0, `${bundler}: the core did not subdivide in the worker`);
    assert.equal(got.page, 0, `${bundler}: the core subdivided on the main thread`);
    assert.deepEqual(got.warnings, [], bundler);
    assert.deepEqual(got.problems, [], bundler);
  }
  // a page whose policy allows no worker: the same model refines on the main thread, and the page
  // says so in the console once (the browser reports the refused worker itself)
  const blocked = await refineIn(builds.vite, {
    'content-security-policy':
      "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:; worker-src 'none'",
  });
  assert.ok(blocked.page > 0, 'the refinement did not run on the main thread');
  assert.equal(blocked.warnings.length, 1, blocked.warnings.join('\n'));
  assert.match(blocked.warnings[0], /no Web Worker could start here/);
  assert.deepEqual(
    blocked.problems.filter((p) => !/worker/i.test(p)),
    [],
  );
});

test('a TypeScript app typed by the installed tarball: tsc --strict resolves ruledlab and ruledlab/view by the package exports', () => {
  const dir = app();
  writeFileSync(
    join(dir, 'main.ts'),
    `import init, { AnalyticSurface, type Invariants, type SubdivideOptions } from 'ruledlab';
import { Stage, SCENES, type Scene, type SceneChangeDetail, type CameraChangeDetail } from 'ruledlab/view';
await init();
const view = document.createElement('ruled-view');
view.scene = 'striction';
view.addEventListener('scene-change', (e) => { const d: SceneChangeDetail = e.detail; console.log(d.scene, d.params); });
view.addEventListener('camera-change', (e) => { const d: CameraChangeDetail = e.detail; console.log(d.camera.split(',').length); });
view.addEventListener('error', (e) => console.log(e.detail.code));
const helicoid = AnalyticSurface.byName('helicoid');
const options: SubdivideOptions = { scheme: 'four-point', steps: 2 };
const s = helicoid.sample(12).subdivide(options);
const inv: Invariants = s.invariants();
const scene: Scene = SCENES[0];
const stage = new Stage(document.body, { controls: true });
await stage.open(scene, {});
stage.viewer.fit();
console.log(inv.distribution.length, view.exportSVG({ bw: true }).length);
// what is not API stays out of the types
// @ts-expect-error the Stage's DOM is internal
stage.legend;
// @ts-expect-error a wrong option is a type error
s.subdivide({ scheme: 'cubic' });
`,
  );
  typeCheck(dir, 'main.ts', { skipLibCheck: false, lib: ['es2022', 'dom', 'esnext.disposable'] });
});

test('ruledlab/course from the installed tarball in Node: a SCORM 2004 package and an .h5p file, typed', () => {
  const dir = app();
  writeFileSync(
    join(dir, 'course.mjs'),
    `import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { scormPackage, h5pPackage, readScorm, readH5p } from 'ruledlab/course';
const require = createRequire(import.meta.url);
const page = readFileSync(require.resolve('ruledlab/ruledlab.html'), 'utf8');
const script = readFileSync(require.resolve('ruledlab/embed'), 'utf8');
const zip = await scormPackage(['torsal-pair', 'chaikin-count'], { standard: 'scorm2004', page });
const h5p = await h5pPackage('hypar-distribution', { script, lang: 'de' });
console.log(JSON.stringify({ scorm: readScorm(zip).tasks.map((t) => t.id), standard: readScorm(zip).standard, h5p: readH5p(h5p).task.id }));
`,
  );
  const out = JSON.parse(execFileSync('node', ['course.mjs'], { cwd: dir, encoding: 'utf8' }));
  assert.deepEqual(out, { scorm: ['torsal-pair', 'chaikin-count'], standard: 'scorm2004', h5p: 'hypar-distribution' });
  writeFileSync(
    join(dir, 'course.ts'),
    `import { scormPackage, type PackageError } from 'ruledlab/course';
const zip: Uint8Array = await scormPackage(['torsal-pair'], { standard: 'scorm12', page: '<html></html>' });
let e: PackageError | null = null;
console.log(zip.length, e);
// @ts-expect-error a standard ruledlab does not write
await scormPackage(['torsal-pair'], { standard: 'aicc' });
`,
  );
  typeCheck(dir, 'course.ts', { lib: ['es2022', 'dom'] });
});

test('every figure and scene in <ruled-view>, cold, from the installed tarball (ruledlab/view)', async () => {
  const dir = app();
  const { server, url } = await startServer({ root: dir });
  let n = 0;
  try {
    await everyElementCold(
      browser,
      (elements) => {
        const name = `cold-${++n}.html`;
        writeFileSync(
          join(dir, name),
          `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>cold</title>
<script type="importmap">{ "imports": { "ruledlab/view": "./node_modules/ruledlab/www/index.js" } }</script>
<script type="module">import 'ruledlab/view';</script></head><body>${elements}</body></html>`,
        );
        return url + name;
      },
      (u) => u.startsWith(url) || u.startsWith('data:') || u.startsWith('blob:'),
    );
  } finally {
    server.close();
  }
});
