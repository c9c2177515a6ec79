// In a course system: the ways Moodle, Canvas, ILIAS and H5P show user content (the book, "In a
// course system"), reproduced on a page of another origin. Each frame must draw, show its
// controls, move its picture when a control is used, log no console error and request nothing
// outside ruledlab's files (the one-file build: nothing but itself).
//   sandbox="allow-scripts"                      an author's sandboxed iframe (kept by Canvas and
//                                                Moodle pages): an opaque origin, no storage, no history
//   sandbox="allow-scripts allow-same-origin"    the same with its origin
//   srcdoc (both sandboxes)                      the one-file page as the frame's content
//   about:blank + document.write                 H5P's way (and Moodle's H5P filter)
//   no sandbox, another site                     Moodle's File resource "embed", Canvas's files
//                                                domain with its own policy (no blob: workers)
//   the parent's own Content-Security-Policy     Canvas with its CSP setting on
//   sandbox=""                                   scripts off (TinyMCE 7's default): a sentence,
//                                                not a blank frame
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { pageSession } from './browser.mjs';
import { otherOrigin, hostPage, drawnShare } from './places.mjs';
import { decodePng, countChanged } from './png.mjs';

const ONEFILE = readFileSync(fileURLToPath(new URL('../../dist/ruledlab.html', import.meta.url)), 'utf8');
const session = pageSession();
const site = otherOrigin();

/** An HTML attribute value. */
const attr = (/** @type {string} */ s) => s.replace(/&/g, '&amp;').replace(/"/g, '&quot;');

/** The one-file build with its state block showing `hash`, as "Download this view" writes it. */
const oneFileAt = (/** @type {string} */ hash) =>
  ONEFILE.replace(
    /(<script type="application\/json" id="ruledlab-state">)[^<]*(<\/script>)/,
    `$1${JSON.stringify({ hash })}$2`,
  );

/**
 * The variants: a name, the parent page's body (given ruledlab's origin), the parent's
 * response headers, headers for ruledlab's one-file page, and whether only the one file may
 * be requested.
 * @type {Array<{name: string, body: (a: string) => string, parent?: Record<string, string>, oneFile: boolean, hint?: string}>}
 */
const VARIANTS = [
  {
    name: 'sandbox allow-scripts, the page',
    oneFile: false,
    body: (a) =>
      `<iframe sandbox="allow-scripts" src="${a}index.html#embed&amp;controls&amp;paper=fig2" title="ruledlab" width="900" height="560"></iframe>`,
  },
  {
    name: 'sandbox allow-scripts, the one-file build',
    oneFile: true,
    body: (a) =>
      `<iframe sandbox="allow-scripts" src="${a}dist/ruledlab.html#embed&amp;controls&amp;paper=fig2" title="ruledlab" width="900" height="560"></iframe>`,
  },
  {
    name: 'sandbox allow-scripts allow-same-origin, the page',
    oneFile: false,
    body: (a) =>
      `<iframe sandbox="allow-scripts allow-same-origin" src="${a}index.html#embed&amp;controls&amp;paper=fig2" title="ruledlab" width="900" height="560" allow="fullscreen"></iframe>`,
  },
  {
    name: 'srcdoc, sandbox allow-scripts',
    oneFile: true,
    body: () =>
      `<iframe sandbox="allow-scripts" srcdoc="${attr(oneFileAt('embed&controls&paper=fig2'))}" title="ruledlab" width="900" height="560"></iframe>`,
  },
  {
    name: 'srcdoc, sandbox allow-scripts allow-same-origin',
    oneFile: true,
    body: () =>
      `<iframe sandbox="allow-scripts allow-same-origin" srcdoc="${attr(oneFileAt('embed&controls&paper=fig2'))}" title="ruledlab" width="900" height="560"></iframe>`,
  },
  {
    name: 'about:blank written by its parent (H5P)',
    oneFile: true,
    body: () => `<iframe id="h5p" class="h5p-iframe" src="about:blank" title="ruledlab" width="900" height="560" allowfullscreen></iframe>
<script type="application/json" id="content">${JSON.stringify(oneFileAt('embed&controls&paper=fig2')).replace(/</g, '\\u003c')}</script>
<script>const d = document.getElementById('h5p').contentDocument; d.open(); d.write(JSON.parse(document.getElementById('content').textContent)); d.close();</script>`,
  },
  {
    name: 'another site, no sandbox, LTI allow list (Moodle File resource, Canvas)',
    oneFile: true,
    body: (a) =>
      `<iframe src="${a}dist/ruledlab.html#embed&amp;controls&amp;paper=fig2" title="ruledlab" width="900" height="560" allowfullscreen allow="geolocation *; microphone *; camera *; midi *; encrypted-media *; autoplay *; clipboard-write *; display-capture *"></iframe>`,
  },
  {
    name: "the parent's own Content-Security-Policy (Canvas)",
    oneFile: false,
    parent: {
      'content-security-policy':
        "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data:; frame-src 'self' blob: http://localhost:*",
    },
    body: (a) =>
      `<iframe src="${a}index.html#embed&amp;controls&amp;paper=fig2" title="ruledlab" width="900" height="560"></iframe>`,
  },
];

/**
 * The requests a frame made outside ruledlab's files: anything but data:, blob: and about:, the
 * parent page `url`, and ruledlab's own files (`oneFile`: the one-file page alone).
 * @param {string[]} requests @param {string} url @param {boolean} oneFile
 */
const foreign = (requests, url, oneFile) =>
  requests.filter(
    (u) =>
      !u.startsWith('data:') &&
      !u.startsWith('blob:') &&
      !u.startsWith('about:') &&
      u.split('#')[0] !== url &&
      (oneFile ? u.split('#')[0] !== `${session.url}dist/ruledlab.html` : !u.startsWith(session.url)),
  );

for (const v of VARIANTS) {
  test(`in a course system: ${v.name} — drawn, controls that move the picture, no error, nothing else loaded`, async () => {
    const url = site.write(`${v.name.replace(/\W+/g, '-')}.html`, hostPage(v.body(session.url)), v.parent);
    const { page, problems, requests } = await session.open(url, { wait: false });
    const frame = page.frameLocator('iframe');
    await frame.locator('.rl-stage[data-ready="1"]').waitFor({ timeout: 60000 });
    await page.waitForTimeout(300);
    const before = await page.locator('iframe').screenshot();
    assert.ok(drawnShare(before) > 0.03, 'nothing drawn in the frame');
    const controls = frame.locator('.rl-controls [name]');
    assert.ok((await controls.count()) >= 5, 'the controls are missing');
    await frame.locator('.rl-controls [name="normals"]').click();
    await page.waitForTimeout(400);
    const after = await page.locator('iframe').screenshot();
    assert.ok(countChanged(decodePng(before), decodePng(after)) > 500, 'a control did not change the picture');
    // a number typed and Enter: applied, and no blocked form submission (sandbox without allow-forms)
    const field = frame.locator('.rl-row[data-key="n"] .rl-exact');
    await field.fill('40');
    await field.press('Enter');
    await frame
      .locator('.rl-row[data-key="n"] output', { hasText: /^40$/ })
      .waitFor({ state: 'attached', timeout: 10000 });
    assert.deepEqual(foreign(requests, url, v.oneFile), [], 'requests outside ruledlab’s files');
    assert.deepEqual(problems, []);
    await page.close();
  });
}

test('in a course system: the one-file build in a sandboxed frame shows the Klein view beside, steered, and nothing else loaded', async () => {
  const url = site.write(
    'klein-sandbox.html',
    hostPage(
      `<iframe sandbox="allow-scripts" src="${session.url}dist/ruledlab.html#embed&amp;controls&amp;scene=strip&amp;klein=40,200,1.5" title="ruledlab" width="1000" height="560"></iframe>`,
    ),
  );
  const { page, problems, requests } = await session.open(url, { wait: false });
  const frame = page.frameLocator('iframe');
  await frame.locator('.rl-stage[data-ready="1"]').waitFor({ timeout: 60000 });
  const pane = frame.locator('.rl-klein');
  const frames = async () => Number((await pane.getAttribute('data-frames')) ?? 0);
  for (let k = 0; k < 100 && !(await frames()); k++) await page.waitForTimeout(100);
  assert.ok((await frames()) > 0, 'the Klein view is drawn in the frame');
  const sliders = frame.locator('.rl-klein-steer input');
  assert.deepEqual(
    await sliders.evaluateAll((all) => all.map((e) => Number(/** @type {HTMLInputElement} */ (e).value))),
    [40, 200, 1.5],
  );
  const before = await pane.screenshot();
  const drawn = await frames();
  await sliders.nth(1).focus();
  for (let i = 0; i < 20; i++) await sliders.nth(1).press('ArrowRight');
  for (let k = 0; k < 50 && (await frames()) === drawn; k++) await page.waitForTimeout(100);
  await page.waitForTimeout(300);
  const after = await pane.screenshot();
  assert.ok(countChanged(decodePng(before), decodePng(after)) > 300, 'β steers the picture in the frame');
  assert.deepEqual(foreign(requests, url, true), [], 'requests outside the one file');
  assert.deepEqual(problems, []);
  await page.close();
});

test('in a course system: Canvas’s files domain policy (no blob: workers) — a large model refines on the main thread', async () => {
  // the one-file page served with Canvas's policy for user files: inline scripts and eval, no blob:
  const policy =
    "default-src 'self'; script-src 'self' 'unsafe-eval' 'unsafe-inline'; frame-src 'self' blob:; img-src 'self' data: blob:; style-src 'self' 'unsafe-inline'";
  const file = site.write('canvas-file.html', oneFileAt('embed&controls&scene=large&n=10000&steps=3'), {
    'content-security-policy': policy,
  });
  const url = site.write(
    'canvas-course.html',
    hostPage(`<iframe src="${file}" title="ruledlab" width="900" height="560"></iframe>`),
  );
  const { page, problems } = await session.open(url, { wait: false });
  const frame = page.frameLocator('iframe');
  await frame.locator('.rl-stage[data-ready="1"]').waitFor({ timeout: 120000 });
  assert.match(await frame.locator('.rl-readout').innerText(), /79[\s,.]?993/);
  // the browser reports the refused worker itself; nothing else may go wrong
  assert.deepEqual(
    problems.filter((p) => !/worker|blob:/i.test(p)),
    [],
  );
  await page.close();
});

test('in a course system: sandbox="" (no scripts) shows a sentence, not a blank frame', async () => {
  const url = site.write(
    'no-scripts.html',
    hostPage(
      `<iframe sandbox="" src="${session.url}dist/ruledlab.html" title="ruledlab" width="900" height="300"></iframe><iframe sandbox="" src="${session.url}index.html" title="ruledlab page" width="900" height="300"></iframe>`,
    ),
  );
  const { page, problems } = await session.open(url, { wait: false });
  for (const k of [0, 1]) {
    const text = await page.frameLocator('iframe').nth(k).locator('body').innerText();
    assert.match(text, /needs JavaScript/, `frame ${k}: ${text}`);
    assert.doesNotMatch(text, /Loading/, `frame ${k}: a "Loading" that never ends`);
  }
  // the browser says it blocked the scripts; nothing else
  assert.deepEqual(
    problems.filter((p) => !/Blocked script execution in .* sandboxed/.test(p)),
    [],
  );
  await page.close();
});

test('in a sandboxed frame the page does without storage and history, and says so only where it matters', async () => {
  const url = site.write(
    'sandboxed-page.html',
    hostPage(
      `<iframe sandbox="allow-scripts" src="${session.url}index.html#scene=curves" title="ruledlab" width="1000" height="700"></iframe>`,
    ),
  );
  const { page, problems } = await session.open(url, { wait: false });
  const frame = page.frameLocator('iframe');
  await frame.locator('.rl-stage[data-ready="1"]').waitFor({ timeout: 60000 });
  // a scene change still works (no history entry to write)
  await frame.locator('#scene').selectOption('strip');
  await frame.locator('.rl-stage[data-scene="strip"][data-ready="1"]').waitFor();
  assert.equal(await frame.locator('.io-stored').isHidden(), true, 'a note about storage before anyone asked for it');
  // an import too large for the link cannot be kept: the page says so there, and shows it
  await frame.locator('.io summary').click();
  const rows = Array.from({ length: 260 }, (_, i) => `${i},0,0,${i},1,${i / 10}`).join('\n');
  await frame.locator('#import-text').fill(rows);
  await frame.locator('#import-button').click();
  await frame.locator('.rl-stage[data-scene="data"][data-ready="1"]').waitFor();
  assert.match(await frame.locator('.io-stored').innerText(), /no storage here/);
  assert.equal(await frame.locator('.rl-fullscreen').isHidden(), true, 'a full-screen button the frame does not allow');
  assert.deepEqual(problems, []);
  await page.close();
});
