// Exercises: the format read and refused as documented, every built-in exercise fits
// its scene, is not solved at its start and is solved by its solution state — checked by the same
// code the page checks with, on what the core computes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab from './load.mjs';
import { SCENES } from '../../www/scenes/index.js';
import { defaults, withChoices } from '../../www/scene.js';
import { translator } from '../../www/i18n/index.js';
import { decodeInput } from '../../www/edit/input.js';
import { readTask, writeTask, taskFromLink, taskLink, TaskError } from '../../www/task/format.js';
import { checkGoal, fitTask, answerNumber, measuresOf, unreadable } from '../../www/task/check.js';
import { outcomeText } from '../../www/task/words.js';
import { builtInTasks, builtInTask } from '../../www/task/builtin.js';
import { drawTask, drawChoices } from '../../www/task/draw.js';

const i18n = translator('en');
const context = { t: i18n.t, format: i18n.format, lang: 'en' };
const sceneOf = (/** @type {string} */ id) => /** @type {any} */ (SCENES.find((s) => s.id === id));

/** The least exercise the format reads, for the tests to vary. */
const BASE = Object.freeze({
  ruledlab: 'exercise',
  version: 1,
  id: 'x',
  title: { en: 'T' },
  prompt: { en: 'P' },
  scene: 'striction',
  goal: [{ value: 'readout.midpointError', below: 1 }],
});

/** The scene of a task at parameters and an edit (the task's start merged in). */
const computeFor = (/** @type {any} */ task) => (/** @type {any} */ params, /** @type {any} */ input) => {
  const scene = sceneOf(task.scene);
  return scene.create(withChoices(scene, { ...task.params, ...params }), { ...context, ...(input ? { input } : {}) });
};

/** The outcome of checking a task in a state (parameters, edit, answers). */
function check(/** @type {any} */ task, /** @type {any} */ state) {
  const scene = sceneOf(task.scene);
  const params = withChoices(scene, { ...task.params, ...(state.params ?? {}) });
  const inputText = state.input ?? null;
  const input = inputText ? decodeInput(inputText) : null;
  const built = scene.create(params, { ...context, ...(input ? { input } : {}) });
  /** @type {Record<string, string | string[]>} */
  const answers = {};
  // (a number the scene computes in this state, { value }: what it built)
  for (const [k, v] of Object.entries(state.answers ?? {}))
    answers[k] = Array.isArray(v) ? v : typeof v === 'object' ? String(measuresOf(built)[v.value]) : String(v);
  return checkGoal(task, built, answers, { scene, params, context });
}

test('the built-in set: at least 12 exercises along the paper, English and German, every one fitting its scene', () => {
  const tasks = builtInTasks();
  assert.ok(tasks.length >= 12, `${tasks.length} exercises`);
  assert.equal(new Set(tasks.map((t) => t.id)).size, tasks.length, 'ids differ');
  for (const task of tasks) {
    assert.ok(task.title.de && task.prompt.de, `${task.id}: German title and prompt`);
    for (const h of task.hints) assert.ok(h.de, `${task.id}: every hint in German`);
    for (const a of task.answers) assert.ok(a.label.de, `${task.id}: answer labels in German`);
    assert.ok(task.solution, `${task.id}: has a solution`);
    fitTask(task, SCENES, computeFor(task));
  }
  // scenes along the paper: Sections 2 (striction), 3 (isometry), 4 (curves, strip, lines), 5 (congruence, focal), 6 (milling)
  const scenes = new Set(tasks.map((t) => t.scene));
  for (const s of [
    'striction',
    'isometry',
    'curves',
    'strip',
    'congruence',
    'milling',
    'formula',
    'formula-congruence',
    'lines',
  ])
    assert.ok(scenes.has(s), `an exercise in ${s}`);
});

/**
 * The exercise as students get it: as it is, or — one that draws numbers — drawn for seeds 0 to
 * 39, which between them draw every value each draw can give (asserted).
 */
function variants(/** @type {any} */ task) {
  if (!Object.keys(task.draw).length) return [task];
  const drawn = Array.from({ length: 40 }, (_, seed) => drawTask(task, seed));
  for (const [name, d] of Object.entries(task.draw))
    assert.deepEqual(
      new Set(drawn.map((t) => t.drawn.values[name])),
      new Set(drawChoices(/** @type {any} */ (d))),
      `${task.id}: the seeds draw every value of ${name}`,
    );
  return drawn;
}

for (const variant of builtInTasks().flatMap(variants)) {
  const task = variant;
  const numbers = task.drawn ? ` (${JSON.stringify(task.drawn.values)})` : '';
  test(`built-in "${task.id}"${numbers}: not solved at its start, solved by its solution`, () => {
    fitTask(task, SCENES, computeFor(task));
    const start = check(task, { input: task.input });
    assert.equal(
      start.solved,
      false,
      `${task.id} is solved at its start: ${JSON.stringify(start.outcomes.map((o) => [o.value, o.target]))}`,
    );
    const solution = /** @type {any} */ (task.solution);
    const done = check(task, {
      params: solution.params,
      input: solution.input ?? (solution.params || solution.answers ? task.input : null),
      answers: solution.answers,
    });
    for (const o of done.outcomes)
      assert.ok(
        o.holds,
        `${task.id}: a condition fails in the solution: value ${o.value}, target ${o.target}, ${o.error ?? ''}`,
      );
    assert.equal(done.solved, true);
  });
}

/** `task` drawn with the first seed that gives `values`. */
function drawnWith(/** @type {any} */ task, /** @type {Record<string, number | string>} */ values) {
  for (let seed = 0; seed < 1000; seed++) {
    const drawn = drawTask(task, seed);
    if (Object.entries(values).every(([k, v]) => drawn.drawn?.values[k] === v)) return /** @type {any} */ (drawn);
  }
  throw new Error(`no seed below 1000 draws ${JSON.stringify(values)}`);
}

test('answers: a wrong number misses by how much and which way (said without the answer), a formula is evaluated by the core and compared point by point', () => {
  const chaikin = drawnWith(builtInTask('chaikin-count'), { steps: 3 });
  const wrong = check(chaikin, { answers: { count: '48' } });
  assert.equal(wrong.solved, false);
  assert.equal(wrong.outcomes[0].value, 48);
  assert.equal(wrong.outcomes[0].target, 50);
  assert.ok(Math.abs(wrong.outcomes[0].miss - 1.999) < 1e-12, '|48 − 50| − 0.001');
  // which way, and whether it is close (within 10 %) — never by how much, which would give 50 away
  assert.equal(wrong.outcomes[0].side, -1);
  assert.equal(outcomeText(wrong.outcomes[0], i18n, chaikin), 'not right yet: a little too small (within 10 %)');
  assert.equal(
    outcomeText(check(chaikin, { answers: { count: '98' } }).outcomes[0], i18n, chaikin),
    'not right yet: too large',
  );
  assert.doesNotMatch(outcomeText(wrong.outcomes[0], translator('de'), chaikin), /50|2/);
  // a count is a whole number; a word is not a number at all (said so, not "not right")
  assert.equal(check(chaikin, { answers: { count: '49.6' } }).solved, false);
  const word = check(chaikin, { answers: { count: 'fünfzig' } });
  assert.equal(/** @type {any} */ (word.outcomes[0].error)?.details?.reason, 'task.check.notNumber');
  assert.match(outcomeText(word.outcomes[0], translator('de'), chaikin), /keine Zahl/);
  const none = check(chaikin, { answers: {} });
  assert.equal(none.solved, false);
  assert.equal(/** @type {any} */ (none.outcomes[0].error)?.details?.reason, 'task.check.noAnswer');
  // the hyperbolic paraboloid's striction curve: (u, 0, 0); a wrong one misses by its largest distance
  const hypar = /** @type {any} */ (builtInTask('hypar-striction'));
  const off = check(hypar, { answers: { s: ['u', '0', '0.1*u'] } });
  assert.equal(off.solved, false);
  // the u range of the preset is [−1, 1]: 0.1·u is farthest at |u| = 1
  assert.ok(Math.abs(off.outcomes[0].value - 0.1) < 1e-12, `max distance ${off.outcomes[0].value}`);
  assert.equal(Math.abs(/** @type {number} */ (off.outcomes[0].at)), 1);
  // a formula the core refuses: its message, with the field's name and column
  const broken = check(hypar, { answers: { s: ['u', '0', '2*'] } });
  assert.equal(broken.solved, false);
  const error = /** @type {any} */ (broken.outcomes[0].error);
  assert.equal(error?.code, 'parse-error');
  assert.match(error.message, /s\[2\]/);
  // … said with the field as the panel labels it, not the core's s[2]
  assert.match(outcomeText(broken.outcomes[0], i18n, hypar), /^s\(u\), z: /);
  const deltaTask = /** @type {any} */ (builtInTask('hypar-distribution'));
  const badDelta = check(deltaTask, { answers: { delta: '1 +' } });
  assert.match(outcomeText(badDelta.outcomes[0], translator('de'), deltaTask), /^δ\(u\): /);
  // German decimal commas in a typed formula; the numbers drawn (k = 2: δ = (1 + 4u²)/2)
  const delta = drawnWith(builtInTask('hypar-distribution'), { k: 2 });
  const de = { ...context, lang: 'de' };
  const scene = sceneOf('formula');
  const params = withChoices(scene, delta.params);
  const built = scene.create(params, de);
  assert.equal(checkGoal(delta, built, { delta: '0,5 + 2,0*u^2' }, { scene, params, context: de }).solved, true);
  // … and the same formula is wrong for another k: the exact δ the core gives follows the number drawn
  const other = drawnWith(builtInTask('hypar-distribution'), { k: 3 });
  const otherParams = withChoices(scene, other.params);
  const otherBuilt = scene.create(otherParams, de);
  const ctx = { scene, params: otherParams, context: de };
  assert.equal(checkGoal(other, otherBuilt, { delta: '0,5 + 2,0*u^2' }, ctx).solved, false);
  assert.equal(checkGoal(other, otherBuilt, { delta: '1/3 + 3*u^2' }, ctx).solved, true);
  assert.equal(answerNumber('−0,5'), -0.5);
  assert.equal(answerNumber('1/3'), 1 / 3);
  assert.ok(Number.isNaN(answerNumber('one half')));
});

test('a condition comparing two values of the scene, and every condition on a value that is not a number fails', () => {
  // coupling pays from n = 5 on (the built-in "coupled-strip" asks for that smallest n)
  const strip = readTask({
    ruledlab: 'exercise',
    version: 1,
    id: 'coupling',
    title: { en: 'x' },
    prompt: { en: 'x' },
    scene: 'strip',
    params: { scheme: 'coupled', n: 3, exact: true },
    change: ['n'],
    goal: [{ value: 'strip.readout.compare.coupled', below: { value: 'strip.readout.compare.midpoint' } }],
  });
  const at3 = check(strip, { params: { n: 3 } });
  const values = measuresOf(computeFor(strip)({ n: 3 }, null));
  assert.equal(at3.outcomes[0].value, values['strip.readout.compare.coupled']);
  assert.equal(at3.outcomes[0].target, values['strip.readout.compare.midpoint']);
  assert.ok(at3.outcomes[0].miss > 0);
  assert.equal(check(strip, { params: { n: 4 } }).solved, false);
  assert.equal(check(strip, { params: { n: 5 } }).solved, true);
  const smallest = /** @type {any} */ (builtInTask('coupled-strip'));
  assert.equal(smallest.goal[0].near, 5, 'the built-in exercise’s answer is the n found here');
  assert.equal(check(smallest, { answers: { n: '4' } }).solved, false);
  const task = readTask({
    ruledlab: 'exercise',
    version: 1,
    id: 'x',
    title: { en: 'x' },
    prompt: { en: 'x' },
    scene: 'striction',
    goal: [{ value: 'readout.nothing', below: 1 }],
  });
  const built = computeFor(task)({}, null);
  const scene = sceneOf('striction');
  const r = checkGoal(task, built, {}, { scene, params: { ...defaults(scene) }, context });
  assert.equal(r.solved, false, 'an absent value is NaN, never below anything');
});

test('the format: round trip through JSON and a link; malformed and hostile exercises refused with a reason', () => {
  for (const task of builtInTasks()) assert.deepEqual(readTask(writeTask(task)), task, task.id);
  const custom = readTask({ ...JSON.parse(writeTask(/** @type {any} */ (builtInTask('torsal-pair')))), id: 'my-own' });
  const link = taskLink(custom, (id) => !!builtInTask(id));
  assert.match(link, /^j\.[A-Za-z0-9_-]+$/);
  assert.deepEqual(taskFromLink(link, builtInTask), custom);
  assert.equal(
    taskLink(/** @type {any} */ (builtInTask('torsal-pair')), (id) => !!builtInTask(id)),
    'torsal-pair',
  );
  /** @type {Array<[any, string]>} */
  const bad = [
    ['{', 'task.error.notJson'],
    ['x'.repeat(40000), 'task.error.tooLong'],
    [{ ...BASE, ruledlab: 'other' }, 'task.error.notExercise'],
    [{ ...BASE, version: 2 }, 'task.error.notExercise'],
    [{ ...BASE, extra: 1 }, 'task.error.unknownKey'],
    [{ ...BASE, id: 'Has Spaces' }, 'task.error.id'],
    [{ ...BASE, title: 'T' }, 'task.error.type'],
    [{ ...BASE, title: { en: 'T', fr: 'T' } }, 'task.error.unknownKey'],
    [{ ...BASE, prompt: { en: 'x'.repeat(3000) } }, 'task.error.text'],
    [{ ...BASE, params: { n: 1e300 } }, 'task.error.number'],
    [{ ...BASE, params: { n: Number.NaN } }, 'task.error.number'],
    [{ ...BASE, goal: [] }, 'task.error.missing'],
    [{ ...BASE, goal: [{ value: 'a', below: 1, above: 2 }] }, 'task.error.condition'],
    [{ ...BASE, goal: [{ value: 'a', near: 1 }] }, 'task.error.condition'],
    [{ ...BASE, goal: [{ answer: 'nope', below: 1 }] }, 'task.error.condition'],
    [{ ...BASE, goal: [{ value: 'a', below: '<script>' }] }, 'task.error.number'],
    [{ ...BASE, hints: [{ en: 'a' }, { en: 'b' }, { en: 'c' }, { en: 'd' }] }, 'task.error.count'],
    [{ ...BASE, answers: [{ id: 's', kind: 'essay', label: { en: 's' } }] }, 'task.error.type'],
    [{ ...BASE, goal: [{ value: 'readout.midpointError', below: { value: 'x', evil: 1 } }] }, 'task.error.unknownKey'],
  ];
  for (const [x, reason] of bad) {
    assert.throws(
      () => readTask(x),
      (e) => e instanceof TaskError && e.code === 'invalid-task' && /** @type {any} */ (e).details.reason === reason,
      `${JSON.stringify(x).slice(0, 80)} → ${reason}`,
    );
  }
  // texts are kept as text (the page shows them with textContent), control characters dropped
  const t = readTask({ ...BASE, title: { en: '<img src=x onerror=alert(1)>\u0007' } });
  assert.equal(t.title.en, '<img src=x onerror=alert(1)>');
});

test('a straight striction curve cannot be had by shrinking: the measure is a share of the curve’s length, and a curve too short is not judged', () => {
  const task = /** @type {any} */ (builtInTask('straight-striction'));
  const value = (/** @type {any} */ params) => check(task, { params }).outcomes[0].value;
  // a tiny range of u (the curve nearly a point) and the whole hyperboloid scaled down both fail
  assert.ok(Number.isNaN(value({ umin: '0', umax: '0.00001' })), 'a curve 10⁻⁵ long is not judged');
  const tiny = { ax: '1e-10*cos(u)', ay: '2e-10*sin(u)', ex: '-1e-10*sin(u)', ey: '2e-10*cos(u)', ez: '3e-10' };
  const start = value({});
  assert.ok(start > 0.1, `the hyperboloid's ellipse: ${start}`);
  assert.ok(Math.abs(value(tiny) - start) < 1e-6 * start, 'scale-free');
  // a short arc of the ellipse is nearly straight, but not to 10⁻⁹ of its length
  assert.ok(value({ umin: '0', umax: '0.01' }) > 1e-5);
  // the helicoid's axis, at another pitch; at a pitch so small that the axis is a dot beside the
  // rulings (10⁻⁶ · 4π against a surface 2 wide) it is not judged
  assert.equal(check(task, { params: { ...task.solution.params, az: '0.1*u' } }).solved, true);
  assert.ok(Number.isNaN(value({ ...task.solution.params, az: '1e-6*u' })));
});

test('hide may name the claims and the explanation besides parameters and readouts', () => {
  const base = { ...BASE, scene: 'strip', goal: [{ value: 'strip.readout.compare.coupled', below: 1 }] };
  const ok = readTask({ ...base, hide: ['claims', 'text', 'n'] });
  fitTask(ok, SCENES, computeFor(ok));
  const bad = readTask({ ...base, hide: ['explanation'] });
  assert.throws(
    () => fitTask(bad, SCENES, computeFor(bad)),
    (e) => e instanceof TaskError && /** @type {any} */ (e).details.reason === 'task.error.unknownValue',
  );
});

test('an exercise that does not fit its scene is refused: unknown scene, parameter, value, edit', () => {
  /** @type {Array<[any, string]>} */
  const bad = [
    [{ ...BASE, scene: 'nowhere' }, 'task.error.unknownScene'],
    [{ ...BASE, params: { nope: 1 } }, 'task.error.unknownParam'],
    [{ ...BASE, params: { n: 10000 } }, 'task.error.badParam'],
    [{ ...BASE, change: ['nope'] }, 'task.error.unknownParam'],
    [{ ...BASE, goal: [{ value: 'readout.nothing', below: 1 }] }, 'task.error.unknownValue'],
    [{ ...BASE, hide: ['readout.nothing'] }, 'task.error.unknownValue'],
    [{ ...BASE, input: 'rulings.AAAA' }, 'task.error.badInput'],
    [
      { ...BASE, scene: 'curves', change: ['handles'], input: 'rulings.AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA' },
      'task.error.badInput',
    ],
    [
      { ...BASE, scene: 'large', change: ['handles'], goal: [{ value: 'readout.rulings', below: 1 }] },
      'task.error.noHandles',
    ],
    [
      {
        ...BASE,
        scene: 'curves',
        answers: [{ id: 's', kind: 'curve', label: { en: 's' } }],
        goal: [{ answer: 's', matches: 'striction', within: 1 }],
      },
      'task.error.noExact',
    ],
  ];
  for (const [x, reason] of bad) {
    const task = readTask(x);
    assert.throws(
      () => fitTask(task, SCENES, computeFor(task)),
      (e) => e instanceof TaskError && /** @type {any} */ (e).details.reason === reason,
      `${JSON.stringify(x).slice(0, 100)} → ${reason}`,
    );
  }
});

test('"What bending keeps": the δ the student reads is δ of the surface, not discretisation error (its sign and size as the exact δ at the pair)', () => {
  const task = /** @type {import('../../www/task/format.js').Task} */ (builtInTask('minding-delta'));
  const scene = /** @type {import('../../www/scene.js').Scene} */ (SCENES.find((s) => s.id === task.scene));
  const built = scene.create(withChoices(scene, task.params), { t: i18n.t, format: i18n.format });
  const shown = /** @type {number} */ (built.measures?.['isometry.deltaMiddle']);
  // the middle pair of the n rulings shown, and the exact δ(u) at its middle
  const analytic = ruledlab.AnalyticSurface.byName(String(task.params.surface));
  try {
    const n = Number(task.params.n);
    // the scene samples the hyperboloid on u ∈ [0, 2.4] (scenes/isometry.js)
    const u = analytic.parameters(n, { uMin: 0, uMax: 2.4, closed: false });
    const middle = Math.floor((n - 2) / 2);
    const exact = analytic.distribution(Float64Array.of((u[middle] + u[middle + 1]) / 2))[0];
    assert.ok(Math.abs(exact) > 0.5, `exact δ ${exact} is far from 0`);
    assert.ok(
      Math.sign(shown) === Math.sign(exact) && Math.abs(shown - exact) < 0.05 * Math.abs(exact),
      `shown ${shown}, exact ${exact}`,
    );
  } finally {
    analytic.free();
  }
});

test('"A close scheme in one step": exactly the two butterfly variants pass, and the hints say so', () => {
  const task = /** @type {import('../../www/task/format.js').Task} */ (builtInTask('congruence-scheme'));
  const scene = /** @type {import('../../www/scene.js').Scene} */ (SCENES.find((s) => s.id === task.scene));
  const schemes = /** @type {any} */ (scene.params.find((p) => p.key === 'scheme'))
    .options()
    .map((/** @type {string[]} */ o) => o[0]);
  const passing = schemes.filter((/** @type {string} */ scheme) => check(task, { params: { scheme } }).solved);
  assert.deepEqual(passing.sort(), ['butterfly', 'diagonal']);
  assert.ok(task.hints.some((h) => /both butterfly variants pass/i.test(h.en)));
});

test('a number the page writes is read where the page asks for one: the readout’s own format in each language, powers of ten, groups of three', () => {
  for (const lang of ['en', 'de']) {
    const { format } = translator(lang);
    for (const x of [0.0018915497, -1.7110714, 12345.678, 1.5e-7, 250000, -3, 0.5])
      assert.equal(
        Number(answerNumber(format(x), lang).toPrecision(3)),
        Number(x.toPrecision(3)),
        `${lang}: ${format(x)} is read as ${answerNumber(format(x), lang)}`,
      );
  }
  assert.equal(answerNumber('1,89·10⁻³', 'de'), 0.00189);
  assert.equal(answerNumber('1.89·10⁻³', 'en'), 0.00189);
  assert.equal(answerNumber('1.89 × 10^-3', 'en'), 0.00189);
  assert.equal(answerNumber('1.89e−3', 'en'), 0.00189);
  assert.equal(answerNumber('250,000', 'en'), 250000);
  assert.equal(answerNumber('250.000', 'de'), 250000);
  assert.equal(answerNumber('0,5', 'en'), 0.5);
  assert.equal(answerNumber('0.5', 'de'), 0.5);
  for (const bad of ['1,89·10', '10⁻', '1..2', '1·10^1.5', 'e-3', '·10⁻³'])
    assert.ok(Number.isNaN(answerNumber(bad, 'en')), `${bad} is not a number`);
});

test('an answer that cannot be read is said with how to write it, and the check does not count', () => {
  const task = readTask(
    JSON.stringify({
      ruledlab: 'exercise',
      version: 1,
      id: 'typed',
      title: { en: 'Typed' },
      prompt: { en: 'δ(u)?' },
      scene: 'striction',
      params: { surface: 'quartic' },
      answers: [
        { id: 'x', kind: 'number', label: { en: 'a number' } },
        { id: 'f', kind: 'function', label: { en: 'δ(u)' } },
      ],
      goal: [
        { answer: 'x', near: 1, within: 0.1 },
        { answer: 'f', matches: 'distribution', within: 1e-6 },
      ],
    }),
  );
  const outcomes = check(task, { answers: { x: 'one', f: '1+u²' } }).outcomes;
  assert.deepEqual(outcomes.map(unreadable), [true, true]);
  // the formula's message says how to write the square
  assert.match(outcomeText(outcomes[1], i18n, task), /u\^2|\^/);
  const readable = check(task, { answers: { x: '1,05', f: '1+u^2' } }).outcomes;
  assert.deepEqual(readable.map(unreadable), [false, false]);
});
