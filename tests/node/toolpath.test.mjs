// Example 6 through the package: ToolPath, refinement, quality, exports, G-code round trip.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab from './load.mjs';

const { ToolPath, importToolPoses, detectImport } = ruledlab;

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

test('G-code: the old options still work, LinuxCNC in machine coordinates on the A-C trunnion by default', () => {
  const path = ToolPath.example(6).refine({ steps: 1 });
  const g = path.export('gcode', { feed: 900, scale: 10, clearance: 3 });
  assert.match(g, /^\(ruledlab tool path: /);
  assert.match(g, /\(machine table-table-ac: A on the table about X/);
  assert.match(g, /\(mode: machine coordinates/);
  assert.match(g, /\nT1 M6\nG43 H1\nS10000 M3\n/);
  assert.match(g, /\nG53 G0 Z400\.0000\nG0 A[-\d.]+ C[-\d.]+\n/);
  assert.match(g, /\nG93 G1 X/);
  assert.ok(g.trimEnd().endsWith('M30'));
  // no nested parentheses or semicolons in comments (rs274: "Unclosed comment found")
  for (const line of g.split('\n')) assert.doesNotMatch(line, /\(.*[(;].*\)/);
});

test('G-code: every dialect, mode and preset; the post reports its linearisation', () => {
  const path = ToolPath.example(7).refine({ steps: 2 });
  for (const machine of ['table-table-ac', 'table-table-bc', 'head-table-bc', 'head-head-ac']) {
    for (const mode of /** @type {const} */ (['tcp', 'machine'])) {
      for (const dialect of /** @type {const} */ (['linuxcnc', 'heidenhain', 'sinumerik'])) {
        const r = path.post({ dialect, mode, machine, scale: 10, tolerance: 0.005 });
        assert.equal(r.poses, path.length + r.inserted);
        assert.equal(r.blockTip.length, r.poses - 1);
        assert.ok(r.after.tip <= 0.005 && r.after.axis <= 0.005, `${machine} ${mode} ${dialect}`);
        assert.ok(Math.max(...r.blockTip, ...r.blockAxis) <= 0.005);
        assert.equal(r.origin[0], 0);
        assert.equal(r.origin[r.poses - 1], path.length - 1);
        assert.equal(r.text, path.export('gcode', { dialect, mode, machine, scale: 10, tolerance: 0.005 }));
      }
    }
  }
  const preset = ToolPath.machine('head-table-bc');
  assert.equal(preset.rotary[0].name, 'B');
  assert.equal(preset.rotary[0].on, 'head');
  // a description of one's own: the preset with another part zero
  const custom = { ...preset, name: 'mine', partZero: [0, 0, 40] };
  assert.match(path.export('gcode', { machine: custom, scale: 10 }), /\(machine mine: B on the head about Y/);
});

test('G-code: a pose beyond the limits is an error with a code naming the pose', () => {
  const seg = new Float64Array([0, 0, 0, 0, 0.2, 1, 1, 0, 0, 1, 0.2, -1]);
  const path = ToolPath.fromSegments(seg, { radius: 0.1, length: 1 });
  assert.throws(
    () => path.export('gcode', { machine: 'table-table-ac' }),
    (e) =>
      e instanceof Error &&
      /** @type {any} */ (e).code === 'unreachable' &&
      /** @type {any} */ (e).details.index === 1 &&
      /pose 1 cannot be reached: A would be/.test(e.message),
  );
});

test('tool poses: imported from CSV and JSON, ruledlab exports round trip with their tool', () => {
  const path = ToolPath.example(5);
  for (const format of /** @type {const} */ (['csv', 'json'])) {
    const text = path.export(format);
    assert.equal(detectImport(text), 'poses');
    const got = importToolPoses(text);
    assert.deepEqual([...got.tips], [...path.tips()]);
    assert.deepEqual([...got.axes], [...path.axes()]);
    assert.deepEqual(got.tool, { radius: 0.25, length: 1.5, end: 'ball' });
    const back = ToolPath.fromPoses(got.poses, got.tool ?? { radius: 1, length: 1 });
    assert.equal(back.export(format), text);
  }
  assert.equal(detectImport('0,0,0,1,0,0\n0,0,1,0,1,1'), 'segments');
  const plain = importToolPoses('x,y,z,i,j,k\n0,0,0,0,0,2\n1,0,0,0,1,1\n');
  assert.deepEqual([...plain.axes.subarray(0, 3)], [0, 0, 1]);
  assert.equal(plain.tool, undefined);
  assert.throws(() => importToolPoses('0,0,0,0,0,1\n1,0,0,0,0,0'), /line 2: pose 1 has a zero axis/);
  const dev = ToolPath.example(7).refine({ steps: 1 }).deviationPerPose(ToolPath.exampleProfile(400));
  assert.equal(dev.length, 13);
  assert.ok(Math.abs(dev[0]) < 1e-3 && Math.max(...dev.map(Math.abs)) < 0.05);
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
    [() => ToolPath.example().export('gcode', { feed: -1 }), /feed: must be a positive number of at most 1e7, got -1/],
    [() => ToolPath.example().export('json', { feed: 100 }), /apply to the "gcode" format only/],
    [
      () => ToolPath.example().export('gcode', { dialect: /** @type {any} */ ('fanuc') }),
      /dialect: unknown value "fanuc", expected one of "linuxcnc", "heidenhain", "sinumerik"/,
    ],
    [() => ToolPath.example().export('gcode', { mode: /** @type {any} */ ('tcpm') }), /expected "tcp" or "machine"/],
    [() => ToolPath.example().export('gcode', { machine: /** @type {any} */ ('hexapod') }), /unknown preset "hexapod"/],
    [() => ToolPath.example().export('gcode', { tolerance: 1e-9 }), /tolerance: must be at least 0.0001/],
    [() => ToolPath.example().export('gcode', { tool: 1.5 }), /tool: must be an integer/],
    [() => ToolPath.example().export('gcode', { spindel: 100 }), /unknown option "spindel"/],
    [
      () => ToolPath.example().export('gcode', { machine: { ...ToolPath.machine('head-head-ac'), travel: 3 } }),
      /machine\.travel must be an array/,
    ],
  ];
  for (const [call, message] of cases) {
    assert.throws(call, (e) => e instanceof Error && message.test(e.message), String(message));
  }
  const ok = ToolPath.fromSegments(seg, { radius: 0.1, length: 1, end: 'flat' });
  assert.equal(ok.length, 2);
});

test('G-code: a rotary axis described without a direction turns as +1, a machine without a name is custom', () => {
  const path = ToolPath.example(7).refine({ steps: 1 });
  const preset = ToolPath.machine('table-table-ac');
  assert.ok(preset.rotary.every((/** @type {{direction: number}} */ r) => r.direction === 1));
  const without = { ...preset, rotary: preset.rotary.map(({ direction, ...rest }) => rest) };
  const options = { dialect: /** @type {const} */ ('linuxcnc'), mode: /** @type {const} */ ('machine'), scale: 10 };
  const gcode = path.export('gcode', { ...options, machine: preset });
  assert.equal(path.export('gcode', { ...options, machine: without }), gcode);
  const reversed = { ...preset, rotary: preset.rotary.map((r) => ({ ...r, direction: -1 })) };
  assert.notEqual(path.export('gcode', { ...options, machine: reversed }), gcode);
  // and one without a name is called "custom"
  const { name, ...unnamed } = preset;
  assert.equal(name, 'table-table-ac');
  assert.match(path.export('gcode', { ...options, machine: unnamed }), /\(machine custom: /);
});
