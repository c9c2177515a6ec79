// The Share dialog, tested as handed out: what it offers from where the page is, and each
// snippet pasted where a lecturer pastes it — the link opened, the iframe and the element put
// into a page of another site, the one-file page's element with the script it hands out put
// beside it and opened from disk — each drawing the same view (scene, parameters, camera,
// language) with no console error and no request outside ruledlab's files.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { copyFileSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { pageSession, launch, watch, ready } from './browser.mjs';
import { otherOrigin, hostPage, drawnShare } from './places.mjs';

const REPO = fileURLToPath(new URL('../..', import.meta.url));
const session = pageSession();
const site = otherOrigin();
/** @type {import('playwright-core').BrowserContext} */
let files;
before(async () => (files = await launch({ acceptDownloads: true })));
after(() => files?.close());

const near = (/** @type {number[]} */ a, /** @type {number[]} */ b) =>
  a.length === b.length && a.every((x, i) => Math.abs(x - b[i]) <= 1e-4 * Math.max(1, Math.abs(x)));

/** Opens the dialog and reads its fields (null where a field is not offered). */
async function dialog(page) {
  await page.locator('#share').click();
  await page.locator('#share-dialog[data-ready="1"] #share-element').waitFor();
  const value = async (id) => ((await page.locator(`#${id}`).count()) ? page.locator(`#${id}`).inputValue() : null);
  return {
    link: await value('share-link'),
    iframe: await value('share-iframe'),
    element: await value('share-element'),
    nowhere: (await page.locator('#share-nowhere').count()) ? await page.locator('#share-nowhere').innerText() : null,
  };
}

test('from the served page: the link, the iframe and the element each show this view on another site', async () => {
  const { page, problems } = await session.open('#scene=curves&w=0.0625&steps=3&lang=de');
  // turn the camera, so that the snippets must carry it
  const box = await page.locator('.rl-view canvas').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 70, box.y + box.height / 2 + 25, { steps: 4 });
  await page.mouse.up();
  await page.waitForTimeout(300);
  const want = await page.evaluate(() => ({
    camera: window.ruledlab.stage.viewer.camera.toArray(),
    params: { ...window.ruledlab.stage.params },
  }));
  const got = await dialog(page);
  assert.equal(got.nowhere, null);
  assert.match(
    got.element,
    /^<script defer src="http:\/\/[^"]+\/dist\/ruledlab-embed\.js"><\/script>\n<ruled-view scene="curves" params="[^"]*" camera="[^"]+" lang="de" controls/,
  );
  await page.close();

  // the link
  const linked = await session.open(got.link.replace(session.url, ''));
  assert.deepEqual(await linked.page.evaluate(() => ({ ...window.ruledlab.stage.params })), want.params);
  assert.ok(
    near(await linked.page.evaluate(() => window.ruledlab.stage.viewer.camera.toArray()), want.camera),
    'the link lost the camera',
  );
  assert.equal(await linked.page.evaluate(() => document.documentElement.lang), 'de');
  await linked.page.close();

  // the iframe and the element, pasted into a course page of another site
  const url = site.write('pasted.html', hostPage(`${got.iframe}\n${got.element}`));
  const pasted = await session.open(url, { wait: false });
  const frame = pasted.page.frameLocator('iframe');
  await frame.locator('.rl-stage[data-ready="1"]').waitFor({ timeout: 60000 });
  await pasted.page.waitForFunction(() => document.querySelector('ruled-view')?.dataset.ready === '1', null, {
    timeout: 60000,
  });
  await pasted.page.waitForTimeout(300);
  const element = await pasted.page.locator('ruled-view').evaluate((v) => ({
    params: { ...v.view.params },
    camera: v.view.viewer.camera.toArray(),
    lang: v.view.i18n.lang,
    controls: v.shadowRoot.querySelectorAll('.rl-controls [name]').length,
  }));
  assert.deepEqual(element.params, want.params);
  assert.ok(near(element.camera, want.camera), `the element lost the camera: ${element.camera} vs ${want.camera}`);
  assert.equal(element.lang, 'de');
  assert.ok(element.controls >= 4);
  assert.ok(drawnShare(await pasted.page.locator('ruled-view').screenshot()) > 0.01, 'the element drew nothing');
  assert.ok(drawnShare(await pasted.page.locator('iframe').screenshot()) > 0.01, 'the iframe drew nothing');
  assert.deepEqual([...problems, ...linked.problems, ...pasted.problems], []);
  const foreign = pasted.requests.filter(
    (u) => !u.startsWith(session.url) && u.split('#')[0] !== url && !u.startsWith('data:') && !u.startsWith('blob:'),
  );
  assert.deepEqual(foreign, []);
  await pasted.page.close();

  // the same two snippets in a course page with a strict Content-Security-Policy of its own (no
  // inline styles): sized by their attributes, no violation logged
  const origin = new URL(session.url).origin;
  const csp = `default-src 'self'; script-src 'self' ${origin} 'wasm-unsafe-eval'; style-src 'self'; frame-src ${origin}; img-src 'self' data: blob:; worker-src blob:; connect-src ${origin}`;
  const strictUrl = site.write(
    'strict.html',
    `<!doctype html><html lang="en"><head><meta charset="utf-8"><meta http-equiv="Content-Security-Policy" content="${csp}"><link rel="icon" href="data:,"><title>course page</title></head><body><div id="column">${got.iframe}\n${got.element}</div></body></html>`,
  );
  const strict = await session.open(strictUrl, { wait: false });
  await strict.page.waitForFunction(() => document.querySelector('ruled-view')?.dataset.ready === '1', null, {
    timeout: 60000,
  });
  await strict.page.frameLocator('iframe').locator('.rl-stage[data-ready="1"]').waitFor({ timeout: 60000 });
  const sizes = await strict.page.evaluate(() => ({
    element: document.querySelector('ruled-view')?.getBoundingClientRect().height,
    iframe: document.querySelector('iframe')?.getBoundingClientRect().width,
    column: document.getElementById('column')?.getBoundingClientRect().width,
  }));
  assert.equal(sizes.element, 560, 'the element keeps the snippet’s height');
  assert.equal(sizes.iframe, sizes.column, 'the iframe fills its column');
  assert.deepEqual(strict.problems, []);
  await strict.page.close();
});

test('from a downloaded file: no address offered, and the element with its script works from disk', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'ruledlab-share-'));
  copyFileSync(join(REPO, 'dist/ruledlab.html'), join(dir, 'ruledlab.html'));
  const page = await files.newPage();
  const problems = watch(page);
  await page.goto(`${pathToFileURL(join(dir, 'ruledlab.html')).href}#paper=fig8&lang=en`);
  await ready(page);
  const got = await dialog(page);
  assert.equal(got.link, null, 'a file:// link offered as if anyone could open it');
  assert.equal(got.iframe, null, 'a file:// iframe offered');
  assert.match(got.nowhere, /opened from a file/);
  assert.match(
    got.element,
    /^<script defer src="ruledlab-embed\.js"><\/script>\n<ruled-view scene="curves" paper="fig8" params="" camera="[^"]+" lang="en"/,
  );
  assert.match(
    await page.locator('#share-dialog').innerText(),
    /Upload ruledlab-embed\.js \(the button below downloads it\) next to your page/,
  );
  // the script it hands out, and the snippet as handed out, side by side in a folder
  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('#share-embed').click()]);
  const site2 = mkdtempSync(join(tmpdir(), 'ruledlab-lecture-'));
  await download.saveAs(join(site2, download.suggestedFilename()));
  assert.equal(download.suggestedFilename(), 'ruledlab-embed.js');
  // exactly dist/ruledlab-embed.js: the page's script with its data blocks' texts in place
  assert.ok(
    readFileSync(join(site2, 'ruledlab-embed.js')).equals(readFileSync(join(REPO, 'dist/ruledlab-embed.js'))),
    'the embed script handed out is not the build’s',
  );
  writeFileSync(join(site2, 'lecture.html'), hostPage(got.element));
  await page.close();
  const lecture = await files.newPage();
  const seen = watch(lecture);
  const requests = [];
  lecture.on('request', (r) => requests.push(r.url()));
  await lecture.goto(pathToFileURL(join(site2, 'lecture.html')).href);
  await lecture.waitForFunction(() => document.querySelector('ruled-view')?.dataset.ready === '1', null, {
    timeout: 60000,
  });
  await lecture.waitForTimeout(300);
  assert.ok(drawnShare(await lecture.locator('ruled-view').screenshot()) > 0.01);
  assert.equal(await lecture.locator('ruled-view').evaluate((v) => v.view.paper?.id), 'fig8');
  assert.deepEqual(
    requests.filter((u) => !u.startsWith('file:') && !u.startsWith('data:') && !u.startsWith('blob:')),
    [],
  );
  assert.deepEqual([...problems, ...seen], []);
  await lecture.close();
});

test('from the one-file page on a server: the link and the iframe, and the element with its script', async () => {
  const { page, problems } = await session.open('dist/ruledlab.html#scene=strip');
  const got = await dialog(page);
  assert.match(got.link, /\/dist\/ruledlab\.html#.*scene=strip/);
  assert.match(got.iframe, /^<iframe src="http[^"]+\/dist\/ruledlab\.html#embed&amp;controls&amp;/);
  assert.match(got.element, /^<script defer src="ruledlab-embed\.js"><\/script>/);
  assert.equal(await page.locator('#share-embed').isVisible(), true);
  assert.deepEqual(problems, []);
  await page.close();
});

// Share is loaded when first opened: a load that fails (the connection dropped, a new release
// replaced the file) is said over the view, in the page's language, and the next click loads it.
test('Share that could not be loaded is said, and the next click loads it', async () => {
  const { page, problems } = await session.open('#scene=striction&lang=de');
  const share = /\/www\/page\/share\.js$/;
  let blocked = 0;
  await page.route(share, (route) => {
    blocked++;
    return route.abort('internetdisconnected');
  });
  await page.locator('#share').click();
  const error = page.locator('.rl-view .rl-error');
  await error.waitFor();
  assert.match(/** @type {string} */ (await error.textContent()), /konnte nicht geladen werden/);
  await page.unroute(share);
  await page.locator('#share').click();
  await page.locator('#share-dialog[data-ready="1"]').waitFor();
  assert.equal(await error.isVisible(), false, 'the sentence stays after Share was loaded');
  assert.equal(blocked, 1);
  // (the request refused here, and the browser's word on it, are the only problems)
  assert.deepEqual(
    problems.filter((p) => !/share\.js|ERR_INTERNET_DISCONNECTED/.test(p)),
    [],
  );
  await page.close();
});
