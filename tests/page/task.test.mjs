// Exercises as a student and a lecturer meet them (issue 28): doing one with the mouse and with
// the keyboard alone (Check, hints, the solution after a first check, progress kept), typed
// formulas checked by the core, the element's task-check and task-solved events and the message to
// the course page around a frame, a hostile or broken exercise link, and writing an exercise from
// a view (Share → Make an exercise) whose link works as handed out.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageSession, ready } from './browser.mjs';
import { otherOrigin } from './places.mjs';

const session = pageSession();
const site = otherOrigin();

/** @typedef {import('playwright-core').Page} Page */

const verdict = (/** @type {Page} */ page) => page.locator('.rl-task-verdict').innerText();
const results = (/** @type {Page} */ page) => page.locator('.rl-task-results li').allInnerTexts();

test('doing an exercise: only what it lets change is enabled, Check says how each condition stands, solved is said, progress is kept', async () => {
  const { page, problems } = await session.open('index.html#task=coupled-strip');
  assert.match(await page.locator('.rl-task h3').innerText(), /Exercise: When coupling pays/);
  const enabled = await page.evaluate(() =>
    [...document.querySelectorAll('.rl-controls [name]')].filter((e) => !e.disabled).map((e) => e.getAttribute('name')),
  );
  assert.deepEqual([...new Set(enabled)], ['n'], 'only n may change');
  assert.equal(await page.locator('.rl-task-solution').isDisabled(), true, 'no solution before a first check');
  // the sentences that would say the answer are hidden: the claims under the readout, the explanation
  assert.equal(await page.locator('.rl-claims').isHidden(), true);
  assert.equal(await page.locator('.rl-text').isHidden(), true);
  // and the data files, which would hold the numbers (the pictures stay)
  const held = () =>
    page.evaluate(() =>
      ['csv', 'invariantsCsv', 'svg'].map((k) => document.querySelector(`[data-export="${k}"]`)?.hidden),
    );
  assert.deepEqual(await held(), [true, true, false]);
  await page.click('.rl-task-check');
  assert.match(await verdict(page), /^Not solved yet: 0 of 1 condition met\./);
  assert.match((await results(page))[0], /✗.*your answer “the smallest n”.*no answer yet/s);
  // a hint; the reader tries n = 6 (the readout compares the schemes there), then answers
  await page.click('.rl-task-hint');
  assert.equal(await page.locator('.rl-task-hints li').count(), 1);
  await page.locator('.rl-controls [name="n"]').fill('6');
  await page.locator('.rl-controls [name="n"]').dispatchEvent('change');
  await page.locator('input[name="task-n"]').fill('4');
  await page.click('.rl-task-check');
  assert.match((await results(page))[0], /not right yet/);
  await page.locator('input[name="task-n"]').fill('5');
  await page.click('.rl-task-check');
  assert.match(await verdict(page), /^✓ Solved: every condition holds\./);
  // the link keeps the reader's n; the menu marks the exercise solved, after a reload too
  assert.match(await page.evaluate(() => location.hash), /task=coupled-strip.*&n=6/);
  await page.reload();
  await ready(page);
  assert.equal(await page.evaluate(() => window.ruledlab.stage.params.n), 6);
  assert.match(await page.locator('#task option:checked').innerText(), /^✓ When coupling pays/);
  // a drawn exercise's title in the list says its numbers as …, never a {placeholder}
  assert.ok((await page.locator('#task option').allInnerTexts()).every((o) => !o.includes('{')));
  // Start over: back to n = 3; Leave: the scene without the exercise
  await page.click('.rl-task-again');
  assert.equal(await page.evaluate(() => window.ruledlab.stage.params.n), 3);
  // no verdict of the figure before: "Solved" would be stale
  assert.equal(await page.locator('.rl-task-verdict').isHidden(), true);
  await page.click('.rl-task-check');
  assert.match(await verdict(page), /^Not solved yet/);
  await page.click('.rl-task-leave');
  assert.equal(await page.locator('.rl-task').isHidden(), true);
  assert.equal(await page.locator('.rl-controls [name="scheme"]').isDisabled(), false);
  assert.equal(await page.locator('.rl-text').isVisible(), true, 'the explanation is back');
  assert.deepEqual(await held(), [false, false, false], 'the data files are back');
  assert.doesNotMatch(await page.evaluate(() => location.hash), /task=/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('back to a solved drag exercise: the figure is the reader’s, not the start, and no condition reads “not yet”', async () => {
  const { page, problems } = await session.open('index.html#task=torsal-pair');
  await ready(page);
  // the reader's edit that solves it (the exercise's own solution, put as her edit would be)
  const solution = await page.evaluate(async () => {
    const { decodeInput } = await import('./www/edit/input.js');
    const stage = window.ruledlab.stage;
    const text = /** @type {string} */ (stage.task?.solution?.input);
    stage.setInput(decodeInput(text), true);
    return text;
  });
  await ready(page);
  await page.click('.rl-task-check');
  assert.match(await verdict(page), /^✓ Solved/);
  // another exercise from the menu, then this one again
  await page.selectOption('#task', 'coupled-strip');
  await page.waitForFunction(() => window.ruledlab.stage.task?.id === 'coupled-strip');
  await ready(page);
  await page.selectOption('#task', 'torsal-pair');
  await page.waitForFunction(() => window.ruledlab.stage.task?.id === 'torsal-pair');
  await ready(page);
  const shown = await page.evaluate(async () => {
    const { encodeInput } = await import('./www/edit/input.js');
    const input = window.ruledlab.stage.input;
    return input ? encodeInput(input) : null;
  });
  assert.equal(shown, solution, 'the figure is the one she solved it with');
  assert.match((await results(page)).join(' '), /✓/, 'her checks are listed');
  await page.click('.rl-task-check');
  assert.match(await verdict(page), /^✓ Solved/, 'checked again, it holds');
  assert.deepEqual(problems, []);
  await page.close();
});

test('with the keyboard alone: Tab to the answer, type, Enter checks; a hint and the solution by Enter', async () => {
  // (seed 0 draws 3 steps: 50 points)
  const { page, problems } = await session.open('index.html#task=chaikin-count&seed=0');
  // a screen reader hears what the exercise asks, then what the figure shows
  const prompt = await page.locator('.rl-task-prompt').innerText();
  const title = await page.locator('.rl-task-title').innerText();
  const heard = await page.evaluate(() => document.querySelector('.rl-stage [aria-live]')?.textContent ?? '');
  assert.ok(heard.startsWith(`${title.replace(/[.!?]$/, '')}`), `${heard} | ${title}`);
  assert.ok(heard.includes(prompt), `${heard} | ${prompt}`);
  // from the top of the page, Tab until the answer field has the keyboard
  await page.evaluate(() => /** @type {HTMLElement} */ (document.activeElement)?.blur());
  let at = '';
  for (let k = 0; k < 40 && at !== 'task-count'; k++) {
    await page.keyboard.press('Tab');
    at = await page.evaluate(() => document.activeElement?.getAttribute('name') ?? '');
  }
  assert.equal(at, 'task-count', 'the answer field is reached by Tab');
  // the held number of steps does not move by the view's keys either (. steps, Space plays)
  await page.locator('.rl-view canvas').focus();
  await page.keyboard.press('.');
  await page.keyboard.press(' ');
  await page.waitForTimeout(300);
  assert.equal(await page.evaluate(() => window.ruledlab.stage.params.steps), 3);
  await page.locator('input[name="task-count"]').focus();
  await page.keyboard.type('48');
  await page.keyboard.press('Enter');
  assert.match(await verdict(page), /^Not solved yet/);
  assert.match((await results(page))[0], /not right yet/);
  assert.doesNotMatch((await results(page))[0], /50/, 'the check does not give the answer away');
  // Tab on to the hint button: Enter shows hint 1
  for (let k = 0; k < 6; k++) {
    await page.keyboard.press('Tab');
    if (await page.evaluate(() => document.activeElement?.classList.contains('rl-task-hint'))) break;
  }
  await page.keyboard.press('Enter');
  assert.match(await page.locator('.rl-task-hints li').first().innerText(), /n − 1 edges/);
  // the solution (offered after a check that did not solve it): its answer filled in, its
  // conditions shown holding, and counted for nothing
  await page.locator('.rl-task-solution').focus();
  await page.keyboard.press('Enter');
  assert.equal(await page.locator('input[name="task-count"]').inputValue(), '50');
  assert.match(await verdict(page), /^Solution shown: it does not count/);
  assert.equal(await page.locator('.rl-task-results li.rl-holds').count(), 1);
  // said once, by the verdict (a status): not by the view's live region too
  assert.doesNotMatch(
    await page.evaluate(() => document.querySelector('.rl-stage [aria-live]')?.textContent ?? ''),
    /Solved/,
  );
  // the buttons that rebuild the panel or take it away leave the keyboard where it can go on
  const focused = () =>
    page.evaluate(() => {
      const a = document.activeElement;
      return a === document.body || !a
        ? 'body'
        : `${a.tagName.toLowerCase()}.${a.className}[${a.getAttribute('name') ?? ''}]`;
    });
  assert.equal(await focused(), 'button.rl-task-solution[]', 'Show the solution keeps the keyboard');
  await page.locator('.rl-task-again').focus();
  await page.keyboard.press('Enter');
  assert.equal(await focused(), 'button.rl-task-again[]', 'Start over keeps the keyboard');
  // the skip link goes to the exercise's first field (the scene's controls are held)
  await page.locator('a.skip').focus();
  await page.keyboard.press('Enter');
  assert.equal(await focused(), 'input.rl-task-number[task-count]');
  await page.locator('.rl-task-leave').focus();
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => !document.querySelector('.rl-task-leave'));
  assert.match(await focused(), /\[(n|steps|scheme|w)\]$/, 'leaving puts the keyboard on the first control');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a typed curve is checked by the core: how far it is from the exact striction curve and where; German decimal commas', async () => {
  const { page, problems } = await session.open('index.html#task=hypar-striction');
  const fill = async (/** @type {string[]} */ xyz) => {
    for (const [k, c] of ['x', 'y', 'z'].entries()) await page.locator(`input[name="task-s-${c}"]`).fill(xyz[k]);
    await page.click('.rl-task-check');
  };
  await fill(['u', '0', '0.1*u']);
  assert.match((await results(page))[0], /up to 0\.100 away, farthest at u = (−)?1/);
  await fill(['u', '0', '2*']);
  assert.match((await results(page))[0], /formula ends where an operand is expected/);
  await fill(['u', '0', '0']);
  assert.match(await verdict(page), /^✓ Solved/);
  // the exact striction curve is held off and hidden: no row of its own to switch on
  assert.equal(await page.locator('.rl-row[data-key="exact"]').isHidden(), true);
  await page.close();
  // (seed 4 draws k = 2: δ(u) = (1 + 4u²)/2)
  const de = await session.open('index.html#task=hypar-distribution&seed=4&lang=de');
  await de.page.locator('input[name="task-delta"]').fill('0,5 + 2,0*u^2');
  await de.page.click('.rl-task-check');
  assert.match(await verdict(de.page), /^✓ Gelöst/);
  assert.deepEqual([...problems, ...de.problems], []);
  await de.page.close();
});

test('<ruled-view task>: task-check and task-solved events; a framed page tells the course page around it by postMessage', async () => {
  const url = site.write(
    'course.html',
    `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>course</title>
<script defer src="${session.url}dist/ruledlab-embed.js"></script></head><body>
<ruled-view id="v" task="chaikin-count" seed="0" lang="en" controls height="560"></ruled-view>
<iframe id="f" sandbox="allow-scripts" src="${session.url}index.html#embed&amp;controls&amp;task=chaikin-count&amp;seed=0" width="800" height="560" title="exercise"></iframe>
<script>
window.events = []; window.messages = [];
document.getElementById('v').addEventListener('task-check', (e) => window.events.push(['check', e.detail]));
document.getElementById('v').addEventListener('task-solved', (e) => window.events.push(['solved', e.detail]));
addEventListener('message', (e) => { if (e.data && e.data.source === 'ruledlab') window.messages.push(e.data); });
</script></body></html>`,
  );
  const { page, problems } = await session.open(url, { wait: false });
  await page.waitForFunction(() => document.querySelector('ruled-view')?.dataset.ready === '1', null, {
    timeout: 60000,
  });
  await page.locator('ruled-view').evaluate((v) => {
    const root = /** @type {ShadowRoot} */ (v.shadowRoot);
    const input = /** @type {HTMLInputElement} */ (root.querySelector('input[name="task-count"]'));
    input.value = '50';
    input.dispatchEvent(new Event('input', { bubbles: true }));
    /** @type {HTMLButtonElement} */ (root.querySelector('.rl-task-check')).click();
  });
  const events = await page.evaluate(() => window.events);
  assert.deepEqual(
    events.map((e) => e[0]),
    ['check', 'solved'],
  );
  assert.equal(events[1][1].task, 'chaikin-count');
  assert.equal(events[1][1].solved, true);
  assert.deepEqual(
    events[1][1].conditions,
    [{ holds: true, value: null, target: null }],
    'an answer’s value stays out of the report',
  );
  assert.deepEqual(events[1][1].answers, { count: '50' });
  // the framed page (sandboxed: no storage) posts its check to the course page
  const frame = page.frameLocator('#f');
  await frame.locator('.rl-stage[data-ready="1"]').waitFor({ timeout: 60000 });
  await frame.locator('input[name="task-count"]').fill('14');
  await frame.locator('.rl-task-check').click();
  await page.waitForFunction(() => window.messages.length > 0);
  const [message] = await page.evaluate(() => window.messages);
  assert.equal(message.type, 'task-check');
  assert.equal(message.version, 1);
  assert.equal(message.task, 'chaikin-count');
  assert.equal(message.solved, false);
  assert.equal(message.state.scene, 'curves');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a hostile or broken exercise link: texts stay text, a broken one is said in the page’s language', async () => {
  const hostile = {
    ruledlab: 'exercise',
    version: 1,
    id: 'x',
    title: { en: '<img src=x onerror="window.__pwned=1">' },
    prompt: { en: '<script>window.__pwned=1</script>' },
    scene: 'striction',
    goal: [{ value: 'readout.midpointError', below: 0.5 }],
  };
  const b64 = Buffer.from(JSON.stringify(hostile)).toString('base64url');
  const { page, problems } = await session.open(`index.html#task=j.${b64}`);
  assert.equal(await page.locator('.rl-task h3 img, .rl-task script').count(), 0);
  assert.match(await page.locator('.rl-task h3').innerText(), /<img src=x/);
  assert.equal(await page.evaluate(() => /** @type {any} */ (window).__pwned), undefined);
  await page.close();
  const broken = await session.open(
    `index.html#task=j.${Buffer.from('{"ruledlab":"exercise","version":1}').toString('base64url')}&lang=de`,
  );
  assert.match(
    await broken.page.locator('.rl-note').innerText(),
    /Die Aufgabe im Link ließ sich nicht lesen \(ihr fehlt „id“\)/,
  );
  await broken.page.close();
  const garbage = await session.open('index.html#task=j.garbage!&lang=de');
  assert.match(await garbage.page.locator('.rl-note').innerText(), /der Link enthält keine Aufgabe/);
  await garbage.page.close();
  const unknown = await session.open('index.html#task=no-such-exercise');
  assert.match(await unknown.page.locator('.rl-note').innerText(), /no built-in exercise "no-such-exercise"/);
  assert.deepEqual([...problems, ...broken.problems, ...garbage.problems, ...unknown.problems], []);
  await unknown.page.close();
});

test('writing an exercise: Share → Make an exercise, a condition from the values now, the solution recorded; its link works as handed out', async () => {
  const { page, problems } = await session.open('index.html#scene=striction&surface=quartic&n=12');
  await page.click('#share');
  await page.click('#share-exercise');
  await page.locator('.rl-author-field input').first().fill('Accurate enough');
  await page.locator('.rl-author-field textarea').first().fill('Choose N so that the polygon is within 0.001.');
  await page.selectOption('[name="author-n"]', 'change');
  await page.getByRole('button', { name: 'Add a condition' }).click();
  await page.selectOption('[name="author-value-0"]', 'readout.midpointError');
  assert.match(await page.locator('[name="author-value-0"] option:checked').innerText(), /now 1\.70·10⁻²/);
  await page.locator('[name="author-bound-0"]').fill('0.001');
  await page.locator('[name="author-bound-0"]').dispatchEvent('change');
  assert.match(await page.locator('.rl-author-status').innerText(), /does not hold at the start/);
  await page.evaluate(() => window.ruledlab.stage.setParam('n', 50, true));
  await page.getByRole('button', { name: 'Record the view as it is now as the solution' }).click();
  assert.match(await page.locator('.rl-author-status').innerText(), /holds in the solution/);
  await page.getByRole('button', { name: 'Make the exercise' }).click();
  const link = await page.locator('#author-link').inputValue();
  assert.match(
    await page.locator('#author-element').inputValue(),
    /<ruled-view task="j\.[A-Za-z0-9_-]+" lang="en" controls height="640">/,
  );
  const json = JSON.parse(await page.locator('#author-json').inputValue());
  assert.deepEqual(json.change, ['n']);
  assert.deepEqual(json.solution, { params: { n: 50 } });
  await page.close();
  // the link as handed out: the exercise at its start, solved by its solution
  const reader = await session.open(link.replace(session.url, ''));
  assert.equal(await reader.page.evaluate(() => window.ruledlab.stage.params.n), 12);
  await reader.page.click('.rl-task-check');
  assert.match(await verdict(reader.page), /^Not solved yet/);
  await reader.page.click('.rl-task-solution');
  assert.match(await verdict(reader.page), /^Solution shown/);
  assert.equal(
    await reader.page.locator('.rl-task-results li.rl-fails').count(),
    0,
    'the solution meets every condition',
  );
  assert.deepEqual([...problems, ...reader.problems], []);
  await reader.page.close();
});

test('an exercise file pasted or uploaded in the import box opens as the exercise; a bad one is said there', async () => {
  const { page, problems } = await session.open('index.html#scene=curves');
  await page.locator('.io summary').click();
  const exercise = {
    ruledlab: 'exercise',
    version: 1,
    id: 'from-a-file',
    title: { en: 'From a file' },
    prompt: { en: 'Choose four steps.' },
    scene: 'curves',
    params: { steps: 1 },
    change: ['steps'],
    goal: [{ value: 'curves.readout.points', above: 100 }],
  };
  await page.locator('#import-text').fill(JSON.stringify(exercise));
  await page.locator('#import-button').click();
  await page.waitForFunction(() => window.ruledlab.stage.task?.id === 'from-a-file');
  assert.match(await page.locator('.rl-task h3').innerText(), /From a file/);
  // (the import box stays open under the exercise)
  await page
    .locator('#import-text')
    .fill(JSON.stringify({ ...exercise, goal: [{ value: 'curves.nothing', above: 1 }] }));
  await page.locator('#import-button').click();
  await page.waitForFunction(() => !document.querySelector('#import-error')?.hidden);
  assert.match(await page.locator('#import-error').innerText(), /computes no value "curves\.nothing"/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('writing an exercise with the keyboard alone: every field of the panel is reached by Tab and works', async () => {
  const { page, problems } = await session.open('index.html#scene=strip&n=3');
  // Share, then Make an exercise, by keyboard
  await page.locator('#share').focus();
  await page.keyboard.press('Enter');
  await page.locator('#share-exercise').focus();
  await page.keyboard.press('Enter');
  // the title field has the keyboard once the author has loaded (it loads on demand); type, Tab to
  // the prompt, type
  await page.waitForFunction(() => document.activeElement?.getAttribute('name') === 'author-title');
  await page.keyboard.type('Beat the midpoint rule');
  await page.keyboard.press('Tab');
  await page.keyboard.type('Choose n.');
  // Tab to the control of n and let the reader change it (the select takes arrow keys)
  let at = '';
  for (let k = 0; k < 20 && at !== 'author-n'; k++) {
    await page.keyboard.press('Tab');
    at = await page.evaluate(() => document.activeElement?.getAttribute('name') ?? '');
  }
  assert.equal(at, 'author-n');
  await page.keyboard.press('ArrowDown');
  assert.equal(await page.locator('[name="author-n"]').inputValue(), 'change');
  // on to "Add a condition", then the bound field: type and leave it
  for (let k = 0; k < 30; k++) {
    await page.keyboard.press('Tab');
    if ((await page.evaluate(() => document.activeElement?.textContent)) === 'Add a condition') break;
  }
  await page.keyboard.press('Enter');
  assert.equal(await page.locator('[name="author-value-0"]').count(), 1);
  const focused = () => page.evaluate(() => document.activeElement?.getAttribute('name') ?? '');
  assert.equal(await focused(), 'author-value-0', 'the new condition’s value has the keyboard');
  // arrows through the values: each one rebuilds the panel, and the keyboard stays on the menu
  for (let k = 0; k < 30; k++) {
    if ((await page.locator('[name="author-value-0"]').inputValue()) === 'strip.readout.compare.coupled') break;
    await page.keyboard.press('ArrowDown');
    assert.equal(await focused(), 'author-value-0', 'ArrowDown kept the keyboard on the menu');
  }
  assert.equal(await page.locator('[name="author-value-0"]').inputValue(), 'strip.readout.compare.coupled');
  // Tab to the test, Tab to the bound: type it and Tab on — to the next control, not to nowhere
  await page.keyboard.press('Tab');
  assert.equal(await focused(), 'author-test-0');
  await page.keyboard.press('Tab');
  assert.equal(await focused(), 'author-bound-0');
  await page.keyboard.press('Control+a');
  await page.keyboard.type('0.008');
  await page.keyboard.press('Tab');
  await page.waitForTimeout(100);
  assert.equal(await focused(), 'author-remove-0', 'Tab from the bound reached the next control');
  // the solution recorded by Enter: the keyboard stays on its button
  for (let k = 0; k < 20 && (await focused()) !== 'author-record-solution'; k++) await page.keyboard.press('Tab');
  await page.keyboard.press('Enter');
  assert.equal(await focused(), 'author-record-solution');
  // Make the exercise by keyboard: its snippets appear
  for (let k = 0; k < 5; k++) {
    await page.keyboard.press('Tab');
    if ((await page.evaluate(() => document.activeElement?.textContent)) === 'Make the exercise') break;
  }
  await page.keyboard.press('Enter');
  await page.waitForSelector('#author-link');
  const json = JSON.parse(await page.locator('#author-json').inputValue());
  assert.equal(json.title.en, 'Beat the midpoint rule');
  assert.deepEqual(json.change, ['n']);
  assert.deepEqual(json.goal, [{ value: 'strip.readout.compare.coupled', below: 0.008 }]);
  assert.deepEqual(problems, []);
  await page.close();
});

test('an exercise that starts from an edit says its figure as edited, once: the cone with ruling 10 moved', async () => {
  const { page, problems } = await session.open('index.html#task=developable-cone');
  await ready(page);
  const { live, description } = await page.evaluate(() => ({
    live: document.querySelector('.rl-stage [aria-live]')?.textContent ?? '',
    description:
      document.getElementById(document.querySelector('.rl-stage canvas')?.getAttribute('aria-describedby') ?? '')
        ?.textContent ?? '',
  }));
  assert.match(description, /Ruling 10 meets neither of its neighbours/);
  assert.ok(live.startsWith('Exercise: Make the cone developable again.'), live);
  assert.ok(live.endsWith(description), `said: ${live}\nshown: ${description}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('an answer that cannot be read does not count: said so, and not listed among the checks as "0 of 1 met"', async () => {
  const { page, problems } = await session.open('index.html#task=coupled-strip');
  await ready(page);
  // (the session's browser may keep earlier checks of this exercise: the list must not change)
  const history = () => page.evaluate(() => document.querySelector('.rl-task-history')?.textContent ?? '');
  const before = await history();
  await page.locator('.rl-task-field input').first().fill('five');
  await page.locator('.rl-task-check').click();
  assert.match(await page.locator('.rl-task-verdict').innerText(), /could not be read .* does not count/);
  assert.equal(await history(), before, 'the unreadable check was listed');
  // a readable answer counts: listed as 0 of 1 met
  await page.locator('.rl-task-field input').first().fill('4');
  await page.locator('.rl-task-check').click();
  assert.notEqual(await history(), before);
  assert.match(await history(), /0 of 1 met/);
  assert.deepEqual(problems, []);
  await page.close();
});
