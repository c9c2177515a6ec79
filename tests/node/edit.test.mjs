// Editing the geometry, without a browser: the edit's link text round-trips bit for bit and
// refuses what is not one; the camera geometry of a drag (a handle projected to the screen and
// the ray back through that pixel, the plane, the line, the box) against exact answers; and every
// scene with handles computes on its own input handed back as an edit, giving the same handles
// and the same picture's geometry.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import './load.mjs';
import { SCENES } from '../../www/scenes/index.js';
import { defaults } from '../../www/scene.js';
import { translator } from '../../www/i18n/index.js';
import {
  decodeInput,
  encodeInput,
  fitsSets,
  handleCount,
  inputOf,
  linkableInput,
  sameInput,
} from '../../www/edit/input.js';
import { clampTo, editBox, invertSimilarity, pointerRay, toScreen, transformPoint } from '../../www/edit/geometry.js';
import { snapPoint } from '../../pkg/ruledlab.js';
import { readTask, writeTask } from '../../www/task/format.js';
import { OrbitCamera } from '../../www/camera.js';
import { coordinates } from '../../www/edit/marks.js';

const i18n = translator('en');
const context = { t: i18n.t, format: i18n.format, lang: 'en' };
const close = (/** @type {number[]} */ a, /** @type {number[]} */ b, eps = 1e-9) =>
  a.length === b.length && a.every((x, i) => Math.abs(x - b[i]) <= eps * Math.max(1, Math.abs(b[i])));

test('an edit in a link: every double bit for bit (−0, subnormals, the largest), sets by key', () => {
  const input = {
    rulings: new Float64Array([0, -0, 1, -1.5, 5e-324, -Number.MAX_VALUE, 0.1, 1 / 3, Math.PI]),
    poses: new Float64Array([2 ** -1074, 123456789.125, -7]),
  };
  const text = encodeInput(input);
  assert.match(text, /^rulings\.[A-Za-z0-9_-]+~poses\.[A-Za-z0-9_-]+$/);
  const back = decodeInput(text);
  assert.ok(back && sameInput(back, input));
  assert.ok(Object.is(back.rulings[1], -0), '−0 stays −0');
  // URLSearchParams leaves base64url as it is (the hash is written through it)
  const q = new URLSearchParams({ input: text });
  assert.equal(new URLSearchParams(q.toString()).get('input'), text);
  assert.equal(handleCount(input), 4);
  assert.equal(linkableInput(input), true);
  assert.equal(linkableInput({ rulings: new Float64Array(3 * 201) }), false);
});

test('an edit in a link: what is not one is refused (null), never half read', () => {
  const good = encodeInput({ rulings: new Float64Array([1, 2, 3]) });
  for (const bad of [
    '',
    'rulings',
    'rulings.',
    `Rulings.${good.split('.')[1]}`,
    `rulings.${good.split('.')[1]}~rulings.${good.split('.')[1]}`,
    `rulings.${good.split('.')[1].slice(0, -3)}`, // not whole points
    'rulings.****',
    encodeInput({ rulings: new Float64Array([Number.NaN, 0, 0]) }),
    encodeInput({ rulings: new Float64Array([Infinity, 0, 0]) }),
    `rulings.${good.split('.')[1]}~<img>.AAAA`,
  ])
    assert.equal(decodeInput(bad), null, bad);
});

test('an edit fits handle sets when its keys and lengths are theirs', () => {
  const sets = [{ key: 'rulings', points: new Float64Array(12), shape: 'pairs', name: 'handle.ruling' }];
  assert.equal(fitsSets({ rulings: new Float64Array(12) }, sets), true);
  assert.equal(fitsSets({ rulings: new Float64Array(6) }, sets), false);
  assert.equal(fitsSets({ rulings: new Float64Array(12), points: new Float64Array(3) }, sets), false);
  assert.equal(fitsSets({ lines: new Float64Array(12) }, sets), false);
  assert.ok(sameInput(inputOf(sets), { rulings: new Float64Array(12) }));
  assert.equal(sameInput({ a: new Float64Array([0]) }, { a: new Float64Array([-0]) }), false, 'bit for bit');
});

test('the pointer’s ray goes through the handle it was projected from (any camera, any view)', () => {
  const camera = new OrbitCamera();
  const points = [
    [0, 0, 0],
    [1.5, -2, 0.7],
    [-3, 4, -1],
  ];
  for (const [yaw, pitch, distance, w, h] of [
    [0.9, 0.35, 10, 800, 600],
    [-2.1, 1.2, 3.5, 390, 490],
    [3, -0.8, 25, 1280, 320],
  ]) {
    Object.assign(camera, { yaw, pitch, distance, target: [0.3, -0.2, 0.1] });
    const m = camera.viewProj(w / h);
    for (const p of points) {
      const s = toScreen(m, p, w, h);
      assert.ok(s.visible);
      const ray = pointerRay(camera, s.x, s.y, w, h);
      // the point lies on the ray: its distance from the ray is rounding
      const d = p.map((x, k) => x - ray.origin[k]);
      const along = d[0] * ray.dir[0] + d[1] * ray.dir[1] + d[2] * ray.dir[2];
      const off = Math.hypot(...d.map((x, k) => x - along * ray.dir[k]));
      // the view-projection is single precision, as WebGL takes it: the pixel is good to ~1e-7
      assert.ok(off < 1e-6 * distance, `off the ray by ${off}`);
    }
  }
});

test('a drag puts a handle where the core says: the plane facing the view keeps its depth; along a line and vertically it stays on that line', () => {
  const bounds = { min: [-50, -50, -50], max: [50, 50, 50] };
  /** @type {import('../../pkg/ruledlab.js').SnapQuery['ray']} */
  const ray = { origin: [0, -10, 0], direction: [0, 1, 0] };
  const at = (/** @type {any} */ constraint, /** @type {[number, number, number]} */ start = [5, 2, 7], r = ray) =>
    snapPoint({ ray: r, start, constraint, targets: [], bounds });
  const point = (/** @type {import('../../pkg/ruledlab.js').Snapped} */ s) => Array.from(s.point ?? []);
  // the plane y = 2 through the handle (normal along the view): the ray meets it at (0, 2, 0)
  assert.deepEqual(point(at({ kind: 'view', normal: [0, 1, 0] })), [0, 2, 0]);
  assert.equal(
    at({ kind: 'view', normal: [1, 0, 0] }, [0, 2, 0]).held,
    'parallel',
    'a ray in the plane gives no point',
  );
  const behind = { origin: [0, 10, 0], direction: [0, 1, 0] };
  assert.equal(at({ kind: 'view', normal: [0, 1, 0] }, [0, 2, 0], behind).held, 'parallel', 'behind the eye');
  // the line through (3, 0, 5) along z: nearest the ray (the y-axis) at (3, 0, 0)
  assert.ok(close(point(at({ kind: 'line', point: [3, 0, 5], direction: [0, 0, 2] })), [3, 0, 0]));
  // a skew line through (1, 0, 0) along (1, 0, 1): (1 + t, 0, t) is nearest the y-axis at t = −½
  assert.ok(close(point(at({ kind: 'line', point: [1, 0, 0], direction: [1, 0, 1] })), [0.5, 0, -0.5]));
  assert.equal(at({ kind: 'line', point: [0, 0, 0], direction: [0, 3, 0] }).held, 'parallel', 'a line along the ray');
  // the modes through the handle at (1, 2, 3): vertically, along its line (here x)
  assert.ok(close(point(at({ kind: 'line', point: [1, 2, 3], direction: [0, 0, 1] }, [1, 2, 3])), [1, 2, 0]));
  assert.ok(close(point(at({ kind: 'line', point: [1, 2, 3], direction: [1, 0, 0] }, [1, 2, 3])), [0, 2, 3]));
});

test('snapPoint: exact onto its targets, bad targets none, bad queries an error with a code', () => {
  /** @type {import('../../pkg/ruledlab.js').SnapQuery} */
  const query = {
    ray: { origin: [0, -10, 1], direction: [0, 1, 0] },
    start: [0, 0, 0],
    constraint: { kind: 'view', normal: [0, 1, 0] },
    targets: [
      { kind: 'line', point: [-1, 0, 0], direction: [2, 0, 2] },
      { kind: 'point', point: [Number.NaN, 0, 0] },
      { kind: 'line', point: [3, 3, 3], direction: [0, 0, 0] },
      { kind: 'point', point: [Number.POSITIVE_INFINITY, 0, 0] },
    ],
    bounds: { min: [-5, -5, -5], max: [5, 5, 5] },
  };
  const { point, snaps } = snapPoint(query);
  assert.deepEqual(Array.from(point ?? []), [0, 0, 1]);
  // the line's point nearest the ray, on it: −1 + t·2 with t = ½
  assert.deepEqual(Array.from(snaps[0] ?? []), [0, 0, 1]);
  // NaN, a ruling of zero length (its point), a point at infinity
  assert.equal(snaps[1], undefined);
  assert.deepEqual(Array.from(snaps[2] ?? []), [3, 3, 3]);
  assert.equal(snaps[3], undefined);
  const code = (/** @type {unknown} */ q) => {
    try {
      snapPoint(/** @type {any} */ (q));
      return 'none';
    } catch (e) {
      return /** @type {{code: string}} */ (e).code;
    }
  };
  assert.equal(code({ ...query, extra: 1 }), 'invalid-argument');
  assert.equal(code({ ...query, constraint: { kind: 'circle' } }), 'invalid-argument');
  assert.equal(code({ ...query, start: [0, 0] }), 'invalid-argument');
  assert.equal(code({ ...query, targets: Array(4097).fill(query.targets?.[0]) }), 'too-large');
  assert.equal(code(null), 'invalid-argument');
});

test('the box of an edit is the scene’s bounds scaled about their centre, a cube where the scene is flat', () => {
  const box = editBox({ min: [0, 0, 0], max: [2, 4, 0] }, 10);
  assert.deepEqual(box, { min: [-19, -18, -20], max: [21, 22, 20] });
  assert.deepEqual(clampTo([100, -100, 5], box), [21, -18, 5]);
});

test('a rigid motion or a similarity and its inverse give back every point, each way round', () => {
  const c = Math.cos(0.7),
    s = Math.sin(0.7);
  // rotation about (1, 1, 1)/√3 composed with a translation, column-major
  const u = 1 / Math.sqrt(3);
  const R = [
    [c + u * u * (1 - c), u * u * (1 - c) - u * s, u * u * (1 - c) + u * s],
    [u * u * (1 - c) + u * s, c + u * u * (1 - c), u * u * (1 - c) - u * s],
    [u * u * (1 - c) - u * s, u * u * (1 - c) + u * s, c + u * u * (1 - c)],
  ];
  const m = new Float64Array([
    R[0][0],
    R[1][0],
    R[2][0],
    0,
    R[0][1],
    R[1][1],
    R[2][1],
    0,
    R[0][2],
    R[1][2],
    R[2][2],
    0,
    3,
    -2,
    5,
    1,
  ]);
  // rigid, and scaled too (the Klein scene's lines beside M): x ↦ 2.5 R x + t; each way round
  const scaled = m.map((x, i) => (i < 12 && i % 4 < 3 ? 2.5 * x : x));
  for (const motion of [m, scaled]) {
    const back = invertSimilarity(motion);
    for (const p of [
      [0, 0, 0],
      [1, 2, 3],
      [-4, 0.5, 9],
    ]) {
      assert.ok(close(transformPoint(back, transformPoint(motion, p)), p, 1e-13));
      assert.ok(close(transformPoint(motion, transformPoint(back, p)), p, 1e-13));
    }
  }
});

test('coordinates are said as the language writes them', () => {
  assert.equal(coordinates([1.2, -0.4, 3], 'en'), '1.20, −0.40, 3.00');
  assert.equal(coordinates([1.2, -0.4, 3], 'de'), '1,20; −0,40; 3,00');
  assert.equal(coordinates([-0.001, 12345.678, 0], 'en'), '0.00, 12345.68, 0.00');
});

test('every scene with handles: its input handed back as an edit gives the same handles and the same geometry', () => {
  const withHandles = [];
  for (const scene of SCENES) {
    if (scene.id === 'large') continue;
    const params = defaults(scene);
    const built = scene.create(params, context);
    if (!built.input) continue;
    withHandles.push(scene.id);
    const input = inputOf(built.input.sets);
    assert.ok(built.input.from.length > 5, `${scene.id}: says what the built-in input is`);
    const edited = scene.create(params, { ...context, input });
    assert.ok(edited.input && sameInput(inputOf(edited.input.sets), input), `${scene.id}: the same handles`);
    // the picture's geometry: the first layer (the rulings, lines, poses or polygon) unchanged
    assert.deepEqual(Array.from(edited.layers[0].positions), Array.from(built.layers[0].positions), scene.id);
    // a parameter an edit holds is one of the scene's
    for (const key of scene.fixed ?? [])
      assert.ok(
        scene.params.some((p) => p.key === key),
        `${scene.id}: ${key}`,
      );
  }
  assert.deepEqual(withHandles.sort(), [
    'congruence',
    'convergence',
    'curves',
    'data',
    'developable',
    'focal',
    'isometry',
    'klein',
    'lines',
    'milling',
    'notation',
    'striction',
    'strip',
  ]);
});

test('an edited striction scene measures on the edit: its readouts are those of the core’s surface of those rulings', async () => {
  const { RuledSurface } = await import('./load.mjs').then((m) => m.default);
  const scene = SCENES.find((s) => s.id === 'striction');
  const params = { ...defaults(scene), n: 12 };
  const input = inputOf(scene.create(params, context).input.sets);
  input.rulings[3 * 5 + 2] += 0.7; // lift ruling 2's end b
  const built = scene.create(params, { ...context, input });
  const surface = RuledSurface.fromSegments(input.rulings);
  try {
    const inv = surface.invariants({ closed: true });
    const mean = inv.distributionMean[Math.floor(inv.distributionMean.length / 2)];
    const read = Object.fromEntries(built.readouts.map((r) => [r.label, r.value]));
    assert.equal(read['readout.rulings'], 12);
    assert.equal(read['readout.meanDelta'], mean);
    assert.equal(read['readout.midpointError'], undefined, 'no error against an exact surface the edit does not have');
    assert.deepEqual(Array.from(built.layers[0].positions), Array.from(surface.segmentsF32()));
  } finally {
    surface.free();
  }
});

test('an exercise’s "edit" field: read, written back, and refused where it is not one', () => {
  const base = {
    ruledlab: 'exercise',
    version: 1,
    id: 'held',
    title: { en: 'Held' },
    prompt: { en: 'Move it.' },
    scene: 'striction',
    change: ['handles'],
    goal: [{ value: 'striction.minAbsDelta', below: 0.01 }],
  };
  const edit = {
    snap: false,
    typed: true,
    constraints: [
      { handle: 'rulings.21', on: 'line', direction: [0, 0, 1] },
      { handle: 'points.3', on: 'plane', normal: [0, 0, 2] },
      { handle: 'poses.6', on: 'fixed' },
    ],
  };
  const task = readTask({ ...base, edit });
  assert.deepEqual(task.edit, edit);
  assert.deepEqual(readTask(writeTask(task)).edit, edit, 'written and read back');
  assert.equal(readTask(base).edit, null);
  assert.deepEqual(readTask({ ...base, edit: {} }).edit, { snap: true, typed: true, constraints: [] });
  for (const bad of [
    [],
    { snap: 'yes' },
    { grid: true },
    { constraints: {} },
    { constraints: [{ handle: 'rulings', on: 'fixed' }] },
    { constraints: [{ handle: 'rulings.1', on: 'circle' }] },
    { constraints: [{ handle: 'rulings.1', on: 'line' }] },
    { constraints: [{ handle: 'rulings.1', on: 'line', direction: [0, 1] }] },
    { constraints: [{ handle: 'rulings.1', on: 'plane', normal: [0, Number.NaN, 1] }] },
    { constraints: [{ handle: 'rulings.1', on: 'fixed', direction: [0, 0, 1] }] },
    { constraints: Array(65).fill({ handle: 'rulings.1', on: 'fixed' }) },
  ])
    assert.throws(() => readTask({ ...base, edit: bad }), { code: 'invalid-task' }, JSON.stringify(bad).slice(0, 60));
});

test('a tool pose’s neighbour angles name the poses each is between: pose 3 has the angle between poses 2 and 3 and the one between 3 and 4, in both languages', async () => {
  const { poseValues } = await import('../../www/edit/sets.js');
  const steps = [0.1, 0.2, 0.3, 0.4, 0.5];
  for (const [lang, words] of /** @type {const} */ ([
    ['en', ['axis angle between poses 2 and 3 (°)', 'axis angle between poses 3 and 4 (°)']],
    ['de', ['Achsenwinkel zwischen den Lagen 2 und 3 (°)', 'Achsenwinkel zwischen den Lagen 3 und 4 (°)']],
  ])) {
    const values = poseValues(steps, null, 1, translator(lang).t)(0, 2 * 3);
    assert.deepEqual(
      values.map((v) => v.label),
      words,
    );
    assert.deepEqual(
      values.map((v) => v.value),
      [steps[2], steps[3]].map((a) => (a * 180) / Math.PI),
    );
  }
  // the first pose has one neighbour
  assert.deepEqual(
    poseValues(steps, null, 1, i18n.t)(0, 1).map((v) => v.label),
    ['axis angle between poses 0 and 1 (°)'],
  );
});

test('the cone exercise’s figure is described as it is seen: the ruling out of place is named (it meets neither neighbour), and an edited cone whose rulings all meet says so', async () => {
  const { builtInTask } = await import('../../www/task/builtin.js');
  const task = /** @type {import('../../www/task/format.js').Task} */ (builtInTask('developable-cone'));
  const scene = /** @type {import('../../www/scene.js').Scene} */ (SCENES.find((s) => s.id === 'isometry'));
  const input = /** @type {import('../../www/scene.js').Input} */ (decodeInput(/** @type {string} */ (task.input)));
  const said = {
    en: 'Ruling 10 meets neither of its neighbours (up to 4.91·10⁻² apart); every other pair of consecutive rulings meets, as on a cone.',
    de: 'Erzeugende 10 trifft keine ihrer Nachbarinnen (bis zu 4,91·10⁻² entfernt); jedes andere Paar aufeinanderfolgender Erzeugender trifft sich, wie auf einem Kegel.',
  };
  for (const [lang, sentence] of Object.entries(said)) {
    const { t, format } = translator(lang);
    const built = scene.create({ ...defaults(scene), ...task.params }, { t, format, lang, input });
    assert.ok(built.description.endsWith(sentence), built.description);
  }
  // the cone itself, as an edit: every ruling meets the vertex
  const cone = scene.create({ ...defaults(scene), surface: 'cone', n: 24 }, context);
  const rulings = /** @type {any} */ (cone).input?.sets?.[0]?.points ?? null;
  assert.ok(rulings, 'the cone scene gives its rulings as input');
  const again = scene.create({ ...defaults(scene), surface: 'cone', n: 24 }, { ...context, input: { rulings } });
  assert.ok(again.description.endsWith('Every pair of consecutive rulings meets, as on a cone.'), again.description);
});

test('“Your data” is named for any source (a notebook’s NumPy arrays too, not “import CSV or JSON”); a grid of lines says “Closed” does not close it, rulings that they have no focal surfaces', () => {
  for (const lang of ['en', 'de']) {
    const { t } = translator(lang);
    assert.doesNotMatch(t('data.title'), /CSV|JSON/, lang);
    assert.match(t('data.text'), /View\.from_segments/, lang);
  }
  const scene = /** @type {import('../../www/scene.js').Scene} */ (SCENES.find((s) => s.id === 'data'));
  // a 2 × 2 grid of lines
  const grid = {
    rows: 2,
    cols: 2,
    segments: new Float64Array([0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, 0, 0.1, 1, 1, 1, 1, 0, 1, 1, 1]),
  };
  const shown = (/** @type {Record<string, any>} */ p, /** @type {any} */ data) =>
    scene.create({ ...defaults(scene), ...p }, { ...context, data });
  assert.equal(shown({ closed: true }, grid).note, i18n.t('data.note.closedGrid'));
  assert.equal(shown({ closed: false }, grid).note, undefined);
  assert.equal(shown({ focal: true }, undefined).note, i18n.t('data.note.focalRulings'));
  assert.equal(shown({ closed: true }, undefined).note, undefined);
});
