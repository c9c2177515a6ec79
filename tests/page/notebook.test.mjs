// ruledlab in a real JupyterLab: the example notebook (examples/notebook.ipynb) run cell by cell
// through JupyterLab's own UI, in the page tests' Chromium, with the Python package installed in
// the project's virtual environment (.venv: scripts/setup.sh --browser; scripts/test.sh installs
// the built wheel there). The views are drawn from NumPy data sent as binary buffers; a slider
// moved in a view is read in Python; parameters set from Python change the picture; figures
// arrive as files; a bad input raises RuledlabError with the core's code at once, a bad parameter
// comes from the view, which works on; an exercise's checks reach Python.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { copyFileSync, existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { randomBytes } from 'node:crypto';
import { launch, watch, ARTIFACTS } from './browser.mjs';
import { decodePng, countDifferent, countChanged } from './png.mjs';

const ROOT = new URL('../../', import.meta.url).pathname;
const JUPYTER = join(ROOT, '.venv/bin/jupyter');
const NOTEBOOK = 'notebook.ipynb';
const BACKGROUND = [251, 250, 247];

/** A free port on the loopback address. @returns {Promise<number>} */
function freePort() {
  return new Promise((resolve, reject) => {
    const server = createServer().listen(0, '127.0.0.1', () => {
      const { port } = /** @type {import('node:net').AddressInfo} */ (server.address());
      server.close(() => resolve(port));
    });
    server.on('error', reject);
  });
}

/** @type {{url: string, dir: string, stop: () => Promise<void>, log: () => string}} */
const lab = { url: '', dir: '', stop: async () => {}, log: () => '' };
/** @type {import('playwright-core').BrowserContext | null} */
let browser = null;

before(async () => {
  assert.ok(existsSync(JUPYTER), `${JUPYTER} is missing: run bash scripts/setup.sh --browser`);
  const dir = mkdtempSync(join(tmpdir(), 'ruledlab-lab-'));
  const home = (/** @type {string} */ name) => {
    const d = join(dir, '.jupyter', name);
    mkdirSync(d, { recursive: true });
    return d;
  };
  const work = join(dir, 'work');
  mkdirSync(work);
  copyFileSync(join(ROOT, 'examples', NOTEBOOK), join(work, NOTEBOOK));
  // no news, no update checks: JupyterLab asks no website for anything
  const settings = home('settings');
  mkdirSync(join(settings, '@jupyterlab/apputils-extension'), { recursive: true });
  writeFileSync(
    join(settings, '@jupyterlab/apputils-extension/notification.jupyterlab-settings'),
    JSON.stringify({ fetchNews: 'false', checkForUpdates: false }),
  );
  const port = await freePort();
  const token = randomBytes(16).toString('hex');
  const env = {
    ...process.env,
    JUPYTER_CONFIG_DIR: home('config'),
    JUPYTER_RUNTIME_DIR: home('runtime'),
    JUPYTERLAB_SETTINGS_DIR: settings,
    JUPYTERLAB_WORKSPACES_DIR: home('workspaces'),
    IPYTHONDIR: home('ipython'),
  };
  let output = '';
  const child = spawn(
    JUPYTER,
    [
      'lab',
      '--no-browser',
      // (the test machine runs as root)
      '--allow-root',
      '--ip=127.0.0.1',
      `--port=${port}`,
      '--port-retries=0',
      `--ServerApp.token=${token}`,
      `--ServerApp.root_dir=${work}`,
      '--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate',
    ],
    { env, detached: true, stdio: ['ignore', 'pipe', 'pipe'] },
  );
  child.stdout.on('data', (d) => (output += d));
  child.stderr.on('data', (d) => (output += d));
  const exited = new Promise((resolve) => child.on('exit', resolve));
  lab.log = () => output;
  lab.stop = async () => {
    // the server and its kernels: the whole process group
    try {
      process.kill(-(/** @type {number} */ (child.pid)), 'SIGTERM');
    } catch {}
    await Promise.race([exited, new Promise((r) => setTimeout(r, 5000))]);
    try {
      process.kill(-(/** @type {number} */ (child.pid)), 'SIGKILL');
    } catch {}
    rmSync(dir, { recursive: true, force: true });
  };
  lab.dir = work;
  lab.url = `http://127.0.0.1:${port}`;
  const t0 = Date.now();
  for (;;) {
    const ok = await fetch(`${lab.url}/api/status?token=${token}`)
      .then((r) => r.ok)
      .catch(() => false);
    if (ok) break;
    if (Date.now() - t0 > 60000 || child.exitCode !== null)
      throw new Error(`JupyterLab did not start:\n${output.slice(-3000)}`);
    await new Promise((r) => setTimeout(r, 250));
  }
  lab.url = `${lab.url}/lab/tree/${NOTEBOOK}?reset&token=${token}`;
  browser = await launch({ viewport: { width: 1280, height: 1000 } });
});

after(async () => {
  await browser?.close();
  await lab.stop();
});

/** @param {import('playwright-core').Locator} locator @param {string} name */
async function grab(locator, name) {
  const png = await locator.screenshot();
  mkdirSync(ARTIFACTS, { recursive: true });
  writeFileSync(join(ARTIFACTS, `${name}.png`), png);
  return decodePng(png);
}

test('the example notebook runs in JupyterLab, with data both ways', { timeout: 600000 }, async () => {
  if (!browser) throw new Error('no browser');
  const page = await browser.newPage();
  const problems = watch(page);
  await page.goto(lab.url);
  const cells = page.locator('.jp-NotebookPanel:not(.lm-mod-hidden) .jp-Notebook .jp-Cell');
  await cells.first().waitFor({ timeout: 120000 });
  // the kernel is up
  await page.waitForSelector('.jp-Notebook-ExecutionIndicator[data-status="idle"]', { timeout: 120000 });

  // every cell is there (JupyterLab renders a long notebook in steps)
  const count = JSON.parse(readFileSync(join(ROOT, 'examples', NOTEBOOK), 'utf8')).cells.length;
  await page.waitForFunction(
    (n) => document.querySelectorAll('.jp-NotebookPanel:not(.lm-mod-hidden) .jp-Notebook .jp-Cell').length === n,
    count,
    { timeout: 60000 },
  );
  /** Runs cell `i` as a person does (click it, Shift+Enter) and waits until it has run; returns its output's text. */
  const run = async (/** @type {number} */ i, /** @type {RegExp} */ source) => {
    const cell = cells.nth(i);
    await cell.scrollIntoViewIfNeeded();
    assert.match(await cell.locator('.jp-InputArea-editor').innerText(), source, `cell ${i} is not the one expected`);
    await cell.locator('.jp-InputArea-prompt').click();
    await page.keyboard.press('Shift+Enter');
    await page.waitForFunction(
      (el) => /^\[\d+\]:$/.test(el?.textContent?.trim() ?? ''),
      await cell.locator('.jp-InputArea-prompt').elementHandle(),
      { timeout: 120000 },
    );
    return cell.locator('.jp-OutputArea').innerText();
  };
  /** The <ruled-view> of cell `i`, once it has drawn. */
  const viewOf = async (/** @type {number} */ i) => {
    const view = cells.nth(i).locator('ruled-view');
    await view.waitFor({ timeout: 60000 });
    await page.waitForFunction(
      (v) => v?.getAttribute('data-ready') === '1' && Number(v.getAttribute('data-frames')) > 0,
      await view.elementHandle(),
      { timeout: 60000 },
    );
    return view;
  };
  const canvas = (/** @type {import('playwright-core').Locator} */ view) => view.locator('canvas').first();
  assert.ok(count >= 20, `the notebook has ${count} cells`);

  try {
    await run(1, /from ruledlab import View/);
    // the invariants computed by the core, in Python
    assert.match(await run(3, /\.invariants\(\)/), /^δ = -1\.463709 ± /m);
    // your rulings from NumPy: drawn
    await run(5, /View\.from_segments\(a, b, editable=True/);
    const surface = await viewOf(5);
    const drawn = await grab(canvas(surface), 'notebook-surface');
    assert.ok(countDifferent(drawn, BACKGROUND) > 0.02 * drawn.width * drawn.height, 'the rulings are drawn');
    // the rulings came through as they were sent, bit for bit, and the readouts arrive in Python
    const back = await run(6, /surface\.data/);
    assert.match(back, /\(48, 3\) True True/);
    assert.match(back, /: \d/, 'the readouts arrive in Python');

    // a slider moved in the view is read in Python
    await run(8, /scene="isometry"/);
    const bending = await viewOf(8);
    const before = await grab(canvas(bending), 'notebook-bending');
    const slider = bending.locator('.rl-controls input[name="t"]');
    await slider.scrollIntoViewIfNeeded();
    await slider.focus();
    for (let k = 0; k < 10; k++) await slider.press('ArrowRight');
    const moved = Number(await slider.inputValue());
    assert.ok(Math.abs(moved - 0.35) < 1e-9, `the slider moved to ${moved}`);
    await page.waitForTimeout(500);
    assert.match(await run(9, /bending\.params\["t"\]/), new RegExp(`t = ${moved}\\b`));

    // parameters set from Python change the picture and the slider
    const shown = await grab(canvas(bending), 'notebook-bending-moved');
    assert.ok(countChanged(before, shown) > 500, 'moving the slider changed the picture');
    assert.match(await run(11, /bending\.params = \{"t": 0\.9/), /t = 0\.9 {2}n = 40/);
    await page.waitForTimeout(300);
    const after = await grab(canvas(bending), 'notebook-bending-python');
    assert.ok(countChanged(shown, after) > 500, 'the parameters from Python changed the picture');
    assert.equal(Number(await slider.inputValue()), 0.9);

    // figures as files
    const figures = await run(13, /await bending\.svg/);
    assert.match(figures, /^\d+ \d+ b'\\x89PNG'/m);
    const svg = readFileSync(join(lab.dir, 'bending.svg'), 'utf8');
    assert.match(svg, /^<\?xml[\s\S]*<svg[\s\S]*<\/svg>\s*$/);
    assert.match(readFileSync(join(lab.dir, 'bending.tex'), 'utf8'), /\\begin\{tikzpicture\}/);

    // a bad input: RuledlabError with the core's code, at once; a bad parameter: from the view,
    // which works on
    assert.match(await run(15, /View\.from_segments\(a, a\)/), /^degenerate \| .*zero length/m);
    assert.match(await run(16, /bad\[2, 1\] = np\.nan/), /^not-finite 2 \| /m);
    assert.match(await run(17, /"t": "half"/), /^invalid-argument t \| /m);
    await page.waitForTimeout(300);
    const worksOn = await grab(canvas(bending), 'notebook-bending-after-error');
    assert.ok(countDifferent(worksOn, BACKGROUND) > 0.02 * worksOn.width * worksOn.height);

    // a congruence from NumPy, with its focal surfaces
    assert.match(await run(19, /\.focal\(\)/), /elliptic, hyperbolic, parabolic lines: \[/);
    await run(20, /View\.from_grid\(p, q/);
    const lines = await grab(canvas(await viewOf(20)), 'notebook-congruence');
    assert.ok(countDifferent(lines, BACKGROUND) > 0.02 * lines.width * lines.height);

    // an exercise: its checks reach Python
    await run(22, /task="striction-accuracy"/);
    const exercise = await viewOf(22);
    const n = exercise.locator('.rl-controls input[name="n"]');
    await n.scrollIntoViewIfNeeded();
    // N = 100 meets every tolerance the exercise draws (5·10⁻⁴ at the tightest)
    await n.fill('100');
    await n.dispatchEvent('change');
    const check = exercise.locator('.rl-task-check');
    await check.click();
    await page.waitForTimeout(500);
    assert.match(await run(23, /checks/), /\('check', True, 1, 1\)/);
    // a figure left as a cell's last line shows in its output when it arrives
    await run(25, /^bending\.png\(scale=1\)$/);
    const image = cells.nth(25).locator('.jp-OutputArea img');
    await image.waitFor({ timeout: 30000 });
    assert.ok((await image.evaluate((img) => /** @type {HTMLImageElement} */ (img).naturalWidth)) > 200);
    // the striction polygon the view computed is the one the core computed in Python
    assert.match(await run(27, /await surface\.layers\(\)/), /^\(2\d, 3\) True$/m);
    await grab(page.locator('.jp-NotebookPanel:not(.lm-mod-hidden)'), 'notebook-page');
    // what the cells printed, for people to read
    const outputs = [];
    for (let i = 0; i < count; i++) {
      const area = cells.nth(i).locator('.jp-OutputArea');
      if (await area.count()) outputs.push(`[${i}] ${await area.evaluate((e) => e.textContent)}`);
    }
    writeFileSync(join(ARTIFACTS, 'notebook-outputs.txt'), outputs.join('\n'));
    assert.deepEqual(
      problems.filter((p) => !/favicon|api\/(kernels|sessions|lab)/.test(p)),
      [],
    );
  } catch (e) {
    await page.screenshot({ path: join(ARTIFACTS, 'notebook-failure.png') }).catch(() => {});
    console.log(lab.log().slice(-4000));
    throw e;
  }
});
