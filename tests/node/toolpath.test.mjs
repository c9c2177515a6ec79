// Example 6 through the package: ToolPath, refinement, quality, exports, G-code round trip.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab from './load.mjs';

const { ToolPath } = ruledlab;

test('the example refines through its given poses with unit axes', () => {
  const path = ToolPath.example();
  assert.equal(path.length, 7);
  const r = path.refine({ steps: 2 });
  assert.equal(r.length, 25);
  const [t0, t1, a1] = [path.tips(), r.tips(), r.axes()];
  for (let i = 0; i < 7; i++) for (let k = 0; k < 3; k++) assert.equal(t1[3 * 4 * i + k], t0[3 * i + k]);
  for (let i = 0; i < 25; i++) assert.ok(Math.abs(Math.hypot(a1[3 * i], a1[3 * i + 1], a1[3 * i + 2]) - 1) < 1e-15);
  const q = r.quality();
  assert.equal(q.angleStep.length, 24);
  assert.ok(q.maxAngleStep > 0 && q.maxAngleStep < 0.1);
  const profile = ToolPath.exampleProfile(300);
  const dev = r.deviation(profile);
  assert.equal(dev.length, 300);
  assert.ok(Math.max(...dev.map(Math.abs)) < Math.max(...path.deviation(profile).map(Math.abs)));
  assert.equal(r.barycentres().length, 75);
  assert.equal(r.segmentsF32().length, 150);
});

test('JSON and CSV exports carry the poses at full precision', () => {
  const path = ToolPath.example(5);
  const json = JSON.parse(path.export('json'));
  assert.equal(json.poses.length, 5);
  assert.deepEqual(json.poses[2].tip, [...path.tips().subarray(6, 9)]);
  assert.deepEqual(json.poses[2].axis, [...path.axes().subarray(6, 9)]);
  assert.equal(json.tool.end, 'ball');
  const rows = path.export('csv').trim().split('\n');
  assert.match(rows[0], /^# ruledlab tool path/);
  assert.equal(rows[1], 'tip_x,tip_y,tip_z,axis_i,axis_j,axis_k');
  assert.deepEqual(rows[4].split(',').map(Number), [...path.tips().subarray(6, 9), ...path.axes().subarray(6, 9)]);
});

test('G-code round trip through an independent JS inverse of the A–C kinematics', () => {
  const path = ToolPath.example(6).refine({ steps: 1 });
  const scale = 10;
  const g = path.export('gcode', { feed: 900, scale, clearance: 3 });
  assert.match(g, /table-table 5-axis/);
  const moves = g.split('\n').filter((l) => l.startsWith('G1 '));
  assert.equal(moves.length, path.length);
  const [tips, axes] = [path.tips(), path.axes()];
  const rad = Math.PI / 180;
  moves.forEach((line, i) => {
    const v = Object.fromEntries(
      line
        .split(' ')
        .slice(1)
        .map((w) => [w[0], Number(w.slice(1))]),
    );
    assert.equal(v.F, 900);
    const [A, C] = [v.A * rad, v.C * rad];
    // R = Rx(A) Rz(C); invert: Rz(−C) Rx(−A)
    const rx = ([x, y, z]) => [x, y * Math.cos(A) + z * Math.sin(A), -y * Math.sin(A) + z * Math.cos(A)];
    const rz = ([x, y, z]) => [x * Math.cos(C) + y * Math.sin(C), -x * Math.sin(C) + y * Math.cos(C), z];
    const tip = rz(rx([v.X, v.Y, v.Z])).map((x) => x / scale);
    const axis = rz(rx([0, 0, 1]));
    for (let k = 0; k < 3; k++) {
      assert.ok(Math.abs(tip[k] - tips[3 * i + k]) < 2e-6, `pose ${i} tip`);
      assert.ok(Math.abs(axis[k] - axes[3 * i + k]) < 1e-7, `pose ${i} axis`);
    }
  });
});

test('bad input throws clear Errors', () => {
  const seg = new Float64Array([0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0, 1]);
  const cases = [
    [() => ToolPath.fromSegments(seg, { radius: 0, length: 1 }), /the tool radius must be a positive number, got 0/],
    [() => ToolPath.fromSegments(seg, { radius: -2, length: 1 }), /got -2/],
    [() => ToolPath.fromSegments(seg, { radius: 0.1 }), /tool.length \(the tool length\) is required/],
    [() => ToolPath.fromSegments(seg), /tool is required/],
    [
      () => ToolPath.fromSegments(seg, { radius: 0.1, length: 1, end: 'bull' }),
      /tool.end: unknown value "bull", expected "ball" or "flat"/,
    ],
    [
      () => ToolPath.fromSegments(new Float64Array([0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1]), { radius: 0.1, length: 1 }),
      /tool axis 0 has zero length/,
    ],
    [
      () =>
        ToolPath.fromSegments(
          seg.map((x, i) => (i === 4 ? Infinity : x)),
          { radius: 0.1, length: 1 },
        ),
      /is inf/,
    ],
    [() => ToolPath.example(1), /count must be an integer from 2/],
    [() => ToolPath.example().refine({ scheme: 'bezier', closed: true }), /must be false|open/],
    [() => ToolPath.example().export('step'), /format must be "json", "csv" or "gcode"/],
    [() => ToolPath.example().export('gcode', { feed: -1 }), /feed: must be a positive number, got -1/],
    [() => ToolPath.example().export('json', { feed: 100 }), /apply to the "gcode" format only/],
  ];
  for (const [call, message] of cases) {
    assert.throws(call, (e) => e instanceof Error && message.test(e.message), String(message));
  }
  const ok = ToolPath.fromSegments(seg, { radius: 0.1, length: 1, end: 'flat' });
  assert.equal(ok.length, 2);
});
