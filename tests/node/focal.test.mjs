// Focal geometry and linear complexes (beyond the paper) through the package: the shapes the
// book documents (docs/src/guide/focal.md), exact answers (two skew lines, a helical surface, a
// hyperboloid), the discrete values against the exact ones, and coded errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab from './load.mjs';

const { LineCongruence, AnalyticCongruence, AnalyticSurface, linearComplex } = ruledlab;

/** Runs `body` with the objects, freeing them after. */
function using(objects, body) {
  try {
    return body(...objects);
  } finally {
    for (const o of objects) o.free();
  }
}

/** Lines from (u, 0, −1) to (0, v, 1): focal points exactly the two ends. */
function skewGrid(rows, cols) {
  const c = [];
  for (let i = 0; i < rows; i++) for (let j = 0; j < cols; j++) c.push(i - 1, 0, -1, 0, j * 0.5, 1);
  return LineCongruence.fromGrid(rows, cols, c);
}

test('focal(): typed arrays of the documented lengths; the ends of lines meeting two skew lines', () => {
  using([skewGrid(3, 4)], (c) => {
    const f = c.focal();
    assert.equal(f.rows, 3);
    assert.equal(f.cols, 4);
    assert.ok(f.points instanceof Float64Array && f.points.length === 6 * 12);
    assert.ok(f.parameters instanceof Float64Array && f.parameters.length === 2 * 12);
    assert.ok(f.kind instanceof Uint8Array && f.kind.length === 12);
    assert.equal(f.torsal.length, 4 * 12);
    assert.equal(f.middle.length, 3 * 12);
    assert.equal(f.normality.length, 12);
    const s = c.segments();
    for (let k = 0; k < 12; k++) {
      assert.equal(f.kind[k], 1);
      for (let x = 0; x < 6; x++) assert.ok(Math.abs(f.points[6 * k + x] - s[6 * k + x]) < 1e-12, `line ${k}`);
    }
  });
});

test('an elliptic congruence: kind 0 and NaN, never a made-up number', () => {
  const spec = { p: ['u', 'v', '0'], e: ['-0.7*v', '0.7*u', '1'], u: [-1, 1], v: [-1, 1], rows: 5, cols: 5 };
  using([AnalyticCongruence.fromFormulas(spec)], (a) => {
    using([a.grid()], (g) => {
      for (const f of [g.focal(), a.focal()]) {
        assert.ok(f.kind.every((k) => k === 0));
        assert.ok(f.points.every(Number.isNaN) && f.parameters.every(Number.isNaN) && f.normality.every(Number.isNaN));
        assert.ok(f.middle.every(Number.isFinite));
      }
      assert.equal(g.focalSheetF32(1).indices.length, 0, 'no focal sheet where no focal point is real');
    });
  });
});

test('Example 5: the discrete focal points approach the exact ones, second order', () => {
  using([AnalyticCongruence.byName('example5')], (a) => {
    const error = (rows, cols, step) => {
      const exact = a.focal(rows, cols);
      return using([a.grid(rows, cols)], (g) => {
        const f = g.focal();
        let worst = 0;
        for (let i = 0; i < rows; i += step) {
          for (let j = 0; j < cols; j += step) {
            const k = i * cols + j;
            if (
              exact.kind[k] !== 1 ||
              Math.abs(exact.parameters[2 * k]) > 20 ||
              Math.abs(exact.parameters[2 * k + 1]) > 20
            )
              continue;
            for (const t of [0, 1])
              worst = Math.max(worst, Math.abs(f.parameters[2 * k + t] - exact.parameters[2 * k + t]));
          }
        }
        return worst;
      });
    };
    const [e1, e2] = [error(29, 25, 4), error(57, 49, 8)];
    assert.ok(Math.log2(e1 / e2) > 1.8, `order ${Math.log2(e1 / e2)} (${e1}, ${e2})`);
  });
});

test('focal sheets and torsal strokes are ready buffers', () => {
  using([AnalyticCongruence.byName('hyperbolic-paraboloid')], (a) => {
    using([a.grid(9, 9)], (g) => {
      const sheet = g.focalSheetF32(2);
      assert.ok(sheet.positions instanceof Float32Array && sheet.positions.length === 3 * 81);
      assert.ok(sheet.indices instanceof Uint32Array && sheet.indices.length > 0 && sheet.indices.length % 3 === 0);
      assert.equal(sheet.normals.length, sheet.positions.length);
      // one plain object with exactly FocalSheetFigure's fields: MeshBuffers' and its own
      assert.deepEqual(Object.keys(sheet), ['positions', 'indices', 'normals', 'min', 'max']);
      assert.ok(sheet.min instanceof Float64Array && sheet.min.length === 3);
      assert.ok(sheet.max instanceof Float64Array && sheet.max.length === 3);
      for (let k = 0; k < 3; k++) assert.ok(sheet.min[k] <= sheet.max[k]);
      const strokes = g.torsalStrokesF32();
      assert.ok(strokes instanceof Float32Array && strokes.length > 0 && strokes.length % 6 === 0);
      assert.throws(
        () => g.focalSheetF32(3),
        (e) => e.code === 'out-of-range' || e.code === 'invalid-argument',
      );
      assert.throws(
        () => g.torsalStrokesF32(-1),
        (e) => e.code === 'invalid-argument',
      );
    });
  });
});

test('linearComplex: a helical surface gives its screw axis, a hyperboloid a regulus, free segments too', () => {
  using([AnalyticSurface.byName('helical')], (h) => {
    using([h.sample(60)], (s) => {
      const f = s.linearComplex();
      assert.equal(f.kind, 'complex');
      assert.equal(f.nullity, 1);
      assert.ok(f.plucker instanceof Float64Array && f.plucker.length === 6);
      assert.ok(Math.hypot(f.axisDirection[0], f.axisDirection[1]) < 1e-9, `axis ${f.axisDirection}`);
      assert.ok(Math.hypot(...f.axisPoint) < 1e-9);
      assert.ok(f.axisSegment instanceof Float64Array && f.axisSegment.length === 6);
      assert.ok(
        Math.hypot(f.axisSegment[0], f.axisSegment[1], f.axisSegment[3], f.axisSegment[4]) < 1e-9,
        'the piece of axis lies on the z-axis',
      );
      assert.ok(f.residual < 1e-12);
      const free = linearComplex(s.segments());
      assert.equal(free.kind, 'complex');
      assert.ok(Math.abs(free.pitch - f.pitch) < 1e-12);
    });
  });
  using([AnalyticSurface.byName('hyperboloid')], (h) => {
    using([h.sample(40)], (s) => assert.equal(s.linearComplex().kind, 'regulus'));
  });
  using([skewGrid(4, 4)], (c) => {
    const f = c.linearComplex();
    assert.equal(f.kind, 'congruence');
    assert.equal(f.nullity, 2);
  });
  assert.throws(
    () => linearComplex([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1], { tolerance: -1 }),
    (e) => e.code === 'invalid-argument' && /tolerance/.test(e.message),
  );
  assert.throws(
    () => linearComplex([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1], { tol: 1 }),
    (e) => e.code === 'invalid-argument' && /tol/.test(e.message),
  );
  assert.throws(
    () => linearComplex('lines'),
    (e) => e.code === 'invalid-argument',
  );
});
