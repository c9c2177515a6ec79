// The exercise author and Share as a lecturer uses them, with the keyboard alone: a typed answer
// (δ(u) checked against the exact curve, a number against a value the scene computes), a
// parameter drawn per attempt, the warnings (a start that already passes, a solution that fails —
// the tangent surface of a helix the prompt calls developable, with the value; a draw for which
// the start passes), Copy on every snippet, ids that keep their letters; Share's options of what
// readers may do, carried into the iframe and the element, Leave shown only where allowed; the
// element's seed, the same numbers as the link's.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { pageSession, ready, setControl } from './browser.mjs';
import { otherOrigin, hostPage } from './places.mjs';

const session = pageSession();
const site = otherOrigin();
const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

/** axe-core's WCAG 2.1 A/AA violations on `page` (none expected). */
async function axe(/** @type {Page} */ page) {
  await page.evaluate(AXE);
  const result = await page.evaluate(() =>
    window.axe.run(document, { runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] } }),
  );
  return result.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
}

/** @typedef {import('playwright-core').Page} Page */

const focused = (/** @type {Page} */ page) => page.evaluate(() => document.activeElement?.getAttribute('name') ?? '');

/** Tab (forward) until the control named `name` has the keyboard; fails after `most` presses. */
async function tabTo(/** @type {Page} */ page, /** @type {string} */ name, most = 60) {
  for (let k = 0; k < most; k++) {
    if ((await focused(page)) === name) return;
    await page.keyboard.press('Tab');
  }
  assert.fail(`${name} was not reached by Tab (at ${await focused(page)})`);
}

/** Types into the focused field, replacing what it holds. */
async function retype(/** @type {Page} */ page, /** @type {string} */ text) {
  await page.keyboard.press('Control+a');
  await page.keyboard.type(text);
}

/** Share, then "Make an exercise", by keyboard. */
async function openAuthor(/** @type {Page} */ page) {
  await page.locator('#share').focus();
  await page.keyboard.press('Enter');
  await page.locator('#share-exercise').focus();
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => document.activeElement?.getAttribute('name') === 'author-title');
}

test('with the keyboard alone: a typed δ(u) and a parameter drawn per attempt; the id keeps its letters; Copy on every snippet; the link works for its numbers', async () => {
  // the lecturer's view: the hyperbolic paraboloid, its e(u) = (0, 1, a·u), a = 2
  const { page, problems } = await session.open('index.html#scene=formula&tool=striction');
  await setControl(page, 'preset', 'hyperbolic-paraboloid');
  await setControl(page, 'ez', 'a*u');
  await setControl(page, 'a', 2);
  await openAuthor(page);
  await page.keyboard.type('Was heißt δ(u)?');
  await page.keyboard.press('Tab');
  await page.keyboard.type('For e(u) = (0, 1, {a}·u): type δ(u).');
  // the parameter a: drawn per attempt, from 2 to 3
  await tabTo(page, 'author-a');
  for (let k = 0; k < 3; k++) await page.keyboard.press('ArrowDown');
  assert.equal(await page.locator('[name="author-a"]').inputValue(), 'draw');
  assert.equal(await focused(page), 'author-a', 'the keyboard stays on the menu');
  await page.keyboard.press('Tab');
  assert.equal(await focused(page), 'author-draw-a-from');
  // from 2 to 3 in steps of 1, each field settled before the next is typed (the author's form is
  // written anew after a change: on a loaded machine a frame or two later)
  for (const [part, value] of [
    ['from', '2'],
    ['to', '3'],
    ['step', '1'],
  ]) {
    await tabTo(page, `author-draw-a-${part}`);
    const typed = await page.locator(`[name="author-draw-a-${part}"]`).elementHandle();
    await retype(page, value);
    await page.keyboard.press('Tab');
    // settled: the form written anew (a new field) with the value typed
    await page.waitForFunction(
      ([name, v, old]) => {
        const input = /** @type {HTMLInputElement | null} */ (document.querySelector(`[name="${name}"]`));
        return input !== old && input?.value === v;
      },
      /** @type {const} */ ([`author-draw-a-${part}`, value, typed]),
    );
  }
  await page.waitForTimeout(100);
  assert.match(await page.locator('.rl-author-draw .rl-author-note').innerText(), /Write \{a\} in the title/);
  // an answer: δ(u), with the answer of the solution typed
  await tabTo(page, 'author-answer-add');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => document.activeElement?.getAttribute('name') === 'author-answer-kind-0');
  await page.keyboard.press('ArrowDown');
  assert.equal(await page.locator('[name="author-answer-kind-0"]').inputValue(), 'function');
  assert.equal(await page.locator('[name="author-answer-label-0"]').inputValue(), 'δ(u)');
  await tabTo(page, 'author-answer-solution-0');
  // a solution that is wrong for the numbers drawn (it is δ for a = 1): warned, for each a, with how far it is
  await page.keyboard.type('1 + u^2');
  await page.keyboard.press('Tab');
  await page.waitForTimeout(100);
  const warned = await page.locator('.rl-author-warnings').innerText();
  assert.match(
    warned,
    /With a = 2: the solution fails condition 1 \(your δ\(u\) agrees with the exact distribution parameter to within 10⁻⁶\): up to [\d.]+ away/,
  );
  assert.match(warned, /With a = 3: the solution fails/);
  await page.keyboard.press('Shift+Tab');
  assert.equal(await focused(page), 'author-answer-solution-0');
  await retype(page, '(1 + a^2*u^2)/a');
  await page.keyboard.press('Tab');
  await page.waitForTimeout(100);
  // for every number drawn the solution holds and the start does not: no warning
  assert.equal(await page.locator('.rl-author-warnings').isHidden(), true);
  // the goal lists the answer as a condition too
  assert.match(
    await page.locator('.rl-author-goal .rl-author-answer-status').innerText(),
    /your δ\(u\) agrees with the exact distribution parameter to within 10⁻⁶: the reader answers it; holds in the solution/,
  );
  await tabTo(page, 'author-make', 80).catch(() => {});
  await page.getByRole('button', { name: 'Make the exercise' }).focus();
  await page.keyboard.press('Enter');
  await page.waitForSelector('#author-json');
  const json = JSON.parse(await page.locator('#author-json').inputValue());
  assert.match(json.id, /^was-heisst-delta-u-[a-z0-9]+$/);
  assert.deepEqual(json.draw, { a: { from: 2, to: 3, step: 1 } });
  assert.deepEqual(json.params.a, { drawn: 'a' });
  assert.deepEqual(json.answers, [{ id: 'answer1', kind: 'function', label: { en: 'δ(u)' } }]);
  assert.deepEqual(json.goal, [{ answer: 'answer1', matches: 'distribution', within: 1e-6 }]);
  assert.deepEqual(json.solution, { answers: { answer1: '(1 + a^2*u^2)/a' } });
  // a Copy button for each snippet, in the author too; Enter on one copies it
  const copies = page.locator('.rl-author-result .share-row button.copy');
  assert.equal(await copies.count(), 4);
  await copies.last().focus();
  await page.keyboard.press('Enter');
  await page
    .locator('.rl-author-result .share-row .share-done')
    .last()
    .filter({ hasText: /Copied|Selected/ })
    .waitFor();
  // copied, the keyboard stays on the button; else it is in the selected text, for Ctrl+C
  const said = await page.locator('.rl-author-result .share-row .share-done').last().textContent();
  assert.equal(
    await page.evaluate(() => document.activeElement?.tagName),
    /Copied/.test(said ?? '') ? 'BUTTON' : 'TEXTAREA',
  );
  // the packages, offered here too
  assert.equal(
    await page.locator('[name="author-scorm12"], [name="author-scorm2004"], [name="author-h5p"]').count(),
    3,
  );
  const link = await page.locator('#author-link').inputValue();
  assert.deepEqual(problems, []);
  await page.close();
  // the link as handed out, with a seed: that reader's a, the exact δ(u) for it
  const reader = await session.open(`${link.replace(session.url, '')}&seed=1`);
  const a = await reader.page.evaluate(() => window.ruledlab.stage.params.a);
  assert.ok(a === 2 || a === 3, `a = ${a}`);
  assert.match(await reader.page.locator('.rl-task-prompt').innerText(), new RegExp(`\\(0, 1, ${a}·u\\)`));
  await reader.page.locator('input[name="task-answer1"]').fill(`1/${a} + ${a}*u^2`);
  await reader.page.keyboard.press('Enter');
  console.log(
    await reader.page.locator('.rl-task').innerText(),
    await reader.page.evaluate(() => JSON.stringify(window.ruledlab.stage.params)),
  );
  assert.match(await reader.page.locator('.rl-task-verdict').innerText(), /^✓ Solved/);
  assert.deepEqual(reader.problems, []);
  await reader.page.close();
});

test('a typed number compared with a value the scene computes; the solution answer is that value', async () => {
  const { page, problems } = await session.open('index.html#scene=isometry&surface=quartic&layout=bend&n=24&t=0');
  await openAuthor(page);
  await page.keyboard.type('δ of the middle pair');
  await tabTo(page, 'author-answer-add');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => document.activeElement?.getAttribute('name') === 'author-answer-kind-0');
  await page.selectOption('[name="author-answer-target-0"]', 'isometry.deltaMiddle');
  await page.locator('[name="author-answer-label-0"]').fill('δ');
  await page.locator('[name="author-answer-label-0"]').dispatchEvent('change');
  await page.locator('[name="author-answer-within-0"]').fill('0.0001');
  await page.locator('[name="author-answer-within-0"]').dispatchEvent('change');
  await page.getByRole('button', { name: 'Make the exercise' }).click();
  await page.waitForSelector('#author-json');
  const json = JSON.parse(await page.locator('#author-json').inputValue());
  assert.deepEqual(json.goal, [{ answer: 'answer1', near: { value: 'isometry.deltaMiddle' }, within: 0.0001 }]);
  assert.deepEqual(json.solution, { answers: { answer1: { value: 'isometry.deltaMiddle' } } });
  // tried as a reader: a wrong number says which way, the solution fills in the value and holds
  await page.getByRole('button', { name: 'Try it as a reader' }).click();
  await page.waitForSelector('.rl-task input[name="task-answer1"]');
  await page.locator('input[name="task-answer1"]').fill('1');
  await page.locator('.rl-task-check').click();
  assert.match(await page.locator('.rl-task-results li').first().innerText(), /not right yet: too large/);
  await page.locator('.rl-task-solution').click();
  // the solution shown: the value filled in, every condition holding, and counted for nothing
  assert.match(await page.locator('.rl-task-verdict').innerText(), /^Solution shown: it does not count/);
  assert.equal(await page.locator('.rl-task-results li.rl-holds').count(), 1);
  assert.deepEqual(problems, []);
  await page.close();
});

test('warnings with the values: the surface the prompt calls developable fails the goal (helix tangent, N = 12), a start that already passes, a draw for which it passes', async () => {
  const { page, problems } = await session.open('index.html#scene=striction&surface=helix-tangent&n=12');
  await openAuthor(page);
  await page.keyboard.type('Developable');
  await page.keyboard.press('Tab');
  await page.keyboard.type('This surface (developable) has torsal rulings only: every δ below 0.001.');
  await page.getByRole('button', { name: 'Add a condition' }).click();
  await page.selectOption('[name="author-value-0"]', 'striction.minAbsDelta');
  await page.locator('[name="author-bound-0"]').fill('0.001');
  await page.locator('[name="author-bound-0"]').dispatchEvent('change');
  await page.waitForTimeout(100);
  // the solution recorded as the view is: it fails, with the value δ = 8.4·10⁻³
  await page.getByRole('button', { name: 'Record the view as it is now as the solution' }).click();
  const warnings = page.locator('.rl-author-warnings');
  await warnings.waitFor();
  assert.match(
    await warnings.innerText(),
    /the solution fails condition 1 \(the smallest \|δ\| of a pair of rulings below 0\.001\): now 8\.4\d*·10⁻³: 7\.4\d*·10⁻³ too large/,
  );
  // a bound the start already meets
  await page.locator('[name="author-bound-0"]').fill('1');
  await page.locator('[name="author-bound-0"]').dispatchEvent('change');
  await page.waitForTimeout(100);
  assert.match(
    await warnings.innerText(),
    /the start already meets every condition, so the reader would have nothing to do \(.*: 8\.4/,
  );
  assert.deepEqual(problems, []);
  await page.close();

  // drawn: N from 8 to 16 and a bound only the larger N meet at the start
  const drawn = await session.open('index.html#scene=striction&surface=quartic&n=12&exact=1');
  await openAuthor(drawn.page);
  await drawn.page.keyboard.type('Accurate');
  await drawn.page.selectOption('[name="author-n"]', 'draw');
  await drawn.page.locator('[name="author-draw-n-from"]').fill('8');
  await drawn.page.locator('[name="author-draw-n-from"]').dispatchEvent('change');
  await drawn.page.locator('[name="author-draw-n-to"]').fill('16');
  await drawn.page.locator('[name="author-draw-n-to"]').dispatchEvent('change');
  await drawn.page.waitForTimeout(100);
  await drawn.page.getByRole('button', { name: 'Add a condition' }).click();
  await drawn.page.selectOption('[name="author-value-0"]', 'readout.midpointError');
  // what a bound is compared with: the value over the numbers that can be drawn, not at N = 12 alone
  const option = await drawn.page.locator('[name="author-value-0"] option:checked').innerText();
  const range = /from ([\d.·⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+) to ([\d.·⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+) over the numbers drawn/.exec(option);
  assert.ok(range, option);
  assert.doesNotMatch(option, /now/);
  // a target named by its readout's label: its subscripts as everywhere (an option holds no <sub>)
  const footpoint = await drawn.page
    .locator('[name="author-value-0"] option[value="readout.footpointError"]')
    .innerText();
  assert.ok(footpoint.startsWith('max |fᵢ,ᵢ₊₁ − s(uᵢ)|'), footpoint);
  await drawn.page.locator('[name="author-bound-0"]').fill('0.012');
  await drawn.page.locator('[name="author-bound-0"]').dispatchEvent('change');
  await drawn.page.waitForTimeout(100);
  const text = await drawn.page.locator('.rl-author-warnings').innerText();
  assert.match(text, /With n = 16: the start already meets every condition/);
  assert.doesNotMatch(text, /With n = 8:/, 'at N = 8 the start does not pass');
  assert.deepEqual(drawn.problems, []);
  await drawn.page.close();
});

test('Share’s options with the keyboard: the snippets carry what readers may do; Leave only where allowed', async () => {
  const { page, problems } = await session.open('index.html#task=coupled-strip&lang=en');
  await page.locator('#share').focus();
  await page.keyboard.press('Enter');
  await page.locator('#share-dialog[data-ready="1"]').waitFor();
  // an exercise: no "drag" option (the exercise says it), the explanation and Leave
  assert.equal(await page.locator('[name="share-reader-edit"]').count(), 0);
  await tabTo(page, 'share-reader-text');
  await page.keyboard.press('Space');
  await page.waitForFunction(() => /&amp;text/.test(document.querySelector('#share-iframe')?.value ?? ''));
  assert.equal(await focused(page), 'share-reader-text', 'the keyboard stays on the option');
  await page.keyboard.press('Tab');
  assert.equal(await focused(page), 'share-reader-leave');
  await page.keyboard.press('Space');
  await page.waitForFunction(() => /&amp;leave/.test(document.querySelector('#share-iframe')?.value ?? ''));
  const iframe = await page.locator('#share-iframe').inputValue();
  const element = await page.locator('#share-element').inputValue();
  assert.match(iframe, /#embed&amp;controls&amp;text&amp;leave&amp;task=coupled-strip/);
  assert.match(element, /<ruled-view task="coupled-strip" lang="en" controls text leave height="640">/);
  // the controls off: neither carries them
  await page.locator('[name="share-reader-controls"]').focus();
  await page.keyboard.press('Space');
  await page.waitForFunction(() => !/controls/.test(document.querySelector('#share-element')?.value ?? 'controls'));
  assert.doesNotMatch(await page.locator('#share-iframe').inputValue(), /controls/);
  await page.locator('[name="share-reader-controls"]').press('Space');
  // what an exercise's snippets carry, said as it is: the exercise, not this view's camera
  assert.match(
    await page.locator('#share-dialog > p').first().innerText(),
    /Each carries the exercise, the language and what readers may do/,
  );
  assert.match(await page.locator('label[for="share-link"]').innerText(), /Link to the exercise/);
  // the solution never offered: the link, the iframe, the element and the packages carry it
  await page.locator('[name="share-reader-solution"]').selectOption('never');
  await page.waitForFunction(() => /solution=never/.test(document.querySelector('#share-link')?.value ?? ''));
  assert.match(await page.locator('#share-iframe').inputValue(), /solution=never/);
  assert.match(await page.locator('#share-element').inputValue(), / solution="never"/);
  assert.deepEqual(problems, []);
  await page.close();

  // pasted on another site: Leave where allowed, not where not
  const plain = iframe.replace('&amp;leave', '');
  const plainElement = element.replace(' leave', '');
  const url = site.write(
    'readers.html',
    hostPage(
      `${iframe.replace('<iframe', '<iframe id="with"')}\n${plain.replace('<iframe', '<iframe id="without"')}\n${element}\n${plainElement.replace('<script', '<script data-twice')}`,
    ),
  );
  const pasted = await session.open(url, { wait: false });
  const framed = (/** @type {string} */ id) => pasted.page.frameLocator(`#${id}`);
  for (const id of ['with', 'without'])
    await framed(id).locator('.rl-stage[data-ready="1"] .rl-task').waitFor({ timeout: 60000 });
  assert.equal(await framed('with').locator('.rl-task-leave').count(), 1);
  assert.equal(await framed('without').locator('.rl-task-leave').count(), 0);
  assert.equal(
    await framed('with').locator('.rl-text').isVisible(),
    false,
    'the exercise hides its explanation itself',
  );
  await pasted.page.waitForFunction(
    () => [...document.querySelectorAll('ruled-view')].every((v) => v.dataset.ready === '1'),
    null,
    { timeout: 60000 },
  );
  const views = pasted.page.locator('ruled-view');
  assert.equal(await views.nth(0).locator('.rl-task-leave').count(), 1);
  assert.equal(await views.nth(1).locator('.rl-task-leave').count(), 0);
  // Leave in the element: the scene without the exercise
  await views.nth(0).locator('.rl-task-leave').click();
  await pasted.page.waitForFunction(() => document.querySelector('ruled-view')?.exercise === null);
  assert.deepEqual(pasted.problems, []);
  await pasted.page.close();
});

test('the element’s seed draws the link’s numbers; a seed that is not one is said and new numbers drawn', async () => {
  const linked = await session.open('index.html#task=striction-accuracy&seed=77');
  const want = await linked.page.evaluate(() => window.ruledlab.stage.task.drawn.values);
  // a check and a hint, kept with the attempt in this browser: back after a reload
  await linked.page.locator('.rl-task-check').click();
  await linked.page.locator('.rl-task-hint').click();
  await linked.page.reload();
  await ready(linked.page);
  assert.deepEqual(
    await linked.page.evaluate(() => window.ruledlab.stage.task.drawn.values),
    want,
    'a reload keeps them',
  );
  assert.equal(await linked.page.locator('.rl-task-history li').count(), 1);
  assert.equal(await linked.page.locator('.rl-task-hints li').count(), 1);
  // Start over: the answers and hints go, the checks stay (they are the attempt's record)
  await linked.page.locator('.rl-task-again').click();
  assert.equal(await linked.page.locator('.rl-task-hints li').count(), 0);
  assert.equal(await linked.page.locator('.rl-task-history li').count(), 1);
  await linked.page.close();
  const url = site.write(
    'seed.html',
    hostPage(`<script defer src="${session.url}dist/ruledlab-embed.js"></script>
<ruled-view id="a" task="striction-accuracy" seed="77" lang="en" controls height="500"></ruled-view>
<ruled-view id="b" task="striction-accuracy" seed="abc" lang="de" controls height="500"></ruled-view>
<script>window.errors = []; document.getElementById('b').addEventListener('error', (e) => window.errors.push(e.detail));</script>`),
  );
  const { page, problems } = await session.open(url, { wait: false });
  await page.waitForFunction(
    () => [...document.querySelectorAll('ruled-view')].every((v) => v.dataset.ready === '1'),
    null,
    { timeout: 60000 },
  );
  assert.deepEqual(await page.locator('#a').evaluate((v) => v.view.task.drawn.values), want);
  assert.equal(await page.locator('#a').evaluate((v) => v.exercise.seed), 77);
  const errors = await page.evaluate(() => window.errors);
  assert.equal(errors[0]?.details?.reason, 'element.note.badSeed');
  assert.match(
    errors[0]?.message,
    /Das Attribut seed ist keine ganze Zahl von 0 bis 4294967295; neue Zahlen wurden gezogen/,
  );
  assert.notEqual(await page.locator('#b').evaluate((v) => v.exercise.seed), null);
  assert.deepEqual(problems, []);
  await page.close();
});

test('axe-core finds no WCAG 2.1 A/AA violation in the author with answers, draws and warnings, nor in Share’s options and packages, in German too', async () => {
  for (const lang of ['en', 'de']) {
    const { page, problems } = await session.open(`index.html#scene=striction&surface=helix-tangent&n=12&lang=${lang}`);
    await page.locator('#share').click();
    await page.locator('#share-dialog[data-ready="1"]').waitFor();
    assert.deepEqual(await axe(page), [], `Share (${lang})`);
    await page.locator('#share-exercise').click();
    await page.locator('[name="author-title"]').fill('x');
    await page.selectOption('[name="author-n"]', 'draw');
    await page.locator('[name="author-add"]').click();
    await page.selectOption('[name="author-value-0"]', 'striction.minAbsDelta');
    await page.locator('[name="author-bound-0"]').fill('0.001');
    await page.locator('[name="author-bound-0"]').dispatchEvent('change');
    await page.locator('[name="author-answer-add"]').click();
    await page.locator('[name="author-record-solution"]').click();
    await page.locator('.rl-author-warnings').waitFor();
    assert.deepEqual(await axe(page), [], `the author (${lang})`);
    assert.deepEqual(problems, []);
    await page.close();
  }
  const exercise = await session.open('index.html#task=torsal-pair&lang=de');
  await exercise.page.locator('#share').click();
  await exercise.page.locator('#share-dialog[data-ready="1"]').waitFor();
  await exercise.page.locator('.rl-package-more summary').click();
  assert.deepEqual(await axe(exercise.page), [], 'Share on an exercise');
  await exercise.page.close();
});

test('the author’s fields never change under the caret: typed with pauses between keys and after Tab, 20 of 20 exported as typed', async () => {
  const { page, problems } = await session.open('index.html#scene=striction&surface=quartic&n=12&exact=1');
  await openAuthor(page);
  await page.keyboard.type('Drawn');
  await page.selectOption('[name="author-n"]', 'draw');
  await page.locator('[name="author-draw-n-from"]').waitFor();
  await page.getByRole('button', { name: 'Add a condition' }).click();
  const runs = [];
  for (let k = 0; k < 20; k++) {
    const from = String(4 + (k % 5));
    const to = String(16 + (k % 7));
    const step = String(1 + (k % 3));
    // as a person types: a key, a pause, Tab, a pause of her own (0 to 570 ms), the next field
    await page.locator('[name="author-draw-n-from"]').focus();
    await page.keyboard.press('Control+a');
    await page.keyboard.type(from, { delay: 60 });
    await page.keyboard.press('Tab');
    await page.waitForTimeout(30 * (k % 20));
    await page.keyboard.type(to, { delay: 40 + 10 * (k % 4) });
    await page.keyboard.press('Tab');
    await page.waitForTimeout(20 * ((k * 7) % 20));
    await page.keyboard.type(step, { delay: 50 });
    // and on into the goal's bound, which rebuilds the panel again
    await page.keyboard.press('Tab');
    await page.locator('[name="author-bound-0"]').focus();
    await page.keyboard.press('Control+a');
    await page.keyboard.type('0.5', { delay: 30 });
    await page.keyboard.press('Tab');
    await page.waitForTimeout(100);
    await page.getByRole('button', { name: 'Make the exercise' }).click();
    await page.waitForSelector('#author-json');
    const json = JSON.parse(await page.locator('#author-json').inputValue());
    runs.push([
      JSON.stringify(json.draw.n),
      JSON.stringify({ from: Number(from), to: Number(to), step: Number(step) }),
    ]);
  }
  assert.deepEqual(
    runs.filter(([got, want]) => got !== want),
    [],
    'every run exported as typed',
  );
  assert.deepEqual(problems, []);
  await page.close();
});
