// Precise by hand: a ruling's end dragged near its neighbour (mouse) or stepped there (keyboard)
// snaps onto the line — δ of the pair 0 to 1e-12 in the package, in Node — and says so; S turns
// snapping off; the values beside the point are the package's for the moved input; an exercise's
// constraints hold (fixed, on a line) and one that cannot is said and lifted; on a phone ✎ keeps
// the page where it is, the edit toolbar has Fit and covers no point, editing ends with the
// scene, points on top of each other come as a list, a pinch zooms by the fingers' ratio; the
// keyboard turns and resets the view while it edits, and D says what the figure shows.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { launch, pageSession, ready, watch } from './browser.mjs';
import { Hand, drawn, finger, handlesOnPage, inputNow } from './hands.mjs';
import '../node/load.mjs';
import { RuledSurface } from '../../pkg/ruledlab.js';
import { translator } from '../../www/i18n/index.js';
import { rulingValues } from '../../www/edit/sets.js';
import { valueText } from '../../www/ui/readout.js';
import { taskLink, readTask } from '../../www/task/format.js';

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
const session = pageSession();

/** @typedef {import('playwright-core').Page} Page */

/** δ of every pair of the page's rulings, computed by the package in Node (a closed surface). */
async function deltas(/** @type {Page} */ page, closed = true) {
  return Array.from(RuledSurface.fromSegments((await inputNow(page)).rulings).invariants({ closed }).distribution);
}

/**
 * Ruling `i`'s end `end` and a point of ruling `j`'s drawn line on screen, away from every point a
 * snap would prefer (handles, footpoints, striction points).
 */
async function aim(/** @type {Page} */ page, /** @type {number} */ i, /** @type {number} */ j) {
  return page.evaluate(
    ([i, j]) => {
      const { stage } = window.ruledlab;
      const b = stage.viewer.canvas.getBoundingClientRect();
      const m = stage.viewer.camera.viewProj(b.width / b.height);
      const s = (/** @type {ArrayLike<number>} */ p) => {
        const w = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
        return {
          x: b.left + (((m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12]) / w + 1) / 2) * b.width,
          y: b.top + ((1 - (m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13]) / w) / 2) * b.height,
        };
      };
      const handles = stage.editor.handles().map((h) => s(h.world));
      const drawnPoints = stage.session.built.layers
        .filter((l) => l.kind === 'points')
        .flatMap((l) => Array.from({ length: l.positions.length / 3 }, (_, k) => s(l.positions.subarray(3 * k))));
      const [a, c] = [handles[2 * j], handles[2 * j + 1]];
      for (const t of [0.35, 0.45, 0.55, 0.65, 0.25, 0.75]) {
        const p = { x: a.x + t * (c.x - a.x), y: a.y + t * (c.y - a.y) };
        if ([...handles, ...drawnPoints].every((q) => Math.hypot(q.x - p.x, q.y - p.y) > 20))
          return { from: handles[2 * i], to: p };
      }
      return null;
    },
    [i, j],
  );
}

/** A mouse drag from `from` to `to` (client px), ending 2 px off the line. */
async function mouseDrag(
  /** @type {Page} */ page,
  /** @type {{x: number, y: number}} */ from,
  /** @type {{x: number, y: number}} */ to,
) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let s = 1; s <= 10; s++)
    await page.mouse.move(from.x + ((to.x + 2 - from.x) * s) / 10, from.y + ((to.y - 2 - from.y) * s) / 10);
}

test('a ruling’s end snaps onto its neighbour exactly — mouse and keyboard; S turns snapping off; the values beside it are the package’s', async () => {
  const { page, problems } = await session.open('index.html#scene=striction&surface=hyperboloid&n=8');
  // the mouse: ruling 0's end a near ruling 1 (its line, not a point): the tip says it snapped
  const path = await aim(page, 0, 1);
  assert.ok(path, 'ruling 1 stands free of points on screen');
  await mouseDrag(page, path.from, path.to);
  await drawn(page);
  assert.match(await page.locator('.rl-handle-tip').innerText(), /◆ on ruling 1/);
  assert.equal(await page.locator('.rl-snap-mark').isVisible(), true, 'a mark where it snapped');
  await page.mouse.up();
  await drawn(page);
  assert.ok(Math.abs((await deltas(page))[0]) < 1e-12, `δ_0,1 = ${(await deltas(page))[0]}`);
  // the live values of the chosen point are the package's on the moved input (a click chooses it)
  const end = (await handlesOnPage(page))[0];
  await page.mouse.click(end.x, end.y);
  await drawn(page);
  const shown = await page.locator('.rl-coords-values dd').allInnerTexts();
  const i18n = translator('en');
  const rulings = (await inputNow(page)).rulings;
  const inv = RuledSurface.fromSegments(rulings).invariants({ closed: true });
  const expected = rulingValues(inv, 8, i18n.t)(0, 0).map((v) => valueText(v.value, v.exactZero, i18n));
  assert.deepEqual(shown, expected, 'φ, h, δ of both pairs and δ̄ beside the point');
  assert.ok(shown.includes('exact'), 'δ_0,1 is said to be exactly 0');
  // typed coordinates (German commas and a minus sign too): the end exactly there, one step of undo
  const fields = page.locator('.rl-coords input');
  for (const [c, text] of ['1', '−2', '0,5'].entries()) await fields.nth(c).fill(text);
  await page.locator('.rl-coords-set').click();
  await drawn(page);
  assert.deepEqual((await inputNow(page)).rulings.slice(0, 3), [1, -2, 0.5]);
  await page.keyboard.press('Control+z');
  await page.keyboard.press('Control+z');
  await drawn(page);
  const before = (await inputNow(page)).rulings.slice(0, 3);
  assert.ok(Math.abs((await deltas(page))[0]) > 0.1, 'two undos: skew again');

  // the keyboard: E, the end of ruling 2, arrows towards ruling 3 until it snaps, Enter
  const target = await aim(page, 2, 3);
  assert.ok(target);
  await page.focus('.rl-view canvas');
  await page.keyboard.press('e');
  for (let k = 0; k < 4; k++) await page.keyboard.press(']');
  assert.equal(await page.evaluate(() => window.ruledlab.stage.editor.selected), 4);
  let snapped = false;
  for (let k = 0; k < 80 && !snapped; k++) {
    const h = (await handlesOnPage(page))[4];
    // the foot of the aim on screen: press the arrow along the larger offset
    const [dx, dy] = [target.to.x - h.x, target.to.y - h.y];
    await page.keyboard.press(
      Math.abs(dx) > Math.abs(dy) ? (dx > 0 ? 'ArrowRight' : 'ArrowLeft') : dy > 0 ? 'ArrowDown' : 'ArrowUp',
    );
    await drawn(page);
    snapped = /◆ on ruling 3/.test(await page.locator('.rl-handle-tip').innerText());
  }
  assert.ok(snapped, 'the arrow keys brought the end onto ruling 3');
  await page.keyboard.press('Enter');
  await drawn(page);
  assert.ok(Math.abs((await deltas(page))[2]) < 1e-12, `δ_2,3 = ${(await deltas(page))[2]}`);
  await page.keyboard.press('Escape');

  // S: snapping off; the same mouse drag leaves the pair skew (and the ⌖ button says so)
  await page.keyboard.press('Control+z');
  await page.focus('.rl-view canvas');
  await page.keyboard.press('s');
  assert.equal(await page.locator('.rl-snap').getAttribute('aria-pressed'), 'false');
  const again = await aim(page, 0, 1);
  assert.ok(again);
  await mouseDrag(page, again.from, again.to);
  await page.mouse.up();
  await drawn(page);
  assert.ok(Math.abs((await deltas(page))[0]) > 1e-6, 'without snapping the end lands where the pointer is');
  assert.notDeepEqual((await inputNow(page)).rulings.slice(0, 3), before);
  await page.focus('.rl-view canvas');
  await page.keyboard.press('s');
  assert.equal(await page.locator('.rl-snap').getAttribute('aria-pressed'), 'true');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a snap onto a striction point or a footpoint is named with its subscripts, in the tip and in what is said: m₄, f₄,₅, never m_{4}', async () => {
  const { page, problems } = await session.open(
    'index.html#scene=striction&surface=hyperboloid&n=8&normals=1&polygon=1',
  );
  /** The screen point of the `k`-th point of the snap targets named `name` (client px). */
  const targetOnScreen = (/** @type {string} */ name, /** @type {number} */ k) =>
    page.evaluate(
      ([name, k]) => {
        const { stage } = window.ruledlab;
        const b = stage.viewer.canvas.getBoundingClientRect();
        const m = stage.viewer.camera.viewProj(b.width / b.height);
        const group = stage.editor.sets[0].targets.find((/** @type {any} */ g) => g.name === name);
        const p = group.points.subarray(3 * Number(k), 3 * Number(k) + 3);
        const w = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
        return {
          x: b.left + (((m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12]) / w + 1) / 2) * b.width,
          y: b.top + ((1 - (m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13]) / w) / 2) * b.height,
        };
      },
      [name, k],
    );
  // ruling 0's end a onto m_4 (the closed surface's striction points are m_0 … m_7), then onto
  // f_4,5 (the footpoint on ruling 4 of the pair (4, 5): target 8)
  for (const [name, k, said] of /** @type {const} */ ([
    ['snap.striction', 4, 'on the striction point m₄'],
    ['snap.footpoint', 8, 'on the footpoint f₄,₅'],
  ])) {
    const from = (await handlesOnPage(page))[0];
    const to = await targetOnScreen(name, k);
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    for (let s = 1; s <= 10; s++)
      await page.mouse.move(from.x + ((to.x + 1 - from.x) * s) / 10, from.y + ((to.y - 1 - from.y) * s) / 10);
    await drawn(page);
    const tip = await page.locator('.rl-tip-snap').innerText();
    assert.equal(tip, `◆ ${said}`);
    const live = await page.evaluate(() => document.querySelector('.rl-stage [aria-live]')?.textContent ?? '');
    assert.ok(live.includes(said), `said: ${live}`);
    await page.mouse.up();
    await drawn(page);
    const after = await page.evaluate(() => document.querySelector('.rl-stage [aria-live]')?.textContent ?? '');
    assert.doesNotMatch(after, /[_{}]/, `said after the drag: ${after}`);
    await page.keyboard.press('Control+z');
    await drawn(page);
  }
  assert.deepEqual(problems, []);
  await page.close();
});

test('an exercise holds its points: fixed, on a line (exactly), and a constraint that cannot hold is said and lifted', async () => {
  const task = readTask({
    ruledlab: 'exercise',
    version: 1,
    id: 'held-points',
    title: { en: 'Held points' },
    prompt: { en: 'Move ruling 1 so that it meets ruling 2.' },
    scene: 'striction',
    params: { surface: 'hyperboloid', n: 8 },
    change: ['handles'],
    // the second condition's value is hidden: beside the point only "closer" or "further"
    goal: [
      { value: 'striction.minAbsDelta', below: 0.01 },
      { value: 'readout.meanDelta', below: -100 },
    ],
    hide: ['readout.meanDelta'],
    edit: {
      constraints: [
        { handle: 'rulings.0', on: 'fixed' },
        { handle: 'rulings.3', on: 'line', direction: [0, 0, 1] },
        { handle: 'rulings.99', on: 'fixed' },
      ],
    },
  });
  const { page, problems } = await session.open(`index.html#task=${taskLink(task, () => false)}`);
  assert.match(await page.locator('.rl-note').innerText(), /“rulings\.99” this scene does not have/);
  const start = (await inputNow(page)).rulings;
  const handles = await handlesOnPage(page);
  // the fixed end does not follow the mouse
  await page.mouse.move(handles[0].x, handles[0].y);
  await page.mouse.down();
  for (let s = 1; s <= 6; s++) await page.mouse.move(handles[0].x + 8 * s, handles[0].y - 6 * s);
  await page.mouse.up();
  await drawn(page);
  assert.deepEqual((await inputNow(page)).rulings.slice(0, 3), start.slice(0, 3));
  // ruling 1's end b stays on its vertical: x and y bit for bit, z moved
  await page.mouse.move(handles[3].x, handles[3].y);
  await page.mouse.down();
  for (let s = 1; s <= 6; s++) await page.mouse.move(handles[3].x + 9 * s, handles[3].y + 7 * s);
  await drawn(page);
  const goals = await page
    .locator('.rl-handle-tip .rl-tip-value.rl-fails, .rl-handle-tip .rl-tip-value.rl-holds')
    .allInnerTexts();
  assert.equal(goals.length, 2, goals.join(' | '));
  assert.match(goals[0], /^the smallest \|δ\| of a pair of rulings: [\d.·⁻−]+ \(goal: below 0\.01\)/);
  assert.match(goals[1], /^δ̄ at the middle ruling: (closer|further|no change)$/, 'a hidden value is not shown');
  await page.mouse.up();
  await drawn(page);
  // the finger lifted: the tip stays with the conditions on the new figure, and they are said
  const after = await page
    .locator('.rl-handle-tip:visible .rl-tip-value.rl-fails, .rl-handle-tip:visible .rl-tip-value.rl-holds')
    .count();
  assert.equal(after, 2, 'the conditions beside the point after the drag');
  await page.waitForFunction(() =>
    /conditions? on the figure hold/.test(document.querySelector('.rl-stage [aria-live]')?.textContent ?? ''),
  );
  const moved = (await inputNow(page)).rulings;
  assert.deepEqual(moved.slice(9, 11), start.slice(9, 11), 'on the line through it along z');
  assert.notEqual(moved[11], start[11]);
  // the tip may always be dismissed: Escape on the view hides it; a new figure does not keep it
  await page.focus('.rl-view canvas');
  await page.keyboard.press('Escape');
  assert.equal(await page.locator('.rl-handle-tip').isVisible(), false, 'Escape dismissed the tip');
  const again = (await handlesOnPage(page))[3];
  await page.mouse.move(again.x, again.y);
  await page.mouse.down();
  for (let s = 1; s <= 3; s++) await page.mouse.move(again.x + 9 * s, again.y - 7 * s);
  await page.mouse.up();
  await drawn(page);
  assert.equal(await page.locator('.rl-handle-tip').isVisible(), true, 'the tip after a second drag');
  await page.locator('.rl-task-leave').click();
  assert.equal(await page.locator('.rl-handle-tip').isVisible(), false, 'the tip left with the exercise');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a phone: ✎ keeps the page where it is, the edit toolbar has Fit and covers no point, editing ends with the scene; points on top of each other come as a list; a pinch zooms by the fingers’ ratio', async () => {
  const phone = await launch({ viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true });
  try {
    const page = await phone.newPage();
    const problems = watch(page);
    const cdp = await page.context().newCDPSession(page);
    const hand = new Hand(page, cdp, finger(3));
    await page.goto(`${session.url}#task=developable-cone`);
    await ready(page);
    // the exercise in sight, then ✎: nothing scrolls
    await page.evaluate(() => document.querySelector('.rl-task')?.scrollIntoView({ block: 'end' }));
    const scrolled = await page.evaluate(() => scrollY);
    await hand.tap(page.locator('.rl-edit'), false);
    assert.equal(await page.evaluate(() => window.ruledlab.stage.editor.editing), true);
    assert.equal(await page.evaluate(() => scrollY), scrolled, '✎ did not scroll the page');
    assert.equal(await page.evaluate(() => document.activeElement?.tagName), 'CANVAS');
    // Fit in the edit toolbar; no point under the bar
    assert.equal(await page.locator('.rl-fit').isVisible(), true, 'Fit while editing');
    await hand.tap(page.locator('.rl-fit'));
    const bar = /** @type {{y: number}} */ (await page.locator('.rl-bar').boundingBox());
    const under = (await handlesOnPage(page)).filter((h) => h.y > bar.y - 4);
    assert.deepEqual(under, [], 'no point under the edit toolbar');
    // the cone's a-ends at its apex: a finger there gets the list, a choice, then the drag moves it
    const handles = await handlesOnPage(page);
    const blob = handles.find(
      (h, k) => k % 2 === 0 && handles.some((o, j) => j !== k && Math.hypot(o.x - h.x, o.y - h.y) < 6),
    );
    assert.ok(blob, 'a-ends on top of each other');
    await hand.touch('touchStart', blob.x, blob.y);
    await hand.lift();
    const list = page.locator('.rl-pick');
    assert.equal(await list.isVisible(), true, 'the list of points there');
    const choices = await list.locator('button').allInnerTexts();
    assert.ok(choices.length >= 2 && choices.every((c) => /^ruling \d+, end a$/.test(c)), choices.join(' | '));
    // axe: the list open, the edit bar and the panel are clean
    await page.evaluate(AXE);
    const result = await page.evaluate(() =>
      window.axe.run(document, {
        runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa'] },
      }),
    );
    assert.deepEqual(
      result.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`),
      [],
    );
    const chosen = list.locator('button').nth(1);
    const name = await chosen.innerText();
    const k = Number(await chosen.getAttribute('data-handle'));
    // (a person reads the list before choosing)
    await page.waitForTimeout(400);
    await hand.tap(chosen);
    assert.equal(await list.isVisible(), false);
    assert.match(await page.locator('.rl-coords h3').innerText(), new RegExp(name));
    const before = await inputNow(page);
    const at = (await handlesOnPage(page))[k];
    await hand.drag(at.x, at.y, at.x + 30, at.y - 20, 6);
    const after = await inputNow(page);
    const movedHandles = [];
    for (let i = 0; 3 * i < after.rulings.length; i++)
      if ([0, 1, 2].some((c) => after.rulings[3 * i + c] !== before.rulings[3 * i + c])) movedHandles.push(i);
    assert.deepEqual(movedHandles, [k], 'the chosen point, and only it');
    // a pinch: the fingers six times as far apart, the view six times as close
    const distance = () => page.evaluate(() => window.ruledlab.stage.viewer.camera.distance);
    const d0 = await distance();
    const c = await page.locator('.rl-view canvas').boundingBox();
    assert.ok(c);
    const [cx, cy] = [c.x + c.width / 2, c.y + 60];
    const pinch = async (/** @type {'touchStart' | 'touchMove'} */ type, /** @type {number} */ half) =>
      cdp.send('Input.dispatchTouchEvent', {
        type,
        touchPoints: [
          { x: cx - half, y: cy, id: 1 },
          { x: cx + half, y: cy, id: 2 },
        ],
      });
    await pinch('touchStart', 10);
    for (let s = 1; s <= 10; s++) await pinch('touchMove', 10 + 5 * s);
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    const ratio = d0 / (await distance());
    assert.ok(Math.abs(ratio - 6) < 0.06, `a 6× spread zoomed ${ratio.toFixed(2)}×`);
    // another scene: editing ends
    await page.evaluate(() => {
      location.hash = '#scene=curves';
    });
    await page.waitForFunction(() => document.querySelector('.rl-stage')?.dataset.scene === 'curves');
    assert.equal(await page.evaluate(() => window.ruledlab.stage.editor.editing), false, 'editing ended');
    assert.equal(await page.locator('.rl-editbar').isVisible(), false);
    assert.deepEqual(problems, []);
  } finally {
    await phone.close();
  }
});

test('the keyboard turns and resets the view while it moves points; D says what the figure shows', async () => {
  const { page, problems } = await session.open('index.html#scene=isometry&n=8');
  const camera = () => page.evaluate(() => window.ruledlab.stage.viewer.camera.toArray());
  const home = await camera();
  await page.focus('.rl-view canvas');
  await page.keyboard.press('e');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Enter');
  assert.deepEqual(await camera(), home, 'the arrows moved a point, not the view');
  await page.keyboard.press('j');
  await page.keyboard.press('i');
  const turned = await camera();
  assert.ok(turned[0] > home[0] && turned[1] > home[1], 'J and I turned the view while editing');
  await page.keyboard.press('+');
  assert.ok((await camera())[2] < home[2], '+ zoomed in');
  await page.keyboard.press('0');
  assert.deepEqual(await camera(), home, '0 is the fitted view again');
  await page.keyboard.press('d');
  const said = await page.evaluate(() => document.querySelector('.rl-stage [aria-live]')?.textContent ?? '');
  assert.match(
    said,
    /^The input, edited\. Surface: .*8 rulings, bent isometrically .* the conoidal model is .* high\.$/,
  );
  assert.deepEqual(problems, []);
  await page.close();
});
