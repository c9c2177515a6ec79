// Every snippet works as handed out: <ruled-view> loaded cold on a page of another site — the
// first ruledlab code there — for every figure of the paper and every scene, from the one-file
// embed script (what the Share dialog hands out) and from the module ruledlab/view (served
// with the CORS header a static CDN sends); in a sandboxed iframe, every figure and scene; what
// fails shows inside the element, in its language, and fires `error`; the camera attribute and
// the camera-change event.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageSession } from './browser.mjs';
import { otherOrigin, hostPage, drawnShare } from './places.mjs';
import { everyElementCold, ELEMENTS } from './cold.mjs';

const session = pageSession();
const site = otherOrigin();
const ours = (/** @type {string} */ u) =>
  u.startsWith(session.url) || u.startsWith(site.url) || u.startsWith('data:') || u.startsWith('blob:');

test('every figure and scene in <ruled-view>, cold, from the one-file embed script on another site', async () => {
  let n = 0;
  await everyElementCold(
    session.browser,
    (elements) =>
      site.write(
        `embed-${++n}.html`,
        hostPage(elements, `<script defer src="${session.url}dist/ruledlab-embed.js"></script>`),
      ),
    ours,
  );
});

test('every figure and scene in <ruled-view>, cold, from the module ruledlab/view on another site', async () => {
  let n = 0;
  await everyElementCold(
    session.browser,
    (elements) =>
      site.write(
        `module-${++n}.html`,
        hostPage(elements, `<script type="module" src="${session.url}www/index.js"></script>`),
      ),
    ours,
  );
});

test('every figure and scene in a sandboxed iframe (allow-scripts), one after another', async () => {
  const url = site.write(
    'walk.html',
    hostPage(
      `<iframe id="f" sandbox="allow-scripts" src="${session.url}index.html#embed&amp;controls&amp;paper=fig1" title="ruledlab" width="800" height="500"></iframe>`,
    ),
  );
  const { page, problems, requests } = await session.open(url, { wait: false });
  const frame = page.frameLocator('#f');
  for (const attrs of ELEMENTS) {
    const [, key, id] = /^(\w+)="([^"]+)"$/.exec(attrs) ?? [];
    const hash = `embed&controls&${key === 'paper' ? 'paper' : 'scene'}=${id}`;
    await page.evaluate(
      ([u, h]) => {
        const frame = /** @type {HTMLIFrameElement} */ (document.getElementById('f'));
        frame.src = `${u}index.html#${h}`;
      },
      [session.url, hash],
    );
    await frame.locator(`.rl-stage[data-ready="1"][data-${key}="${id}"]`).waitFor({ timeout: 60000 });
  }
  await page.waitForTimeout(300);
  assert.ok(drawnShare(await page.locator('#f').screenshot()) > 0.01);
  assert.deepEqual(problems, []);
  assert.deepEqual(
    requests.filter((u) => !ours(u)),
    [],
  );
  await page.close();
});

test('what fails shows inside the element, in its language, and fires `error`; never a blank box', async () => {
  const url = site.write(
    'failing.html',
    hostPage(
      `<ruled-view id="scene" scene="nope" lang="de" style="display: block; height: 200px"></ruled-view>
<ruled-view id="paper" paper="fig99" lang="en" style="display: block; height: 200px"></ruled-view>
<ruled-view id="camera" scene="curves" camera="1,2" lang="de" style="display: block; height: 200px"></ruled-view>
<ruled-view id="task" task="nope" lang="de" style="display: block; height: 200px"></ruled-view>
<ruled-view id="params" scene="striction" params="n=lots" style="display: block; height: 200px"></ruled-view>
<ruled-view id="input" scene="curves" input="points.garbage" style="display: block; height: 200px"></ruled-view>`,
      `<script>window.errors = []; addEventListener('error', (e) => e.target?.tagName === 'RULED-VIEW' && errors.push([e.target.id, e.detail.message, e.detail.code, e.detail.details?.option ?? null]), true);</script><script defer src="${session.url}dist/ruledlab-embed.js"></script>`,
    ),
  );
  const { page, problems } = await session.open(url, { wait: false });
  await page.waitForFunction(
    () => window.errors.length >= 6 && document.getElementById('input').dataset.ready === '1',
    null,
    { timeout: 30000 },
  );
  const shown = await page.evaluate(() =>
    Object.fromEntries(
      [...document.querySelectorAll('ruled-view')].map((v) => [
        v.id,
        [...v.shadowRoot.querySelectorAll('.rl-error:not([hidden]), .rl-note:not([hidden])')]
          .map((e) => e.textContent)
          .join(' '),
      ]),
    ),
  );
  assert.match(shown.scene, /^Eine Szene „nope“ gibt es nicht/);
  assert.match(shown.paper, /^There is no figure or example of the paper called “fig99”/);
  assert.match(shown.camera, /Das Attribut camera ist nicht lesbar/);
  const errors = await page.evaluate(() => window.errors);
  // an attribute refused (the scene shown without it) fires `error` too, so the page around can tell
  assert.deepEqual(errors.map(([id, , code, option]) => [id, code, option]).sort(), [
    ['camera', 'invalid-argument', 'camera'],
    ['input', 'invalid-argument', 'input'],
    ['paper', 'invalid-argument', 'paper'],
    ['params', 'invalid-argument', 'params'],
    ['scene', 'invalid-argument', 'scene'],
    ['task', 'invalid-argument', 'task'],
  ]);
  assert.match(errors.find(([id]) => id === 'task')[1], /Das Attribut task ließ sich nicht lesen/);
  assert.match(errors.find(([id]) => id === 'scene')[1], /^Eine Szene/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('without WebGL2 the element says why, inside its box, in its language, and fires `error`', async () => {
  const url = site.write(
    'no-webgl.html',
    hostPage(
      `<ruled-view id="v" scene="curves" lang="de" style="display: block; height: 200px"></ruled-view>`,
      `<script>HTMLCanvasElement.prototype.getContext = function () { return null; }; window.errors = []; addEventListener('error', (e) => e.target?.tagName === 'RULED-VIEW' && errors.push(e.detail.message), true);</script><script defer src="${session.url}dist/ruledlab-embed.js"></script>`,
    ),
  );
  const { page, problems } = await session.open(url, { wait: false });
  await page.waitForFunction(() => window.errors.length === 1, null, { timeout: 30000 });
  const text = await page.locator('#v').evaluate((v) => v.shadowRoot.textContent);
  assert.match(text, /ruledlab konnte nicht starten: Dieser Browser \(oder dieses Gerät\) bietet kein WebGL2/);
  assert.match((await page.evaluate(() => window.errors))[0], /WebGL2/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the camera attribute sets the view; camera-change hands out the value that restores it', async () => {
  const url = site.write(
    'camera.html',
    hostPage(
      `<ruled-view id="v" scene="striction" camera="1.2,0.3,14,0,0,0.5" style="display: block; width: 600px; height: 400px"></ruled-view>`,
      `<script defer src="${session.url}dist/ruledlab-embed.js"></script>`,
    ),
  );
  const { page, problems } = await session.open(url, { wait: false });
  await page.waitForFunction(() => document.getElementById('v').dataset.ready === '1');
  assert.equal(await page.locator('#v').evaluate((v) => v.camera), '1.2,0.3,14,0,0,0.5');
  const changed = page.evaluate(
    () =>
      new Promise((resolve) =>
        document.getElementById('v').addEventListener('camera-change', (e) => resolve(e.detail), { once: true }),
      ),
  );
  const box = await page.locator('#v').boundingBox();
  await page.mouse.move(box.x + 300, box.y + 200);
  await page.mouse.down();
  await page.mouse.move(box.x + 360, box.y + 230, { steps: 4 });
  await page.mouse.up();
  const detail = await changed;
  assert.match(detail.camera, /^-?[\d.]+(,-?[\d.e-]+){5}$/);
  assert.notEqual(detail.camera, '1.2,0.3,14,0,0,0.5');
  // the value restores the view in another element
  const restored = await page.evaluate(async (camera) => {
    const w = document.createElement('ruled-view');
    w.setAttribute('scene', 'striction');
    w.setAttribute('camera', camera);
    document.body.append(w);
    await new Promise((r) => w.addEventListener('scene-change', r, { once: true }));
    return w.camera;
  }, detail.camera);
  assert.equal(restored, detail.camera);
  assert.deepEqual(problems, []);
  await page.close();
});
