// SCORM packages as a course system plays them: the package made on the page (Share on an
// exercise) or by the package's function in Node, unzipped on another origin, its manifest read
// in the browser (well-formed XML; the default organization's item, its resource's href) to find
// the launch file, which a host page frames while it runs scorm-again — the runtime course systems
// use — as window.API (SCORM 1.2) or window.API_1484_11 (SCORM 2004). A student fails and solves
// exercises with the page's own controls; the test reads what the runtime recorded (score, status,
// objectives, interactions, time, suspend_data), reloads with that data and finds her work again.
// A runtime that throws or answers "false", and a package whose exercises are hostile, are
// survived with a message in the page's language and the student's work kept.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { copyFileSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { createRequire } from 'node:module';
import { pageSession } from './browser.mjs';
import { otherOrigin } from './places.mjs';
import { unzipSync, strFromU8 } from '../../pkg/zip.js';
import { scormPackage } from '../../www/course/scorm-package.js';
import { readScorm } from '../../www/course/read.js';
import { SCORM12_SCHEMAS } from '../../pkg/scorm-schemas.js';
import { readSuspend } from '../../www/page/suspend.js';
import { readAttempt } from '../../www/task/attempt.js';
import { drawTask, seedOf } from '../../www/task/draw.js';
import { builtInTask } from '../../www/task/builtin.js';

const REPO = fileURLToPath(new URL('../..', import.meta.url));
const ONEFILE = readFileSync(join(REPO, 'dist/ruledlab.html'), 'utf8');
const session = pageSession();
const site = otherOrigin();

/** @typedef {import('playwright-core').Page} Page */

/** Unzips `bytes` into the site's folder `name`/ (its URL). */
const unpack = (/** @type {Uint8Array} */ bytes, /** @type {string} */ name) => site.unpack(bytes, name);

/** Serves scorm-again's runtimes next to the packages. */
function runtimes() {
  for (const f of ['scorm12.js', 'scorm2004.js'])
    copyFileSync(join(REPO, 'node_modules/scorm-again/dist', f), join(site.dir, f));
}

/**
 * A course system's page: the runtime as window.API / API_1484_11 (loaded with `saved`, a
 * flattened cmi, as an LMS restores an attempt), the manifest read as an LMS reads it, the launch
 * file it names in a frame. `api`: a script that replaces the runtime (a hostile one).
 */
function lms(/** @type {string} */ name, /** @type {string} */ folder, version = '1.2', saved = {}, api = '') {
  const global = version === '1.2' ? 'API' : 'API_1484_11';
  const html = `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>LMS</title>
<script src="${version === '1.2' ? 'scorm12.js' : 'scorm2004.js'}"></script></head><body>
<p id="launch"></p>
<iframe id="sco" title="the activity" width="1100" height="760"></iframe>
<script>
window.${global} = new ${version === '1.2' ? 'Scorm12API' : 'Scorm2004API'}({ logLevel: 5, autocommit: false });
window.${global}.loadFromFlattenedJSON(${JSON.stringify(saved)});
window.calls = [];
${api}
(async () => {
  const text = await (await fetch('${folder}imsmanifest.xml')).text();
  const xml = new DOMParser().parseFromString(text, 'application/xml');
  if (xml.querySelector('parsererror')) throw new Error('imsmanifest.xml is not well-formed');
  const orgs = xml.getElementsByTagName('organizations')[0];
  const org = [...xml.getElementsByTagName('organization')].find((o) => o.getAttribute('identifier') === orgs.getAttribute('default'));
  const item = org.getElementsByTagName('item')[0];
  const resource = [...xml.getElementsByTagName('resource')].find((r) => r.getAttribute('identifier') === item.getAttribute('identifierref'));
  window.manifest = { schemaversion: xml.getElementsByTagName('schemaversion')[0].textContent, title: org.getElementsByTagName('title')[0].textContent,
    scormtype: resource.getAttribute('adlcp:scormtype') ?? resource.getAttribute('adlcp:scormType'), href: resource.getAttribute('href') };
  document.getElementById('launch').textContent = window.manifest.href;
  document.getElementById('sco').src = '${folder}' + window.manifest.href;
})();
</script></body></html>`;
  return site.write(name, html);
}

/** The framed activity, once its exercise is shown. */
async function activity(/** @type {Page} */ page) {
  const frame = page.frameLocator('#sco');
  await frame.locator('.rl-stage[data-ready="1"] .rl-task h3').waitFor({ timeout: 60000 });
  return frame;
}

/** The runtime's data model, flattened (what an LMS stores). */
const cmi = (/** @type {Page} */ page, version = '1.2') =>
  page.evaluate((v) => {
    const api = /** @type {any} */ (window)[v === '1.2' ? 'API' : 'API_1484_11'];
    return api.renderCMIToJSONObject();
  }, version);

/** Chaikin's count after `steps` steps from 8 points (n → 2(n − 1)), as a student works it out. */
const chaikin = (/** @type {number} */ steps) => {
  let n = 8;
  for (let k = 0; k < steps; k++) n = 2 * (n - 1);
  return n;
};

test('SCORM 1.2 from Share: found by its manifest, failed and then solved with the page’s controls, recorded; a reload resumes from suspend_data', async () => {
  runtimes();
  // the lecturer: Share on a built-in exercise that draws its numbers → SCORM 1.2 package
  const lecturer = await session.open('index.html#task=chaikin-count&lang=en');
  await lecturer.page.locator('#share').click();
  await lecturer.page.locator('#share-dialog[data-ready="1"]').waitFor();
  const [download] = await Promise.all([
    lecturer.page.waitForEvent('download'),
    lecturer.page.locator('[name="share-scorm12"]').click(),
  ]);
  assert.equal(download.suggestedFilename(), 'chaikin-count-scorm12.zip');
  const bytes = new Uint8Array(readFileSync(/** @type {string} */ (await download.path())));
  // the manifest, the schema files it names, the page
  assert.deepEqual(
    Object.keys(unzipSync(bytes)).sort(),
    ['imsmanifest.xml', 'index.html', ...Object.keys(SCORM12_SCHEMAS)].sort(),
  );
  assert.deepEqual(lecturer.problems, []);
  await lecturer.page.close();

  unpack(bytes, 'p12');
  const { page, problems, requests } = await session.open(lms('lms12.html', 'p12/'), { wait: false });
  const frame = await activity(page);
  assert.deepEqual(await page.evaluate(() => window.manifest), {
    schemaversion: '1.2',
    title: 'Count Chaikin’s points',
    scormtype: 'sco',
    href: 'index.html',
  });
  // the student's numbers, and the course bar saying the course system records
  const steps = Number(/steps = (\d)/.exec(await frame.locator('.rl-task-drawn').innerText())?.[1]);
  assert.ok(steps >= 2 && steps <= 4, `steps drawn: ${steps}`);
  assert.match(await frame.locator('.rl-course-status').innerText(), /SCORM 1\.2/);
  // a wrong answer, by the page's own controls
  await frame.locator('input[name="task-count"]').fill('7');
  await frame.locator('.rl-task-check').click();
  assert.match(await frame.locator('.rl-task-results li').first().innerText(), /too small/);
  let data = await cmi(page);
  // the attempt stays open: "failed" would make a course system open the next launch for review
  assert.equal(data.cmi.core.lesson_status, 'incomplete');
  assert.equal(data.cmi.core.score.raw, '0');
  assert.equal(data.cmi.core.score.max, '100');
  const interactions = async () =>
    Object.values((await cmi(page)).cmi.interactions ?? {}).map((/** @type {any} */ i) => ({
      id: i.id,
      type: i.type,
      result: i.result,
      response: i.student_response,
    }));
  assert.deepEqual(await interactions(), [{ id: 'chaikin-count.c1', type: 'fill-in', result: 'wrong', response: '7' }]);
  // solved: the same interaction updated, the score full, passed
  await frame.locator('input[name="task-count"]').fill(String(chaikin(steps)));
  await frame.locator('input[name="task-count"]').press('Enter');
  await frame.locator('.rl-task-verdict.rl-task-solved').waitFor();
  data = await cmi(page);
  assert.equal(data.cmi.core.lesson_status, 'passed');
  assert.equal(data.cmi.core.score.raw, '100');
  assert.deepEqual(await interactions(), [
    { id: 'chaikin-count.c1', type: 'fill-in', result: 'correct', response: String(chaikin(steps)) },
  ]);
  // never the expected value: no correct response is written
  assert.deepEqual(data.cmi.interactions['0'].correct_responses, {});
  assert.equal(data.cmi.objectives['0'].id, 'chaikin-count');
  assert.equal(data.cmi.objectives['0'].status, 'passed');
  const suspend = readSuspend(data.cmi.suspend_data, ['chaikin-count']);
  assert.equal(suspend?.at, 0);
  assert.equal(readAttempt(suspend?.attempts[0])?.checks.length, 2);
  assert.match(await frame.locator('.rl-course-status').innerText(), /1 of 1 conditions met.*Recorded/s);
  // nothing requested outside the package and the runtime
  assert.deepEqual(
    requests.filter((r) => !r.startsWith(site.url) && !r.startsWith('data:') && !r.startsWith('blob:')),
    [],
  );
  // leaving: the page terminates (LMSFinish) with exit "" (solved) and the time spent
  await page.locator('#sco').evaluate((f) => f.remove());
  await page.waitForFunction(() => window.API.isTerminated());
  // (this browser's own copy of the attempt goes: what comes back is the course system's)
  await page.evaluate(() => localStorage.clear());
  data = await cmi(page);
  assert.equal(data.cmi.core.exit, '');
  // SCORM 1.2's CMITimespan: HHHH:MM:SS with one or two decimals of a second (RTE 3.4.2.2; the
  // runtime may write its own; Moodle's scorm_12.js: ^([0-9]{2,4}):([0-9]{2}):([0-9]{2})(\.[0-9]{1,2})?$)
  assert.match(data.cmi.core.session_time, /^\d{2,4}:\d\d:\d\d(\.\d{1,2})?$/);
  assert.deepEqual(problems, []);
  await page.close();

  // back later: the course system hands the attempt to a new runtime; her numbers, answer and checks are there
  const saved = {
    'cmi.suspend_data': data.cmi.suspend_data,
    'cmi.core.entry': 'resume',
    'cmi.core.student_name': 'Noether, Emmy',
  };
  const back = await session.open(lms('lms12b.html', 'p12/', '1.2', saved), { wait: false });
  const again = await activity(back.page);
  assert.match(await again.locator('.rl-task-drawn').innerText(), new RegExp(`steps = ${steps}`));
  assert.equal(await again.locator('input[name="task-count"]').inputValue(), String(chaikin(steps)));
  assert.equal(await again.locator('.rl-task-history li').count(), 2);
  assert.match(await again.locator('.rl-course-status').innerText(), /Noether, Emmy/);
  assert.deepEqual(back.problems, []);
  await back.page.close();
});

test('SCORM 2004 from the package’s function: three exercises as one activity, the score their sum; one solved by the controls, one failed; resumed where she left', async () => {
  runtimes();
  // a program makes the package (Node, the one-file page given), in German
  const bytes = await scormPackage(['striction-accuracy', 'chaikin-count', 'coupled-strip'], {
    standard: 'scorm2004',
    page: ONEFILE,
    lang: 'de',
  });
  const folder = unpack(bytes, 'p2004');
  assert.match(strFromU8(unzipSync(bytes)['imsmanifest.xml']), /adlcp:scormType="sco"/);
  const { page, problems } = await session.open(lms('lms2004.html', 'p2004/', '2004'), { wait: false });
  const frame = await activity(page);
  assert.deepEqual(await page.evaluate(() => window.manifest), {
    schemaversion: '2004 4th Edition',
    title: 'Wie viele Erzeugende für …? · Chaikins Punkte zählen · Wann sich die Kopplung lohnt',
    scormtype: 'sco',
    href: 'index.html',
  });
  assert.ok(folder);
  // the course bar: two exercises to choose, in German
  assert.deepEqual(
    (await frame.locator('[name="course-task"] option').allInnerTexts()).map((t) => t.replace(/ für .*\?/, ' für …?')),
    ['1. Wie viele Erzeugende für …?', '2. Chaikins Punkte zählen', '3. Wann sich die Kopplung lohnt'],
  );
  // exercise 1: her own start N and tolerance; she sets N = 100 with the control and checks
  const n = frame.locator('.rl-controls [name="n"]');
  await n.fill('100');
  await n.dispatchEvent('change');
  await frame.locator('.rl-task-check').click();
  await frame.locator('.rl-task-verdict.rl-task-solved').waitFor();
  // exercise 2, chosen in the bar: a wrong answer
  await frame.locator('[name="course-task"]').selectOption('1');
  await frame.locator('.rl-task h3', { hasText: 'Chaikins Punkte' }).waitFor();
  await frame.locator('input[name="task-count"]').fill('1000');
  await frame.locator('.rl-task-check').click();
  assert.match(await frame.locator('.rl-task-results li').first().innerText(), /zu groß/);
  // exercise 3: solved by its answer (n = 5)
  await frame.locator('[name="course-task"]').selectOption('2');
  await frame.locator('.rl-task h3', { hasText: 'Kopplung' }).waitFor();
  await frame.locator('input[name="task-n"]').fill('5');
  await frame.locator('.rl-task-check').click();
  await frame.locator('.rl-task-verdict.rl-task-solved').waitFor();
  let data = (await cmi(page, '2004')).cmi;
  // the score is the sum (2 of 3 conditions); the attempt stays open until all are solved or she ends it
  assert.deepEqual(
    [data.score.raw, data.score.max, data.score.scaled, data.completion_status, data.success_status],
    ['66.67', '100', '0.6666667', 'incomplete', 'unknown'],
  );
  assert.deepEqual(
    Object.values(data.objectives).map((/** @type {any} */ o) => [o.id, o.success_status, o.score.raw]),
    [
      ['striction-accuracy', 'passed', '1'],
      ['chaikin-count', 'unknown', '0'],
      ['coupled-strip', 'passed', '1'],
    ],
  );
  const inter = Object.values(data.interactions).map((/** @type {any} */ i) => [i.id, i.type, i.result]);
  assert.deepEqual(inter, [
    ['striction-accuracy.c1', 'numeric', 'correct'],
    ['chaikin-count.c1', 'other', 'incorrect'],
    ['coupled-strip.c1', 'other', 'correct'],
  ]);
  // the value she reached, and what she typed (never the expected value); the condition in words
  const [first, second] = /** @type {any[]} */ (Object.values(data.interactions));
  await frame.locator('[name="course-task"]').selectOption('1');
  await frame.locator('.rl-task h3', { hasText: 'Chaikins Punkte' }).waitFor();
  assert.ok(Number(first.learner_response) > 0 && Number(first.learner_response) < 2e-3, first.learner_response);
  assert.match(first.description, /Kehlpolygons.*unter/);
  assert.equal(second.learner_response, '1000');
  assert.match(await frame.locator('.rl-course-status').innerText(), /Bisher: 2 von 3 Bedingungen erfüllt/);
  // she leaves with one exercise unsolved: exit "suspend", the time spent
  await page.locator('#sco').evaluate((f) => f.remove());
  await page.waitForFunction(() => window.API_1484_11.isTerminated());
  await page.evaluate(() => localStorage.clear());
  data = (await cmi(page, '2004')).cmi;
  assert.equal(data.exit, 'suspend');
  assert.match(data.session_time, /^PT/);
  assert.deepEqual(problems, []);
  await page.close();

  // back: the same exercise, her answer, her numbers, her score
  const saved = { 'cmi.suspend_data': data.suspend_data, 'cmi.entry': 'resume' };
  const back = await session.open(lms('lms2004b.html', 'p2004/', '2004', saved), { wait: false });
  const again = await activity(back.page);
  assert.match(await again.locator('.rl-task h3').innerText(), /Chaikins Punkte/);
  assert.equal(await again.locator('input[name="task-count"]').inputValue(), '1000');
  assert.match(await again.locator('[name="course-task"] option').first().innerText(), /^✓ 1\./);
  assert.match(await again.locator('.rl-course-status').innerText(), /2 von 3/);
  assert.deepEqual(back.problems, []);
  await back.page.close();
});

test('a runtime that answers "false" or throws: said in the page’s language, the work kept and sent again with the next check', async () => {
  runtimes();
  const bytes = await scormPackage(['coupled-strip'], { standard: 'scorm12', page: ONEFILE, lang: 'de' });
  unpack(bytes, 'hostile');
  // LMSSetValue answers "false" (error 351) while window.failing is set; LMSCommit throws once
  const api = `window.failing = true; window.throwing = false;
const api = window.API, set = api.LMSSetValue.bind(api), commit = api.LMSCommit.bind(api), error = api.LMSGetLastError.bind(api);
api.LMSSetValue = (k, v) => (window.failing ? 'false' : set(k, v));
api.LMSGetLastError = () => (window.failing ? '351' : error());
api.LMSGetErrorString = () => 'General Set Failure';
api.LMSCommit = (x) => { if (window.throwing) throw new Error('network down'); return commit(x); };`;
  const { page, problems } = await session.open(lms('lms-hostile.html', 'hostile/', '1.2', {}, api), { wait: false });
  const frame = await activity(page);
  await frame.locator('input[name="task-n"]').fill('5');
  await frame.locator('.rl-task-check').click();
  // the check is the page's, whatever the course system does
  assert.match(await frame.locator('.rl-task-verdict').innerText(), /^✓ Gelöst/);
  const problem = frame.locator('.rl-course-problem');
  assert.match(
    await problem.innerText(),
    /Die Lernplattform hat das Ergebnis nicht angenommen \(LMSSetValue cmi\.[\w.]+: Fehler 351, „General Set Failure“\)\. Ihre Arbeit bleibt hier/,
  );
  assert.equal((await cmi(page)).cmi.core.lesson_status, 'not attempted', 'nothing was taken');
  // the course system throws: said too
  await page.evaluate(() => {
    window.failing = false;
    window.throwing = true;
  });
  await frame.locator('.rl-task-check').click();
  assert.match(await problem.innerText(), /Die Lernplattform ist gescheitert \(LMSCommit: „network down“\)/);
  // it recovers: the next check records everything, the message goes
  await page.evaluate(() => {
    window.throwing = false;
  });
  await frame.locator('.rl-task-check').click();
  await problem.waitFor({ state: 'hidden' });
  const data = (await cmi(page)).cmi;
  assert.equal(data.core.lesson_status, 'passed');
  assert.equal(await frame.locator('input[name="task-n"]').inputValue(), '5', 'her answer stayed');
  assert.equal(await frame.locator('.rl-task-history li').count(), 3, 'every check kept');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a hostile package or suspend_data: markup stays text, absurd numbers are refused in the page’s language, nothing breaks', async () => {
  const hostile = {
    ruledlab: 'exercise',
    version: 1,
    id: 'hostile',
    title: { en: '<img src=x onerror="parent.pwned=1">' },
    prompt: { en: '<script>parent.pwned=1</script>' },
    scene: 'curves',
    params: { steps: 1 },
    change: ['steps'],
    goal: [{ value: 'curves.readout.points', above: 100 }],
  };
  const packed = (/** @type {unknown[]} */ tasks, /** @type {string} */ lang) =>
    ONEFILE.replace(
      /(<script type="application\/json" id="ruledlab-state">)[^<]*(<\/script>)/,
      `$1${JSON.stringify({ hash: `embed&controls&lang=${lang}`, course: { standard: 'scorm12', title: '<b>x</b>', tasks } }).replace(/</g, '\\u003c')}$2`,
    );
  mkdirSync(join(site.dir, 'bad'), { recursive: true });
  writeFileSync(join(site.dir, 'bad/imsmanifest.xml'), readFileSync(join(site.dir, 'p12/imsmanifest.xml')));
  writeFileSync(join(site.dir, 'bad/index.html'), packed([hostile], 'en'));
  // garbage where the attempt should be: a seed that is not one, markup, impossible checks
  const saved = {
    'cmi.suspend_data': JSON.stringify({
      v: 1,
      seed: 'abc',
      at: 99,
      a: [{ answers: { x: '<b>bold</b>' }, hints: 1e300, checks: [{ at: 1e300, passed: 5, of: 1 }, 'x'] }],
    }),
    'cmi.core.entry': 'resume',
  };
  const { page, problems } = await session.open(lms('lms-bad.html', 'bad/', '1.2', saved), { wait: false });
  const frame = await activity(page);
  assert.match(await frame.locator('.rl-task h3').innerText(), /<img src=x/);
  assert.equal(await frame.locator('.rl-task h3 img, .rl-task script, .rl-course b').count(), 0);
  assert.equal(await frame.locator('.rl-course h2').innerText(), '<b>x</b>');
  assert.equal(await frame.locator('.rl-task-history li').count(), 0, 'impossible checks are dropped');
  assert.equal(await page.evaluate(() => /** @type {any} */ (window).pwned), undefined);
  await frame.locator('.rl-task-check').click();
  assert.match(await frame.locator('.rl-task-verdict').innerText(), /^Not solved yet/);
  assert.deepEqual(problems, []);
  await page.close();

  // an exercise with an absurd number: the package's exercises are refused, said in German
  writeFileSync(join(site.dir, 'bad/index.html'), packed([{ ...hostile, params: { steps: 1e300 } }], 'de'));
  const absurd = await session.open(lms('lms-absurd.html', 'bad/'), { wait: false });
  const broken = absurd.page.frameLocator('#sco').locator('.rl-course-problem');
  await broken.waitFor({ timeout: 60000 });
  assert.match(
    await broken.innerText(),
    /Die Aufgaben dieses Pakets lassen sich nicht lesen \(„params\.steps“ muss eine endliche Zahl/,
  );
  assert.deepEqual(absurd.problems, []);
  await absurd.page.close();
});

test('without a course system the package’s page works as anywhere, and says that nothing is recorded; its bar is accessible', async () => {
  const { page, problems } = await session.open(`${site.url}p12/index.html`);
  assert.match(await page.locator('.rl-course-status').innerText(), /No course system records here/);
  await page.evaluate(readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8'));
  const result = await page.evaluate(() =>
    window.axe.run(document, { runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] } }),
  );
  assert.deepEqual(
    result.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`),
    [],
  );
  await page.locator('input[name="task-count"]').fill('3');
  await page.locator('.rl-task-check').click();
  assert.match(await page.locator('.rl-task-verdict').innerText(), /^Not solved yet/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('Share: exercises ticked under “More exercises” go into the same SCORM package, one activity', async () => {
  const { page, problems } = await session.open('index.html#task=torsal-pair&lang=en');
  await page.locator('#share').click();
  await page.locator('#share-dialog[data-ready="1"]').waitFor();
  await page.locator('.rl-package-more summary').click();
  await page.locator('[name="share-more-coupled-strip"]').check();
  await page.locator('[name="share-more-hypar-striction"]').check();
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.locator('[name="share-scorm2004"]').click(),
  ]);
  const read = readScorm(new Uint8Array(readFileSync(/** @type {string} */ (await download.path()))));
  assert.equal(read.standard, 'scorm2004');
  assert.deepEqual(
    read.tasks.map((t) => t.id),
    ['torsal-pair', 'coupled-strip', 'hypar-striction'],
  );
  assert.equal(
    read.title,
    'Make a pair of rulings torsal · When coupling pays · The striction curve of the hyperbolic paraboloid',
  );
  assert.match(await page.locator('.rl-package-note').innerText(), /Made: upload the zip file as a SCORM package/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a shown solution earns nothing: after a wrong check, Show the solution and a check after it leave the score and status as the wrong check left them, the interactions neutral (1.2 and 2004)', async () => {
  runtimes();
  for (const version of /** @type {const} */ (['1.2', '2004'])) {
    const standard = version === '1.2' ? 'scorm12' : 'scorm2004';
    const bytes = await scormPackage(['coupled-strip'], { standard, page: ONEFILE, lang: 'en' });
    unpack(bytes, `shown${version}`);
    const { page, problems } = await session.open(lms(`lms-shown${version}.html`, `shown${version}/`, version), {
      wait: false,
    });
    const frame = await activity(page);
    // the solution is not offered before a first check
    assert.equal(await frame.locator('.rl-task-solution').isDisabled(), true);
    await frame.locator('input[name="task-n"]').fill('9');
    await frame.locator('.rl-task-check').click();
    await frame.locator('.rl-task-solution:not([disabled])').click();
    // the page says it counts for nothing; the answer is filled in and every condition holds
    assert.match(await frame.locator('.rl-task-verdict').innerText(), /Solution shown: it does not count/);
    assert.equal(await frame.locator('input[name="task-n"]').inputValue(), '5');
    assert.equal(await frame.locator('.rl-task-verdict.rl-task-solved').count(), 0);
    // she checks the solution's answer herself: still nothing
    await frame.locator('.rl-task-check').click();
    assert.match(await frame.locator('.rl-task-verdict').innerText(), /not counted: the solution was shown/);
    const data = (await cmi(page, version)).cmi;
    const interactions = /** @type {any[]} */ (Object.values(data.interactions));
    if (version === '1.2') {
      assert.deepEqual([data.core.score.raw, data.core.lesson_status], ['0', 'incomplete']);
      assert.equal(data.objectives['0'].status, 'incomplete');
    } else {
      assert.deepEqual(
        [data.score.raw, data.score.scaled, data.success_status, data.completion_status],
        ['0', '0', 'unknown', 'incomplete'],
      );
      assert.match(interactions[0].description, /^\(solution shown: not counted\)/);
    }
    // one interaction per condition, its result the latest: neutral (the solution's check, then hers)
    assert.deepEqual(
      interactions.map((i) => [i.id, i.result]),
      [['coupled-strip.c1', 'neutral']],
    );
    // the history says which checks count
    assert.deepEqual(
      (await frame.locator('.rl-task-history li').allInnerTexts()).map((t) => t.replace(/^[\d:. APM]+: /, '')),
      ['1 of 1 met (not counted: after the solution)', 'solution shown (not counted)', '0 of 1 met'],
    );
    assert.match(await frame.locator('.rl-course-status').innerText(), /Score so far: 0 of 1/);
    // the view's Reset (as Start over) keeps the attempt's checks and the solution's mark
    await frame.locator('.rl-reset').click();
    await frame.locator('input[name="task-n"]').fill('5');
    await frame.locator('.rl-task-check').click();
    assert.match(await frame.locator('.rl-task-verdict').innerText(), /not counted/);
    assert.equal(await frame.locator('.rl-task-history li').count(), 4);
    // the student leaves and comes back: still shown, still nothing
    await page.locator('#sco').evaluate((f) => f.remove());
    const saved = {
      'cmi.suspend_data': (await cmi(page, version)).cmi.suspend_data,
      [version === '1.2' ? 'cmi.core.entry' : 'cmi.entry']: 'resume',
    };
    assert.deepEqual(problems, []);
    await page.close();
    const back = await session.open(lms(`lms-shown${version}b.html`, `shown${version}/`, version, saved), {
      wait: false,
    });
    const again = await activity(back.page);
    await again.locator('.rl-task-check').click();
    assert.match(await again.locator('.rl-task-verdict').innerText(), /not counted/);
    const after = (await cmi(back.page, version)).cmi;
    assert.equal(version === '1.2' ? after.core.score.raw : after.score.raw, '0');
    assert.deepEqual(back.problems, []);
    await back.page.close();
  }
});

test('a lecturer may offer the solution only after N checks, or never: said on the button, held to by the page', async () => {
  runtimes();
  const bytes = await scormPackage(['coupled-strip'], { page: ONEFILE, lang: 'en', readers: { solution: 2 } });
  unpack(bytes, 'after2');
  const { page, problems } = await session.open(lms('lms-after2.html', 'after2/'), { wait: false });
  const frame = await activity(page);
  const button = frame.locator('.rl-task-solution');
  assert.match(/** @type {string} */ (await button.getAttribute('title')), /once 2 checks have not solved/);
  await frame.locator('input[name="task-n"]').fill('9');
  await frame.locator('.rl-task-check').click();
  assert.equal(await button.isDisabled(), true, 'one check is not enough');
  await frame.locator('.rl-task-check').click();
  assert.equal(await button.isDisabled(), false);
  assert.deepEqual(problems, []);
  await page.close();
  const never = await scormPackage(['coupled-strip'], { page: ONEFILE, lang: 'en', readers: { solution: null } });
  unpack(never, 'never');
  const other = await session.open(lms('lms-never.html', 'never/'), { wait: false });
  const f = await activity(other.page);
  await f.locator('input[name="task-n"]').fill('9');
  for (let k = 0; k < 3; k++) await f.locator('.rl-task-check').click();
  assert.equal(await f.locator('.rl-task-solution').isHidden(), true);
  assert.deepEqual(other.problems, []);
  await other.page.close();
});

test('two learners on one lab computer never see each other’s work; each finds her own again; a copy kept here is read only for its learner (1.2 and 2004)', async () => {
  runtimes();
  for (const version of /** @type {const} */ (['1.2', '2004'])) {
    const standard = version === '1.2' ? 'scorm12' : 'scorm2004';
    const id = version === '1.2' ? 'cmi.core.student_id' : 'cmi.learner_id';
    const name = version === '1.2' ? 'cmi.core.student_name' : 'cmi.learner_name';
    const entry = version === '1.2' ? 'cmi.core.entry' : 'cmi.entry';
    const bytes = await scormPackage(['coupled-strip'], { standard, page: ONEFILE, lang: 'en' });
    const folder = `two${version}`;
    unpack(bytes, folder);
    // Alice: a wrong answer, then she leaves (the attempt open)
    const alice = await session.open(
      lms(`alice${version}.html`, `${folder}/`, version, { [id]: 'u-alice', [name]: 'Alice' }),
      {
        wait: false,
      },
    );
    let frame = await activity(alice.page);
    await frame.locator('input[name="task-n"]').fill('7');
    await frame.locator('.rl-task-check').click();
    await alice.page.locator('#sco').evaluate((f) => f.remove());
    const aliceData = (await cmi(alice.page, version)).cmi;
    assert.equal(version === '1.2' ? aliceData.core.exit : aliceData.exit, 'suspend');
    assert.equal(version === '1.2' ? aliceData.core.lesson_status : aliceData.completion_status, 'incomplete');
    await alice.page.close();
    // Bob, next, in the same browser: a new learner, nothing kept for him
    const bob = await session.open(lms(`bob${version}.html`, `${folder}/`, version, { [id]: 'u-bob', [name]: 'Bob' }), {
      wait: false,
    });
    frame = await activity(bob.page);
    assert.equal(await frame.locator('input[name="task-n"]').inputValue(), '');
    assert.equal(await frame.locator('.rl-task-history li').count(), 0);
    assert.match(await frame.locator('.rl-course-status').innerText(), /Score so far: 0 of 1/);
    // he leaves without typing: his record holds nothing of hers
    await bob.page.locator('#sco').evaluate((f) => f.remove());
    const bobData = (await cmi(bob.page, version)).cmi;
    assert.deepEqual(bobData.interactions ?? {}, {});
    assert.notEqual(version === '1.2' ? bobData.core.lesson_status : bobData.success_status, 'passed');
    assert.doesNotMatch(bobData.suspend_data, /"7"/);
    assert.deepEqual(bob.problems, []);
    await bob.page.close();
    // Alice back: the course system's record of her attempt resumes it
    const back = await session.open(
      lms(`alice${version}b.html`, `${folder}/`, version, {
        [id]: 'u-alice',
        [name]: 'Alice',
        [entry]: 'resume',
        'cmi.suspend_data': aliceData.suspend_data,
      }),
      { wait: false },
    );
    frame = await activity(back.page);
    assert.equal(await frame.locator('input[name="task-n"]').inputValue(), '7');
    assert.equal(await frame.locator('.rl-task-history li').count(), 1);
    await back.page.close();
    // Alice again, and the course system lost her attempt (its last saving failed): this browser's
    // copy of hers, keyed by her id and the package, restores it, and says so
    const lost = await session.open(
      lms(`alice${version}c.html`, `${folder}/`, version, { [id]: 'u-alice', [name]: 'Alice', [entry]: 'resume' }),
      { wait: false },
    );
    frame = await activity(lost.page);
    assert.equal(await frame.locator('input[name="task-n"]').inputValue(), '7');
    assert.match(await frame.locator('.rl-course-mode').innerText(), /restored from this browser/);
    await lost.page.close();
    // … but never for Bob, nor for a learner the course system does not name
    for (const who of [{ [id]: 'u-bob' }, {}]) {
      const other = await session.open(
        lms(`other${version}.html`, `${folder}/`, version, { ...who, [entry]: 'resume' }),
        {
          wait: false,
        },
      );
      frame = await activity(other.page);
      assert.equal(await frame.locator('input[name="task-n"]').inputValue(), '', JSON.stringify(who));
      await other.page.close();
    }
    // nothing of the course's in the storage every page of this origin shares, under the exercise's own name
    const { page } = await session.open(site.write('blank.html', '<!doctype html><title>blank</title>'), {
      wait: false,
    });
    const keys = await page.evaluate(() => Object.keys(localStorage));
    assert.deepEqual(
      keys.filter((k) => k.startsWith('ruledlab.attempt.') || k === 'ruledlab.progress'),
      [],
    );
    await page.evaluate(() => localStorage.clear());
    await page.close();
  }
});

test('a course system that will not start the session, a review, browsing and no credit: each said; nothing that counts is written', async () => {
  runtimes();
  const bytes = await scormPackage(['coupled-strip'], { standard: 'scorm2004', page: ONEFILE, lang: 'en' });
  unpack(bytes, 'modes');
  // Initialize answers "false": said, and the bar claims nothing
  const refuse = `const api = window.API_1484_11; api.Initialize = () => 'false'; api.GetLastError = () => '102'; api.GetErrorString = () => 'General Initialization Failure';`;
  const failed = await session.open(lms('lms-init.html', 'modes/', '2004', {}, refuse), { wait: false });
  let frame = await activity(failed.page);
  assert.match(
    await frame.locator('.rl-course-problem').innerText(),
    /The course system did not start the session \(Initialize: error 102, “General Initialization Failure”\): nothing you do here is recorded/,
  );
  await frame.locator('input[name="task-n"]').fill('5');
  await frame.locator('.rl-task-check').click();
  assert.doesNotMatch(await frame.locator('.rl-course-status').innerText(), /records|Recorded/);
  assert.equal(await frame.locator('[name="course-end"]').isHidden(), true);
  assert.deepEqual(failed.problems, []);
  await failed.page.close();

  // a recorded attempt (a wrong check, left open) to review
  const first = await session.open(lms('lms-first.html', 'modes/', '2004'), { wait: false });
  frame = await activity(first.page);
  await frame.locator('input[name="task-n"]').fill('7');
  await frame.locator('.rl-task-check').click();
  await first.page.locator('#sco').evaluate((f) => f.remove());
  const recorded = (await cmi(first.page, '2004')).cmi;
  await first.page.close();
  for (const [mode, credit, said] of [
    ['review', 'no-credit', /opened this attempt for review/],
    ['browse', 'no-credit', /opened this activity for browsing/],
    ['normal', 'no-credit', /not graded/],
  ]) {
    const saved = {
      'cmi.suspend_data': recorded.suspend_data,
      'cmi.entry': 'resume',
      'cmi.mode': mode,
      'cmi.credit': credit,
    };
    const { page, problems } = await session.open(lms(`lms-${mode}.html`, 'modes/', '2004', saved), { wait: false });
    frame = await activity(page);
    assert.match(await frame.locator('.rl-course-mode').innerText(), said);
    // her work is there; she may check, and nothing that counts is written
    assert.equal(await frame.locator('input[name="task-n"]').inputValue(), '7');
    await frame.locator('input[name="task-n"]').fill('5');
    await frame.locator('.rl-task-check').click();
    await frame.locator('.rl-task-verdict.rl-task-solved').waitFor();
    await page.locator('#sco').evaluate((f) => f.remove());
    const data = (await cmi(page, '2004')).cmi;
    assert.deepEqual([data.score.raw, data.success_status, data.interactions ?? {}], ['', 'unknown', {}], mode);
    // (without credit in a normal attempt her work is kept; a review keeps the attempt as it was)
    assert.equal(data.suspend_data.includes('"5"'), mode === 'normal', mode);
    assert.deepEqual(problems, []);
    await page.close();
  }
});

test('ending the attempt: asked once more, then recorded as done (1.2 failed, 2004 completed and failed) and the session ended; nothing after it is recorded', async () => {
  runtimes();
  for (const version of /** @type {const} */ (['1.2', '2004'])) {
    const bytes = await scormPackage(['coupled-strip', 'chaikin-count'], {
      standard: version === '1.2' ? 'scorm12' : 'scorm2004',
      page: ONEFILE,
      lang: 'en',
    });
    unpack(bytes, `end${version}`);
    const { page, problems } = await session.open(lms(`lms-end${version}.html`, `end${version}/`, version), {
      wait: false,
    });
    const frame = await activity(page);
    await frame.locator('input[name="task-n"]').fill('5');
    await frame.locator('.rl-task-check').click();
    await frame.locator('[name="course-end"]').click();
    assert.match(await frame.locator('.rl-course-confirm').innerText(), /End the attempt with 1 of 2 conditions met\?/);
    // "Keep working" keeps it open
    await frame.locator('[name="course-end-no"]').click();
    assert.equal(await frame.locator('.rl-course-confirm').isHidden(), true);
    await frame.locator('[name="course-end"]').click();
    await frame.locator('[name="course-end-yes"]').click();
    await page.waitForFunction((v) => window[v === '1.2' ? 'API' : 'API_1484_11'].isTerminated(), version);
    const data = (await cmi(page, version)).cmi;
    if (version === '1.2')
      assert.deepEqual([data.core.lesson_status, data.core.exit, data.core.score.raw], ['failed', '', '50']);
    else
      assert.deepEqual(
        [data.completion_status, data.success_status, data.exit, data.score.raw],
        ['completed', 'failed', 'normal', '50'],
      );
    assert.match(await frame.locator('.rl-course-status').innerText(), /You ended this attempt/);
    assert.equal(await frame.locator('[name="course-end"]').isHidden(), true);
    assert.deepEqual(problems, []);
    await page.close();
  }
});

test('numbers drawn per learner: the same at every launch of hers (a new attempt and a review too), another learner’s her own', async () => {
  runtimes();
  const bytes = await scormPackage(['hypar-distribution'], { page: ONEFILE, lang: 'en', draw: 'learner' });
  unpack(bytes, 'learner');
  const packageKey = seedOf(JSON.stringify(['scorm12', readScorm(bytes).title, ['hypar-distribution']])).toString(36);
  const task = /** @type {import('../../www/task/format.js').Task} */ (builtInTask('hypar-distribution'));
  /** The k the page must draw for a learner: from her id and the package, as the page computes it. */
  const expected = (/** @type {string} */ id) => drawTask(task, seedOf(`${id}\u0000${packageKey}`)).drawn?.values.k;
  // two learners whose numbers differ (found, not hoped for)
  const ids = ['u-1', 'u-2', 'u-3', 'u-4', 'u-5'];
  const other = ids.find((id) => expected(id) !== expected('u-1'));
  assert.ok(other);
  /** The k a launch shows. */
  const shown = async (/** @type {string} */ name, /** @type {Record<string, string>} */ saved) => {
    const { page, problems } = await session.open(lms(name, 'learner/', '1.2', saved), { wait: false });
    const frame = await activity(page);
    const k = Number(/k = (−?\d)/.exec(await frame.locator('.rl-task-drawn').innerText())?.[1].replace('−', '-'));
    assert.deepEqual(problems, []);
    await page.close();
    return k;
  };
  assert.equal(await shown('l1.html', { 'cmi.core.student_id': 'u-1' }), expected('u-1'));
  assert.equal(
    await shown('l2.html', { 'cmi.core.student_id': 'u-1', 'cmi.core.lesson_mode': 'review' }),
    expected('u-1'),
  );
  assert.equal(
    await shown('l3.html', { 'cmi.core.student_id': /** @type {string} */ (other) }),
    expected(/** @type {string} */ (other)),
  );
});
