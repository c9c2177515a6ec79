// The production build (`npm run build` → dist/web/, scripts/web.mjs) as `npm start` serves it
// (scripts/serve.mjs): what the build must contain, checked without timing anything (the
// benchmark, bench/lighthouse.mjs, measures speed). Every file has its gzip and brotli beside it
// and is sent compressed as the browser accepts, with Vary and the right type; hashed names are
// cached for a year, the rest revalidated; the first scene requests only the page, its entry
// and the chunks the entry imports, the stylesheet, the icon and the wasm (once, compiled by
// WebAssembly.instantiateStreaming) — not the other language, the Share dialog, the exercise
// author, the figure exports or the worker, which load when first used; every scene draws from the bundle; and the
// page works in a sandboxed frame of a course system. The other page tests use the unbundled
// page (npm run dev): they test what the page does, and their failures point at www/'s lines.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { request } from 'node:http';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { brotliDecompressSync, gunzipSync } from 'node:zlib';
import { startServer, SITE } from '../../scripts/serve.mjs';
import { launch, watch, ready, framesAfter, shoot, showScene } from './browser.mjs';
import { otherOrigin, hostPage, drawnShare } from './places.mjs';
import { countDifferent } from './png.mjs';

const REPO = fileURLToPath(new URL('../..', import.meta.url));
/** What the build wrote (scripts/web.mjs): the entry, its chunks, the wasm, what loads later. */
const MANIFEST = JSON.parse(readFileSync(join(REPO, 'dist/web-manifest.json'), 'utf8'));
const BACKGROUND = [251, 250, 247];
const site = otherOrigin();
/** @type {import('node:http').Server} */
let server;
let url = '';
/** @type {import('playwright-core').BrowserContext} */
let browser;
before(async () => {
  ({ server, url } = await startServer({ root: SITE }));
  browser = await launch();
});
after(async () => {
  await browser?.close();
  server?.close();
});

/** A GET of `path` with `headers`: status, headers and the body's bytes. */
function get(/** @type {string} */ path, /** @type {Record<string, string>} */ headers = {}) {
  return new Promise((resolve, reject) => {
    request(url + path, { headers }, (res) => {
      /** @type {Buffer[]} */
      const parts = [];
      res.on('data', (b) => parts.push(b));
      res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, body: Buffer.concat(parts) }));
    })
      .on('error', reject)
      .end();
  });
}

test('every file of the site has its gzip and brotli beside it, holding the same bytes; the page names only hashed files that are there', () => {
  const files = Object.keys(MANIFEST.sizes);
  assert.ok(files.includes('index.html') && files.includes(MANIFEST.wasm) && files.includes(MANIFEST.entry));
  for (const file of files) {
    const path = join(SITE, file);
    const bytes = readFileSync(path);
    for (const [suffix, decode] of [
      ['.gz', gunzipSync],
      ['.br', brotliDecompressSync],
    ]) {
      // (a file too small to gain from compression goes as it is)
      if (!existsSync(path + suffix)) {
        assert.ok(bytes.length < 256, `${file}${suffix} is missing`);
        continue;
      }
      assert.ok(decode(readFileSync(path + suffix)).equals(bytes), `${file}${suffix} holds other bytes`);
    }
  }
  const html = readFileSync(join(SITE, 'index.html'), 'utf8');
  // (the skip link's "#main" is no file)
  const named = [...html.matchAll(/(?:href|src)="([^"#][^"]*)"/g)].map((m) => m[1]);
  assert.ok(named.length >= 4, named.join(' '));
  for (const file of named) {
    assert.match(file, /^assets\/[\w-]+-[0-9A-Z]{8}\.\w+$/, `${file} is not a hashed file`);
    assert.ok(existsSync(join(SITE, file)), `${file} is not in the site`);
  }
  // the module, its chunks and the wasm: started by the first lines in the head, once the shell
  // is painted
  for (const file of [MANIFEST.entry, MANIFEST.wasm, ...MANIFEST.initial]) {
    assert.ok(html.includes(`"${file}"`), `the page does not start ${file}`);
    assert.ok(existsSync(join(SITE, file)), `${file} is not in the site`);
  }
});

test('served as the browser accepts: brotli, else gzip, else as it is, with Vary, its type and its cache lifetime', async () => {
  const wasm = readFileSync(join(SITE, MANIFEST.wasm));
  const br = /** @type {any} */ (await get(MANIFEST.wasm, { 'accept-encoding': 'gzip, deflate, br' }));
  assert.equal(br.status, 200);
  assert.equal(br.headers['content-encoding'], 'br');
  assert.equal(br.headers.vary, 'accept-encoding');
  // application/wasm: the browser compiles the module while it downloads
  assert.equal(br.headers['content-type'], 'application/wasm');
  assert.equal(br.headers['cache-control'], 'public, max-age=31536000, immutable');
  assert.ok(brotliDecompressSync(br.body).equals(wasm));
  assert.ok(br.body.length < 0.5 * wasm.length, `brotli keeps ${br.body.length} of ${wasm.length} bytes`);
  const gz = /** @type {any} */ (await get(MANIFEST.wasm, { 'accept-encoding': 'gzip' }));
  assert.equal(gz.headers['content-encoding'], 'gzip');
  assert.ok(gunzipSync(gz.body).equals(wasm));
  const plain = /** @type {any} */ (await get(MANIFEST.wasm));
  assert.equal(plain.headers['content-encoding'], undefined);
  assert.equal(plain.headers.vary, 'accept-encoding');
  assert.equal(Number(plain.headers['content-length']), wasm.length);
  assert.ok(plain.body.equals(wasm));
  const page = /** @type {any} */ (await get('', { 'accept-encoding': 'br' }));
  assert.equal(page.headers['content-type'], 'text/html; charset=utf-8');
  assert.equal(page.headers['content-encoding'], 'br');
  // not hashed: revalidated (an unchanged page answers 304)
  assert.equal(page.headers['cache-control'], 'no-cache');
  const again = /** @type {any} */ (await get('', { 'accept-encoding': 'br', 'if-none-match': page.headers.etag }));
  assert.equal(again.status, 304);
  const entry = /** @type {any} */ (await get(MANIFEST.entry, { 'accept-encoding': 'br' }));
  assert.equal(entry.headers['content-type'], 'text/javascript; charset=utf-8');
  assert.equal(entry.headers['cache-control'], 'public, max-age=31536000, immutable');
});

test('the first scene requests only what it draws; the other language, the Share dialog, the exercise author and the figure exports load when first used', async () => {
  const page = await browser.newPage({ viewport: { width: 412, height: 823 }, isMobile: true, hasTouch: true });
  const problems = watch(page);
  page.on('console', (m) => /instantiateStreaming/.test(m.text()) && problems.push(`console: ${m.text()}`));
  /** @type {string[]} */
  const requests = [];
  page.on('request', (r) => requests.push(r.url().replace(url, '').split('#')[0]));
  // counts the ways the wasm is compiled (wasm-bindgen falls back to instantiate() when it cannot stream)
  await page.addInitScript(() => {
    const counts = { streaming: 0, bytes: 0 };
    Object.assign(window, { compiled: counts });
    const { instantiateStreaming, instantiate } = WebAssembly;
    WebAssembly.instantiateStreaming = (...args) => {
      counts.streaming++;
      return instantiateStreaming(...args);
    };
    WebAssembly.instantiate = /** @type {any} */ (
      (/** @type {any[]} */ ...args) => {
        if (!(args[0] instanceof WebAssembly.Module)) counts.bytes++;
        return /** @type {any} */ (instantiate)(...args);
      }
    );
  });
  await page.goto(`${url}#scene=striction`);
  await ready(page);
  await framesAfter(page, 0);
  const image = await shoot(page, 'build-striction');
  assert.ok(countDifferent(image, BACKGROUND) > 0.02 * image.width * image.height, 'nothing drawn');
  const first = [...new Set(requests)];
  const allowed = new Set(['', ...MANIFEST.initial, MANIFEST.wasm]);
  for (const file of first)
    assert.ok(
      allowed.has(file) || /^assets\/(style|noscript|favicon|boot)-/.test(file),
      `the first scene requested ${file}`,
    );
  for (const [what, files] of Object.entries(MANIFEST.lazy))
    for (const file of /** @type {string[]} */ (files)) {
      assert.ok(!MANIFEST.initial.includes(file), `${what} (${file}) is in the entry's chunks`);
      assert.ok(!first.includes(file), `${what} (${file}) loaded with the first scene`);
    }
  assert.ok(!first.includes(MANIFEST.worker), 'the worker started for a figure that needs none');
  // no CAM code with a teaching scene: neither the CAM module's glue (a lazy chunk) nor its wasm
  assert.ok(!first.includes(MANIFEST.camWasm), 'the CAM module loaded with the first scene');
  assert.equal(requests.filter((r) => r === MANIFEST.wasm).length, 1, 'the wasm was fetched more than once');
  assert.deepEqual(await page.evaluate(() => /** @type {any} */ (window).compiled), { streaming: 1, bytes: 0 });

  // each part loads when the reader first asks for it, and works
  const loaded = (/** @type {string} */ what) =>
    /** @type {string[]} */ (MANIFEST.lazy[what]).filter((f) => requests.includes(f));
  // (on a phone the Share button and the pickers are behind the header's Menu button)
  if (await page.locator('#menu').isVisible()) await page.locator('#menu').click();
  await page.locator('#share').click();
  await page.locator('#share-dialog[open]').waitFor();
  assert.ok(loaded('the Share dialog').length > 0, 'the Share dialog opened without its module');
  assert.deepEqual(loaded('the exercise author'), []);
  await page.locator('#share-exercise').click();
  await page.locator('.rl-author-field input').first().waitFor();
  assert.ok(loaded('the exercise author').length > 0, 'Make an exercise opened without its module');
  await page.locator('.io summary').click();
  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('[data-export="svg"]').click()]);
  assert.match(readFileSync(/** @type {string} */ (await download.path()), 'utf8'), /<svg/);
  assert.ok(loaded('the figure exports').length > 0, 'an SVG was written without the exports module');
  assert.deepEqual(loaded('the other language'), []);
  if (await page.locator('#menu').isVisible()) await page.locator('#menu').click();
  await page.locator('#lang').selectOption('de');
  await page.waitForFunction(() => document.documentElement.lang === 'de');
  assert.match(await page.locator('.rl-panel h2').first().innerText(), /Kehlpolygon/);
  assert.ok(loaded('the other language').length > 0);
  // the milling scene: the CAM module comes now, once, and draws
  assert.deepEqual(loaded('the CAM module'), []);
  await page.evaluate(() => {
    location.hash = '#scene=milling&lang=de';
  });
  await page.waitForFunction(() => document.querySelector('.rl-stage')?.getAttribute('data-scene') === 'milling');
  await ready(page);
  assert.ok(loaded('the CAM module').length > 0, 'the milling scene opened without the CAM module');
  assert.equal(requests.filter((r) => r === MANIFEST.camWasm).length, 1, 'the CAM wasm was fetched other than once');
  assert.deepEqual(problems, []);
  await page.close();
});

test('every scene draws from the bundle, in one page followed from link to link', async () => {
  const page = await browser.newPage();
  const problems = watch(page);
  await page.goto(`${url}#scene=striction`);
  await ready(page);
  for (const id of await page.evaluate(() => /** @type {any} */ (window).ruledlab.scenes.map((s) => s.id))) {
    await showScene(page, `#scene=${id}`, id);
    const image = await shoot(page, `build-${id}`);
    assert.ok(countDifferent(image, BACKGROUND) > 0.005 * image.width * image.height, `${id} drew nothing`);
  }
  assert.deepEqual(problems, []);
  await page.close();
});

test('in a course system: the production page in a sandboxed frame of another origin draws, and is editable', async () => {
  const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
  const problems = watch(page);
  await page.goto(
    site.write(
      'course.html',
      hostPage(
        `<iframe sandbox="allow-scripts" src="${url}#embed&amp;controls&amp;paper=fig2" title="ruledlab" width="900" height="560"></iframe>`,
      ),
    ),
  );
  const frame = page.frameLocator('iframe');
  await frame.locator('.rl-stage[data-ready="1"]').waitFor({ timeout: 30000 });
  await frame.locator('body[data-frames]').waitFor();
  assert.ok(drawnShare(await page.locator('iframe').screenshot()) > 0.02, 'the frame drew nothing');
  assert.ok((await frame.locator('.rl-controls [name]').count()) > 3, 'no controls in the frame');
  assert.deepEqual(problems, []);
  await page.close();
});
