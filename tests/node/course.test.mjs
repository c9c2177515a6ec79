// Course systems from Node (ruledlab/course): SCORM packages and .h5p files made by the package's
// functions and read back, what the package's page writes to a SCORM runtime (every value in the
// format SCORM 1.2 and 2004 define), drawn numbers (the same for a seed everywhere, every value
// of a draw reachable, a bad draw or seed refused), and attempts read back from storage or a
// course system whatever they hold. The real runtimes and player: tests/page/scorm.test.mjs and
// tests/page/h5p.test.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import './load.mjs';
import { strFromU8, unzipSync } from '../../pkg/zip.js';
import { scormPackage, h5pPackage, readH5p, readScorm, readZip, makeZip, H5P_FOLDER } from '../../www/course/index.js';
import { H5P_PATCH } from '../../www/course/h5p-package.js';
import { h5pExercise } from '../../www/course/h5p-exercise.js';
import { scormValues, decimal, timespan, moment, findRuntime } from '../../www/page/scorm.js';
import { readSuspend, writeSuspend } from '../../www/page/suspend.js';
import { readSolutionRule, writeSolutionRule } from '../../www/task/solution-rule.js';
import { SCORM2004_SCHEMAS } from '../../pkg/scorm-schemas.js';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { readTask, writeTask, readSeed, linkSeed } from '../../www/task/format.js';
import { drawTask, drawChoices, drawnValues } from '../../www/task/draw.js';
import { readAttempt, bestCheck } from '../../www/task/attempt.js';
import { builtInTask, builtInTasks } from '../../www/task/builtin.js';
import { fitTask } from '../../www/task/check.js';
import { SCENES } from '../../www/scenes/index.js';
import { withChoices } from '../../www/scene.js';
import {
  MAX_PACKAGE_BYTES,
  MAX_SOLUTION_AFTER,
  MAX_TASK_HISTORY,
  SCORM12_RESPONSE,
  SCORM12_SUSPEND,
} from '../../www/limits.js';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const PAGE = readFileSync(`${ROOT}dist/ruledlab.html`, 'utf8');
const EMBED = readFileSync(`${ROOT}dist/ruledlab-embed.js`, 'utf8');

/** A code of what was thrown. */
const reason = (/** @type {() => unknown} */ f) => {
  try {
    f();
  } catch (e) {
    return /** @type {any} */ (e).details?.reason ?? /** @type {any} */ (e).message;
  }
  return 'nothing thrown';
};
const rejects = async (/** @type {() => Promise<unknown>} */ f) => {
  try {
    await f();
  } catch (e) {
    return /** @type {any} */ (e).details?.reason ?? /** @type {any} */ (e).message;
  }
  return 'nothing thrown';
};

const EXERCISE = {
  ruledlab: 'exercise',
  version: 1,
  id: 'heisst-torsal',
  title: { en: 'What does <torsal> mean & why?' },
  prompt: { en: 'Choose {k} steps.' },
  scene: 'curves',
  draw: { k: { from: 1, to: 5, step: 2 }, lim: { list: [10, 0.5] } },
  params: { steps: { drawn: 'k' } },
  change: ['steps'],
  goal: [{ value: 'curves.readout.points', above: { drawn: 'lim' } }],
  hints: [{ en: 'k is {k}, the bound {lim}.' }],
};

test('drawn numbers: every value of a draw reachable, the same for a seed, texts and bounds filled; the written form kept', () => {
  const task = readTask(EXERCISE);
  assert.deepEqual(drawChoices(task.draw.k), [1, 3, 5]);
  assert.deepEqual(drawChoices({ from: 0.2, to: 0.8, step: 0.1 }), [0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8]);
  // a drawn parameter holds the draw's first value until drawn
  assert.equal(task.params.steps, 1);
  assert.deepEqual(task.drawnParams, { steps: 'k' });
  const seen = new Set();
  for (let seed = 0; seed < 60; seed++) {
    const d = drawTask(task, seed);
    assert.deepEqual(drawTask(task, seed), d, 'the same seed draws the same numbers');
    const { k, lim } = /** @type {any} */ (d.drawn).values;
    seen.add(`${k}/${lim}`);
    assert.equal(d.params.steps, k);
    assert.equal(d.goal[0].above, lim);
    assert.equal(d.prompt.en, `Choose ${k} steps.`);
    assert.equal(d.hints[0].en, `k is ${k}, the bound ${lim}.`);
  }
  assert.equal(seen.size, 6, `every pair drawn: ${[...seen]}`);
  // the link and the JSON keep the exercise as written, not one student's numbers
  const drawn = drawTask(task, 7);
  assert.deepEqual(readTask(writeTask(drawn)), task);
  assert.deepEqual(JSON.parse(writeTask(drawn)).params, { steps: { drawn: 'k' } });
  // other exercises' ids draw other numbers from the same seed (its id is in the draw)
  const other = readTask({ ...EXERCISE, id: 'another' });
  assert.ok(
    Array.from({ length: 20 }, (_, s) => drawnValues(task, s).k !== drawnValues(other, s).k).some(Boolean),
    'the draws depend on the exercise',
  );
  // a drawn German text writes its numbers the German way
  const de = drawTask(
    readTask({
      ...EXERCISE,
      prompt: { de: 'Bis {x}.' },
      draw: { ...EXERCISE.draw, x: { list: [0.5] }, lim: { list: [1] } },
    }),
    1,
  );
  assert.equal(de.prompt.de, 'Bis 0,5.');
});

test('a draw, a drawn reference or a seed that is not one is refused with its reason', () => {
  const with_ = (/** @type {Record<string, unknown>} */ o) => () => readTask({ ...EXERCISE, ...o });
  assert.equal(reason(with_({ draw: { ...EXERCISE.draw, k: { from: 5, to: 1 } } })), 'task.error.draw');
  assert.equal(reason(with_({ draw: { k: { from: 1, to: 5, step: 0 } } })), 'task.error.draw');
  assert.equal(reason(with_({ draw: { k: { from: 0, to: 1e9, step: 1e-3 } } })), 'task.error.draw');
  assert.equal(reason(with_({ draw: { k: { list: [] } } })), 'task.error.draw');
  assert.equal(reason(with_({ draw: { k: { from: 1, to: 2, by: 1 } } })), 'task.error.draw');
  assert.equal(reason(with_({ draw: { k: { from: 1, to: Number.NaN } } })), 'task.error.number');
  assert.equal(reason(with_({ draw: { k: { from: 1, to: 1e300 } } })), 'task.error.number');
  assert.equal(reason(with_({ params: { steps: { drawn: 'nope' } } })), 'task.error.notDrawn');
  assert.equal(
    reason(with_({ goal: [{ value: 'curves.readout.points', above: { drawn: 'nope' } }] })),
    'task.error.notDrawn',
  );
  assert.equal(reason(with_({ params: { steps: { drawn: 'k', more: 1 } } })), 'task.error.unknownKey');
  for (const bad of ['abc', '-1', '1.5', '4294967296', '', ' 12 x', '1e3'])
    assert.equal(
      reason(() => readSeed(bad)),
      'task.error.seed',
      bad,
    );
  assert.equal(readSeed('4294967295'), 4294967295);
  assert.deepEqual(linkSeed('x').note, { key: 'task', note: 'note.badSeed', vars: { max: '4294967295' } });
  assert.deepEqual(linkSeed(null), { seed: null, note: null });
  assert.equal(
    reason(() => drawTask(readTask(EXERCISE), -1)),
    'task.error.seed',
  );
});

test('a drawn parameter must be one the scene takes for every value drawn', () => {
  const scene = /** @type {any} */ (SCENES.find((s) => s.id === 'striction'));
  const compute = (/** @type {any} */ task) => (/** @type {any} */ params, /** @type {any} */ input) =>
    scene.create(withChoices(scene, { ...task.params, ...params }), {
      t: (/** @type {string} */ k) => k,
      format: String,
      lang: 'en',
      ...(input ? { input } : {}),
    });
  const base = {
    ruledlab: 'exercise',
    version: 1,
    id: 'n',
    title: { en: 'n' },
    prompt: { en: 'n' },
    scene: 'striction',
    params: { n: { drawn: 'n' } },
    change: ['n'],
    goal: [{ value: 'readout.midpointError', below: 1 }],
  };
  const ok = drawTask(readTask({ ...base, draw: { n: { from: 8, to: 16 } } }), 1);
  assert.equal(fitTask(ok, SCENES, compute(ok)).id, 'striction');
  for (const draw of [{ from: 2, to: 16 }, { list: [12, 500] }, { from: 8, to: 9, step: 0.5 }]) {
    const bad = drawTask(readTask({ ...base, draw: { n: draw } }), 1);
    assert.equal(
      reason(() => fitTask(bad, SCENES, compute(bad))),
      'task.error.drawnParam',
      JSON.stringify(draw),
    );
  }
});

test('an attempt read back from storage or a course system keeps what is one and drops the rest', () => {
  const good = {
    seed: 12,
    params: { n: 40 },
    input: 'rulings.AAAA',
    answers: { s: ['u', '0', '0'], n: '5' },
    hints: 1,
    checks: [
      { at: 1, passed: 0, of: 1 },
      { at: 2, passed: 1, of: 1 },
    ],
    shown: false,
  };
  assert.deepEqual(readAttempt(JSON.parse(JSON.stringify(good))), good);
  assert.equal(bestCheck(good)?.at, 2);
  // a solution shown, and every check after it, count for nothing: the best stays the one before
  const shown = readAttempt({
    ...good,
    checks: [
      { at: 1, passed: 0, of: 1 },
      { at: 2, passed: 1, of: 1, shown: 'solution' },
      { at: 3, passed: 1, of: 1, shown: 'after' },
    ],
  });
  assert.equal(shown?.shown, true, 'a check marked as made after the solution says the solution was shown');
  assert.deepEqual(bestCheck(shown), { at: 1, passed: 0, of: 1 });
  assert.equal(bestCheck({ checks: [{ at: 2, passed: 1, of: 1, shown: 'solution' }] }), null);
  assert.equal(readAttempt({ checks: [{ at: 1, passed: 0, of: 1, shown: 'bogus' }] })?.checks[0].shown, undefined);
  assert.equal(readAttempt('x'), null);
  assert.equal(readAttempt([1]), null);
  const hostile = readAttempt({
    seed: 'abc',
    params: { 'a b': 1, n: Number.POSITIVE_INFINITY, ok: 'x'.repeat(5000), fine: true, __proto__x: 1 },
    input: { x: 1 },
    answers: { s: ['u'], t: 5, '<b>': 'x', u: '<b>bold</b>' },
    hints: 1e300,
    checks: [{ at: 1e300, passed: 1, of: 1 }, { at: 1, passed: 3, of: 2 }, 'x', { at: 3, passed: 1, of: 2 }],
  });
  assert.deepEqual(hostile, {
    seed: null,
    params: { fine: true },
    input: null,
    answers: { u: '<b>bold</b>' },
    hints: 0,
    checks: [{ at: 3, passed: 1, of: 2 }],
    shown: false,
  });
});

test('what the package’s page writes to a SCORM runtime, in the formats SCORM 1.2 and 2004 define', () => {
  assert.equal(decimal(0.0018915), '0.0018915');
  assert.equal(decimal(1e-12), '0');
  assert.equal(decimal(2.5), '2.5');
  assert.equal(decimal(1e12), '');
  assert.equal(decimal(Number.NaN), '');
  assert.equal(timespan(3723.456, '1.2'), '0001:02:03.46');
  assert.equal(timespan(3723.456, '2004'), 'PT1H2M3.46S');
  const when = new Date(2026, 11, 4, 9, 5, 7);
  assert.equal(moment(when, '1.2'), '09:05:07');
  assert.equal(moment(when, '2004'), '2026-12-04T09:05:07');
  const tasks = [
    {
      id: 'a',
      title: 'A',
      of: 2,
      best: { passed: 1, of: 2 },
      conditions: [
        { id: 'a.c1', holds: true, numeric: true, response: '0.5', description: 'd1' },
        { id: 'a.c2', holds: false, numeric: false, response: 'x'.repeat(300), description: 'd2' },
      ],
    },
    { id: 'b', title: 'B', of: 1, best: null, conditions: null },
  ];
  /** @type {string[]} */
  const order = ['b.c1'];
  const v12 = Object.fromEntries(scormValues('1.2', tasks, order, { seconds: 5, now: when }));
  assert.deepEqual(order, ['b.c1', 'a.c1', 'a.c2'], 'new interactions appended in the order first checked');
  assert.equal(v12['cmi.core.score.raw'], '33.33');
  assert.equal(v12['cmi.core.score.max'], '100');
  assert.equal(v12['cmi.core.lesson_status'], 'incomplete', 'b is not checked yet');
  assert.equal(v12['cmi.objectives.1.status'], 'incomplete');
  assert.equal(v12['cmi.interactions.1.id'], 'a.c1');
  assert.equal(v12['cmi.interactions.1.type'], 'numeric');
  assert.equal(v12['cmi.interactions.2.result'], 'wrong');
  assert.equal(v12['cmi.interactions.2.student_response'].length, SCORM12_RESPONSE);
  assert.equal(v12['cmi.core.session_time'], '0000:00:05.00');
  assert.ok(!Object.keys(v12).some((k) => k.includes('correct_responses')), 'never the expected value');
  const v2004 = Object.fromEntries(
    scormValues('2004', [tasks[0], { ...tasks[1], best: { passed: 1, of: 1 } }], [], { seconds: 5, now: when }),
  );
  assert.deepEqual(
    ['raw', 'min', 'max', 'scaled'].map((k) => v2004[`cmi.score.${k}`]),
    ['66.67', '0', '100', '0.6666667'],
  );
  // each exercise's own count: its objective
  assert.deepEqual(
    ['raw', 'max', 'scaled'].map((k) => v2004[`cmi.objectives.0.score.${k}`]),
    ['1', '2', '0.5'],
  );
  assert.deepEqual([v12['cmi.objectives.0.score.raw'], v12['cmi.objectives.0.score.max']], ['1', '2']);
  // the attempt stays open until every exercise is solved or she ends it (a course system treats
  // "completed", "passed" and "failed" as finished and opens the next launch for review)
  assert.equal(v2004['cmi.completion_status'], 'incomplete');
  assert.equal(v2004['cmi.success_status'], 'unknown');
  assert.equal(v2004['cmi.objectives.0.success_status'], 'unknown');
  assert.equal(v2004['cmi.objectives.1.success_status'], 'passed');
  const ended = Object.fromEntries(
    scormValues('2004', [tasks[0], { ...tasks[1], best: { passed: 1, of: 1 } }], [], {
      seconds: 5,
      now: when,
      ended: true,
    }),
  );
  assert.deepEqual(
    [ended['cmi.completion_status'], ended['cmi.success_status'], ended['cmi.progress_measure']],
    ['completed', 'failed', '1'],
  );
  const ended12 = Object.fromEntries(scormValues('1.2', tasks, [], { seconds: 5, now: when, ended: true }));
  assert.equal(ended12['cmi.core.lesson_status'], 'failed');
  const solvedAll = (/** @type {'1.2' | '2004'} */ v) =>
    Object.fromEntries(
      scormValues(
        v,
        [
          { ...tasks[0], best: { passed: 2, of: 2 } },
          { ...tasks[1], best: { passed: 1, of: 1 } },
        ],
        [],
        {
          seconds: 5,
          now: when,
        },
      ),
    );
  assert.equal(solvedAll('1.2')['cmi.core.lesson_status'], 'passed');
  assert.deepEqual(
    [solvedAll('2004')['cmi.completion_status'], solvedAll('2004')['cmi.success_status']],
    ['completed', 'passed'],
  );
  // a condition checked with the solution shown (or after it): recorded as neutral, in both
  const shownTasks = [{ ...tasks[0], conditions: tasks[0].conditions.map((c) => ({ ...c, shown: true })) }];
  const n12 = Object.fromEntries(scormValues('1.2', shownTasks, [], { seconds: 5, now: when }));
  const n2004 = Object.fromEntries(scormValues('2004', shownTasks, [], { seconds: 5, now: when }));
  assert.deepEqual([n12['cmi.interactions.0.result'], n12['cmi.interactions.1.result']], ['neutral', 'neutral']);
  assert.deepEqual([n2004['cmi.interactions.0.result'], n2004['cmi.interactions.1.result']], ['neutral', 'neutral']);
  assert.equal(v2004['cmi.interactions.1.type'], 'other');
  assert.equal(v2004['cmi.interactions.1.result'], 'incorrect');
  assert.equal(v2004['cmi.interactions.0.learner_response'], '0.5');
  assert.equal(v2004['cmi.session_time'], 'PT0H0M5.00S');
  // the runtime is looked for up the frames and stops at another origin without throwing
  const top = { API_1484_11: { Initialize() {} } };
  const frame = { parent: { parent: top } };
  /** @type {any} */ (top).parent = top;
  assert.equal(findRuntime(/** @type {any} */ (frame), '2004')?.version, '2004');
  const guarded = {
    get parent() {
      throw new Error('SecurityError');
    },
  };
  assert.equal(findRuntime(/** @type {any} */ (guarded)), null);
});

test('a SCORM package from Node: its manifest, its launch file set to the exercises, read back; refused where it must be', async () => {
  const zip = await scormPackage(
    [
      'torsal-pair',
      EXERCISE,
      JSON.stringify({ ...EXERCISE, id: 'second', draw: { ...EXERCISE.draw, lim: { list: [1] } } }),
    ].slice(0, 1),
    {
      standard: 'scorm2004',
      page: PAGE,
    },
  );
  const files = unzipSync(zip);
  // the manifest, the schema files it names (the standard's: SCORM 2004 4th edition's), the page
  assert.deepEqual(
    Object.keys(files).sort(),
    ['imsmanifest.xml', 'index.html', ...Object.keys(SCORM2004_SCHEMAS)].sort(),
  );
  const manifest = strFromU8(files['imsmanifest.xml']);
  assert.match(manifest, /<schemaversion>2004 4th Edition<\/schemaversion>/);
  assert.match(manifest, /adlcp:scormType="sco" href="index.html"/);
  assert.equal(readScorm(zip).tasks[0].id, 'torsal-pair');
  // two exercises, one of them with markup in its title: one activity, the title escaped in the manifest
  const ok = EXERCISE;
  const two = await scormPackage(['torsal-pair', ok], { page: PAGE });
  const read = readScorm(two);
  assert.equal(read.standard, 'scorm12');
  assert.deepEqual(
    read.tasks.map((t) => t.id),
    ['torsal-pair', 'heisst-torsal'],
  );
  assert.match(
    strFromU8(unzipSync(two)['imsmanifest.xml']),
    /<title>Make a pair of rulings torsal · What does &lt;torsal&gt; mean &amp; why\?<\/title>/,
  );
  // the same exercises make the same bytes
  assert.deepEqual(await scormPackage(['torsal-pair', ok], { page: PAGE }), two);
  // refused: no exercises, too many, an unknown one, a broken one, not the one-file page, no page in Node
  assert.equal(await rejects(() => scormPackage([], { page: PAGE })), 'course.error.noTasks');
  assert.equal(
    await rejects(() => scormPackage(Array(13).fill('torsal-pair'), { page: PAGE })),
    'course.error.noTasks',
  );
  assert.equal(await rejects(() => scormPackage(['no-such'], { page: PAGE })), 'task.error.unknownBuiltIn');
  assert.equal(await rejects(() => scormPackage([{ ...EXERCISE, goal: [] }], { page: PAGE })), 'task.error.missing');
  assert.equal(
    await rejects(() => scormPackage(['torsal-pair'], { page: '<html></html>' })),
    'course.error.notOneFile',
  );
  assert.equal(await rejects(() => scormPackage(['torsal-pair'])), 'course.error.noPage');
  assert.equal(
    await rejects(() => scormPackage(['torsal-pair'], { page: PAGE, standard: /** @type {any} */ ('aicc') })),
    'course.error.standard',
  );
  // read back: not a zip, no manifest, a path leaving the folder, too large
  assert.equal(
    reason(() => readScorm(new Uint8Array([1, 2, 3]))),
    'course.error.notZip',
  );
  assert.equal(
    reason(() => readScorm(makeZip({ 'a.txt': 'x' }))),
    'course.error.missing',
  );
  assert.equal(
    reason(() => readZip(makeZip({ '../evil.txt': 'x' }))),
    'course.error.badName',
  );
  assert.equal(
    reason(() => readZip(new Uint8Array(MAX_PACKAGE_BYTES + 1))),
    'course.error.tooLarge',
  );
  const bomb = makeZip({ 'zeros.bin': new Uint8Array(MAX_PACKAGE_BYTES + 1) });
  assert.ok(bomb.length < 1024 * 1024, 'a small zip that unpacks large');
  assert.equal(
    reason(() => readZip(bomb)),
    'course.error.tooLarge',
  );
});

test('an .h5p file from Node: H5P’s files, the library at ruledlab’s version, the exercise read back', async () => {
  const bytes = await h5pPackage('chaikin-count', { script: EMBED, lang: 'de' });
  const files = unzipSync(bytes);
  const h5p = JSON.parse(strFromU8(files['h5p.json']));
  assert.equal(h5p.mainLibrary, 'H5P.RuledlabExercise');
  assert.equal(h5p.title, 'Chaikins Punkte zählen');
  assert.deepEqual(h5p.preloadedDependencies, [
    { machineName: 'H5P.RuledlabExercise', majorVersion: 1, minorVersion: 0 },
  ]);
  const library = JSON.parse(strFromU8(files[`${H5P_FOLDER}/library.json`]));
  assert.deepEqual(library.preloadedJs, [{ path: 'ruledlab-embed.js' }]);
  assert.equal(strFromU8(files[`${H5P_FOLDER}/ruledlab-embed.js`]), EMBED);
  // the library's patch version is ruledlab's version, so that a newer ruledlab updates it
  const { version } = JSON.parse(readFileSync(`${ROOT}package.json`, 'utf8'));
  const [major, minor, patch] = version.split('.').map(Number);
  assert.equal(H5P_PATCH, major * 10000 + minor * 100 + patch);
  assert.equal(library.patchVersion, H5P_PATCH);
  const de = JSON.parse(strFromU8(files[`${H5P_FOLDER}/language/de.json`]));
  assert.equal(de.semantics[0].label, 'Aufgabe');
  assert.equal(readH5p(bytes).task.id, 'chaikin-count');
  // JSON as H5P's editor stores it (escaped for HTML) is read; what is no exercise is refused
  const escaped = JSON.stringify(EXERCISE).replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
  assert.equal(h5pExercise(escaped).title.en, 'What does <torsal> mean & why?');
  assert.equal(h5pExercise(JSON.stringify(EXERCISE)).title.en, 'What does <torsal> mean & why?');
  assert.equal(h5pExercise('chaikin-count'), builtInTask('chaikin-count'));
  assert.equal(
    reason(() => h5pExercise('no-such')),
    'task.error.unknownBuiltIn',
  );
  assert.equal(
    reason(() => h5pExercise(42)),
    'task.error.unknownBuiltIn',
  );
  assert.equal(
    reason(() => h5pExercise('{broken')),
    'task.error.notJson',
  );
  assert.equal(await rejects(() => h5pPackage('chaikin-count')), 'course.error.noScript');
  assert.equal(await rejects(() => h5pPackage('chaikin-count', { script: 'alert(1)' })), 'course.error.noScript');
  assert.equal(
    reason(() => readH5p(makeZip({ 'h5p.json': '{"mainLibrary":"H5P.Other"}', 'content/content.json': '{}' }))),
    'course.error.notH5p',
  );
});

/**
 * xmllint's verdict on the manifest in `dir`, against the schemas its xsi:schemaLocation names (as
 * a validating course system reads it: one schema importing each namespace from its location, no
 * network); what xmllint writes to stderr ("… validates" or the errors).
 */
function validate(/** @type {string} */ dir) {
  const manifest = readFileSync(join(dir, 'imsmanifest.xml'), 'utf8');
  const pairs = (/xsi:schemaLocation="([^"]*)"/.exec(manifest)?.[1] ?? '').trim().split(/\s+/);
  const imports = [];
  for (let k = 0; k + 1 < pairs.length; k += 2)
    imports.push(`<xsd:import namespace="${pairs[k]}" schemaLocation="${pairs[k + 1]}"/>`);
  writeFileSync(
    join(dir, 'all.xsd'),
    `<?xml version="1.0"?><xsd:schema xmlns:xsd="http://www.w3.org/2001/XMLSchema" targetNamespace="urn:ruledlab:all">${imports.join('')}</xsd:schema>`,
  );
  const run = spawnSync('xmllint', ['--noout', '--nonet', '--schema', 'all.xsd', 'imsmanifest.xml'], {
    cwd: dir,
    encoding: 'utf8',
  });
  return { ok: run.status === 0, said: run.stderr, located: pairs.filter((_, k) => k % 2 === 1) };
}

test('the manifests validate against the ADL/IMS schemas they carry (xmllint), SCORM 1.2 and 2004', async () => {
  for (const standard of /** @type {const} */ (['scorm12', 'scorm2004'])) {
    const zip = await scormPackage(['torsal-pair', EXERCISE], { standard, page: PAGE, title: 'A <set> & “more”' });
    const dir = mkdtempSync(join(tmpdir(), 'ruledlab-scorm-'));
    for (const [name, data] of Object.entries(unzipSync(zip))) writeFileSync(join(dir, name), data);
    const { ok, said, located } = validate(dir);
    assert.ok(ok, `${standard}: ${said}`);
    assert.match(said, /imsmanifest\.xml validates/);
    // every schema the manifest names by location is in the package, the content-packaging one first
    assert.equal(located[0], standard === 'scorm12' ? 'imscp_rootv1p1p2.xsd' : 'imscp_v1p1.xsd');
    for (const file of located) assert.ok(unzipSync(zip)[file], `${standard}: ${file} is in the package`);
  }
  // a manifest that breaks its schema is caught (the check can fail)
  const dir = mkdtempSync(join(tmpdir(), 'ruledlab-scorm-'));
  const zip = await scormPackage(['torsal-pair'], { page: PAGE });
  for (const [name, data] of Object.entries(unzipSync(zip))) writeFileSync(join(dir, name), data);
  writeFileSync(
    join(dir, 'imsmanifest.xml'),
    strFromU8(unzipSync(zip)['imsmanifest.xml']).replace('adlcp:scormtype="sco"', 'adlcp:scormtype="lesson"'),
  );
  const broken = validate(dir);
  assert.equal(broken.ok, false);
  assert.match(broken.said, /scormtype/);
});

test('suspend_data: compact, read back as written (and in its first form), under SCORM 1.2’s 4096 characters after 50 checks of the largest exercise', () => {
  const ids = ['torsal-pair', 'chaikin-count'];
  /** @type {any} */
  const a = readAttempt({
    seed: 7,
    params: { n: 40 },
    input: 'rulings.AAAA',
    answers: { count: '26' },
    hints: 2,
    checks: [
      { at: 1_765_000_000_000, passed: 0, of: 1 },
      { at: 1_765_000_060_000, passed: 1, of: 1, shown: 'solution' },
    ],
  });
  const text = writeSuspend(
    { seed: 7, at: 1, ended: true, order: ['chaikin-count.c1', 'torsal-pair.c2'], attempts: [null, a] },
    ids,
    4096,
    bestCheck,
  );
  const back = readSuspend(text, ids);
  assert.deepEqual(
    [back?.seed, back?.at, back?.ended, back?.order],
    [7, 1, true, ['chaikin-count.c1', 'torsal-pair.c2']],
  );
  const read = readAttempt(back?.attempts[1]);
  assert.deepEqual({ ...read, seed: 7 }, a, 'the attempt comes back as it went');
  assert.equal(readAttempt(back?.attempts[0]), null);
  // the first form, as packages wrote it before
  const v1 = JSON.stringify({
    v: 1,
    seed: 3,
    at: 0,
    i: ['torsal-pair.c1'],
    a: [{ answers: { x: '1' }, checks: [{ at: 5, passed: 1, of: 1 }] }],
  });
  const old = readSuspend(v1, ids);
  assert.deepEqual([old?.seed, old?.at, old?.order], [3, 0, ['torsal-pair.c1']]);
  assert.deepEqual(readAttempt(old?.attempts[0])?.checks, [{ at: 5, passed: 1, of: 1 }]);
  assert.equal(readSuspend('not json', ids), null);
  assert.equal(readSuspend('[1]', ids), null);
  // the largest built-in exercise (most conditions, an edit of its points, answers): 50 checks in
  // a package of all twelve it may hold — the history keeps MAX_TASK_HISTORY, the rest is trimmed
  const all = builtInTasks().slice(0, 12);
  const big = all.map((task) => {
    const checks = Array.from({ length: 50 }, (_, k) => ({
      at: 1_765_000_000_000 + k * 61_000,
      passed: k % (task.goal.length + 1),
      of: task.goal.length,
    }));
    return readAttempt({
      seed: 4_000_000_000,
      params: Object.fromEntries(task.change.filter((c) => c !== 'handles').map((c) => [c, 12.345678])),
      input: task.input ?? null,
      answers: Object.fromEntries(
        task.answers.map((x) => [x.id, x.kind === 'curve' ? ['u*cos(u)', 'u*sin(u)', '2*u'] : '1.2345678']),
      ),
      hints: task.hints.length,
      checks: checks.slice(-MAX_TASK_HISTORY),
    });
  });
  const order = all.flatMap((task) => task.goal.map((_, j) => `${task.id}.c${j + 1}`));
  const packed = writeSuspend(
    { seed: 4_000_000_000, at: 0, ended: false, order, attempts: big },
    all.map((t) => t.id),
    SCORM12_SUSPEND,
    bestCheck,
  );
  assert.ok(packed.length <= SCORM12_SUSPEND, `${packed.length} characters`);
  // and what stays is read back: the best check of each exercise, the exercise shown's edit
  const kept = readSuspend(
    packed,
    all.map((t) => t.id),
  );
  for (let k = 0; k < all.length; k++) assert.deepEqual(bestCheck(readAttempt(kept?.attempts[k])), bestCheck(big[k]));
  assert.equal(readAttempt(kept?.attempts[0])?.input, big[0]?.input ?? null);
  // one exercise alone keeps every one of its last MAX_TASK_HISTORY checks
  const one = writeSuspend(
    { seed: 1, at: 0, ended: false, order: [], attempts: [big[0]] },
    [all[0].id],
    SCORM12_SUSPEND,
    bestCheck,
  );
  assert.equal(readAttempt(readSuspend(one, [all[0].id])?.attempts[0])?.checks.length, MAX_TASK_HISTORY);
});

test('when the solution may be shown: "never" or a number of checks, read and written the same way everywhere', () => {
  assert.deepEqual(readSolutionRule('never'), { after: null });
  assert.deepEqual(readSolutionRule('0'), { after: 0 });
  assert.deepEqual(readSolutionRule(String(MAX_SOLUTION_AFTER)), { after: MAX_SOLUTION_AFTER });
  for (const bad of ['', '-1', '1.5', String(MAX_SOLUTION_AFTER + 1), 'always', '1e1', null, undefined])
    assert.equal(readSolutionRule(/** @type {any} */ (bad)), null, String(bad));
  assert.equal(writeSolutionRule({ after: 1 }), null, 'the default is not written');
  assert.equal(writeSolutionRule({ after: null }), 'never');
  assert.equal(writeSolutionRule({ after: 3 }), '3');
});

test('H5P’s own rules: every content field is one semantics.json names, the library holds only files H5P allows, a problem set plays its exercises', async () => {
  const bytes = await h5pPackage(['torsal-pair', 'chaikin-count', EXERCISE], {
    script: EMBED,
    title: 'Set 1',
    readers: { leave: true, solution: null, controls: true, edit: true, text: false },
    draw: 'learner',
  });
  const files = unzipSync(bytes);
  const content = JSON.parse(strFromU8(files['content/content.json']));
  const semantics = JSON.parse(strFromU8(files[`${H5P_FOLDER}/semantics.json`]));
  /** Every key of `value` is a field of `fields` (H5P drops the others: H5PContentValidator::validateGroup). */
  const covered = (/** @type {any} */ value, /** @type {any[]} */ fields, /** @type {string} */ where) => {
    for (const [key, v] of Object.entries(value)) {
      const field = fields.find((f) => f.name === key);
      assert.ok(field, `${where}${key} is in semantics.json`);
      if (field.type === 'group') covered(v, field.fields, `${where}${key}.`);
      if (field.type === 'list')
        for (const x of /** @type {unknown[]} */ (v))
          assert.equal(typeof x, field.field.type === 'text' ? 'string' : typeof x);
      if (field.type === 'select')
        assert.ok(
          field.options.some((/** @type {any} */ o) => o.value === v),
          `${where}${key} = ${v} is an option`,
        );
    }
  };
  covered(content, semantics, '');
  assert.deepEqual(content.readers, { controls: true, text: false, edit: true, leave: true, solution: 'never' });
  assert.equal(content.draw, 'learner');
  assert.equal(content.more.length, 2);
  // H5P's default whitelist for a library: its content list (json, images, …) and js, css, svg, xml — no wasm
  const allowed = new Set(
    'json png jpg jpeg gif bmp tif tiff eot ttf woff woff2 otf webm mp4 ogg mp3 m4a wav txt pdf rtf doc docx xls xlsx ppt pptx odt ods odp csv diff patch swf md textile vtt webvtt gltf glb js css svg xml'.split(
      ' ',
    ),
  );
  for (const name of Object.keys(files))
    assert.ok(allowed.has(name.split('.').at(-1) ?? ''), `${name} is a file type H5P allows`);
  assert.deepEqual(
    readH5p(bytes).tasks.map((t) => t.id),
    ['torsal-pair', 'chaikin-count', 'heisst-torsal'],
  );
  assert.equal(JSON.parse(strFromU8(files['h5p.json'])).title, 'Set 1');
});
