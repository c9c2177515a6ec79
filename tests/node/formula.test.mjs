// Surfaces and congruences typed as formulas, through the package: exact values against the
// built-in surfaces, every error with its code and column, and the module usable afterwards.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab from './load.mjs';

const { AnalyticSurface, AnalyticCongruence } = ruledlab;
const near = (a, b, tol = 1e-12) => Math.abs(a - b) <= tol * Math.max(1, Math.abs(a), Math.abs(b));

/** Runs `use` on every object `make` returns, freeing them afterwards. */
function using(objects, use) {
  try {
    return use(...objects);
  } finally {
    for (const o of objects) o.free();
  }
}

const HYPERBOLOID = {
  a: ['a*cos(u)', 'b*sin(u)', '0'],
  e: ['-a*sin(u)', 'b*cos(u)', 'c'],
  u: [0, '2*pi'],
  closed: true,
  parameters: { a: 1, b: 2, c: 3 },
};

test('the hyperboloid of Example 1 typed as formulas equals the built-in one', () => {
  using([AnalyticSurface.fromFormulas(HYPERBOLOID), AnalyticSurface.byName('hyperboloid')], (typed, built) => {
    assert.equal(typed.name, 'formula');
    const u = new Float64Array([0.1, 0.7, 2, 4.5]);
    for (const f of ['striction', 'distribution', 'centralTangent']) {
      const [a, b] = [typed[f](u), built[f](u)];
      a.forEach((x, i) => {
        assert.ok(near(x, b[i]), `${f}[${i}]: ${x} vs ${b[i]}`);
      });
    }
    using([typed.sample(24), built.sample(24)], (s, t) => {
      const [a, b] = [s.segments(), t.segments()];
      a.forEach((x, i) => {
        assert.ok(near(x, b[i]), `segment ${i}`);
      });
    });
    const study = typed.convergence({ u: 0.7, h0: 0.1, levels: 6 });
    const order = (name) => study.series.find((s) => s.name === name).fittedOrder;
    assert.ok(Math.abs(order('footpoint') - 1) < 0.1 && Math.abs(order('midpoint') - 2) < 0.1);
  });
});

test('interval ends may be formulas of the parameters; v defaults to [-1, 1]', () => {
  using(
    [AnalyticSurface.fromFormulas({ a: ['u', '0', '0'], e: ['0', '1', 'u'], u: ['-a', 'a*pi'], parameters: { a: 2 } })],
    (s) => {
      using([s.sample(3)], (r) => {
        const seg = r.segments();
        assert.ok(near(seg[0], -2) && near(seg[1], -1) && near(seg[6 * 2], 2 * Math.PI) && near(seg[6 * 2 + 4], 1));
      });
    },
  );
});

test('Example 5 typed as formulas: the same grid and errors as the built-in congruence', () => {
  const spec = {
    p: ['u', 'v', 'sin(2*u + 1.5*v)/2'],
    e: ['u', 'v', 'sin(u) + 1.3*cos(v)'],
    u: [-1.1, 1.1],
    v: [-1.1, 1.1],
    rows: 8,
    cols: 7,
  };
  using([AnalyticCongruence.fromFormulas(spec), AnalyticCongruence.byName('example5')], (typed, built) => {
    using([typed.grid(), built.grid()], (g, h) => {
      assert.equal(g.rows, 8);
      assert.equal(g.cols, 7);
      const [a, b] = [g.segments(), h.segments()];
      a.forEach((x, i) => {
        assert.ok(near(x, b[i]), `coordinate ${i}`);
      });
      using([g.subdivide({ scheme: 'butterfly' })], (r) => {
        assert.deepEqual(typed.errors(r), built.errors(r));
      });
    });
  });
});

/** The thrown error of `f` (fails if it returns). */
function thrown(f) {
  try {
    f();
  } catch (e) {
    return e;
  }
  assert.fail('expected an error');
}

test('bad formulas throw errors with codes, columns and clear messages', () => {
  const base = { a: ['cos(u)', 'sin(u)', '0'], e: ['0', '0', '1'], u: [0, 1] };
  const cases = [
    [
      { ...base, a: ['cos(u)', 'sni(u)', '0'] },
      'parse-error',
      'AnalyticSurface.fromFormulas: a[1]: unknown function "sni" at column 1',
      { option: 'a[1]', column: 1 },
    ],
    [
      { ...base, a: ['cos(u)', '2*x', '0'] },
      'parse-error',
      'a[1]: unknown name "x" at column 3; known: u, a, b, c, pi, e',
      { column: 3 },
    ],
    [{ ...base, a: ['1/u', '0', '0'] }, 'not-finite', 'a[0] is not finite at u = 0', { option: 'a[0]' }],
    [{ ...base, e: ['u', 'u', '0'] }, 'degenerate', 'e: e(u) vanishes at u = 0', {}],
    [{ ...base, e: ['sqrt(u)', '1', '0'] }, 'not-finite', 'e[0]: the derivative is not finite at u = 0', {}],
    [
      { ...base, a: ['x'.repeat(1001), '0', '0'] },
      'too-large',
      'a[0]: 1001 characters exceed the limit of 1000',
      { limit: 1000 },
    ],
    [
      { ...base, a: [`${'('.repeat(65)}u${')'.repeat(65)}`, '0', '0'] },
      'too-large',
      'levels of nesting exceed the limit of 64',
      { column: 65 },
    ],
    [{ ...base, u: [1, 1] }, 'invalid-argument', 'u: needs min < max, got [1, 1]', { option: 'u' }],
    [{ ...base, u: [0, 'pi/0'] }, 'invalid-argument', 'u: needs two finite numbers', {}],
    [
      { ...base, colour: 'red' },
      'invalid-argument',
      'unknown option "colour"; known options: a, e, u, v, closed, parameters',
      { option: 'colour' },
    ],
    [{ ...base, a: ['u', '0'] }, 'invalid-argument', 'invalid length 2, expected an array of length 3', {}],
    [{ ...base, u: [0, true] }, 'invalid-argument', 'expected a number or a formula such as "2*pi"', {}],
    [
      { ...base, parameters: { d: 1 } },
      'invalid-argument',
      'unknown option "parameters.d"; known options: a, b, c',
      { option: 'parameters.d' },
    ],
    [
      'cos(u)',
      'invalid-argument',
      'spec must be an object { a, e, u, v, closed, parameters, decimalComma }, got a string',
      {},
    ],
  ];
  for (const [spec, code, message, details] of cases) {
    const e = thrown(() => AnalyticSurface.fromFormulas(spec));
    assert.ok(e instanceof Error);
    assert.equal(e.code, code, e.message);
    assert.ok(e.message.includes(message), `${e.message}\n  should contain: ${message}`);
    for (const [k, v] of Object.entries(details)) assert.equal(e.details[k], v, `${e.message}: details.${k}`);
  }
  // still usable
  using([AnalyticSurface.fromFormulas(base)], (s) => assert.equal(s.name, 'formula'));
});

test('congruence formulas name their errors too', () => {
  const base = { p: ['u', 'v', '0'], e: ['u', 'v', '1'], u: [-1, 1], v: [-1, 1] };
  let e = thrown(() => AnalyticCongruence.fromFormulas({ ...base, e: ['u', 'v', '0'] }));
  assert.equal(e.code, 'degenerate');
  assert.match(e.message, /e\(u, v\) vanishes at \(u, v\) = \(0, 0\)/);
  e = thrown(() => AnalyticCongruence.fromFormulas({ ...base, rows: 1 }));
  assert.equal(e.code, 'invalid-argument');
  assert.equal(e.details.option, 'rows');
  e = thrown(() => AnalyticCongruence.fromFormulas({ ...base, p: ['u', 'w', '0'] }));
  assert.equal(e.code, 'parse-error');
  assert.match(e.message, /p\[1\]: unknown name "w" at column 1; known: u, v, a, b, c, pi, e/);
});

test('the page’s formula presets are the core’s catalogue: each typed preset is its surface or congruence to 1e-12', async () => {
  const { SURFACE_PRESETS, CONGRUENCE_PRESETS } = await import('../../pkg/catalogue.js');
  assert.deepEqual(SURFACE_PRESETS, AnalyticSurface.formulaPresets(), 'pkg/catalogue.js is stale');
  assert.deepEqual(CONGRUENCE_PRESETS, AnalyticCongruence.formulaPresets(), 'pkg/catalogue.js is stale');
  const u = new Float64Array([0.1, 0.4, 0.9]);
  for (const preset of SURFACE_PRESETS) {
    const { name, ...formulas } = preset;
    using([AnalyticSurface.fromFormulas(formulas), AnalyticSurface.byName(name)], (typed, named) => {
      using([typed.sample(24), named.sample(24)], (a, b) => {
        const [x, y] = [a.segments(), b.segments()];
        x.forEach((v, i) => {
          assert.ok(near(v, y[i]), `${name}: segment coordinate ${i}: ${v} vs ${y[i]}`);
        });
      });
      const [s, t] = [typed.distribution(u), named.distribution(u)];
      s.forEach((v, i) => {
        assert.ok(near(v, t[i]), `${name}: δ`);
      });
    });
  }
  for (const preset of CONGRUENCE_PRESETS) {
    const { name, reach, ...formulas } = preset;
    assert.ok(reach > 0);
    using([AnalyticCongruence.fromFormulas(formulas), AnalyticCongruence.byName(name)], (typed, named) => {
      using([typed.grid(), named.grid()], (a, b) => {
        const [x, y] = [a.segments(), b.segments()];
        assert.equal(x.length, y.length);
        x.forEach((v, i) => {
          assert.ok(near(v, y[i]), `${name}: coordinate ${i}`);
        });
      });
    });
  }
});

test('“Closed in u” on a surface whose ends do not meet is said (a helicoid typed over the hyperboloid keeps its “closed”); every closed preset, the Möbius band too, closes', async () => {
  const { SCENES } = await import('../../www/scenes/index.js');
  const { defaults, withChoices } = await import('../../www/scene.js');
  const { translator } = await import('../../www/i18n/index.js');
  const { SURFACE_PRESETS } = await import('../../www/catalogue.js');
  const scene = /** @type {import('../../www/scene.js').Scene} */ (SCENES.find((s) => s.id === 'formula'));
  const problemsOf = (/** @type {Record<string, any>} */ p, lang = 'en') => {
    const { t, format } = translator(lang);
    return scene.create({ ...defaults(scene), ...p }, { t, format, lang }).problems ?? [];
  };
  const helicoid = { ax: '0', ay: '0', az: 'u/2', ex: 'cos(u)', ey: 'sin(u)', ez: '0' };
  assert.equal(defaults(scene).closed, true, 'the hyperboloid’s fields are closed');
  for (const tool of ['striction', 'subdivision'])
    assert.deepEqual(problemsOf({ ...helicoid, tool }), [
      '“Closed in u” follows the last ruling by the first, but this surface does not close: its ruling at u = 6.283 is not the one at u = 0 (3.142 apart, at 0 rad). Uncheck it for a surface that does not close.',
    ]);
  assert.match(
    problemsOf(helicoid, 'de')[0],
    /^„In u geschlossen“ .* u = 6,283 ist nicht die bei u = 0 \(3,142 entfernt, unter 0 rad\)/,
  );
  assert.deepEqual(problemsOf({ ...helicoid, closed: false }), []);
  let closed = 0;
  for (const { name } of SURFACE_PRESETS) {
    const p = withChoices(scene, { preset: name });
    if (!p.closed) continue;
    closed++;
    // (a cylinder's parallel pairs are said too: not this)
    assert.deepEqual(
      problemsOf(p).filter((/** @type {string} */ x) => x.startsWith('“Closed in u”')),
      [],
      name,
    );
  }
  assert.ok(closed >= 4, `${closed} closed presets`);
});

test('an option the core names in an error is the formula scenes’ field', async () => {
  const { SCENES } = await import('../../www/scenes/index.js');
  const fieldOf = (/** @type {string} */ id) => /** @type {any} */ (SCENES.find((s) => s.id === id)).fieldOf;
  const surface = fieldOf('formula');
  const congruence = fieldOf('formula-congruence');
  assert.deepEqual(['a[0]', 'a[2]', 'e[1]', 'u[1]', 'v[0]', 'u', 'e', 'parameters', 'p[0]', 'rows'].map(surface), [
    'ax',
    'az',
    'ey',
    'umax',
    'vmin',
    ['umin', 'umax'],
    ['ex', 'ey', 'ez'],
    'a',
    null,
    null,
  ]);
  assert.deepEqual(
    ['p[0]', 'p[2]', 'e[2]', 'u[0]', 'v[1]', 'v', 'rows', 'cols', 'a[0]', 'parameters'].map(congruence),
    ['px', 'pz', 'ez', 'umin', 'vmax', ['vmin', 'vmax'], 'rows', 'cols', null, null],
  );
});
