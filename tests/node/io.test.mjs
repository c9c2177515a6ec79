// Import and export of segments: round trips, malformed files with line and column.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab, { cam } from './load.mjs';

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
    [`[${'['.repeat(5000)}`, /nested deeper than 16 levels/],
  ];
  for (const [text, message] of cases)
    assert.throws(
      () => importSegments(text),
      (e) => e instanceof Error && message.test(e.message),
      String(message),
    );
  assert.throws(() => importSegments(42), /text must be a string, got a number/);
  // the three readers refuse a text that is not one and a format they do not read alike, naming it
  for (const read of [importSegments, cam.importToolPoses, cam.importTarget]) {
    assert.throws(() => read(42), /text must be a string, got a number/, read.name);
    assert.throws(() => read('0,0,0,1,0,0', 'xml'), /format must be "csv" or "json", got "xml"/, read.name);
    assert.throws(() => read('0,0,0,1,0,0', 5), /format must be "csv" or "json", got a number/, read.name);
  }
  assert.throws(
    () => AnalyticSurface.byName('cone').sample(3).export('xml'),
    /format must be "csv", "json", "obj", "invariants-csv" or "invariants-json", got "xml"/,
  );
  assert.throws(
    () => AnalyticCongruence.byName('example5').grid().export('invariants-json'),
    /format must be "csv", "json" or "obj"/,
  );
  assert.throws(
    () =>
      AnalyticSurface.byName('cone')
        .sample(3)
        .export('obj', { name: 'x'.repeat(201) }),
    (e) => e.code === 'invalid-argument' && e.details.option === 'name',
  );
});

test('OBJ: the endpoints as vertices at full precision, a line per ruling, a quad per strip', () => {
  const s = AnalyticSurface.byName('helicoid').sample(9);
  const text = s.export('obj', { name: 'my helicoid' });
  const lines = text.trim().split('\n');
  assert.equal(lines[1], 'o my_helicoid');
  const v = lines.filter((l) => l.startsWith('v ')).flatMap((l) => l.slice(2).split(' ').map(Number));
  assert.deepEqual(Float64Array.from(v), s.segments());
  assert.equal(lines.filter((l) => l.startsWith('l ')).length, 9);
  const faces = lines.filter((l) => l.startsWith('f ')).map((l) => l.slice(2).split(' ').map(Number));
  assert.equal(faces.length, 8);
  assert.deepEqual(faces[3], [7, 8, 10, 9]);
  const c = AnalyticCongruence.byName('example5').grid();
  const cobj = c.export('obj');
  assert.equal(cobj.split('\n').filter((l) => l.startsWith('l ')).length, 56);
  assert.ok(!/^f /m.test(cobj), 'a congruence has no faces');
  for (const o of [s, c]) o.free();
});

test('the invariants as JSON and CSV are the invariants() of the surface', () => {
  const s = AnalyticSurface.byName('hyperboloid').sample(12);
  const inv = s.invariants();
  const json = JSON.parse(s.export('invariants-json'));
  for (const key of [
    'angle',
    'distance',
    'distribution',
    'footpoints',
    'centralNormal',
    'striction',
    'distributionMean',
    'perpendicularMidpoints',
  ]) {
    assert.deepEqual(
      json[key],
      Array.from(inv[key], (x) => (Number.isFinite(x) ? x : null)),
      key,
    );
  }
  assert.deepEqual(json.parallel, Array.from(inv.parallel, Number));
  const rows = s.export('invariants-csv').trim().split('\n');
  assert.equal(rows[0], 'pair,angle,distance,distribution,f0x,f0y,f0z,f1x,f1y,f1z,nx,ny,nz,parallel');
  assert.equal(rows.length, 1 + inv.angle.length);
  const r5 = rows[6].split(',').map(Number);
  assert.deepEqual(r5.slice(0, 4), [5, inv.angle[5], inv.distance[5], inv.distribution[5]]);
  assert.deepEqual(r5.slice(4, 10), Array.from(inv.footpoints.subarray(30, 36)));
  s.free();
});
