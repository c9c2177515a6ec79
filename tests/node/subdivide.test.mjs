// Section 4 through the package: subdivide, recut, subdividePolygon, turningAngles, and their errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab, { sampled } from './load.mjs';

const { AnalyticSurface, subdividePolygon, turningAngles } = ruledlab;

const quartic = (n = 12) => sampled('quartic', n);

test('interpolatory schemes: 2N − 1 rulings per step, old rulings bit for bit at even indices', () => {
  const s = quartic();
  const old = s.segments();
  for (const options of [
    { scheme: 'four-point' },
    { scheme: 'four-point', w: 1 / 13, steps: 2 },
    { scheme: 'variational' },
    { scheme: 'variational', n: 5, variant: 'averaged' },
  ]) {
    const r = s.subdivide(options);
    const steps = options.steps ?? 1;
    assert.equal(r.length, (12 - 1) * 2 ** steps + 1, JSON.stringify(options));
    const seg = r.segments();
    for (let i = 0; i < 12; i++) {
      for (let k = 0; k < 6; k++) assert.equal(seg[6 * i * 2 ** steps + k], old[6 * i + k]);
    }
    r.free();
  }
});

test('approximating schemes and sizes', () => {
  const s = quartic(6);
  assert.equal(s.subdivide({ scheme: 'chaikin', steps: 2 }).length, 18);
  assert.equal(s.subdivide({ scheme: 'bspline', degree: 3 }).length, 9);
  assert.equal(s.subdivide({ scheme: 'bezier', steps: 2 }).length, 21);
  assert.equal(s.subdivide({ scheme: 'four-point', steps: 0 }).length, 6);
});

test('literal variational equals the midpoint rule', () => {
  const s = quartic();
  const a = s.subdivide({ scheme: 'variational', variant: 'literal' }).segments();
  const b = s.subdivide({ scheme: 'bspline', degree: 1 }).segments();
  a.forEach((x, i) => {
    assert.ok(Math.abs(x - b[i]) < 1e-12);
  });
});

test('recut gives segments of one length centred on the striction points', () => {
  const h = AnalyticSurface.byName('hyperboloid').sample(20, { uMin: 0, uMax: 2, closed: false });
  const r = h.recut(0.5);
  const seg = r.segments();
  const m = h.invariants().striction;
  for (let i = 1; i < 19; i++) {
    const len = Math.hypot(
      seg[6 * i + 3] - seg[6 * i],
      seg[6 * i + 4] - seg[6 * i + 1],
      seg[6 * i + 5] - seg[6 * i + 2],
    );
    assert.ok(Math.abs(len - 0.5) < 1e-12);
    for (let k = 0; k < 3; k++)
      assert.ok(Math.abs((seg[6 * i + k] + seg[6 * i + 3 + k]) / 2 - m[3 * (i - 1) + k]) < 1e-12);
  }
  assert.throws(() => h.recut(-1), /RuledSurface.recut: length: must be a positive finite number, got -1/);
});

test('subdividePolygon: Chaikin and four-point on a polygon', () => {
  const p = new Float64Array([0, 0, 0, 4, 0, 0, 4, 4, 0]);
  assert.deepEqual([...subdividePolygon(p, { scheme: 'chaikin' })], [1, 0, 0, 3, 0, 0, 4, 1, 0, 4, 3, 0]);
  const q = subdividePolygon(p, { scheme: 'four-point', closed: true });
  assert.equal(q.length, 18);
  assert.throws(
    () => subdividePolygon(new Float64Array([0, 0, NaN, 1, 1, 1]), { scheme: 'chaikin' }),
    /coordinate 2 \(point 0, z\) is NaN/,
  );
  assert.throws(
    () => subdividePolygon(new Float64Array(7), { scheme: 'chaikin' }),
    /point coordinates: length 7 is not a multiple of 3/,
  );
  assert.throws(() => subdividePolygon(p, { scheme: 'variational' }), /refines ruled strips, not polygons/);
});

test('bad options throw clear Errors and the surface stays usable', () => {
  const s = quartic(6);
  const cases = [
    [{}, /options.scheme is required/],
    [undefined, /options.scheme is required/],
    [
      { scheme: 'loop' },
      /options.scheme: unknown value "loop", expected one of "chaikin", "bspline", "bezier", "four-point", "variational"/,
    ],
    [
      { scheme: 4 },
      /options.scheme: expected one of "chaikin", "bspline", "bezier", "four-point", "variational", got the number 4/,
    ],
    [{ scheme: 'chaikin', w: 0.1 }, /options.w applies to the "four-point" scheme only, not to "chaikin"/],
    [{ scheme: 'four-point', w: 0.5 }, /w: must be a number in \[−1\/4, 1\/4\]/],
    [{ scheme: 'four-point', w: NaN }, /options.w must be a finite number, got NaN/],
    [{ scheme: 'four-point', steps: -1 }, /options.steps must be an integer from 0 to 24, got -1/],
    [{ scheme: 'four-point', steps: 1.5 }, /got 1.5/],
    [{ scheme: 'four-point', steps: 22 }, /rulings after subdivision: .* exceeds the limit of 4194304/],
    [{ scheme: 'variational', n: 2 }, /options.n must be an integer from 3 to 1000, got 2/],
    [
      { scheme: 'variational', variant: 'fancy' },
      /options.variant: unknown value "fancy", expected one of "coupled", "literal", "averaged"/,
    ],
    [{ scheme: 'variational', closed: true }, /refines open polygons and strips only/],
    [{ scheme: 'bezier', closed: true }, /open polygons and strips only/],
    [{ scheme: 'bspline', degree: 9 }, /options.degree must be an integer from 1 to 7, got 9/],
    [{ scheme: 'four-point', colour: 'red' }, /unknown option "colour"/],
    [{ scheme: 'four-point', closed: 'yes' }, /options.closed: expected true or false, got the string "yes"/],
  ];
  for (const [options, message] of cases) {
    assert.throws(
      () => s.subdivide(options),
      (e) => e instanceof Error && message.test(e.message),
      String(message),
    );
  }
  assert.equal(s.subdivide({ scheme: 'four-point' }).length, 11);
});

test('space "lines": the result does not depend on where the endpoints sit', () => {
  const s = quartic(9);
  const seg = s.segments();
  const slid = seg.slice();
  for (let i = 0; i < 9; i++) {
    for (let k = 0; k < 3; k++) {
      const d = seg[6 * i + 3 + k] - seg[6 * i + k];
      slid[6 * i + k] += (0.3 * i - 1) * d;
      slid[6 * i + 3 + k] += 0.2 * i * d;
    }
  }
  const moved = ruledlab.RuledSurface.fromSegments(slid);
  const a = s.subdivide({ scheme: 'four-point', space: 'lines', length: 1, steps: 2 }).segments();
  const b = moved.subdivide({ scheme: 'four-point', space: 'lines', length: 1, steps: 2 }).segments();
  assert.equal(a.length, 6 * 33);
  a.forEach((x, i) => {
    assert.ok(Math.abs(x - b[i]) < 1e-12, `${i}: ${x} vs ${b[i]}`);
  });
  // while the endpoint scheme does move
  const c = s.subdivide({ scheme: 'four-point', steps: 2 }).segments();
  const d = moved.subdivide({ scheme: 'four-point', steps: 2 }).segments();
  assert.ok(c.some((x, i) => Math.abs(x - d[i]) > 1e-3));
  assert.throws(
    () => s.subdivide({ scheme: 'variational', space: 'lines' }),
    /line space supports "chaikin", "bspline" and "four-point"/,
  );
  assert.throws(() => s.subdivide({ scheme: 'four-point', length: 2 }), /options.length applies to space "lines" only/);
  assert.throws(
    () => s.subdivide({ scheme: 'four-point', space: 'plane' }),
    /options.space: unknown value "plane", expected "points" or "lines"/,
  );
});

test('congruences: butterfly in line space', () => {
  const c = ruledlab.AnalyticCongruence.byName('sphere').grid(5, 5);
  const r = c.subdivide({ scheme: 'butterfly', space: 'lines', length: 0.5 });
  assert.deepEqual([r.rows, r.cols], [9, 9]);
  const seg = r.segments();
  for (let k = 0; k < 81; k++)
    assert.ok(
      Math.abs(
        Math.hypot(seg[6 * k + 3] - seg[6 * k], seg[6 * k + 4] - seg[6 * k + 1], seg[6 * k + 5] - seg[6 * k + 2]) - 0.5,
      ) < 1e-12,
    );
  assert.throws(
    () => c.subdivide({ scheme: 'variational', space: 'lines' }),
    /options.space applies to the "butterfly" scheme only/,
  );
});

/** The curves scene's control polygon (www/scenes/curves.js): eight points in a zigzag. */
const ZIGZAG = new Float64Array([
  0, 0, 0, 2, 3, 0, 4, 0.5, 0, 6.5, 3.5, 0, 8, -0.5, 0, 5.5, -3, 0, 3, -1.5, 0, 1, -3.2, 0,
]);

test('turningAngles: the four-point polygons still straighten out beyond w = 1/8 (issue 33)', () => {
  const late = (/** @type {number} */ w, /** @type {boolean} */ closed) => {
    const a = turningAngles(ZIGZAG, { scheme: 'four-point', w, steps: 12, closed });
    assert.equal(a.length, 13);
    return [a[8], a[12]].map((x) => Math.round(x * 1000) / 1000);
  };
  // closed: still falling at 0.14 and 0.15, beyond the paper's 1/8, and at 0.17; sharp at 0.171
  assert.deepEqual(late(0.14, true), [0.393, 0.188]);
  assert.deepEqual(late(0.15, true), [0.557, 0.317]);
  assert.deepEqual(late(0.17, true), [1.041, 0.996]);
  assert.deepEqual(late(0.171, true), [1.142, 1.156]);
  // near π (the polygon turns back) at the slider's end
  assert.ok(late(0.2, true)[1] > 3.1);
  // open, the end rule gives out between 0.126 and 0.127
  assert.deepEqual(late(0.126, false), [1.742, 1.221]);
  assert.deepEqual(late(0.127, false), [2.088, 2.278]);
  // the exact answer on the square (±1, 0), (0, ±1): π/2, then acos(8/17) after a step with w = 1/16
  const square = [1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0];
  const [a0, a1] = turningAngles(square, { scheme: 'four-point', closed: true });
  assert.ok(Math.abs(a0 - Math.PI / 2) < 1e-12 && Math.abs(a1 - Math.acos(8 / 17)) < 1e-12);
  // Chaikin's limit is C¹: its angle falls at every step
  const chaikin = turningAngles(ZIGZAG, { scheme: 'chaikin', steps: 8 });
  for (let k = 1; k < chaikin.length; k++) assert.ok(chaikin[k] < chaikin[k - 1]);
});

test('turningAngles: its errors carry codes', () => {
  const code = (/** @type {() => unknown} */ f, /** @type {string} */ expected, /** @type {RegExp} */ message) =>
    assert.throws(f, (/** @type {any} */ e) => e.code === expected && message.test(e.message));
  code(() => turningAngles(ZIGZAG, { scheme: 'variational' }), 'invalid-argument', /^turningAngles: .*not polygons/);
  code(() => turningAngles(ZIGZAG, { scheme: 'four-point', w: 0.3 }), 'invalid-argument', /\[−1\/4, 1\/4\]/);
  code(() => turningAngles(ZIGZAG, { scheme: 'four-point', steps: 25 }), 'invalid-argument', /steps/);
  code(() => turningAngles(ZIGZAG, { scheme: 'four-point', steps: 20 }), 'too-large', /rulings after subdivision/);
  code(() => turningAngles([0, 0, 0], { scheme: 'chaikin' }), 'too-small', /points/);
  code(() => turningAngles([0, 0, NaN, 1, 1, 1], { scheme: 'chaikin' }), 'not-finite', /NaN/);
  code(() => turningAngles(ZIGZAG, { scheme: 'chaikin', space: 'lines' }), 'invalid-argument', /not polygons/);
  code(() => turningAngles(ZIGZAG, undefined), 'invalid-argument', /scheme/);
});
