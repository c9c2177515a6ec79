// The Klein view beside the 3D view: the lines of any scene as points of the Klein quadric, asked
// for by the toolbar's button, by the link (`klein`) and by <ruled-view klein>. Drawn (pixels), as
// many points as the scene has lines (read from what the scene exports), a net for a congruence's
// grid, a note where a scene has no lines of its own; the button a toggle the link keeps; the
// element's attribute and property; a finger at 390 px; axe-core clean; no console error.
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { mkdirSync, writeFileSync } from 'node:fs';
import { pageSession, setControl, launch, watch, ready, ARTIFACTS } from './browser.mjs';
import { startServer } from '../../scripts/serve.mjs';
import { countDifferent, countChanged, decodePng } from './png.mjs';
import { finger, Hand, handlesOnPage } from './hands.mjs';

const session = pageSession();
const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
const BACKGROUND = [251, 250, 247];

/** @typedef {import('playwright-core').Page} Page */

/**
 * The Klein view's canvas alone, once it has drawn more than `after` frames (what lies over it
 * hidden for the shot: legend, toolbar), saved as `<name>.png`.
 * @param {Page} page @param {string} name @param {{host?: string, after?: number}} [options]
 *   host: a <ruled-view>'s selector
 */
async function kleinShot(page, name, { host = '', after = 0 } = {}) {
  const root = host ? page.locator(host) : page;
  const pane = root.locator('.rl-klein');
  await page.waitForFunction(
    ([h, n]) => {
      const box = (h ? document.querySelector(h)?.shadowRoot : document)?.querySelector('.rl-klein');
      return Number(/** @type {HTMLElement | undefined} */ (box)?.dataset.frames ?? 0) > Number(n);
    },
    [host, after],
  );
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  // (in a narrow box the legend is in the panel: none to hide there)
  const over = root.locator('.rl-klein > :not(canvas), .rl-view > .rl-bar');
  const hide = (/** @type {string} */ v) =>
    over.evaluateAll((all, value) => {
      for (const e of all) /** @type {HTMLElement} */ (e).style.visibility = value;
    }, v);
  await hide('hidden');
  const png = await pane.locator('canvas').screenshot();
  await hide('');
  mkdirSync(ARTIFACTS, { recursive: true });
  writeFileSync(join(ARTIFACTS, `${name}.png`), png);
  return decodePng(png);
}

/** The frames the Klein view has drawn. @param {Page} page */
const kleinFrames = (page) =>
  page.evaluate(() => Number(document.querySelector('.rl-klein')?.getAttribute('data-frames') ?? 0));

/** The lines the scene shown exports (what the Klein view draws), counted. @param {Page} page */
const exportedLines = (page) =>
  page.evaluate(() => {
    const built = /** @type {any} */ (window).ruledlab.stage.session.built;
    return built?.data ? built.data.segments.length / 6 : 0;
  });

const description = (/** @type {Page} */ page) => page.locator('.rl-klein .rl-sr-only').textContent();

test('the link opens the Klein view beside the 3D view: every line of the scene a point, drawn; the scene’s controls change it', async () => {
  const { page, problems } = await session.open('#scene=lines&klein');
  assert.equal(await page.locator('.rl-klein').isVisible(), true);
  assert.equal(await page.locator('.rl-klein-toggle').getAttribute('aria-pressed'), 'true');
  const lines = await exportedLines(page);
  assert.ok(lines > 8, `${lines} lines`);
  assert.match(
    (await description(page)) ?? '',
    new RegExp(`the ${lines} lines of the scene as points of the Klein quadric M`),
  );
  // the line-space scheme's points before they are projected back: drawn beside, said, in the legend
  assert.match((await description(page)) ?? '', /leave it by up to ρ = \d/);
  assert.match(await page.locator('.rl-klein-legend').innerText(), /before they are projected back onto M/);
  assert.match(await page.locator('.rl-readout').innerText(), /largest distance ρ from the Klein quadric/);
  // its canvas is described, and drawn: M's outline, the points and their steps
  const canvas = page.locator('.rl-klein canvas');
  assert.equal(
    await canvas.getAttribute('aria-describedby'),
    await page.locator('.rl-klein .rl-sr-only').getAttribute('id'),
  );
  const before = await kleinShot(page, 'klein-pane-lines');
  assert.ok(countDifferent(before, BACKGROUND) > 0.01 * before.width * before.height, 'the Klein view is drawn');
  // a control of the scene changes the lines, and so their points on M
  const frames = await kleinFrames(page);
  await setControl(page, 'surface', 'hyperboloid');
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.params.surface === 'hyperboloid');
  const after = await kleinShot(page, 'klein-pane-hyperboloid', { after: frames });
  assert.ok(countChanged(before, after) > 500, 'the Klein view follows the scene');
  assert.match((await description(page)) ?? '', /Torsal steps \(Ω = 0: consecutive lines meet\): \d+ of \d+/);
  // axe-core: the split view is as accessible as the view alone
  await page.evaluate(AXE);
  const result = await page.evaluate(() =>
    /** @type {any} */ (window).axe.run(document, {
      runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22a', 'wcag22aa'] },
    }),
  );
  assert.deepEqual(
    result.violations.map(
      (/** @type {any} */ v) => `${v.id}: ${v.nodes.map((/** @type {any} */ n) => n.target.join(' ')).join(', ')}`,
    ),
    [],
  );
  assert.deepEqual(problems, []);
  await page.close();
});

test('the button is a toggle the link keeps; a congruence is a net; a scene without lines of its own says so', async () => {
  const { page, problems } = await session.open('#scene=focal');
  assert.equal(await page.locator('.rl-klein').isVisible(), false);
  assert.equal(await page.locator('.rl-klein canvas').count(), 0, 'no WebGL context until asked for');
  await page.locator('.rl-klein-toggle').click();
  await page.waitForFunction(() => location.hash.includes('&klein'));
  assert.equal(await page.locator('.rl-klein-toggle').getAttribute('aria-pressed'), 'true');
  // the focal scene's congruence: a rows × cols grid, a net on M
  const lines = await exportedLines(page);
  const grid = await page.evaluate(() => /** @type {any} */ (window).ruledlab.stage.session.built.data.grid);
  assert.equal(grid.rows * grid.cols, lines);
  assert.match(
    (await description(page)) ?? '',
    new RegExp(`the ${grid.rows} × ${grid.cols} lines of the grid as points of the Klein quadric M, a net`),
  );
  const net = await kleinShot(page, 'klein-pane-focal');
  assert.ok(countDifferent(net, BACKGROUND) > 0.01 * net.width * net.height);
  // a scene of curves has no lines of its own: a note, no picture
  await page.evaluate(() => (location.hash = '#scene=curves&klein'));
  await page.waitForFunction(() => document.querySelector('.rl-stage')?.getAttribute('data-scene') === 'curves');
  await page.locator('.rl-klein-note').waitFor();
  assert.match(await page.locator('.rl-klein-note').innerText(), /no lines of its own/);
  assert.equal(await page.locator('.rl-klein canvas').isVisible(), false);
  // off again: the pane and its context gone, the link without it
  await page.locator('.rl-klein-toggle').click();
  await page.waitForFunction(() => !location.hash.includes('klein'));
  assert.equal(await page.locator('.rl-klein').isVisible(), false);
  assert.equal(await page.locator('.rl-klein canvas').count(), 0);
  // and on again: a canvas of its own, drawn, its legend back
  await page.evaluate(() => (location.hash = '#scene=focal'));
  await page.waitForFunction(() => document.querySelector('.rl-stage')?.getAttribute('data-scene') === 'focal');
  await page.locator('.rl-klein-toggle').click();
  await page.locator('.rl-klein canvas').waitFor();
  assert.equal(await page.locator('.rl-klein canvas').count(), 1);
  assert.equal(await page.locator('.rl-klein-legend').isVisible(), true);
  const again = await kleinShot(page, 'klein-pane-again');
  assert.ok(countDifferent(again, BACKGROUND) > 0.01 * again.width * again.height);
  assert.deepEqual(problems, []);
  await page.close();
});

test('<ruled-view klein>: the attribute and the property show and hide the Klein view; the button sets the attribute', async () => {
  const { page, problems } = await session.open('examples/web-component.html', { wait: false });
  await page.evaluate(() => {
    const view = document.createElement('ruled-view');
    view.id = 'k';
    view.setAttribute('scene', 'developable');
    view.setAttribute('klein', '');
    view.setAttribute('height', '420px');
    document.body.prepend(view);
  });
  const view = page.locator('#k');
  await view.locator('.rl-klein canvas').waitFor();
  assert.equal(await view.locator('.rl-klein-toggle').getAttribute('aria-pressed'), 'true', 'pressed from the start');
  await page.waitForFunction(() =>
    /the \d+ lines of the scene/.test(
      document.querySelector('#k')?.shadowRoot?.querySelector('.rl-klein .rl-sr-only')?.textContent ?? '',
    ),
  );
  const drawn = await kleinShot(page, 'klein-element', { host: '#k' });
  assert.ok(countDifferent(drawn, BACKGROUND) > 0.01 * drawn.width * drawn.height, 'the element draws the Klein view');
  await page.evaluate(() => {
    /** @type {any} */ (document.querySelector('#k')).klein = false;
  });
  assert.equal(await view.locator('.rl-klein').isVisible(), false);
  await view.locator('.rl-klein-toggle').click();
  assert.equal(await view.getAttribute('klein'), '');
  assert.equal(await view.locator('.rl-klein').isVisible(), true);
  assert.deepEqual(problems, []);
  await page.close();
});

/** A phone, for the finger test. */
const phone = { server: /** @type {import('node:http').Server | null} */ (null), context: /** @type {any} */ (null) };
after(async () => {
  await phone.context?.close();
  phone.server?.close();
});

/** The Klein view's sliders' values, α β ℓ, as the page shows them. @param {import('playwright-core').Locator | Page} root */
const sliders = (root) =>
  root
    .locator('.rl-klein-steer input')
    .evaluateAll((all) => all.map((e) => Number(/** @type {HTMLInputElement} */ (e).value)));

test('the Klein view’s image steered by its sliders: the picture changes, the link keeps klein=α,β,ℓ and restores it, a bad value is said; <ruled-view klein="α,β,ℓ"> is written back when let go', async () => {
  const { page, problems } = await session.open('#scene=striction&klein=12,200,2.35');
  assert.equal(await page.locator('.rl-klein-steer').isVisible(), true);
  assert.deepEqual(await sliders(page), [12, 200, 2.35]);
  assert.deepEqual(await page.locator('.rl-klein-steer output').allInnerTexts(), ['12°', '200°', '2.35']);
  assert.match((await description(page)) ?? '', /α = 12°, β = 200°, ℓ = 2\.35/);
  // each slider is named for what it steers, in the Klein view (not the scene's sliders)
  assert.deepEqual(
    await page.locator('.rl-klein-steer input').evaluateAll((all) => all.map((e) => e.getAttribute('aria-label'))),
    [
      'Klein view: Mix α of the two spheres (°)',
      'Klein view: Turn β of the second sphere (°)',
      'Klein view: Unit of length ℓ',
    ],
  );
  const before = await kleinShot(page, 'klein-steer-before');
  // by keyboard: α five steps up; the picture changes and the link says so
  const frames = await kleinFrames(page);
  await page.locator('.rl-klein-steer input').first().focus();
  for (let i = 0; i < 5; i++) await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => location.hash.includes('klein=17%2C200%2C2.35'));
  assert.match((await description(page)) ?? '', /α = 17°/);
  const after = await kleinShot(page, 'klein-steer-after', { after: frames });
  assert.ok(countChanged(before, after) > 300, 'the image follows α');
  // the link restores it, as handed out
  const link = await page.evaluate(() => location.href);
  const again = await page.context().newPage();
  await again.goto(link);
  await ready(again);
  await again.locator('.rl-klein canvas').waitFor();
  assert.deepEqual(await sliders(again), [17, 200, 2.35]);
  await again.close();
  // a link whose image is not three numbers: said, and the default image drawn
  await page.goto(`${link.split('#')[0]}#scene=striction&klein=12,200`);
  await ready(page);
  await page.locator('.rl-klein canvas').waitFor();
  assert.deepEqual(await sliders(page), [30, 90, 1]);
  assert.match(await page.locator('.rl-note').innerText(), /not three numbers α,β,ℓ/);
  assert.deepEqual(problems, []);
  await page.close();

  // the element: a value out of range held and written back, an error event naming the attribute
  const { page: host, problems: hostProblems } = await session.open('examples/web-component.html', { wait: false });
  await host.waitForFunction(() => customElements.get('ruled-view'));
  const refused = await host.evaluate(async () => {
    const view = /** @type {any} */ (document.createElement('ruled-view'));
    /** @type {unknown[]} */
    const errors = [];
    view.addEventListener('error', (/** @type {CustomEvent} */ e) => errors.push(e.detail.details));
    view.setAttribute('scene', 'striction');
    view.setAttribute('klein', '120,10,1');
    view.setAttribute('height', '420');
    view.id = 'steered';
    document.body.append(view);
    await view.opening;
    return errors;
  });
  assert.deepEqual(refused, [{ option: 'klein', reason: 'element.note.kleinHeld' }]);
  const element = host.locator('#steered');
  assert.equal(await element.getAttribute('klein'), '90,10,1');
  await element.locator('.rl-klein canvas').waitFor();
  assert.deepEqual(await sliders(element), [90, 10, 1]);
  // a step of the slider does not rewrite the attribute; letting go does
  const turn = element.locator('.rl-klein-steer input').nth(1);
  await turn.evaluate((e) => {
    /** @type {HTMLInputElement} */ (e).value = '40';
    e.dispatchEvent(new Event('input', { bubbles: true }));
  });
  assert.equal(await element.getAttribute('klein'), '90,10,1');
  assert.deepEqual(
    await host.evaluate(() => /** @type {any} */ (document.querySelector('#steered')).stage.projection),
    {
      mix: 90,
      turn: 40,
      unit: 1,
    },
  );
  await turn.evaluate((e) => e.dispatchEvent(new Event('change', { bubbles: true })));
  assert.equal(await element.getAttribute('klein'), '90,40,1');
  // the attribute steers the view; a bare klein is the scene's own image
  await element.evaluate((e) => e.setAttribute('klein', '45,0,0.5'));
  await host.waitForFunction(
    () => /** @type {any} */ (document.querySelector('#steered')).stage.kleinImage.unit === 0.5,
  );
  assert.deepEqual(await sliders(element), [45, 0, 0.5]);
  await element.evaluate((e) => e.setAttribute('klein', ''));
  await host.waitForFunction(() => /** @type {any} */ (document.querySelector('#steered')).stage.kleinImage.mix === 30);
  assert.deepEqual(hostProblems, []);
  await host.close();
});

test('by finger at 390 px: the button opens the Klein view under the 3D view, its legend in the panel', async () => {
  const started = await startServer();
  phone.server = started.server;
  phone.context = await launch({ viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true });
  const page = await phone.context.newPage();
  const problems = watch(page);
  await page.goto(`${started.url}#scene=strip`);
  await ready(page);
  const hand = new Hand(page, await page.context().newCDPSession(page), finger());
  await hand.tap(page.locator('.rl-klein-toggle'), false);
  await page.locator('.rl-klein canvas').waitFor();
  const [view, pane] = await Promise.all(
    ['.rl-view > canvas', '.rl-klein'].map(async (s) => /** @type {any} */ (await page.locator(s).boundingBox())),
  );
  assert.ok(pane.y >= view.y + view.height - 1, 'the Klein view under the 3D view');
  assert.ok(Math.abs(pane.width - view.width) < 2, 'as wide');
  // the Klein view's legend under the view's, in the panel
  assert.equal(await page.locator('.rl-panel .rl-klein-legend').isVisible(), true);
  const drawn = await kleinShot(page, 'klein-phone');
  assert.ok(countDifferent(drawn, BACKGROUND) > 0.01 * drawn.width * drawn.height);
  assert.match(await page.evaluate(() => location.hash), /&klein/);
  // a tap on a point of M (a finger, a few pixels off) marks its line in both views
  const at = await onScreen(page, 7, 'klein');
  await hand.touch('touchStart', at.x, at.y);
  await hand.lift();
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.state.marked !== null);
  assert.ok(Math.abs((await marked(page)) - 7) <= 1, `line ${await marked(page)}`);
  assert.equal(await page.locator('.rl-klein-ring').isVisible(), true);
  assert.equal(await page.locator('.rl-line-mark').isVisible(), true);
  // the view's sliders under its legend in the panel, big enough for a finger; α dragged up by finger
  const alpha = page.locator('.rl-panel .rl-klein-steer input').first();
  assert.equal(await alpha.isVisible(), true);
  await alpha.scrollIntoViewIfNeeded();
  const track = /** @type {{x: number, y: number, width: number, height: number}} */ (await alpha.boundingBox());
  assert.ok(track.height >= 44, `the slider is ${track.height} px high`);
  const y = track.y + track.height / 2;
  await hand.drag(track.x + (track.width * 30) / 90, y, track.x + track.width * 0.75, y, 10);
  await page.waitForFunction(() => /klein=\d+%2C90%2C1(&|$)/.test(location.hash));
  const [mix] = await sliders(page);
  assert.ok(mix > 50 && mix <= 90, `α ${mix}`);
  assert.match((await description(page)) ?? '', new RegExp(`α = ${mix}°`));
  assert.deepEqual(problems, []);
  await page.close();

  // an element without a panel, 390 px wide: the sliders folded under their summary (the Klein
  // view's half is small), a tap unfolds them
  const host = await phone.context.newPage();
  const hostProblems = watch(host);
  await host.goto(`${started.url}examples/web-component.html`);
  await host.waitForFunction(() => customElements.get('ruled-view'));
  await host.evaluate(() => {
    document.body.innerHTML = '<ruled-view scene="strip" klein height="520"></ruled-view>';
  });
  const element = host.locator('ruled-view');
  await element.locator('.rl-klein canvas').waitFor();
  const steer = element.locator('.rl-klein-steer');
  await steer.waitFor();
  assert.equal(await steer.evaluate((d) => /** @type {HTMLDetailsElement} */ (d).open), false);
  assert.equal(await element.locator('.rl-klein-steer input').first().isVisible(), false);
  const fingerOn = new Hand(host, await host.context().newCDPSession(host), finger(11));
  await fingerOn.tap(element.locator('.rl-klein-steer summary'), false);
  await element.locator('.rl-klein-steer input').first().waitFor({ state: 'visible' });
  assert.deepEqual(hostProblems, []);
  await host.close();
});

/**
 * Where a line of the scene is on screen (page CSS px): its point on M in the Klein view
 * (`klein`), or the middle of its stroke in the 3D view — projected by each view's camera as the
 * handles' rings are (tests/page/hands.mjs).
 * @param {Page} page @param {number} i @param {'klein' | 'space'} where
 */
const onScreen = (page, i, where) =>
  page.evaluate(
    ([i, where]) => {
      const { stage } = /** @type {any} */ (window).ruledlab;
      const viewer = where === 'klein' ? stage.kleinPane.viewer : stage.viewer;
      const b = viewer.canvas.getBoundingClientRect();
      const m = viewer.camera.viewProj(b.width / b.height);
      const { segments: s, transform: t } = stage.session.built.data;
      const mid = [0, 1, 2].map((k) => (s[6 * i + k] + s[6 * i + 3 + k]) / 2);
      // (where the 3D view moves the lines: their model matrix, column-major)
      const moved = t ? [0, 1, 2].map((r) => t[r] * mid[0] + t[4 + r] * mid[1] + t[8 + r] * mid[2] + t[12 + r]) : mid;
      const p = where === 'klein' ? Array.from(stage.kleinPane.points.slice(3 * i, 3 * i + 3)) : moved;
      const w = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
      return {
        x: b.left + (((m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12]) / w + 1) / 2) * b.width,
        y: b.top + ((1 - (m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13]) / w) / 2) * b.height,
      };
    },
    /** @type {const} */ ([i, where]),
  );

/**
 * How far (px) the point `p` lies from the stroke (x1, y1)–(x2, y2): the projection of a point of
 * a line lies on the line's projected stroke (its middle need not be the stroke's middle).
 * @param {{x: number, y: number}} p @param {number[]} stroke
 */
function offStroke(p, [x1, y1, x2, y2]) {
  const [dx, dy] = [x2 - x1, y2 - y1];
  const t = Math.max(0, Math.min(1, ((p.x - x1) * dx + (p.y - y1) * dy) / (dx * dx + dy * dy)));
  return Math.hypot(x1 + t * dx - p.x, y1 + t * dy - p.y);
}

/** The marked line's stroke in the 3D view, on the page: [x1, y1, x2, y2] (CSS px). @param {Page} page */
async function markedStroke(page) {
  const box = /** @type {any} */ (await page.locator('.rl-view > canvas').boundingBox());
  const ends = await page
    .locator('.rl-line-mark line')
    .evaluate((l) => ['x1', 'y1', 'x2', 'y2'].map((k) => Number(l.getAttribute(k))));
  return ends.map((v, k) => v + (k % 2 ? box.y : box.x));
}

const marked = (/** @type {Page} */ page) =>
  page.evaluate(() => /** @type {any} */ (window).ruledlab.stage.state.marked);

test('linked both ways: pointing at a point on M marks its line in space, pointing at a line rings its point; [ and ] step the mark; a drag moves the points', async () => {
  const { page, problems } = await session.open('#scene=lines&klein');
  await kleinShot(page, 'klein-link-before');
  // a point on M: its line bold in space, its point ringed, the description says which
  let at = await onScreen(page, 5, 'klein');
  await page.mouse.move(at.x, at.y);
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.state.marked !== null);
  assert.equal(await marked(page), 5);
  assert.equal(await page.locator('.rl-line-mark').isVisible(), true, 'the line marked in space');
  assert.equal(await page.locator('.rl-klein-ring').isVisible(), true, 'its point ringed on M');
  const ring = /** @type {any} */ (await page.locator('.rl-klein-ring').boundingBox());
  assert.ok(Math.hypot(ring.x + ring.width / 2 - at.x, ring.y + ring.height / 2 - at.y) < 2, 'the ring on the point');
  assert.match((await description(page)) ?? '', /Line 5 of \d+ is marked/);
  writeFileSync(join(ARTIFACTS, 'klein-linked.png'), await page.screenshot());
  // the stroke in space runs through the line's middle, as projected
  const mid = await onScreen(page, 5, 'space');
  const stroke = await markedStroke(page);
  assert.ok(offStroke(mid, stroke) < 1.5, `stroke ${stroke}`);
  const box = /** @type {any} */ (await page.locator('.rl-view > canvas').boundingBox());
  // leaving unmarks; pointing at another line in space rings its point
  await page.mouse.move(box.x + 4, box.y + box.height - 4);
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.state.marked === null);
  assert.equal(await page.locator('.rl-klein-ring').isVisible(), false);
  at = await onScreen(page, 20, 'space');
  await page.mouse.move(at.x, at.y);
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.state.marked !== null);
  const chosen = await marked(page);
  // (lines of a surface cross on screen: the one under the pointer may be a neighbour)
  assert.ok(Math.abs(chosen - 20) <= 2, `line ${chosen}`);
  assert.equal(await page.locator('.rl-klein-ring').isVisible(), true);
  const point = await onScreen(page, chosen, 'klein');
  const ringed = /** @type {any} */ (await page.locator('.rl-klein-ring').boundingBox());
  assert.ok(Math.hypot(ringed.x + ringed.width / 2 - point.x, ringed.y + ringed.height / 2 - point.y) < 2);
  // from the keyboard: ] and [ in the Klein view step the mark, and say it
  await page.locator('.rl-klein canvas').focus();
  await page.keyboard.press(']');
  assert.equal(await marked(page), chosen + 1);
  await page.keyboard.press('[');
  await page.keyboard.press('[');
  assert.equal(await marked(page), chosen - 1);
  await page.waitForFunction(
    (i) => document.querySelector('.rl-view [aria-live]')?.textContent?.includes(`Line ${i} of`),
    chosen - 1,
  );
  assert.deepEqual(problems, []);
  await page.close();
});

test('a drag of a handle in space moves the points on M with it', async () => {
  const { page, problems } = await session.open('#scene=striction&klein');
  const before = await kleinShot(page, 'klein-drag-before');
  const frames = await kleinFrames(page);
  await page.locator('.rl-edit').click();
  const { handlesOnPage } = await import('./hands.mjs');
  const handle = (await handlesOnPage(page)).find((h) => h.free);
  assert.ok(handle, 'a handle in sight');
  await page.mouse.move(handle.x, handle.y);
  await page.mouse.down();
  await page.mouse.move(handle.x + 40, handle.y - 30, { steps: 6 });
  await page.mouse.up();
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.input !== null);
  const after = await kleinShot(page, 'klein-drag-after', { after: frames });
  assert.ok(countChanged(before, after) > 30, 'the points moved with the handle');
  assert.deepEqual(problems, []);
  await page.close();
});

test('in a scene that moves its lines (the bent surface of the isometry scene), the mark is drawn where the line is', async () => {
  const { page, problems } = await session.open('#scene=isometry&klein');
  await kleinShot(page, 'klein-isometry');
  const at = await onScreen(page, 12, 'space');
  await page.mouse.move(at.x, at.y);
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.state.marked !== null);
  const chosen = await marked(page);
  assert.ok(Math.abs(chosen - 12) <= 1, `line ${chosen}`);
  const mid = await onScreen(page, chosen, 'space');
  const stroke = await markedStroke(page);
  assert.ok(offStroke(mid, stroke) < 1.5, `the stroke on the line as drawn: ${JSON.stringify({ mid, stroke })}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('milling’s tool axes on M, and the view in German', async () => {
  // the milling scene (its CAM module loaded when asked for): its tool axes are the lines
  const { page, problems } = await session.open('#scene=milling&klein');
  await page.waitForFunction(() =>
    /the \d+ lines of the scene/.test(document.querySelector('.rl-klein .rl-sr-only')?.textContent ?? ''),
  );
  const axes = await exportedLines(page);
  assert.ok(axes > 1);
  assert.match((await description(page)) ?? '', new RegExp(`the ${axes} lines of the scene`));
  const drawn = await kleinShot(page, 'klein-milling');
  assert.ok(countDifferent(drawn, BACKGROUND) > 0.005 * drawn.width * drawn.height, 'the tool axes drawn on M');
  // in German: the button, the description, the note of a scene without lines
  await page.evaluate(() => (location.hash = '#scene=focal&klein&lang=de'));
  await page.waitForFunction(() =>
    /Daneben die Klein-Ansicht/.test(document.querySelector('.rl-klein .rl-sr-only')?.textContent ?? ''),
  );
  assert.equal(await page.locator('.rl-klein-toggle').getAttribute('aria-label'), 'Klein-Quadrik');
  assert.match((await description(page)) ?? '', /Geraden des Gitters als Punkte der Klein-Quadrik M, ein Netz/);
  await page.evaluate(() => (location.hash = '#scene=curves&klein&lang=de'));
  await page.locator('.rl-klein-note').waitFor();
  assert.match(await page.locator('.rl-klein-note').innerText(), /keine eigenen Geraden/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('in the Klein scene itself a click on a point of M, or on a line in space, marks that ruling; a press on a handle keeps the handle', async () => {
  const { page, problems } = await session.open('#scene=klein&surface=helix-tangent&n=8');
  /**
   * Where point `i` of M is drawn, on the page; or a spot on line `i` in space clear of every
   * handle (a press near a ruling's end takes the handle), where that line is the one nearest.
   */
  const at = (/** @type {number} */ i, /** @type {'point' | 'line'} */ what) =>
    page.evaluate(
      ([i, what]) => {
        const { stage } = /** @type {any} */ (window).ruledlab;
        const pick = stage.session.built.pick;
        const b = stage.viewer.canvas.getBoundingClientRect();
        const m = stage.viewer.camera.viewProj(b.width / b.height);
        const screen = (/** @type {number[]} */ p) => {
          const w = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
          return {
            x: (((m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12]) / w + 1) / 2) * b.width,
            y: ((1 - (m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13]) / w) / 2) * b.height,
          };
        };
        const page = (/** @type {{x: number, y: number}} */ q) => ({ x: b.left + q.x, y: b.top + q.y });
        if (what === 'point') return page(screen(Array.from(pick.points.slice(3 * i, 3 * i + 3))));
        const s = pick.lines;
        const t = pick.transform;
        const moved = (/** @type {number} */ u) =>
          [0, 1, 2].map((k) => {
            const q = [0, 1, 2].map((c) => (1 - u) * s[6 * i + c] + u * s[6 * i + 3 + c]);
            return t[k] * q[0] + t[4 + k] * q[1] + t[8 + k] * q[2] + t[12 + k];
          });
        const handles = stage.editor.handles().map((/** @type {any} */ h) => screen(h.world));
        for (let u = 0.2; u <= 0.8; u += 0.05) {
          const q = screen(moved(u));
          const clear = handles.every((/** @type {any} */ h) => Math.hypot(h.x - q.x, h.y - q.y) > 14);
          if (clear && stage.scenePick.nearest(q.x, q.y) === i) return page(q);
        }
        throw new Error(`no spot on line ${i} clear of the handles`);
      },
      /** @type {const} */ ([i, what]),
    );
  const mark = () => page.evaluate(() => /** @type {any} */ (window).ruledlab.stage.params.mark);
  assert.equal(await mark(), 0);
  let p = await at(3, 'point');
  await page.mouse.click(p.x + 2, p.y - 2);
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.params.mark === 3);
  await page.waitForFunction(() => /&mark=3(&|$)/.test(location.hash));
  // the view's description says which
  const said = await page.evaluate(
    () =>
      document.getElementById(document.querySelector('.rl-view > canvas')?.getAttribute('aria-describedby') ?? '')
        ?.textContent,
  );
  assert.match(said ?? '', /Ruling R_?3 is marked/);
  p = await at(6, 'line');
  await page.mouse.click(p.x, p.y);
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.params.mark === 6);
  // a drag turns the view and marks nothing
  p = await at(2, 'point');
  await page.mouse.move(p.x, p.y);
  await page.mouse.down();
  await page.mouse.move(p.x + 60, p.y + 20, { steps: 5 });
  await page.mouse.up();
  assert.equal(await mark(), 6);
  // in Edit, a press on a ruling's end takes the handle: the mark stays
  await page.locator('.rl-edit').click();
  const end = (await handlesOnPage(page))[9];
  await page.mouse.click(end.x, end.y);
  assert.equal(await page.evaluate(() => /** @type {any} */ (window).ruledlab.stage.editor.selected), 9);
  assert.equal(await mark(), 6);
  // with the Klein view beside: the ruling chosen is the line marked there too (its ring stays)
  await page.locator('.rl-edit').click();
  await page.locator('.rl-klein-toggle').click();
  await page.locator('.rl-klein canvas').waitFor();
  await page.waitForTimeout(300);
  p = await at(4, 'point');
  await page.mouse.click(p.x, p.y);
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.params.mark === 4);
  await page.waitForFunction(() => /** @type {any} */ (window).ruledlab.stage.state.marked === 4);
  assert.equal(await page.locator('.rl-klein-ring').isVisible(), true);
  assert.deepEqual(problems, []);
  await page.close();
});
