// The H5P content type as a course system plays it: an .h5p file made on the page (Share on an
// exercise), unzipped on another origin and played by h5p-standalone (H5P's own player core,
// without a server). The content loads and draws, a student fails and solves it with the page's
// own controls, and the one xAPI statement of her attempt — what Moodle's and ILIAS's H5P
// activities record as one attempt — carries the right score; a shown solution sends nothing and
// changes no score; the question contract (getScore, getMaxScore, showSolutions, resetTask,
// getXAPIData, getCurrentState) answers as H5P expects; a saved state brings her numbers back;
// two learners on one browser never share one; a problem set scores the sum of its exercises.
// Content that is hostile (markup, absurd numbers, JSON escaped by H5P's editor) is shown as
// text or refused with a message in the page's language.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { cpSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { pageSession } from './browser.mjs';
import { otherOrigin, drawnShare } from './places.mjs';
import { unzipSync, strFromU8 } from '../../pkg/zip.js';
import { h5pPackage } from '../../www/course/h5p-package.js';

const REPO = fileURLToPath(new URL('../..', import.meta.url));
const session = pageSession();
const site = otherOrigin();

/** @typedef {import('playwright-core').Page} Page */

/** Unzips `bytes` into the site's folder `name`/; the player next to it. */
function unpack(/** @type {Uint8Array} */ bytes, /** @type {string} */ name) {
  site.unpack(bytes, name);
  cpSync(join(REPO, 'node_modules/h5p-standalone/dist'), join(site.dir, 'player'), { recursive: true });
}

/**
 * A course page playing the content of folder `name` with h5p-standalone, collecting its xAPI
 * statements; `previous`: the state H5P saved for the student (getCurrentState).
 */
function course(
  /** @type {string} */ page,
  /** @type {string} */ name,
  /** @type {unknown} */ previous = null,
  /** @type {{name: string, mail: string} | null} */ user = null,
) {
  const state = previous
    ? // (H5P's core reads contentUserData[0].state, as a course system hands it over)
      `saveFreq: 3600, contentUserData: [{ state: ${JSON.stringify(JSON.stringify(previous))} }],`
    : '';
  // a learner the course system names, and its endpoint of saved states (nothing saved: none.json),
  // which H5P asks when it knows the learner
  if (user) site.write('none.json', JSON.stringify({ success: true, data: false }));
  const who = user
    ? `user: ${JSON.stringify(user)}, ajax: { contentUserDataUrl: 'none.json?c=:contentId&t=:dataType&s=:subContentId' },`
    : '';
  return site.write(
    page,
    `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>course</title>
<script src="player/main.bundle.js"></script></head><body>
<div id="h5p-container"></div>
<script>
window.statements = [];
new H5PStandalone.H5P(document.getElementById('h5p-container'), {
  id: 'exercise', h5pJsonPath: '${name}', frameJs: 'player/frame.bundle.js', frameCss: 'player/styles/h5p.css', ${state} ${who}
}).then(() => {
  H5P.externalDispatcher.on('xAPI', (e) => window.statements.push(e.data.statement));
  window.played = true;
});
</script></body></html>`,
  );
}

/** The H5P frame, once the exercise in it is shown. */
async function played(/** @type {Page} */ page) {
  await page.waitForFunction(() => window.played === true, null, { timeout: 60000 });
  const frame = page.frameLocator('iframe.h5p-iframe');
  await frame.locator('ruled-view[data-ready="1"]').waitFor({ timeout: 60000 });
  const handle = /** @type {import('playwright-core').Frame} */ (
    page.frames().find((f) => f !== page.mainFrame() && f.url() !== 'about:blank') ??
      page.frames().find((f) => f !== page.mainFrame())
  );
  return { frame, handle };
}

/** The score of the statements of `verb` so far. */
const scores = (/** @type {Page} */ page, /** @type {string} */ verb) =>
  page.evaluate(
    (v) =>
      window.statements
        .filter((s) => s.verb.id.endsWith(`/${v}`))
        .map((s) => ({ raw: s.result.score.raw, max: s.result.score.max, success: s.result.success })),
    verb,
  );

test('an .h5p file from Share plays in h5p-standalone: drawn, failed and solved by the page’s controls, the xAPI score right, H5P’s question contract kept', async () => {
  // the lecturer: Share on an exercise that draws its numbers → H5P file
  const lecturer = await session.open('index.html#task=hypar-distribution&lang=en');
  await lecturer.page.locator('#share').click();
  await lecturer.page.locator('#share-dialog[data-ready="1"]').waitFor();
  const [download] = await Promise.all([
    lecturer.page.waitForEvent('download'),
    lecturer.page.locator('[name="share-h5p"]').click(),
  ]);
  assert.equal(download.suggestedFilename(), 'hypar-distribution.h5p');
  const bytes = new Uint8Array(readFileSync(/** @type {string} */ (await download.path())));
  await lecturer.page.close();
  const files = unzipSync(bytes);
  assert.deepEqual(Object.keys(files).sort(), [
    'H5P.RuledlabExercise-1.0/language/de.json',
    'H5P.RuledlabExercise-1.0/library.json',
    'H5P.RuledlabExercise-1.0/ruledlab-embed.js',
    'H5P.RuledlabExercise-1.0/semantics.json',
    'content/content.json',
    'h5p.json',
  ]);
  const library = JSON.parse(strFromU8(files['H5P.RuledlabExercise-1.0/library.json']));
  assert.equal(library.machineName, 'H5P.RuledlabExercise');
  assert.equal(library.runnable, 1);
  const semantics = JSON.parse(strFromU8(files['H5P.RuledlabExercise-1.0/semantics.json']));
  assert.deepEqual(
    semantics.map((/** @type {any} */ f) => f.name),
    ['exercise', 'more', 'title', 'language', 'height', 'readers', 'draw'],
  );
  unpack(bytes, 'hd');

  const { page, problems, requests } = await session.open(course('play.html', 'hd'), { wait: false });
  const { frame, handle } = await played(page);
  // it draws: the view has pixels other than the paper's
  await frame.locator('ruled-view[data-frames]').waitFor();
  const view = await frame.locator('ruled-view').boundingBox();
  const png = await page.screenshot({ clip: /** @type {any} */ (view) });
  assert.ok(drawnShare(png) > 0.05, `drawn: ${drawnShare(png)}`);
  const k = Number(/k = (−?\d)/.exec(await frame.locator('.rl-task-drawn').innerText())?.[1].replace('−', '-'));
  assert.ok([-3, -2, 2, 3].includes(k), `k drawn: ${k}`);
  assert.equal(await handle.evaluate(() => H5P.instances[0].getMaxScore()), 1);
  assert.equal(await handle.evaluate(() => H5P.instances[0].getAnswerGiven()), false);
  // a wrong δ(u) (the one for k = 1), by the page's own field and button
  await frame.locator('input[name="task-delta"]').fill('1 + u^2');
  await frame.locator('.rl-task-check').click();
  assert.match(await frame.locator('.rl-task-results li').first().innerText(), /up to .* away/);
  // a check that does not solve it ends no attempt: nothing is sent (each statement would be a graded attempt)
  assert.deepEqual(await scores(page, 'answered'), []);
  assert.equal(await handle.evaluate(() => H5P.instances[0].getScore()), 0);
  assert.match(
    await frame.locator('.h5p-ruledlab-status').innerText(),
    /Recorded when you solve the exercise or end the attempt/,
  );
  // the right one for her k: one statement, answered with the full score (and nothing more)
  await frame.locator('input[name="task-delta"]').fill(`1/(${k}) + (${k})*u^2`);
  await frame.locator('.rl-task-check').click();
  await frame.locator('.rl-task-verdict.rl-task-solved').waitFor();
  assert.deepEqual(await scores(page, 'answered'), [{ raw: 1, max: 1, success: true }]);
  assert.deepEqual(await scores(page, 'completed'), []);
  assert.equal(await page.evaluate(() => window.statements.at(-1).result.completion), true);
  // the statement: what she typed and her numbers, never the expected formula
  const response = await page.evaluate(() => window.statements.at(-1).result.response);
  assert.equal(JSON.parse(response)[0].answers.delta, `1/(${k}) + (${k})*u^2`);
  assert.doesNotMatch(response, /expected|target/);
  // H5P's question contract
  const contract = await handle.evaluate(() => {
    const h = H5P.instances[0];
    return {
      score: h.getScore(),
      max: h.getMaxScore(),
      given: h.getAnswerGiven(),
      xapi: h.getXAPIData().statement.result.score,
      state: h.getCurrentState(),
    };
  });
  assert.deepEqual([contract.score, contract.max, contract.given], [1, 1, true]);
  assert.deepEqual(contract.xapi, { min: 0, max: 1, raw: 1, scaled: 1 });
  assert.equal(contract.state.attempts[0].checks.length, 2);
  const seed = contract.state.seed;
  // a check after it: nothing more is sent
  await frame.locator('.rl-task-check').click();
  assert.equal((await scores(page, 'answered')).length, 1);
  // Retry: a new attempt, new numbers
  await handle.evaluate(() => H5P.instances[0].resetTask());
  assert.equal(await handle.evaluate(() => H5P.instances[0].getScore()), 0);
  await frame.locator('.rl-task-history').waitFor({ state: 'hidden' });
  assert.equal(await frame.locator('input[name="task-delta"]').inputValue(), '');
  // H5P's showSolutions only shows — and not before a first check (the lecturer's rule)
  await handle.evaluate(() => H5P.instances[0].showSolutions());
  assert.equal(await frame.locator('.rl-task-verdict:not([hidden])').count(), 0);
  // nothing from elsewhere: the player, the content, the library
  assert.deepEqual(
    requests.filter((r) => !r.startsWith(site.url) && !/^(data|blob|about):/.test(r)),
    [],
  );
  assert.deepEqual(problems, []);
  await page.close();

  // the state H5P saved for her: the same numbers, her answer and checks again
  const back = await session.open(course('back.html', 'hd', contract.state), { wait: false });
  const again = await played(back.page);
  assert.equal(await again.handle.evaluate(() => H5P.instances[0].getCurrentState().seed), seed);
  await again.frame.locator('.rl-task-history li').first().waitFor();
  assert.equal(await again.frame.locator('.rl-task-history li').count(), 2);
  assert.equal(await again.frame.locator('input[name="task-delta"]').inputValue(), `1/(${k}) + (${k})*u^2`);
  assert.deepEqual(back.problems, []);
  await back.page.close();
});

test('hostile H5P content: markup stays text, JSON escaped by H5P’s editor is read, absurd numbers are refused in the page’s language', async () => {
  const exercise = {
    ruledlab: 'exercise',
    version: 1,
    id: 'escaped',
    title: { en: '<img src=x onerror="top.pwned=1">' },
    prompt: { en: 'How many points after two steps? & “quotes”' },
    scene: 'curves',
    params: { scheme: 'chaikin', steps: 2, closed: false },
    answers: [{ id: 'count', kind: 'number', label: { en: '<b>count</b>' } }],
    goal: [{ answer: 'count', near: { value: 'curves.readout.points' }, within: 0.001 }],
  };
  const write = (/** @type {string} */ name, /** @type {unknown} */ params) => {
    const json = (/** @type {unknown} */ x) => JSON.stringify(x);
    const dir = join(site.dir, name);
    mkdirSync(join(dir, 'content'), { recursive: true });
    cpSync(join(site.dir, 'hd/H5P.RuledlabExercise-1.0'), join(dir, 'H5P.RuledlabExercise-1.0'), { recursive: true });
    writeFileSync(join(dir, 'h5p.json'), readFileSync(join(site.dir, 'hd/h5p.json')));
    writeFileSync(join(dir, 'content/content.json'), json(params));
  };
  // as H5P's editor stores a text field: its characters escaped for HTML
  const escaped = JSON.stringify(exercise)
    .replace(/&/g, '&amp;')
    .replace(/"/g, '&quot;')
    .replace(/</g, '&lt;')
    .replace(/>/g, '&gt;');
  write('escaped', { exercise: escaped, language: 'en' });
  const { page, problems } = await session.open(course('escaped.html', 'escaped'), { wait: false });
  const { frame } = await played(page);
  assert.match(await frame.locator('.rl-task h3').innerText(), /<img src=x/);
  assert.match(await frame.locator('.rl-task-prompt').innerText(), /& “quotes”/);
  assert.equal(await frame.locator('.rl-task h3 img, .rl-task b').count(), 0);
  await frame.locator('input[name="task-count"]').fill('26');
  await frame.locator('.rl-task-check').click();
  await frame.locator('.rl-task-verdict.rl-task-solved').waitFor();
  assert.deepEqual(await scores(page, 'answered'), [{ raw: 1, max: 1, success: true }]);
  assert.equal(await page.evaluate(() => /** @type {any} */ (window).pwned), undefined);
  assert.deepEqual(problems, []);
  await page.close();

  // an absurd number: refused, in German, where the exercise would be
  write('absurd', { exercise: JSON.stringify({ ...exercise, params: { steps: 1e300 } }), language: 'de' });
  const absurd = await session.open(course('absurd.html', 'absurd'), { wait: false });
  await absurd.page.waitForFunction(() => window.played === true, null, { timeout: 60000 });
  const problem = absurd.page.frameLocator('iframe.h5p-iframe').locator('.h5p-ruledlab-problem');
  assert.match(
    await problem.innerText(),
    /^Diese Aufgabe lässt sich nicht zeigen: „params\.steps“ muss eine endliche Zahl vom Betrag höchstens 1e12 sein\.$/,
  );
  assert.equal(await absurd.page.evaluate(() => H5P.instances?.[0]?.getMaxScore?.() ?? null), null);
  assert.deepEqual(absurd.problems, []);
  await absurd.page.close();
});

/** An .h5p's files in folder `name` (made by the package's function), its content set to `params`. */
async function content(/** @type {string} */ name, /** @type {unknown} */ params) {
  const script = readFileSync(join(REPO, 'dist/ruledlab-embed.js'), 'utf8');
  unpack(await h5pPackage('coupled-strip', { script }), name);
  writeFileSync(join(site.dir, name, 'content/content.json'), JSON.stringify(params));
}

test('H5P: a shown solution sends nothing and changes no score; ending the attempt sends its one statement with the score of her own checks', async () => {
  await content('shown', { exercise: 'coupled-strip', language: 'en' });
  const { page, problems } = await session.open(course('shown.html', 'shown'), { wait: false });
  const { frame, handle } = await played(page);
  await frame.locator('input[name="task-n"]').fill('9');
  await frame.locator('.rl-task-check').click();
  // H5P's showSolutions, as a host calls it: shown, counted for nothing
  await handle.evaluate(() => H5P.instances[0].showSolutions());
  await frame.locator('.rl-task-verdict', { hasText: 'Solution shown' }).waitFor();
  assert.equal(await frame.locator('input[name="task-n"]').inputValue(), '5');
  assert.equal(await handle.evaluate(() => H5P.instances[0].getScore()), 0);
  // her own check of the solution's answer: not counted, nothing sent
  await frame.locator('.rl-task-check').click();
  assert.match(await frame.locator('.rl-task-verdict').innerText(), /not counted/);
  assert.deepEqual(await scores(page, 'answered'), []);
  assert.equal(await handle.evaluate(() => H5P.instances[0].getXAPIData().statement.result.score.raw), 0);
  // she ends the attempt: one statement, with what her own checks earned
  await frame.locator('[name="h5p-ruledlab-end"]').click();
  await frame.locator('[name="h5p-ruledlab-end-yes"]').click();
  assert.deepEqual(await scores(page, 'answered'), [{ raw: 0, max: 1, success: false }]);
  assert.match(await frame.locator('.h5p-ruledlab-status').innerText(), /Recorded: 0 of 1/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('H5P: two learners on one browser never share an attempt; numbers drawn per learner stay hers', async () => {
  await content('learners', { exercise: 'hypar-distribution', language: 'en', draw: 'learner' });
  const alice = { name: 'Alice', mail: 'alice@example.org' };
  const bob = { name: 'Bob', mail: 'bob@example.org' };
  const k = async (/** @type {import('playwright-core').FrameLocator} */ frame) =>
    Number(/k = (−?\d)/.exec(await frame.locator('.rl-task-drawn').innerText())?.[1].replace('−', '-'));
  // Alice types an answer and checks; H5P keeps her state (the course system's, per learner)
  const first = await session.open(course('alice.html', 'learners', null, alice), { wait: false });
  let played1 = await played(first.page);
  const aliceK = await k(played1.frame);
  await played1.frame.locator('input[name="task-delta"]').fill('1 + u^2');
  await played1.frame.locator('.rl-task-check').click();
  const aliceState = await played1.handle.evaluate(() => H5P.instances[0].getCurrentState());
  await first.page.close();
  // Bob, in the same browser, no state of his own: nothing of Alice's
  const second = await session.open(course('bob.html', 'learners', null, bob), { wait: false });
  const played2 = await played(second.page);
  assert.equal(await played2.frame.locator('input[name="task-delta"]').inputValue(), '');
  assert.equal(await played2.frame.locator('.rl-task-history li').count(), 0);
  assert.equal(await played2.handle.evaluate(() => H5P.instances[0].getScore()), 0);
  await second.page.close();
  // Alice again, with her state and without (a new attempt): her k both times
  for (const previous of [aliceState, null]) {
    const again = await session.open(course('alice2.html', 'learners', previous, alice), { wait: false });
    played1 = await played(again.page);
    assert.equal(await k(played1.frame), aliceK);
    assert.equal(await played1.frame.locator('input[name="task-delta"]').inputValue(), previous ? '1 + u^2' : '');
    assert.deepEqual(again.problems, []);
    await again.page.close();
  }
});

test('H5P: a problem set of three exercises, one activity: the score their sum, one statement once all are solved', async () => {
  await content('set', {
    exercise: 'coupled-strip',
    more: ['chaikin-count', 'striction-accuracy'],
    title: 'Set 1',
    language: 'en',
  });
  const { page, problems } = await session.open(course('set.html', 'set'), { wait: false });
  const { frame, handle } = await played(page);
  assert.equal(await frame.locator('.h5p-ruledlab-title').innerText(), 'Set 1');
  assert.equal(await handle.evaluate(() => H5P.instances[0].getMaxScore()), 3);
  assert.deepEqual(
    (await frame.locator('[name="h5p-ruledlab-task"] option').allInnerTexts()).map((t) =>
      t.replace(/ for .*\?/, ' for …?'),
    ),
    ['1. When coupling pays', '2. Count Chaikin’s points', '3. How many rulings for …?'],
  );
  await frame.locator('input[name="task-n"]').fill('5');
  await frame.locator('.rl-task-check').click();
  await frame.locator('.rl-task-verdict.rl-task-solved').waitFor();
  assert.deepEqual(await scores(page, 'answered'), []);
  // exercise 2: Chaikin's count (8 points, its steps shown in the view)
  await frame.locator('[name="h5p-ruledlab-task"]').selectOption('1');
  await frame.locator('.rl-task h3', { hasText: 'Chaikin' }).waitFor();
  const steps = Number(/steps = (\d)/.exec(await frame.locator('.rl-task-drawn').innerText())?.[1]);
  let n = 8;
  for (let j = 0; j < steps; j++) n = 2 * (n - 1);
  await frame.locator('input[name="task-count"]').fill(String(n));
  await frame.locator('.rl-task-check').click();
  await frame.locator('.rl-task-verdict.rl-task-solved').waitFor();
  assert.equal(await handle.evaluate(() => H5P.instances[0].getScore()), 2);
  // exercise 3: N = 100 meets its tolerance
  await frame.locator('[name="h5p-ruledlab-task"]').selectOption('2');
  await frame.locator('.rl-task h3', { hasText: 'How many rulings' }).waitFor();
  const control = frame.locator('.rl-controls [name="n"]');
  await control.fill('100');
  await control.dispatchEvent('change');
  await frame.locator('.rl-task-check').click();
  await frame.locator('.rl-task-verdict.rl-task-solved').waitFor();
  assert.deepEqual(await scores(page, 'answered'), [{ raw: 3, max: 3, success: true }]);
  // back to the first: her solved attempt is there
  await frame.locator('[name="h5p-ruledlab-task"]').selectOption('0');
  await frame.locator('.rl-task h3', { hasText: 'coupling' }).waitFor();
  await frame.locator('.rl-task-history li').first().waitFor();
  assert.equal(await frame.locator('input[name="task-n"]').inputValue(), '5');
  assert.deepEqual(problems, []);
  await page.close();
});
