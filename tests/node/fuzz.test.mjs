// Every export under random and adversarial arguments: each call returns or throws an Error
// (never a wasm trap, a WebAssembly.RuntimeError), and the module keeps working afterwards.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import ruledlab, { cam } from './load.mjs';

const {
  RuledSurface,
  AnalyticSurface,
  InvariantsBuffer,
  LineCongruence,
  AnalyticCongruence,
  subdividePolygon,
  turningAngles,
  importSegments,
  meshNormalsF32,
  linearComplex,
  kleinView,
  kleinDeparture,
  hiddenLines,
} = ruledlab;
const { ToolPath } = cam;

let seed = Number(process.env.FUZZ_SEED ?? 12345);
const random = () => {
  seed = (seed * 1103515245 + 12345) % 2147483648;
  return seed / 2147483648;
};
const pick = (xs) => xs[Math.floor(random() * xs.length)];

const NUMBERS = [
  0,
  -0,
  1,
  -1,
  0.5,
  2,
  3,
  7,
  12,
  1e-300,
  1e300,
  -1e300,
  NaN,
  Infinity,
  -Infinity,
  2 ** 31,
  2 ** 53,
  1.5,
  -3.7,
  1e9,
];
const SMALL = [0, 1, 2, 3, 4, 6, 12, -1, 1.5, NaN, Infinity, 1e9, 25];
const STRINGS = [
  '',
  'four-point',
  'chaikin',
  'bspline',
  'bezier',
  'variational',
  'butterfly',
  'lines',
  'points',
  'coupled',
  'literal',
  'averaged',
  'two-stage',
  'json',
  'csv',
  'gcode',
  'hyperboloid',
  'sphere',
  'example5',
  'flat',
  'ball',
  '💥',
];
const KEYS = [
  'scheme',
  'steps',
  'w',
  'n',
  'variant',
  'degree',
  'closed',
  'space',
  'length',
  'K',
  'diagonalOnly',
  'u',
  'h0',
  'levels',
  'uMin',
  'uMax',
  'vMin',
  'vMax',
  'radius',
  'end',
  'feed',
  'scale',
  'clearance',
  'junk',
];

function typedArray() {
  const n = pick([0, 1, 3, 5, 6, 11, 12, 18, 24, 36, 60, 72]);
  const a = new Float64Array(n);
  const mode = pick(['nice', 'nice', 'nice', 'adversarial', 'zeros', 'repeat']);
  for (let i = 0; i < n; i++) {
    a[i] =
      mode === 'nice'
        ? random() * 4 - 2
        : mode === 'zeros'
          ? 0
          : mode === 'repeat'
            ? i % 6 < 3
              ? 1
              : 1
            : pick(NUMBERS);
  }
  return a;
}

function options() {
  const o = {};
  const count = pick([0, 1, 2, 3, 4]);
  for (let i = 0; i < count; i++) {
    const k = pick(KEYS);
    o[k] = pick([
      () => pick(SMALL),
      () => pick(STRINGS),
      () => pick([true, false]),
      () => random() * 0.3 - 0.1,
      () => null,
      () => [1, 2],
      () => ({}),
    ])();
  }
  return o;
}

function value() {
  return pick([
    () => pick(NUMBERS),
    () => pick(STRINGS),
    typedArray,
    typedArray,
    options,
    () => undefined,
    () => null,
    () => [1, 2, 3],
    () => new Float32Array(6),
    () => ({ length: 6 }),
    () => true,
    () => 10n,
    () => Symbol('x'),
    () => [1, '2', {}],
    () => new Uint8Array(12),
  ])();
}

/** A valid object of each class to call methods on. */
function fixtures() {
  const hyp = AnalyticSurface.byName('hyperboloid');
  return {
    hyp,
    surface: hyp.sample(pick([2, 3, 5, 9, 20]), { closed: false }),
    congruence: AnalyticCongruence.byName('example5').grid(pick([2, 3, 4]), pick([2, 3, 5])),
    analyticCongruence: AnalyticCongruence.byName('sphere'),
    path: ToolPath.example(pick([2, 3, 7])),
  };
}

/** Text for the importers: random bytes, or a valid file with random damage. */
function text() {
  const valid = pick([
    '0,0,0,1,0,0\n0,0,1,0,1,1\n',
    'ax,ay,az,bx,by,bz\n1,2,3,4,5,6\n',
    '[[0,0,0,1,0,0],[0,0,1,0,1,1]]',
    '{"rows": 2, "cols": 2, "segments": [[0,0,0,1,0,0],[0,0,1,0,1,1],[1,0,0,1,1,0],[1,0,1,1,1,1]]}',
    '[1,2,3,4,5,6]',
  ]);
  const chars = '0123456789.,;-+eE[]{}":# \n\tabcxyz\\\u00e9\u{1F4A5}';
  if (random() < 0.3) return Array.from({ length: Math.floor(random() * 60) }, () => pick([...chars])).join('');
  const s = [...valid];
  for (let k = Math.floor(random() * 4); k > 0; k--) {
    const at = Math.floor(random() * (s.length + 1));
    const op = pick(['insert', 'delete', 'replace', 'cut']);
    if (op === 'insert') s.splice(at, 0, pick([...chars]));
    else if (op === 'delete') s.splice(at, 1);
    else if (op === 'replace') s[at] = pick([...chars]);
    else s.length = at;
  }
  return s.join('');
}

/** A formula: a valid one, a damaged one, or hostile text (nesting, numbers, names, unicode, other syntaxes). */
function formula() {
  const valid = pick([
    'cos(u)',
    'a*sin(u)',
    'u^2/2',
    'atan2(v, u)',
    'exp(-u*u)',
    'sqrt(1 + u^2)',
    '1',
    'sin(2*u + 1.5*v)/2',
  ]);
  const hostile = pick([
    `${'('.repeat(70)}u${')'.repeat(70)}`,
    `${'u+'.repeat(600)}u`,
    `${'-'.repeat(9)}u`,
    '1e308*1e308',
    '1/0',
    'sni(u)',
    'π*u',
    '2u',
    'u;u',
    '"x"',
    '<img src=x>',
    'u == 1',
    '9'.repeat(500),
    'atan2(u)',
    '',
    ' ',
    'log(-u)',
    '\u0000',
    '💥',
  ]);
  const chars = '0123456789.,+-*/^() uvabcepisncotqrlx\u00e9π';
  if (random() < 0.3) return hostile;
  if (random() < 0.3) return Array.from({ length: Math.floor(random() * 30) }, () => pick([...chars])).join('');
  const s = [...valid];
  for (let k = Math.floor(random() * 3); k > 0; k--)
    s.splice(Math.floor(random() * (s.length + 1)), pick([0, 1]), pick([...chars]));
  return s.join('');
}

// the book's table of error codes (docs/src/guide/errors.md): every thrown Error has one of them
const CODES = [
  ...readFileSync(new URL('../../docs/src/guide/errors.md', import.meta.url), 'utf8').matchAll(
    /^\| `([a-z-]+)` \| (?!meaning)/gm,
  ),
].map((m) => m[1]);
test('the book lists the error codes', () => {
  assert.deepEqual(CODES, [
    'invalid-argument',
    'not-finite',
    'out-of-range',
    'too-large',
    'too-small',
    'parse-error',
    'degenerate',
    'not-converged',
    'singular',
    'unreachable',
    'freed',
    'invalid-state',
    'internal',
  ]);
});

const CALLS = [
  (_f) =>
    AnalyticSurface.fromFormulas(
      pick([
        value(),
        {
          a: [formula(), formula(), formula()],
          e: [formula(), formula(), formula()],
          u: [pick([0, -1, formula()]), pick([1, 2, formula()])],
          ...pick([
            {},
            { v: [formula(), 1] },
            { closed: pick([true, 1]) },
            { parameters: { a: pick(NUMBERS) } },
            options(),
          ]),
        },
      ]),
    ),
  (_f) =>
    AnalyticCongruence.fromFormulas(
      pick([
        value(),
        {
          p: [formula(), formula(), formula()],
          e: [formula(), formula(), formula()],
          u: [-1, 1],
          v: [pick([-1, formula()]), 1],
          rows: pick([undefined, ...SMALL]),
          cols: pick([undefined, ...SMALL]),
        },
      ]),
    ),
  (f) => f.surface.invariants(pick([undefined, { closed: pick([true, false, value()]) }, value()])),
  (f) => f.surface.slide(value()),
  (f) => f.surface.maxAngleTo(pick([f.surface, f.surface.conoidal(), value()])),
  (f) => f.surface.maxEdgeChange(f.surface.bend(0.5)),
  (f) => f.surface.insertedF32(pick([...SMALL, value()])),
  (f) => f.surface.endsF32(pick([...SMALL, value()]), pick(SMALL)),
  (f) => f.surface.everyF32(pick([...SMALL, value()])),
  (f) => f.surface.triangulationF32(pick([...SMALL, value()]), pick([1, 2, ...SMALL])),
  (f) => f.surface.divisionPoint(pick(SMALL), pick(SMALL), pick(SMALL)),
  (f) => [
    f.surface.referenceFrame(),
    f.surface.developmentInSpace(),
    f.surface.developmentStriction(),
    f.surface.developmentStrictionInSpace(),
    f.surface.developmentEnvelope(),
    f.surface.developmentEnvelopeInSpace(),
    f.surface.directions(),
    f.surface.meanLength(),
  ],
  (f) => f.hyp.parameters(pick([...SMALL, value()]), pick([undefined, options()])),
  (f) => f.hyp.samplingErrors(pick([...SMALL, value()]), pick([undefined, options()])),
  (f) => f.hyp.insertedDistance(f.surface, pick(SMALL), pick(NUMBERS), pick(NUMBERS)),
  (f) => f.congruence.insertedF32(pick([...SMALL, value()])),
  (f) => f.congruence.directorF32(pick([...SMALL, value()])),
  (f) => f.congruence.insertedDirectorF32(pick(SMALL), pick(SMALL)),
  (f) =>
    f.analyticCongruence.grid(pick([undefined, ...SMALL]), pick([undefined, ...SMALL]), pick([undefined, ...NUMBERS])),
  (_f) => ToolPath.examplePart(pick([...SMALL, value()]), pick(SMALL)),
  (f) => f.path.envelopeMesh(pick([...SMALL, value()])),
  (f) => f.path.toolMesh(pick(SMALL), pick(SMALL)),
  (f) => f.path.insertedF32(pick([...SMALL, value()])),
  (_f) => importSegments(text()),
  (_f) => importSegments(text(), pick(['csv', 'json', undefined, value()])),
  (f) => f.surface.export(pick(['csv', 'json', value()])),
  (f) => f.congruence.export(pick(['csv', 'json', value()])),
  (_f) => RuledSurface.fromSegments(value()),
  (f) => f.surface.invariants(),
  (f) => f.surface.invariantsInto(pick([value(), f.surface.invariants(), {}])),
  (f) => {
    const buffer = new InvariantsBuffer();
    try {
      f.surface.invariantsInPlace(buffer, pick([undefined, value(), options()]));
      return buffer.striction.length;
    } finally {
      buffer.free();
    }
  },
  (f) => f.surface.invariantsInPlace(value()),
  (f) => f.surface.hinge(value()),
  (f) => f.surface.hinge(new Float64Array(Math.max(f.surface.length - 2, 0)).map(() => pick(NUMBERS))),
  (f) => f.surface.bend(pick([...NUMBERS, value()])),
  (f) => f.surface.conoidal(),
  (f) => f.surface.development(),
  (f) => f.surface.nonDevelopability(),
  (f) => f.surface.envelopeRadii(),
  (f) => f.surface.subdivide(value()),
  (f) => f.surface.subdivide(options()),
  (f) => f.surface.subdivide({ scheme: pick(STRINGS), steps: pick(SMALL), ...options() }),
  (f) => f.surface.recut(pick([undefined, ...NUMBERS])),
  (_f) => AnalyticSurface.byName(value()),
  (f) => f.hyp.sample(pick([...SMALL, value()]), pick([value(), options()])),
  (f) => f.hyp.striction(value()),
  (f) => f.hyp.distribution(value()),
  (f) => f.hyp.centralTangent(value()),
  (f) => f.hyp.convergence(pick([value(), options()])),
  (f) => f.hyp.distances(value(), pick(NUMBERS), pick(NUMBERS)),
  (_f) => subdividePolygon(value(), pick([value(), options(), { scheme: pick(STRINGS), ...options() }])),
  (_f) => turningAngles(value(), pick([value(), options(), { scheme: pick(STRINGS), ...options() }])),
  (_f) => LineCongruence.fromGrid(pick(SMALL), pick(SMALL), value()),
  (f) => f.congruence.subdivide(pick([value(), options(), { scheme: pick(STRINGS), ...options() }])),
  (f) => f.congruence.row(pick([...SMALL, value()])),
  (f) => f.congruence.column(pick([...SMALL, value()])),
  (_f) => AnalyticCongruence.byName(value()),
  (f) => f.analyticCongruence.grid(pick([undefined, ...SMALL]), pick([undefined, ...SMALL])),
  (f) => f.analyticCongruence.errors(pick([f.congruence, value()])),
  (f) => f.analyticCongruence.diagonalErrors(pick([f.congruence, value()])),
  (_f) =>
    ToolPath.fromSegments(
      value(),
      pick([value(), options(), { radius: pick(NUMBERS), length: pick(NUMBERS), end: pick(STRINGS) }]),
    ),
  (_f) => ToolPath.example(pick([undefined, ...SMALL])),
  (f) => f.path.refine(pick([value(), options()])),
  (f) => f.path.deviation(value()),
  (f) => f.path.export(pick([value(), ...STRINGS]), pick([value(), options()])),
  (_f) => ToolPath.exampleProfile(pick(SMALL)),
  (f) => f.path.quality(),
  (_f) =>
    ToolPath.rulingAligned(
      value(),
      pick([value(), options(), { radius: pick(NUMBERS), length: pick(NUMBERS), end: pick(STRINGS) }]),
      pick([1, -1, ...SMALL, value()]),
    ),
  (f) =>
    cam.optimisePoses(
      pick([f.path, value()]),
      pick([value(), ToolPath.exampleProfile(pick([1, 2, 20]))]),
      pick([undefined, value(), options(), { rounds: pick([0, 1, 2, NaN, -1, 1.5, 1e9]), fairness: pick(NUMBERS) }]),
      pick([undefined, value(), () => {}]),
    ),
  (f) =>
    meshNormalsF32(pick([value(), f.surface.segmentsF32()]), pick([value(), new Uint32Array([0, 1, 2]), [0, 1, 9]])),
  (f) => f.surface.recut(value()),
  (f) => f.hyp.sample(value(), pick([value(), options()])),
  (f) => f.congruence.focal(),
  (f) => f.congruence.focalSheetF32(pick([1, 2, ...SMALL, value()])),
  (f) => f.congruence.torsalStrokesF32(pick([undefined, ...NUMBERS, value()])),
  (f) => f.congruence.linearComplex(pick([undefined, value(), options(), { tolerance: pick(NUMBERS) }])),
  (f) => f.surface.linearComplex(pick([undefined, value(), options(), { tolerance: pick(NUMBERS) }])),
  (f) =>
    linearComplex(pick([value(), f.surface.segments(), [0, 0, 0, 1, 0, 0]]), pick([undefined, value(), options()])),
  (f) =>
    kleinView(
      pick([value(), f.surface.segments(), [0, 0, 0, 1, 0, 0]]),
      pick([
        undefined,
        value(),
        options(),
        { mix: pick(NUMBERS), turn: pick(NUMBERS), unit: pick(NUMBERS), closed: pick([true, false, value()]) },
      ]),
    ),
  (f) =>
    kleinDeparture(
      pick([value(), f.surface.segments(), [0, 0, 0, 1, 0, 0]]),
      pick([
        undefined,
        value(),
        options(),
        { scheme: pick(['chaikin', 'bspline', 'four-point', 'bezier', value()]), steps: pick([...SMALL, value()]) },
      ]),
      pick([undefined, value(), options(), { mix: pick(NUMBERS), turn: pick(NUMBERS), unit: pick(NUMBERS) }]),
    ),
  (f) => f.analyticCongruence.focal(pick([undefined, ...SMALL, value()]), pick([undefined, ...SMALL, value()])),
  (f) =>
    hiddenLines(
      pick([
        value(),
        options(),
        {
          viewProj: pick([
            value(),
            [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -0.1, -1, 0, 0, 5, 8],
            new Array(16).fill(0).map(() => pick(NUMBERS)),
          ]),
          width: pick([640, ...NUMBERS]),
          height: pick([420, ...NUMBERS]),
          meshes: pick([
            value(),
            [],
            [
              {
                positions: pick([value(), f.surface.segmentsF32()]),
                indices: pick([value(), new Uint32Array([0, 1, 2, 1, 2, 3]), [0, 1, 9], [2 ** 32 - 1, 0, 1]]),
                ...(random() < 0.3 ? { transform: value() } : {}),
              },
            ],
          ]),
          lines: pick([
            value(),
            [],
            [
              {
                kind: pick(['segments', 'polyline', 'points', ...STRINGS]),
                positions: pick([value(), f.surface.segmentsF32()]),
                ...(random() < 0.3 ? { closed: pick([true, value()]) } : {}),
              },
            ],
          ]),
        },
      ]),
      pick([undefined, value(), options(), { tolerance: pick(NUMBERS), minPiece: pick(NUMBERS) }]),
    ),
];

test('100 000 random and adversarial calls: only Errors, never a trap; the module keeps working', () => {
  let fx = fixtures();
  let errors = 0;
  const probe = RuledSurface.fromSegments(new Float64Array([0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 1]));
  const probeAngle = probe.invariants().angle[0];
  for (let i = 0; i < 100000; i++) {
    if (i % 500 === 0) fx = fixtures();
    const call = pick(CALLS);
    try {
      const result = call(fx);
      for (const r of Array.isArray(result) ? result : [result]) r?.free?.();
    } catch (e) {
      assert.ok(!(e instanceof WebAssembly.RuntimeError), `wasm trap in call ${CALLS.indexOf(call)}: ${e.stack}`);
      assert.ok(e instanceof Error, `not an Error: ${e}`);
      assert.ok(e.message.length > 10, `unclear message: ${e.message}`);
      // (`internal`, documented for the glue's unknown errors, is a bug wherever it is met)
      assert.ok(CODES.includes(e.code) && e.code !== 'internal', `no documented code on: ${e.message} (${e.code})`);
      errors++;
      // the module keeps working after every error
      assert.equal(probe.invariants().angle[0], probeAngle);
    }
  }
  // still working
  const s = RuledSurface.fromSegments(new Float64Array([0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 1, 1, 2]));
  assert.equal(s.invariants().angle.length, 2);
  assert.ok(errors > 1000, `only ${errors} errors: the fuzz is not adversarial enough`);
});
