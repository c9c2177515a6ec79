// Import and export of segments: round trips, malformed files with line and column.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab from './load.mjs';

const { RuledSurface, LineCongruence, AnalyticSurface, AnalyticCongruence, importSegments } = ruledlab;

test('export → import gives the same numbers (CSV and JSON, surfaces and congruences)', () => {
  const s = AnalyticSurface.byName('quartic').sample(17);
  for (const format of ['csv', 'json']) {
    const back = importSegments(s.export(format));
    assert.deepEqual(back.segments, s.segments(), format);
    assert.equal(RuledSurface.fromSegments(back.segments).length, 17);
  }
  const c = AnalyticCongruence.byName('example5').grid();
  const g = importSegments(c.export('json'));
  assert.deepEqual([g.rows, g.cols], [8, 7]);
  const c2 = LineCongruence.fromGrid(g.rows, g.cols, g.segments);
  assert.deepEqual(c2.segments(), c.segments());
});

test('CSV with a header, comments, other separators', () => {
  const r = importSegments('# my rulings\nax;ay;az;bx;by;bz\n0;0;0;1;0;0\n0 0 1 0 1 1\n');
  assert.deepEqual([...r.segments], [0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 1]);
  assert.equal(r.rows, undefined);
});

test('malformed files are rejected with the line and column', () => {
  const cases = [
    ['0,0,0,1,0,0\n0,0,0,1,0\n', /importSegments: csv: line 2, column 10: expected 6 numbers/],
    ['0,0,0,1,0,0\n1,2,three,4,5,6\n', /line 2, column 5: "three" is not a number/],
    ['[[0,0,0,1,0,0],\n [0,0,0,1,0]]', /json: line 2, column 2: a segment needs 6 numbers, found 5/],
    ['{"rows": 2, "cols": 3, "segments": [[0,0,0,1,0,0]]}', /a 2 × 3 grid needs 6 segments, found 1/],
    ['[' + '['.repeat(5000), /nested deeper than 16 levels/],
  ];
  for (const [text, message] of cases) assert.throws(() => importSegments(text), (e) => e instanceof Error && message.test(e.message), String(message));
  assert.throws(() => importSegments(42), /text must be a string, got a number/);
  assert.throws(() => importSegments('0,0,0,1,0,0', 'xml'), /format must be "csv" or "json"/);
  assert.throws(() => AnalyticSurface.byName('cone').sample(3).export('obj'), /format must be "csv" or "json"/);
});
