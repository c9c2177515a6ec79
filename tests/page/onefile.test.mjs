// The one-file builds: dist/ruledlab.html opened from disk (file://) works in full with no
// request but the file itself and data:/blob: URLs; dist/ruledlab-embed.js defines
// <ruled-view> from one classic script; the page downloads the current view as one file that
// opens with that view; and the unbundled page opened from disk says what to do.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { copyFileSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { gzipSync } from 'node:zlib';
import { launch, watch, shoot, ready, pageSession, showScene } from './browser.mjs';
import { countDifferent } from './png.mjs';

const REPO = fileURLToPath(new URL('../..', import.meta.url));
const ONEFILE = pathToFileURL(join(REPO, 'dist/ruledlab.html')).href;
const BACKGROUND = [251, 250, 247];
const session = pageSession();
let browser;
before(async () => (browser = await launch()));
after(async () => browser?.close());

/** Opens a file:// URL, recording problems and requests. */
async function openFile(url) {
  const page = await browser.newPage();
  const problems = watch(page);
  const requests = [];
  page.on('request', (r) => requests.push(r.url()));
  await page.goto(url);
  return { page, problems, requests };
}

const foreign = (requests, file) =>
  requests.filter((u) => !u.startsWith('data:') && !u.startsWith('blob:') && u.split('#')[0] !== file);

test('dist/ruledlab.html from disk: every scene draws, nothing is requested but the file itself', async () => {
  const html = readFileSync(join(REPO, 'dist/ruledlab.html'));
  console.log(
    `# dist/ruledlab.html: ${(html.length / 1024).toFixed(0)} KiB, ${(gzipSync(html).length / 1024).toFixed(0)} KiB gzipped`,
  );
  // the wasm modules and the worker beside the script in data blocks, never parsed as
  // JavaScript: the script the browser evaluates holds none of their text
  const text = html.toString('utf8');
  const blocks = Object.fromEntries(
    [...text.matchAll(/<script type="text\/plain" id="([a-z-]+)">([\s\S]*?)<\/script>/g)].map((m) => [m[1], m[2]]),
  );
  assert.deepEqual(Object.keys(blocks), ['ruledlab-wasm', 'ruledlab-cam-wasm', 'ruledlab-worker']);
  assert.equal(
    Buffer.from(blocks['ruledlab-wasm'], 'hex').compare(readFileSync(join(REPO, 'pkg/ruledlab_bg.wasm'))),
    0,
    'the teaching module, whole',
  );
  const script = /<script type="module" id="ruledlab-script">([\s\S]*?)<\/script>/.exec(text)?.[1] ?? '';
  assert.ok(
    script.length > 0 && script.length < blocks['ruledlab-wasm'].length / 1.5,
    `the script: ${script.length} characters`,
  );
  assert.ok(!script.includes(blocks['ruledlab-wasm'].slice(0, 4096)), 'the wasm in the script too');
  // one page from disk, walking every scene by its link (the milling scene starts the CAM module
  // from its block)
  const { page, problems, requests } = await openFile(ONEFILE);
  await ready(page);
  const scenes = await page.evaluate(() => window.ruledlab.scenes.map((s) => s.id));
  for (const id of scenes) {
    await showScene(page, `#scene=${id}`, id);
    const image = await shoot(page, `onefile-${id}`);
    assert.ok(countDifferent(image, BACKGROUND) > 0.005 * image.width * image.height, `${id} drew nothing`);
  }
  assert.deepEqual(problems, []);
  assert.deepEqual(foreign(requests, ONEFILE), []);
  await page.close();
});

test('the one-file build refines a large model in its inlined worker', async () => {
  const { page, problems, requests } = await openFile(`${ONEFILE}#scene=large&n=10000&steps=3`);
  await ready(page, 120000);
  assert.match(await page.locator('.rl-readout').innerText(), /79[\s,.]?993/);
  assert.ok(
    requests.some((u) => u.startsWith('blob:')),
    'the worker came from a blob: URL',
  );
  assert.deepEqual(problems, []);
  assert.deepEqual(foreign(requests, `${ONEFILE}#scene=large&n=10000&steps=3`.split('#')[0]), []);
  await page.close();
});

test('dist/ruledlab-embed.js: one classic script defines <ruled-view>, from disk too', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'ruledlab-embed-'));
  copyFileSync(join(REPO, 'dist/ruledlab-embed.js'), join(dir, 'ruledlab-embed.js'));
  writeFileSync(
    join(dir, 'index.html'),
    '<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>embed</title><script src="ruledlab-embed.js"></script></head><body><ruled-view id="v" scene="curves" controls></ruled-view></body></html>',
  );
  const url = pathToFileURL(join(dir, 'index.html')).href;
  const { page, problems, requests } = await openFile(url);
  await page.waitForFunction(() => document.getElementById('v').dataset.ready === '1', null, { timeout: 30000 });
  const png = await page.locator('#v').screenshot();
  const { decodePng } = await import('./png.mjs');
  const image = decodePng(png);
  assert.ok(countDifferent(image, BACKGROUND) > 0.01 * image.width * image.height);
  assert.ok(await page.locator('#v').evaluate((v) => v.shadowRoot.querySelectorAll('.rl-controls input').length > 2));
  assert.deepEqual(problems, []);
  assert.deepEqual(
    requests.filter((u) => u.startsWith('http')),
    [],
  );
  await page.close();
});

test('the page downloads the current view as one HTML file, which opens with that view', async () => {
  const { page, problems } = await session.open('#scene=curves&steps=2&w=0.0625&closed=1');
  await page.locator('#share').click();
  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('#share-onefile').click()]);
  const path = join(mkdtempSync(join(tmpdir(), 'ruledlab-view-')), 'view.html');
  await download.saveAs(path);
  await page.close();
  const opened = await openFile(pathToFileURL(path).href);
  await ready(opened.page);
  assert.equal(await opened.page.evaluate(() => window.ruledlab.stage.scene.id), 'curves');
  assert.deepEqual(await opened.page.evaluate(() => ({ ...window.ruledlab.stage.params })), {
    scheme: 'four-point',
    steps: 2,
    w: 0.0625,
    closed: true,
    levels: true,
  });
  assert.deepEqual([...problems, ...opened.problems], []);
  // downloaded again from the one-file build itself, the view survives a second round
  await opened.page.locator('#share').click();
  const [again] = await Promise.all([
    opened.page.waitForEvent('download'),
    opened.page.locator('#share-onefile').click(),
  ]);
  const path2 = join(mkdtempSync(join(tmpdir(), 'ruledlab-view-')), 'view.html');
  await again.saveAs(path2);
  await opened.page.close();
  const twice = await openFile(pathToFileURL(path2).href);
  await ready(twice.page);
  assert.equal(await twice.page.evaluate(() => window.ruledlab.stage.params.w), 0.0625);
  assert.deepEqual(twice.problems, []);
  await twice.page.close();
});

test('the unbundled page opened from disk says what to do instead of staying blank', async () => {
  const page = await browser.newPage();
  await page.goto(pathToFileURL(join(REPO, 'index.html')).href);
  await page.waitForFunction(() => /npm start/.test(document.getElementById('boot')?.textContent ?? ''));
  assert.match(await page.locator('#boot').innerText(), /dist\/ruledlab\.html/);
  await page.close();
});
