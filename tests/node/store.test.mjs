// The view's state and its one writer (www/store.js): each change gives the state it says and
// nothing else, the state is frozen (a write to it throws), a parameter an exercise holds or an
// edit replaces changes by no route, a choice sets what its rule sets, and a change that changes
// nothing tells nobody.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import './load.mjs';
import { Store, initialState, reduce, heldReason } from '../../www/store.js';
import { SCENES } from '../../www/scenes/index.js';
import { defaults } from '../../www/scene.js';
import { builtInTask } from '../../www/task/builtin.js';

const scene = (/** @type {string} */ id) =>
  /** @type {import('../../www/scene.js').Scene} */ (SCENES.find((s) => s.id === id));

test('each change gives the state it says; a change that changes nothing tells nobody; the state is frozen', () => {
  /** @type {Array<[any, any, any]>} */
  const told = [];
  const store = new Store(initialState({ lang: 'de' }), (next, previous, change) =>
    told.push([next, previous, change]),
  );
  assert.equal(store.state.scene, null);
  const striction = scene('striction');
  assert.ok(store.dispatch({ type: 'open', scene: striction, params: defaults(striction) }));
  assert.equal(store.state.scene, striction);
  assert.equal(store.state.lang, 'de', 'what the opening does not name stays');
  assert.equal(told.length, 1);
  // the state is frozen: only dispatch writes it
  assert.throws(() => {
    /** @type {any} */ (store.state).scene = null;
  }, TypeError);
  // a parameter: set, and the one changed last named
  store.dispatch({ type: 'param', key: 'n', value: 40 });
  assert.equal(store.state.params.n, 40);
  assert.equal(store.state.changed, 'n');
  // the same value again changes nothing and tells nobody
  assert.equal(store.dispatch({ type: 'param', key: 'n', value: 40 }), false);
  assert.equal(told.length, 2);
  // an input: kept, and whether it is still moving
  const input = { rulings: new Float64Array(6) };
  store.dispatch({ type: 'input', input, moving: true });
  assert.deepEqual([store.state.input, store.state.moving], [input, true]);
  store.dispatch({ type: 'input', input, moving: false });
  assert.equal(store.state.moving, false);
  // the language, the panel, editing
  store.dispatch({ type: 'lang', lang: 'en' });
  store.dispatch({ type: 'panel', controls: false, text: true });
  store.dispatch({ type: 'editable', on: true });
  assert.deepEqual(
    [store.state.lang, store.state.controls, store.state.text, store.state.editable],
    ['en', false, true, true],
  );
  assert.equal(store.dispatch({ type: 'panel', controls: false, text: true }), false);
  // the view: the 3D view alone, then the Klein view beside it; the same again changes nothing
  assert.equal(store.state.view, 'space');
  store.dispatch({ type: 'view', view: 'split' });
  assert.equal(store.state.view, 'split');
  assert.equal(store.dispatch({ type: 'view', view: 'split' }), false);
  // a line marked in both views; new lines (a parameter, an edit, an opening) or closing the view forget it
  store.dispatch({ type: 'mark', line: 3 });
  assert.equal(store.state.marked, 3);
  store.dispatch({ type: 'view', view: 'space' });
  assert.equal(store.state.marked, null);
  for (const change of /** @type {import('../../www/store.js').StageChange[]} */ ([
    { type: 'input', input: null },
    { type: 'param', key: 'n', value: 41 },
    { type: 'params', params: { n: 40 } },
    { type: 'open', scene: store.state.scene, params: store.state.params },
  ])) {
    store.dispatch({ type: 'mark', line: 2 });
    store.dispatch(change);
    assert.equal(store.state.marked, null, change.type);
  }
  // every state told is the one after, the one before is what it was
  for (const [next, previous] of told) assert.notEqual(next, previous);
});

test('a parameter an exercise holds, or an edit replaces, changes by no route; a choice sets what its rule sets', () => {
  const exercise = /** @type {import('../../www/task/format.js').Task} */ (builtInTask('coupled-strip'));
  const strip = scene(exercise.scene);
  let state = reduce(initialState(), { type: 'open', scene: strip, params: defaults(strip), exercise });
  const held = strip.params.find((p) => !exercise.change.includes(p.key));
  assert.ok(held);
  assert.equal(heldReason(state, held.key), 'task.reason.locked');
  assert.equal(reduce(state, { type: 'param', key: held.key, value: 'x' }), state, 'held: unchanged');
  assert.notEqual(reduce(state, { type: 'param', key: 'n', value: 7 }), state, 'what it lets change changes');
  // an edit holds what it replaces (the scene's `fixed`), outside an exercise
  const milling = scene('milling');
  state = reduce(initialState(), { type: 'open', scene: milling, params: defaults(milling) });
  const fixed = /** @type {string[]} */ (milling.fixed)[0];
  assert.equal(heldReason(state, fixed), null);
  state = reduce(state, { type: 'input', input: { poses: new Float64Array(12) } });
  assert.equal(heldReason(state, fixed), 'edit.reason.fixed');
  assert.equal(reduce(state, { type: 'param', key: fixed, value: 9 }), state);
  // a choice with a rule (a preset) sets the values it names with it
  const formula = scene('formula');
  const preset = formula.params.find((p) => p.sets);
  assert.ok(preset, 'the formula scene has a choice with a rule');
  state = reduce(initialState(), { type: 'open', scene: formula, params: defaults(formula) });
  const options = /** @type {any} */ (preset).options;
  const value = (typeof options === 'function' ? options() : options)
    .map((/** @type {any} */ o) => (Array.isArray(o) ? o[0] : o.value))
    .find((/** @type {any} */ v) => v !== state.params[preset.key]);
  const next = reduce(state, { type: 'param', key: preset.key, value });
  assert.deepEqual(next.params, {
    ...state.params,
    [preset.key]: value,
    ...(preset.sets?.(value, state.params) ?? {}),
  });
});

test('the units menu converts the job: the same tool, tolerances, feed and part in the other units, and back', () => {
  const milling = scene('milling');
  let state = reduce(initialState(), { type: 'open', scene: milling, params: defaults(milling) });
  state = reduce(state, { type: 'param', key: 'stock', value: '-5 -10 0 75 10 20' });
  const mm = state.params;
  assert.equal(mm.units, 'mm');
  state = reduce(state, { type: 'param', key: 'units', value: 'inch' });
  const inch = state.params;
  // every length and feed divided by 25.4 (15 significant digits), the scale of the poses too
  for (const key of ['radius', 'length', 'gauge', 'holder', 'holderLength', 'tolerance', 'clearance', 'feed', 'scale'])
    assert.ok(
      Math.abs(Number(inch[key]) * 25.4 - Number(mm[key])) <= 1e-11 * Number(mm[key]),
      `${key}: ${mm[key]} mm, ${inch[key]} inch`,
    );
  assert.equal(inch.radius, 0.0984251968503937);
  assert.equal(inch.tolerance, 0.000393700787401575);
  assert.equal(
    inch.stock,
    '-0.196850393700787 -0.393700787401575 0 2.95275590551181 0.393700787401575 0.78740157480315',
  );
  // what has no length stays: the spindle's speed, the angular tolerance, the pole cone
  for (const key of ['spindle', 'angular', 'cone', 'poses', 'steps']) assert.equal(inch[key], mm[key], key);
  // and back: the values typed before
  state = reduce(state, { type: 'param', key: 'units', value: 'mm' });
  for (const key of ['radius', 'length', 'gauge', 'holder', 'holderLength', 'tolerance', 'clearance', 'feed', 'scale'])
    assert.equal(state.params[key], mm[key], key);
  assert.equal(state.params.stock, '-5 -10 0 75 10 20');
  // an inch job (a tool of radius 2.5 in, a tolerance of 0.00004 in) in millimetres: nothing
  // clamped, though 63.5 mm is beyond the radius slider's 50
  state = reduce(state, { type: 'param', key: 'units', value: 'inch' });
  state = reduce(state, { type: 'param', key: 'radius', value: 2.5 });
  state = reduce(state, { type: 'param', key: 'tolerance', value: 0.00004 });
  state = reduce(state, { type: 'param', key: 'units', value: 'mm' });
  assert.equal(state.params.radius, 63.5);
  assert.equal(state.params.tolerance, 0.001016);
  state = reduce(state, { type: 'param', key: 'units', value: 'inch' });
  assert.equal(state.params.radius, 2.5);
  assert.equal(state.params.tolerance, 0.00004);
  // a stock text that is not six numbers stays as typed
  state = reduce(state, { type: 'param', key: 'stock', value: '1 2 3' });
  assert.equal(reduce(state, { type: 'param', key: 'units', value: 'inch' }).params.stock, '1 2 3');
});

test('the Klein view’s projection: held in its ranges and on its steps, null for the scene’s own image, the same image changes nothing', () => {
  let state = initialState();
  assert.equal(state.projection, null);
  state = reduce(state, { type: 'projection', projection: { mix: 12, turn: 200, unit: 2.5 } });
  assert.deepEqual(state.projection, { mix: 12, turn: 200, unit: 2.5 });
  assert.ok(Object.isFrozen(state.projection));
  // the same image: the same state
  assert.equal(reduce(state, { type: 'projection', projection: { mix: 12, turn: 200, unit: 2.5 } }), state);
  // outside its range: at the nearest end; between steps: on the nearest, written with the step's digits
  const held = reduce(state, { type: 'projection', projection: { mix: -5, turn: 361.2, unit: 0.1 + 0.2 } });
  assert.deepEqual(held.projection, { mix: 0, turn: 360, unit: 0.3 });
  assert.deepEqual(
    reduce(state, { type: 'projection', projection: { mix: 44.6, turn: 9.4, unit: 1.024 } }).projection,
    {
      mix: 45,
      turn: 9,
      unit: 1,
    },
  );
  assert.deepEqual(reduce(state, { type: 'projection', projection: { mix: 90, turn: 0, unit: 9 } }).projection, {
    mix: 90,
    turn: 0,
    unit: 4,
  });
  // null: the scene's own image again; closing the view keeps the reader's image
  assert.equal(reduce(state, { type: 'projection', projection: null }).projection, null);
  assert.deepEqual(reduce(state, { type: 'view', view: 'space' }).projection, state.projection);
});
