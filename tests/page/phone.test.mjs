// Every built-in exercise solved on a 390 × 844 phone with a finger, as a student would: touch
// events (Chrome DevTools' Input.dispatchTouchEvent) off by up to ±4 CSS px, using only what the
// page offers a person — a finger on a control, its number field and − / + steps, typed answers,
// and for the points: snapping (a ruling's end onto its neighbour), the ↕ and ⤡ buttons of the ✎
// bar with a fine drag after a long press (watching the value beside the point), and a point's
// coordinates typed after a tap. Check must say solved; the torsal pair's δ is 0 to 1e-12 in the
// package too.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { launch, ready, watch } from './browser.mjs';
import { Hand, drawn, finger, handlesOnPage, readNumber, liveValue, inputNow } from './hands.mjs';
import { startServer } from '../../scripts/serve.mjs';
import '../node/load.mjs';
import { RuledSurface } from '../../pkg/ruledlab.js';
import { builtInTasks } from '../../www/task/builtin.js';
import { decodeInput } from '../../www/edit/input.js';

/** @typedef {import('playwright-core').Page} Page */

/** @type {import('node:http').Server} */
let server;
let url = '';
/** @type {import('playwright-core').BrowserContext} */
let phone;
before(async () => {
  ({ server, url } = await startServer());
  phone = await launch({ viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true });
});
after(async () => {
  await phone?.close();
  server?.close();
});

/** Sets a control as a finger does: its menu, its number field, a text field, − / + or the slider itself. */
async function setControl(
  /** @type {Page} */ page,
  /** @type {Hand} */ hand,
  /** @type {string} */ key,
  /** @type {string | number | boolean} */ value,
) {
  const row = page.locator(`.rl-row[data-key="${key}"]`);
  const select = row.locator('select');
  if (await select.count()) return select.selectOption(String(value));
  const field = row.locator('input[type=text]:visible');
  if (await field.count()) {
    await hand.tap(field);
    await field.fill(String(value));
    await field.evaluate((e) => e.blur());
    return;
  }
  const param = () => page.evaluate((k) => window.ruledlab.stage.params[k], key);
  const steps = row.locator('.rl-step:visible');
  for (let k = 0; k < 60 && (await param()) !== value; k++) {
    if (await steps.count()) {
      await hand.tap(steps.nth(Number(await param()) < Number(value) ? 1 : 0));
      continue;
    }
    // the slider: a tap where the value is on its track (again where the finger missed)
    const slider = row.locator('input[type=range]');
    await slider.scrollIntoViewIfNeeded();
    const [box, min, max] = await slider.evaluate((e) => [
      e.getBoundingClientRect().toJSON(),
      Number(e.min),
      Number(e.max),
    ]);
    await hand.touch(
      'touchStart',
      box.x + 10 + ((Number(value) - min) / (max - min)) * (box.width - 20),
      box.y + box.height / 2,
    );
    await hand.lift();
  }
  assert.equal(await param(), value, `${key} set by a finger`);
}

/** The finger's ways with the points, by exercise. @type {Record<string, (page: Page, hand: Hand) => Promise<void>>} */
const POINTS = {
  // a ruling's end dragged onto its neighbour: it snaps onto the line, exactly
  async 'torsal-pair'(page, hand) {
    const handles = await handlesOnPage(page);
    const points = await page.evaluate(() => {
      const { stage } = window.ruledlab;
      const b = stage.viewer.canvas.getBoundingClientRect();
      const m = stage.viewer.camera.viewProj(b.width / b.height);
      const s = (/** @type {number[]} */ [x, y, z]) => {
        const w = m[3] * x + m[7] * y + m[11] * z + m[15];
        return [
          b.left + (((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) / 2) * b.width,
          b.top + ((1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) / 2) * b.height,
        ];
      };
      // every point drawn a snap could take instead: the handles, the footpoints, the striction points
      const drawnPoints = stage.session.built.layers
        .filter((l) => l.kind === 'points')
        .flatMap((l) =>
          Array.from({ length: l.positions.length / 3 }, (_, k) =>
            s(Array.from(l.positions.subarray(3 * k, 3 * k + 3))),
          ),
        );
      return [...stage.editor.handles().map((h) => s(h.world)), ...drawnPoints];
    });
    const n = handles.length / 2;
    for (let i = 0; i < n; i++) {
      for (const end of [0, 1]) {
        const h = handles[2 * i + end];
        if (!h.free || handles.some((o) => o !== h && Math.hypot(o.x - h.x, o.y - h.y) < 24)) continue;
        const j = (i + 1) % n;
        const [a, b] = [handles[2 * j], handles[2 * j + 1]];
        // a point of the neighbour's drawn line, away from every point a snap could prefer
        for (const t of [0.3, 0.4, 0.5, 0.6, 0.7]) {
          const x = a.x + t * (b.x - a.x),
            y = a.y + t * (b.y - a.y);
          const bar = await page.locator('.rl-bar').boundingBox();
          if (!bar || y > bar.y - 10 || points.some((p) => Math.hypot(p[0] - x, p[1] - y) < 26)) continue;
          await hand.drag(h.x, h.y, x, y, 10);
          const input = (await inputNow(page)).rulings;
          const delta = RuledSurface.fromSegments(input).invariants({ closed: true }).distribution[i];
          assert.ok(Math.abs(delta) < 1e-12, `δ_${i},${j} = ${delta} after the snap (the package's, in Node)`);
          return;
        }
      }
    }
    throw new Error('no ruling end and neighbour stand free on the phone');
  },
  // each ruling's end a dragged onto ruling 0's end a: it snaps onto the point, and the rulings
  // through one point (a cone) meet pair by pair exactly
  async 'make-developable'(page, hand) {
    for (let k = 1; k < 4; k++) {
      const handles = await handlesOnPage(page);
      const [h, apex] = [handles[2 * k], handles[0]];
      assert.ok(h.free && apex.free, `ruling ${k}, end a and ruling 0, end a are in sight, clear of the bars`);
      await hand.drag(h.x, h.y, apex.x, apex.y, 10);
      const input = (await inputNow(page)).rulings;
      const delta = RuledSurface.fromSegments(input).invariants().distribution[k - 1];
      assert.ok(Math.abs(delta) < 1e-12, `δ_${k - 1},${k} = ${delta} after the snap (the package's, in Node)`);
    }
  },
  // ruling 10's end b, ↕ along z, a fine drag down watching the height beside it
  async 'developable-cone'(page, hand) {
    await hand.tap(page.locator('.rl-edit'));
    await hand.tap(page.locator('.rl-mode-vertical'));
    const end = (await handlesOnPage(page))[21];
    assert.ok(end.free, 'ruling 10, end b is in sight, clear of the bars');
    await fineDrag(page, hand, end, 0.005);
  },
  // pose 3's tip, tapped; its z typed lower by 0.3 (the hint's number)
  async 'tool-back'(page, hand) {
    const tip = (await handlesOnPage(page))[6];
    assert.ok(tip.free, 'pose 3’s tip is in sight, clear of the bars');
    await hand.touch('touchStart', tip.x, tip.y);
    await hand.lift();
    await lowerTyped(page, hand, 0.3);
  },
  // R_5's end b, tapped (where other ends lie under the finger, the list that names each; tapped
  // again where the finger took a neighbour); its z typed lower by 0.3 (the hint's number)
  async 'klein-complex'(page, hand) {
    const heading = page.locator('.rl-coords');
    for (let tries = 0; tries < 6 && !/ruling 5, end b/.test(await heading.innerText().catch(() => '')); tries++) {
      const end = (await handlesOnPage(page))[11];
      assert.ok(end.free, 'R_5’s end b is in sight, clear of the bars');
      await hand.touch('touchStart', end.x, end.y);
      await hand.lift();
      const named = page.locator('.rl-pick button', { hasText: 'ruling 5, end b' });
      if (await named.isVisible().catch(() => false)) {
        // (a person reads the list first: a tap within PICK_SETTLE of its opening is the press's end)
        await page.waitForTimeout(500);
        await hand.tap(named, false);
      }
    }
    assert.match(await heading.innerText(), /ruling 5, end b/, 'the finger took R_5’s end b');
    await lowerTyped(page, hand, 0.3);
  },
  // ends slid along their own rulings (⤡): the lines stay, the endpoints move
  async 'line-space-slide'(page, hand) {
    await hand.tap(page.locator('.rl-edit'));
    await hand.tap(page.locator('.rl-mode-line'));
    // the turn of the endpoint scheme's rulings, as the readout shows it: each end is slid outward
    // by a third of its ruling on screen, and the slide taken back (↶) where the turn fell
    const turn = () =>
      page.evaluate(
        () => window.ruledlab.stage.session.built.readouts.find((r) => r.label === 'lines.readout.endpoints').value,
      );
    let best = await turn();
    for (let round = 0; round < 3 && best <= 0.05; round++)
      for (let k = 0; k < 18 && best <= 0.05; k++) {
        const handles = await handlesOnPage(page);
        const [h, o] = [handles[k], handles[k ^ 1]];
        if (!h.free || handles.some((g) => g !== h && Math.hypot(g.x - h.x, g.y - h.y) < 24)) continue;
        await hand.drag(h.x, h.y, h.x - (o.x - h.x) * 0.3, h.y - (o.y - h.y) * 0.3, 8);
        const now = await turn();
        if (now > best) best = now;
        else await hand.tap(page.locator('.rl-undo'));
      }
  },
};

/** The selected point's z, as its coordinates show it, typed lower by `by` and set (a tap on Move it there). */
async function lowerTyped(/** @type {Page} */ page, /** @type {Hand} */ hand, /** @type {number} */ by) {
  const z = page.locator('.rl-coords input').nth(2);
  const now = Number((await z.inputValue()).replace('−', '-'));
  await hand.tap(z);
  await z.fill(String(Math.round((now - by) * 1e6) / 1e6));
  await hand.tap(page.locator('.rl-coords-set'));
  await drawn(page);
}

/**
 * A long press on `point`, then the finger moved in small steps (the point follows at a fifth of
 * its speed along the mode's line) until the value beside it is below `goal`.
 */
async function fineDrag(
  /** @type {Page} */ page,
  /** @type {Hand} */ hand,
  /** @type {{x: number, y: number}} */ point,
  /** @type {number} */ goal,
) {
  await hand.touch('touchStart', point.x, point.y);
  await page.waitForTimeout(700);
  assert.match(await page.locator('.rl-handle-tip').innerText(), /fine/, 'a long press makes the drag fine');
  let [x, y] = [point.x, point.y];
  let direction = 1;
  let step = 6;
  let best = Number.POSITIVE_INFINITY;
  for (let k = 0; k < 160; k++) {
    y += direction * step;
    await hand.touch('touchMove', x, y);
    await drawn(page);
    await drawn(page);
    const value = await liveValue(page);
    if (value < goal) break;
    // further than the best so far: back, in smaller steps
    if (value > best) {
      direction = -direction;
      step = Math.max(2, step / 2);
    }
    best = Math.min(best, value);
  }
  await hand.lift();
}

test('every built-in exercise solved on a 390 × 844 phone with a finger off by up to ±4 px', async () => {
  const solved = [];
  for (const task of builtInTasks()) {
    const page = await phone.newPage();
    const problems = watch(page);
    const cdp = await page.context().newCDPSession(page);
    const hand = new Hand(page, cdp, finger(task.id.length * 7919));
    await page.goto(`${url}#task=${task.id}`);
    await ready(page);
    const solution = task.solution ?? {};
    for (const [key, value] of Object.entries(solution.params ?? {}))
      if (task.change.includes(key)) await setControl(page, hand, key, value);
    if (task.change.includes('handles')) {
      const way = POINTS[task.id];
      if (way) await way(page, hand);
      else {
        // a new exercise: its solution's points, typed after a tap on each (where it allows typing)
        const target = solution.input ? decodeInput(solution.input) : null;
        assert.ok(target && (task.edit?.typed ?? true), `${task.id}: no finger way to its points`);
        await typePoints(page, hand, target);
      }
    }
    for (const answer of task.answers) {
      const value = solution.answers?.[answer.id];
      // what a student reads off the figure (the δ kept by bending), or worked out
      const typed =
        task.id === 'minding-delta'
          ? await page
              .evaluate(() => {
                // the number as the readout shows it
                const k = window.ruledlab.stage.session.built.readouts.findIndex(
                  (r) => r.label === 'isometry.readout.delta',
                );
                return document.querySelectorAll('.rl-readout dd')[k].textContent;
              })
              .then((shown) => String(readNumber(shown)))
          : value && typeof value === 'object' && 'value' in value
            ? // a number the scene computes for the numbers drawn (a count worked out by hand)
              await page.evaluate(
                (key) => window.ruledlab.stage.session.built.readouts.find((r) => r.label === key)?.value,
                value.value,
              )
            : value;
      const fields = Array.isArray(typed)
        ? typed.map((_, k) => `task-${answer.id}-${'xyz'[k]}`)
        : [`task-${answer.id}`];
      for (const [k, name] of fields.entries()) {
        const field = page.locator(`input[name="${name}"]`);
        await hand.tap(field);
        await field.fill(String(Array.isArray(typed) ? typed[k] : typed));
      }
    }
    // Check, tapped again where the page did not take the tap (as a student would): on a loaded
    // machine a tap can land while the page is still settling from the last move
    const verdictShown = page.locator('.rl-task-verdict');
    for (let tries = 0; tries < 3 && !(await verdictShown.isVisible()); tries++) {
      await hand.tap(page.locator('.rl-task-check'));
      await verdictShown.waitFor({ state: 'visible', timeout: 8_000 }).catch(() => {});
    }
    assert.ok(await verdictShown.isVisible(), `${task.id}: Check gave no verdict after three taps`);
    const verdict = await page.locator('.rl-task-verdict').innerText();
    assert.match(verdict, /Solved/, `${task.id}: ${verdict}`);
    assert.deepEqual(problems, [], task.id);
    solved.push(task.id);
    await page.close();
  }
  assert.equal(solved.length, builtInTasks().length);
});

/** Each point of `target` that differs from the page's, tapped and its coordinates typed. */
async function typePoints(
  /** @type {Page} */ page,
  /** @type {Hand} */ hand,
  /** @type {import('../../www/scene.js').Input} */ target,
) {
  const now = await inputNow(page);
  const handles = await handlesOnPage(page);
  let k = 0;
  for (const [key, points] of Object.entries(target))
    for (let i = 0; 3 * i < points.length; i++, k++) {
      const p = Array.from(points.subarray(3 * i, 3 * i + 3));
      if (p.every((x, c) => x === now[key][3 * i + c])) continue;
      await hand.touch('touchStart', handles[k].x, handles[k].y);
      await hand.lift();
      const fields = page.locator('.rl-coords input');
      for (let c = 0; c < 3; c++) await fields.nth(c).fill(String(p[c]));
      await hand.tap(page.locator('.rl-coords-set'));
    }
}

test('phone keyboards: a number answer takes a minus (the keyboard, not iOS’s decimal keypad, which has none), a fraction field too; no answer or formula field capitalises or corrects; the view’s name lists the gestures', async () => {
  const page = await phone.newPage();
  const problems = watch(page);
  /** The keyboard attributes of the fields `selector` finds. */
  const keyboard = (/** @type {string} */ selector) =>
    page.$$eval(selector, (fields) =>
      fields.map((f) => [f.getAttribute('inputmode'), f.getAttribute('autocapitalize'), f.getAttribute('autocorrect')]),
    );
  // minding-delta: its answer is −1.711
  await page.goto(`${url}#task=minding-delta`);
  await ready(page);
  assert.deepEqual(await keyboard('input[name="task-delta"]'), [['text', 'off', 'off']]);
  // the view's accessible name says the gestures too, not only keys and mouse
  assert.match(
    /** @type {string} */ (await page.locator('.rl-view canvas').getAttribute('aria-label')),
    /On a touch screen, drag one finger to turn it, two fingers together to move it, and spread or pinch two fingers to zoom\.$/,
  );
  await page.locator('input[name="task-delta"]').fill('−1.711');
  assert.equal(await page.locator('input[name="task-delta"]').inputValue(), '−1.711');
  // a curve typed as three formulas
  await page.goto(`${url}#task=hypar-striction`);
  await ready(page);
  assert.deepEqual(await keyboard('.rl-task-answers input'), Array(3).fill(['text', 'off', 'off']));
  // the scene's own formula fields, and the exact value of w (from −0.05, and fractions as 1/13)
  await page.goto(`${url}#scene=formula`);
  await ready(page);
  const formulas = await keyboard('.rl-controls input.rl-formula');
  assert.ok(formulas.length >= 6, `${formulas.length} formula fields`);
  for (const f of formulas) assert.deepEqual(f.slice(1), ['off', 'off']);
  await page.goto(`${url}#scene=curves&scheme=four-point`);
  await ready(page);
  assert.deepEqual(await keyboard('.rl-row[data-key="w"] input.rl-exact'), [['text', null, null]]);
  assert.deepEqual(problems, []);
  await page.close();
});
