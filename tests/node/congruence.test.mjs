// Section 5 through the package: LineCongruence and AnalyticCongruence.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab from './load.mjs';

const { LineCongruence, AnalyticCongruence } = ruledlab;

function flatGrid(rows, cols) {
  const c = new Float64Array(6 * rows * cols);
  for (let i = 0; i < rows; i++) {
    for (let j = 0; j < cols; j++) c.set([i, j, Math.sin(i + j), i + 0.1 * j, j, 2], 6 * (i * cols + j));
  }
  return c;
}

test('fromGrid, rows, cols, segments, rows and columns as ruled surfaces', () => {
  const coords = flatGrid(3, 4);
  const c = LineCongruence.fromGrid(3, 4, coords);
  assert.equal(c.rows, 3);
  assert.equal(c.cols, 4);
  assert.deepEqual(c.segments(), coords);
  assert.equal(c.segmentsF32().length, 72);
  const row = c.row(1);
  assert.equal(row.length, 4);
  assert.equal(row.invariants().angle.length, 3);
  assert.equal(c.column(3).length, 3);
  c.free();
});

test('butterfly and variational keep the old lines and double the grid; Example 5', () => {
  const ex = AnalyticCongruence.byName('example5');
  const c = ex.grid();
  assert.deepEqual([c.rows, c.cols], [8, 7]);
  const old = c.segments();
  const errors = {};
  for (const [name, options] of [
    ['butterfly', { scheme: 'butterfly' }],
    ['two-stage', { scheme: 'variational', variant: 'two-stage', K: 6 }],
    ['coupled', { scheme: 'variational' }],
  ]) {
    const r = c.subdivide(options);
    assert.deepEqual([r.rows, r.cols], [15, 13]);
    const seg = r.segments();
    for (let i = 0; i < 8; i++) {
      for (let j = 0; j < 7; j++) {
        for (let k = 0; k < 6; k++) assert.equal(seg[6 * (2 * i * 13 + 2 * j) + k], old[6 * (i * 7 + j) + k]);
      }
    }
    errors[name] = ex.errors(r);
  }
  assert.ok(
    errors.butterfly.distance < errors.coupled.distance && errors.coupled.distance < errors['two-stage'].distance,
    JSON.stringify(errors),
  );
  const diag = c.subdivide({ scheme: 'butterfly', diagonalOnly: true });
  assert.deepEqual([diag.rows, diag.cols], [7, 6]);
});

test('bad input throws clear Errors and the module keeps working', () => {
  const c = LineCongruence.fromGrid(3, 4, flatGrid(3, 4));
  const cases = [
    [() => LineCongruence.fromGrid(3, 4, flatGrid(3, 3)), /a 3 × 4 grid needs 72 numbers \(6 per line\), got 54/],
    [() => LineCongruence.fromGrid(1, 4, flatGrid(1, 4)), /rows must be an integer from 2/],
    [() => LineCongruence.fromGrid(2.5, 4, flatGrid(3, 4)), /got 2.5/],
    [() => LineCongruence.fromGrid(3, 4, [1, 2, 3]), /a 3 × 4 grid needs 72 numbers \(6 per line\), got 3/],
    [
      () => LineCongruence.fromGrid(3, 4, 'x'),
      /coords must be a Float64Array, Float32Array or array of numbers, got a string/,
    ],
    [
      () => LineCongruence.fromGrid(4096, 4096, new Float64Array(6)),
      /lines \(rows × cols\): 16777216 exceeds the limit/,
    ],
    [
      () =>
        LineCongruence.fromGrid(
          3,
          4,
          flatGrid(3, 4).map((x, i) => (i === 9 ? NaN : x)),
        ),
      /coordinate 9 \(line \(0, 1\), q.x\) is NaN/,
    ],
    [
      () => c.subdivide({ scheme: 'loop' }),
      /options.scheme: unknown value "loop", expected "butterfly" or "variational"/,
    ],
    [() => c.subdivide({}), /options.scheme is required/],
    [() => c.subdivide({ scheme: 'butterfly', K: 6 }), /options.K applies to the "variational" scheme only/],
    [() => c.subdivide({ scheme: 'butterfly', w: 1 }), /w: must be a number in \[−1\/4, 1\/4\], got 1/],
    [() => c.subdivide({ scheme: 'variational', K: 2 }), /options.K must be an integer from 3 to 1000, got 2/],
    [
      () => c.subdivide({ scheme: 'variational', variant: 'magic' }),
      /options.variant: unknown value "magic", expected one of "paper", "two-stage", "coupled"/,
    ],
    [() => c.subdivide({ scheme: 'butterfly', steps: 12 }), /lines after subdivision: .* exceeds the limit/],
    [() => c.row(3), /LineCongruence.row: i must be an integer from 0 to 2, got 3/],
    [() => AnalyticCongruence.byName('torus'), /unknown congruence "torus"/],
    [() => AnalyticCongruence.byName('sphere').grid(1, 5), /rows must be an integer from 2/],
  ];
  for (const [call, message] of cases) {
    assert.throws(call, (e) => e instanceof Error && message.test(e.message), String(message));
  }
  assert.equal(c.subdivide({ scheme: 'butterfly' }).rows, 5);
});

test('diagonalErrors: the accuracy of Fig. 13’s diagonal lines, measured at the cells’ centres', () => {
  for (const name of ['sphere', 'hyperbolic-paraboloid', 'example5']) {
    const analytic = AnalyticCongruence.byName(name);
    const grid = analytic.grid();
    const diagonal = grid.subdivide({ scheme: 'butterfly', diagonalOnly: true });
    const full = grid.subdivide({ scheme: 'butterfly' });
    const [d, b] = [analytic.diagonalErrors(diagonal), analytic.errors(full)];
    // the diagonal lines are some of the full step's new lines: never farther off
    assert.ok(d.distance <= b.distance && d.angle <= b.angle, `${name}: ${JSON.stringify([d, b])}`);
    assert.ok(d.angle > 0);
    // measured as if they were a refined grid, they would be compared with the wrong lines
    assert.notDeepEqual(analytic.errors(diagonal), d);
    for (const o of [diagonal, full, grid, analytic]) o.free();
  }
  // the hyperbolic paraboloid's points (u, v, uv) are bilinear: the inserted points lie on it
  const h = AnalyticCongruence.byName('hyperbolic-paraboloid');
  const g = h.grid();
  const diagonal = g.subdivide({ scheme: 'butterfly', diagonalOnly: true });
  assert.ok(h.diagonalErrors(diagonal).distance < 1e-15);
  for (const o of [diagonal, g, h]) o.free();
});
