// Lighthouse on the served production page (dist/web/, `npm run build`) and on the one-file build
// (dist/ruledlab.html, served the same way), mobile and desktop profiles, three scenes: the scores,
// LCP, TBT, transfer size and requests of each, and the page's own User Timing marks (www/timing.js,
// src/wasm/timing.rs): when the wasm was compiled, when the first frame was drawn and presented,
// the time in the core, in the scenes' create() and in uploading before it, and the tasks before
// and of the first frame — so a goal missed because this machine draws WebGL in software shows as
// such. Lighthouse is installed on demand (pinned, into target/lighthouse/: not a dependency of
// the package, not needed by `npm test`). Rewrites the book's block "bench-lighthouse"
// (docs/src/internals/page-speed.md).
//
//   node bench/lighthouse.mjs [--root DIR] [--page PATH] [--onefile PATH] [--runs N] [--profiles mobile,desktop] [--json FILE] [--no-book]
//
// --root: the directory served (default dist/web); --page: the page's path in it (default: the
// directory's index.html); --onefile: the one-file build's path in it (default dist/ruledlab.html);
// --runs: runs per case (default 3), the median kept (by performance score); --json: every result.
import { execFile, execFileSync } from 'node:child_process';
import { promisify } from 'node:util';
import { cpus, loadavg, tmpdir } from 'node:os';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { startServer } from '../scripts/serve.mjs';
import { rewriteBlock } from '../scripts/doc-block.mjs';

const REPO = fileURLToPath(new URL('..', import.meta.url));
/** The Lighthouse release: 12.x runs on Node 20 (13 wants Node 22). */
const LIGHTHOUSE = '12.2.3';
const TOOLS = join(REPO, 'target/lighthouse');
const SCENES = ['striction', 'congruence', 'focal'];
/** The goals for loading on a phone. */
const GOALS = { performance: 0.9, lcp: 2500, tbt: 200, accessibility: 1, bestPractices: 1 };

const { values: args } = parseArgs({
  options: {
    root: { type: 'string', default: join(REPO, 'dist/web') },
    page: { type: 'string', default: '' },
    onefile: { type: 'string', default: 'dist/ruledlab.html' },
    runs: { type: 'string', default: '3' },
    json: { type: 'string' },
    'no-book': { type: 'boolean', default: false },
    profiles: { type: 'string', default: 'mobile,desktop' },
  },
});

/** The Lighthouse CLI, installed into target/lighthouse/ when it is not there yet. */
function lighthouseBin() {
  const bin = join(TOOLS, 'node_modules/.bin/lighthouse');
  const manifest = join(TOOLS, 'node_modules/lighthouse/package.json');
  if (!existsSync(manifest) || JSON.parse(readFileSync(manifest, 'utf8')).version !== LIGHTHOUSE) {
    console.log(`installing lighthouse@${LIGHTHOUSE} into target/lighthouse/ (for the benchmark only)`);
    mkdirSync(TOOLS, { recursive: true });
    if (!existsSync(join(TOOLS, 'package.json'))) writeFileSync(join(TOOLS, 'package.json'), '{ "private": true }\n');
    execFileSync('npm', ['install', '--no-audit', '--no-fund', '-E', `lighthouse@${LIGHTHOUSE}`], {
      cwd: TOOLS,
      stdio: 'inherit',
    });
  }
  return bin;
}

/**
 * @typedef {object} Result
 * @property {string} build
 * @property {string} profile
 * @property {string} scene
 * @property {number} performance
 * @property {number} accessibility
 * @property {number} bestPractices
 * @property {number} lcp            ms (simulated)
 * @property {number} tbt            ms (simulated)
 * @property {number} bytes          transferred
 * @property {number} requests
 * @property {number} slowdown       the profile's CPU slowdown (4 on the phone, 1 on the desktop)
 * @property {number | null} wasm    ms from navigation to the mark ruledlab:wasm-compiled (observed)
 * @property {number | null} frame   ms to ruledlab:first-frame: the first frame's draw calls made (observed)
 * @property {number | null} presented  ms to ruledlab:first-frame-presented: the next frame begun (observed)
 * @property {number} core           ms in the core's measures (ruledlab:core:…) before the first frame
 * @property {number} compute        ms in ruledlab:compute (the scenes' create(): core and buffers) before it
 * @property {number} upload         ms in ruledlab:upload (buffers and shaders to the GPU) before it
 * @property {number} frameTask      ms, the main-thread task that drew the first frame (observed)
 * @property {number} longest        ms, the longest main-thread task before that one (observed)
 * @property {boolean} frameLongest  whether the first frame's task is the load's longest (observed)
 * @property {number} simulatedLongest  ms, the longest task in Lighthouse's simulation
 * @property {number} cls            cumulative layout shift
 * @property {number} fcp            ms (simulated)
 * @property {number} longestLoad    ms, the longest main-thread task of the whole load (observed)
 * @property {number} over50         main-thread tasks over 50 ms in the load (observed)
 * @property {number} load           the machine's load average (1 min) when the run began
 */

/**
 * One Lighthouse run of `url`.
 * @param {string} bin @param {string} url @param {'mobile' | 'desktop'} profile
 */
async function run(bin, url, profile, attempts = 3) {
  for (let k = 1; ; k++) {
    try {
      return await runOnce(bin, url, profile);
    } catch (e) {
      // Chromium now and then loses its target on a busy machine: try again
      if (k >= attempts) throw e;
      console.log(`lighthouse failed (${/** @type {Error} */ (e).message.split('\n')[0]}); again`);
    }
  }
}

/** @param {string} bin @param {string} url @param {'mobile' | 'desktop'} profile */
async function runOnce(bin, url, profile) {
  const dir = mkdtempSync(join(tmpdir(), 'ruledlab-lh-'));
  const out = join(dir, 'report.json');
  try {
    // asynchronously: the server answering the browser runs in this process
    await promisify(execFile)(
      bin,
      [
        url,
        '--quiet',
        '--output=json',
        `--output-path=${out}`,
        '--only-categories=performance,accessibility,best-practices',
        '--chrome-flags=--headless=new --no-sandbox',
        ...(profile === 'desktop' ? ['--preset=desktop'] : []),
      ],
      { env: { ...process.env, CHROME_PATH: process.env.CHROME_PATH ?? '/usr/bin/chromium' }, maxBuffer: 1 << 26 },
    );
    return JSON.parse(readFileSync(out, 'utf8'));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/**
 * What the tables show of a report.
 * @param {any} report @returns {Omit<Result, 'build' | 'profile' | 'scene'>}
 */
export function summarize(report) {
  const a = report.audits;
  const c = report.categories;
  /** @type {Array<{name: string, timingType: string, startTime: number, duration?: number}>} */
  const timings = a['user-timings']?.details?.items ?? [];
  const mark = (/** @type {string} */ name) =>
    timings.find((t) => t.name === name && t.timingType === 'Mark')?.startTime ?? null;
  const frame = mark('ruledlab:first-frame');
  const before = (/** @type {string} */ prefix) =>
    timings
      .filter((t) => t.timingType === 'Measure' && t.name.startsWith(prefix))
      .filter((t) => frame === null || t.startTime <= frame)
      .reduce((sum, t) => sum + (t.duration ?? 0), 0);
  /** @type {Array<{startTime: number, duration: number}>} */
  const tasks = a['main-thread-tasks']?.details?.items ?? [];
  const drawing = tasks.find((t) => frame !== null && t.startTime <= frame && frame <= t.startTime + t.duration);
  const longest = tasks
    .filter((t) => t !== drawing && (drawing === undefined || t.startTime < drawing.startTime))
    .reduce((most, t) => Math.max(most, t.duration), 0);
  /** @type {Array<{duration: number}>} */
  const simulated = a['long-tasks']?.details?.items ?? [];
  return {
    performance: c.performance.score,
    accessibility: c.accessibility.score,
    bestPractices: c['best-practices'].score,
    lcp: a['largest-contentful-paint'].numericValue,
    tbt: a['total-blocking-time'].numericValue,
    bytes: a['total-byte-weight'].numericValue,
    requests: a['network-requests'].details.items.length,
    slowdown: report.configSettings.throttling.cpuSlowdownMultiplier,
    wasm: mark('ruledlab:wasm-compiled'),
    frame,
    presented: mark('ruledlab:first-frame-presented'),
    core: before('ruledlab:core:'),
    compute: before('ruledlab:compute'),
    upload: before('ruledlab:upload'),
    frameTask: drawing?.duration ?? 0,
    longest,
    frameLongest: !!drawing && tasks.every((t) => t.duration <= drawing.duration),
    simulatedLongest: simulated.reduce((most, t) => Math.max(most, t.duration), 0),
    cls: a['cumulative-layout-shift'].numericValue,
    fcp: a['first-contentful-paint'].numericValue,
    longestLoad: tasks.reduce((most, t) => Math.max(most, t.duration), 0),
    over50: tasks.filter((t) => t.duration > 50).length,
    load: 0,
  };
}

/** The median run of `results` by performance score. @param {Result[]} results */
const median = (results) => [...results].sort((x, y) => x.performance - y.performance)[Math.floor(results.length / 2)];

const bin = lighthouseBin();
const { server, url } = await startServer({ root: resolve(args.root) });
/** @type {Result[]} */
const results = [];
/** Every run of a case, by its median. @type {Map<Result, Result[]>} */
const runsOf = new Map();
try {
  for (const [build, path] of [
    ['page', args.page],
    ['one file', args.onefile],
  ]) {
    for (const profile of /** @type {Array<'mobile' | 'desktop'>} */ (args.profiles.split(','))) {
      for (const scene of SCENES) {
        /** @type {Result[]} */
        const runs = [];
        for (let k = 0; k < Number(args.runs); k++) {
          const load = loadavg()[0];
          const report = await run(bin, `${url}${path}#scene=${scene}`, profile);
          runs.push({ build, profile, scene, ...summarize(report), load });
        }
        const r = median(runs);
        results.push(r);
        runsOf.set(r, runs);
        console.log(
          `${build} ${profile} ${scene}: runs ${runs.map((x) => `${x.performance} (LCP ${x.lcp.toFixed(0)}, TBT ${x.tbt.toFixed(0)}, load ${x.load.toFixed(1)})`).join(', ')}; median: performance ${r.performance}, LCP ${r.lcp.toFixed(0)} ms, TBT ${r.tbt.toFixed(0)} ms, CLS ${r.cls}, ${(r.bytes / 1024).toFixed(0)} KiB in ${r.requests} requests; wasm ${r.wasm?.toFixed(0)} ms, first frame ${r.frame?.toFixed(0)} ms, presented ${r.presented?.toFixed(0)} ms, its task ${r.frameTask.toFixed(0)} ms; a11y ${r.accessibility}, best practices ${r.bestPractices}`,
        );
      }
    }
  }
} finally {
  server.close();
}
if (args.json) writeFileSync(args.json, `${JSON.stringify(results, null, 2)}\n`);

const seconds = (/** @type {number} */ x) => `${(x / 1000).toFixed(2)} s`;
const ms = (/** @type {number | null} */ x) => (x === null ? '—' : `${x.toFixed(0)} ms`);
const date = new Date().toISOString().slice(0, 10);
const mobile = results.filter((r) => r.profile === 'mobile');
/** "met" or "not met", with the cases that miss. @param {(r: Result) => boolean} ok @param {Result[]} of */
const status = (ok, of) => {
  const missed = of.filter((r) => !ok(r));
  return missed.length === 0
    ? `met in all ${of.length}`
    : `not met in ${missed.length} of ${of.length} (${missed.map((r) => `${r.build} ${r.profile} ${r.scene}`).join(', ')})`;
};
/**
 * The blocking time the first frame's task adds to TBT: where it is the longest task of the
 * load, the longest task of the simulation is that task scaled, and its excess over 50 ms counts;
 * null where another task is longer (then it cannot be told apart).
 */
const frameBlocking = (/** @type {Result} */ r) => (r.frameLongest ? Math.max(0, r.simulatedLongest - 50) : null);
const name = (/** @type {Result} */ r) => `${r.build} | ${r.profile} | ${r.scene}`;
const block = [
  `<!-- written by bench/lighthouse.mjs (npm run bench) on ${date} -->`,
  '',
  `Lighthouse ${LIGHTHOUSE} on the served production page and the one-file build, ${date}, this machine (${cpus().length} cores, headless Chromium, software WebGL). Lighthouse simulates the mobile profile (a mid-range phone: 4× CPU slowdown, slow 4G of 1.6 Mbit/s with 150 ms round trips) from one unthrottled load; LCP and TBT are its simulation.`,
  '',
  `The median of ${args.runs} runs each (by performance); the runs' scores and the machine's load average (1 min) when each began are in the last column: other work shares these 2 cores, and a loaded machine lengthens every task Lighthouse then multiplies.`,
  '',
  '| build | profile | scene | performance | FCP | LCP | TBT | CLS | transferred | requests | accessibility | best practices | runs (load) |',
  '|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|',
  ...results.map(
    (r) =>
      `| ${name(r)} | ${r.performance.toFixed(2)} | ${seconds(r.fcp)} | ${seconds(r.lcp)} | ${r.tbt.toFixed(0)} ms | ${r.cls.toFixed(3)} | ${(r.bytes / 1024).toFixed(0)} KiB | ${r.requests} | ${r.accessibility.toFixed(2)} | ${r.bestPractices.toFixed(2)} | ${(runsOf.get(r) ?? []).map((x) => `${x.performance.toFixed(2)} (${x.load.toFixed(1)})`).join(', ')} |`,
  ),
  '',
  "The page's own marks in the same loads (unthrottled, ms from navigation): the wasm compiled and instantiated; the first frame's draw calls made; the next frame begun (the GPU's part done: here SwiftShader draws, and the frame is read back for the software compositor); before the first frame the time in the core (`ruledlab:core:…`, set by the bindings), in the scenes' `create()` (core and buffers) and in uploading buffers; the main-thread task that drew the first frame, and the longest task before it. Where the first frame's task is the longest of the load, it is also the longest task of the simulation, scaled to the phone's CPU: the last column is that simulated task's blocking time (its excess over 50 ms), which it alone adds to TBT.",
  '',
  '| build | profile | scene | wasm compiled | first frame | presented | core | create() | upload | first frame task | longest task before it | its share of TBT (simulated) | longest task of the load | tasks over 50 ms |',
  '|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|',
  ...results.map(
    (r) =>
      `| ${name(r)} | ${ms(r.wasm)} | ${ms(r.frame)} | ${ms(r.presented)} | ${ms(r.core)} | ${ms(r.compute)} | ${ms(r.upload)} | ${ms(r.frameTask)} | ${ms(r.longest)} | ${ms(frameBlocking(r))} | ${ms(r.longestLoad)} | ${r.over50} |`,
  ),
  '',
  '| goal | where it stands |',
  '|---|---|',
  `| mobile performance ≥ ${GOALS.performance} | ${status((r) => r.performance >= GOALS.performance, mobile)} |`,
  `| mobile LCP ≤ ${GOALS.lcp / 1000} s | ${status((r) => r.lcp <= GOALS.lcp, mobile)} |`,
  `| mobile TBT ≤ ${GOALS.tbt} ms | ${status((r) => r.tbt <= GOALS.tbt, mobile)}; without the first frame's task: ${status((r) => r.tbt - (frameBlocking(r) ?? 0) <= GOALS.tbt, mobile)} |`,
  `| CLS 0 | ${status((r) => r.cls === 0, results)} |`,
  `| no task over 50 ms on this machine (observed) | ${status((r) => r.over50 === 0, results)} |`,
  `| accessibility 1.0 | ${status((r) => r.accessibility >= GOALS.accessibility, results)} |`,
  `| best practices 1.0 | ${status((r) => r.bestPractices >= GOALS.bestPractices, results)} |`,
].join('\n');
console.log(block);
if (!args['no-book'] && rewriteBlock('bench-lighthouse', block))
  console.log('docs/src/internals/page-speed.md: Lighthouse table rewritten');
