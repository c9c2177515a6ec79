// hiddenLines, the core's hidden lines as the exports call it: exact answers through the JS API
// (a line behind a square, hidden exactly over the square's shadow, with the page's camera
// matrix) and errors with codes for every kind of bad figure.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab from './load.mjs';
import { perspective, lookAt, multiply } from '../../www/math.js';

const { hiddenLines } = ruledlab;

/** The page's camera looking down at the origin from (0, 0, 10), on 640 × 420 pixels. */
const viewProj = multiply(
  perspective((35 * Math.PI) / 180, 640 / 420, 0.1, 1000),
  lookAt([0, 0, 10], [0, 0, 0], [0, 1, 0]),
);
const square = {
  positions: new Float32Array([-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0]),
  indices: new Uint32Array([0, 1, 2, 0, 2, 3]),
};
/** Pixel position of a point, as the viewer projects it. */
const project = (/** @type {number[]} */ [x, y, z]) => {
  const m = viewProj;
  const w = m[3] * x + m[7] * y + m[11] * z + m[15];
  return [
    (((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) / 2) * 640,
    ((1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) / 2) * 420,
  ];
};

test('a line behind a square is hidden exactly over the square’s shadow; dots too', () => {
  const { lines } = hiddenLines({
    viewProj,
    width: 640,
    height: 420,
    meshes: [square],
    lines: [
      { kind: 'segments', positions: new Float32Array([-5, 0.25, -1, 5, 0.25, -1]) },
      { kind: 'points', positions: [0, 0, -1, 3, 0, -1] },
      { kind: 'polyline', positions: [-3, 0, 1, 0, 0, 1, 3, 0, 1], closed: false },
    ],
  });
  const [segment, dots, front] = lines;
  assert.deepEqual([...segment.visible], [1, 0, 1]);
  assert.deepEqual([...segment.runs], [0, 2, 2, 2, 4, 2]);
  // the shadow of x = ±1 on the plane z = −1, seen from z = 10: x = ±1.1 (f32 camera: 1e-3 px)
  const near = (/** @type {number[]} */ a, /** @type {number[]} */ b) => Math.hypot(a[0] - b[0], a[1] - b[1]) < 1e-3;
  assert.ok(near([...segment.points.subarray(4, 6)], project([-1.1, 0.25, -1])));
  assert.ok(near([...segment.points.subarray(6, 8)], project([1.1, 0.25, -1])));
  assert.deepEqual([...dots.visible], [0, 1]);
  assert.deepEqual([...front.visible], [1]);
  assert.equal(front.points.length, 6);
});

test('bad figures are Errors with codes, naming what is wrong', () => {
  const good = { viewProj, width: 640, height: 420, meshes: [square], lines: [] };
  for (const [figure, options, words] of [
    [undefined, undefined, 'figure must be an object'],
    [{ ...good, extra: 1 }, undefined, 'unknown field "extra"'],
    [{ ...good, viewProj: [1, 2, 3] }, undefined, '16 numbers'],
    [{ ...good, viewProj: new Float32Array(16) }, undefined, 'not invertible'],
    [{ ...good, width: -1 }, undefined, 'width must be'],
    [{ ...good, meshes: {} }, undefined, 'meshes must be an array'],
    [{ ...good, meshes: [{ positions: [0, 0], indices: [] }] }, undefined, '3 numbers per point'],
    [{ ...good, lines: [{ kind: 'curve', positions: [] }] }, undefined, 'kind must be'],
    [{ ...good, lines: [{ kind: 'segments', positions: [0, 0, 0] }] }, undefined, '6 numbers each'],
    [{ ...good, lines: [{ kind: 'points', positions: [0, 0, 0], transform: [1] }] }, undefined, 'transform must be'],
    [good, { tolerance: -1 }, 'tolerance must be'],
    [good, { minPiece: 'a' }, 'minPiece must be'],
    [good, { tolerence: 1 }, 'unknown field "tolerence"'],
  ]) {
    assert.throws(
      () => hiddenLines(figure, options),
      (/** @type {any} */ e) => e instanceof Error && e.code === 'invalid-argument' && e.message.includes(words),
      words,
    );
  }
});
