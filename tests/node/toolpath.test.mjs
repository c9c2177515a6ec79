// Example 6 through the package: ToolPath, refinement, quality, exports, G-code round trip.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab, { cam } from './load.mjs';
import { niceTicks, tickText } from '../../www/diagrams/plot.js';

const { detectImport } = ruledlab;
const { ToolPath, importToolPoses, importTarget, optimisePoses } = cam;

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
  assert.throws(() => importToolPoses('0,0,0,0,0,1\n1,0,0,0,0,0'), /line 2: pose 1 has a zero tool axis/);
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

test('a job: units, tool, feeds, tolerances, stock and pole cone in the program and its numbers', () => {
  const path = ToolPath.example(7, { radius: 0.3, length: 2, end: 'flat' }).refine({ steps: 2 });
  const r = path.post({
    machine: 'head-head-ac',
    mode: 'tcp',
    units: 'inch',
    scale: 0.4,
    feed: 40,
    spindle: 12000,
    direction: 'ccw',
    coolant: 'mist',
    tolerance: 0.0005,
    angularTolerance: 0.2,
    gauge: 3,
    holder: { radius: 0.8, length: 1 },
    stock: [
      [-1, -1, -1],
      [4, 1, 0.5],
    ],
    clearance: 0.2,
    poleCone: 2,
    input: { stride: 4, lines: [2, 3, 4, 5, 6, 7, 8] },
  });
  assert.match(r.text, /^\(ruledlab tool path: /);
  assert.match(r.text, /\nG20 G90 G94/);
  // the header's long comments wrap onto lines of their own
  const header = r.text.replaceAll(')\n(  ', ' ');
  assert.match(
    header,
    /\(tool 1: flat end, radius 0\.1200 inch, length 0\.8000 inch, gauge length 3\.0000 inch, holder radius 0\.8000 length 1\.0000 inch\)/,
  );
  assert.match(header, /\(spindle 12000 1\/min counter-clockwise <M4>, coolant mist <M7>\)/);
  assert.match(r.text, /\nS12000 M4\n/);
  assert.match(r.text, /\nG64 P0\.0005 Q0\n/);
  assert.match(r.text, /\nM68 E3 Q1\nM66 E0 L0\n/);
  assert.equal(r.units, 'inch');
  assert.deepEqual(r.letters, ['X', 'Y', 'Z', 'C', 'A']);
  assert.equal(r.axes.length, 5 * r.poses);
  assert.equal(r.blockMinutes.length, r.poses - 1);
  assert.equal(r.blockRotarySpeed.length, 2 * (r.poses - 1));
  assert.equal(r.blockLimit.length, r.poses - 1);
  assert.ok(r.blockFeed.every((f) => f <= 40 + 1e-9));
  assert.equal(r.adjusted.length, r.poses);
  assert.deepEqual(r.stock, [
    [-1, -1, -1],
    [4, 1, 0.5],
  ]);
  assert.ok(Array.isArray(r.warnings) && Array.isArray(r.unwinds));
  // an unknown key in a machine description at any depth: its path, and the key meant
  const machine = ToolPath.machine('table-table-ac');
  const bad = { ...machine, rotary: [{ ...machine.rotary[0], maxx: 100 }, machine.rotary[1]] };
  assert.throws(
    () => path.export('gcode', { machine: bad }),
    /machine\.rotary\[0\]\.maxx: unknown key; did you mean max\?/,
  );
  const pivot = { ...machine, rotary: [machine.rotary[0], { ...machine.rotary[1], pviot: [0, 0, 0] }] };
  assert.throws(
    () => path.export('gcode', { machine: pivot }),
    /machine\.rotary\[1\]\.pviot: unknown key; did you mean pivot\?/,
  );
  assert.throws(
    () => path.export('gcode', { machine: { ...machine, partzero: [0, 0, 0] } }),
    /did you mean partZero\?/,
  );
  assert.throws(() => path.export('gcode', { holder: { radius: 1, lenght: 2 } }), /unknown option "holder\.lenght"/);
  // speed and acceleration limits in a description slow the blocks
  const slow = { ...machine, rotary: machine.rotary.map((a) => ({ ...a, speed: 100 })) };
  const s = path.post({ machine: slow, scale: 10 });
  assert.ok(Array.from(s.blockLimit).some((l) => l === 1));
  assert.ok(s.blockRotarySpeed.every((v) => v <= 100 + 1e-9));
  assert.ok(s.warnings.some((w) => w.reason === 'warn-slowed'));
});

test('errors and warnings name the input pose and its line; the progress of a post is told', () => {
  const text = 'x,y,z,i,j,k\n0,0,0,0,0,1\n10,0,0,0,0,1\n10,0,0,0,0,1\n20,0,0,0,-0.99,0.14\n';
  const got = importToolPoses(text);
  assert.deepEqual(Array.from(got.lines), [2, 3, 4, 5]);
  const path = ToolPath.fromPoses(got.poses, { radius: 3, length: 30 });
  const r = path.post({ machine: 'table-table-bc', input: { stride: 1, lines: Array.from(got.lines) } });
  const dup = r.warnings.find((w) => w.reason === 'warn-duplicate-pose');
  assert.deepEqual([dup?.pose, dup?.line], [2, 4]);
  assert.match(dup?.message ?? '', /pose 2 repeats pose 1: no block written for it \(line 4\)/);
  /** @type {number[]} */
  const seen = [];
  path.post({ machine: 'table-table-ac', scale: 1 }, (/** @type {number} */ f) => seen.push(f));
  assert.ok(seen.length >= 3 && seen.at(-1) === 1 && seen.every((f, i) => i === 0 || f >= seen[i - 1]), String(seen));
  // a pose beyond A's limits, refined by midpoints to 4 poses a pose: the input's pose 1, its line 3
  const far = ToolPath.fromPoses([0, 0, 0, 0, 0.2, 1, 1, 0, 0, 0, -0.766, -0.643, 2, 0, 0, 0, 0, 1], {
    radius: 0.1,
    length: 1,
  });
  assert.throws(
    () => far.refine({ scheme: 'bspline', degree: 1, steps: 2 }).post({ input: { stride: 4, lines: [2, 3, 4] } }),
    (e) =>
      /** @type {any} */ (e).details.index === 1 &&
      /** @type {any} */ (e).details.line === 3 &&
      /\(line 3\)$/.test(String(/** @type {any} */ (e).message)),
  );
});

test('CAM tables, rotary angles for a machine, units, target curves and the deviation from them', () => {
  assert.equal(detectImport('X,Y,Z,I,J,K\n0,0,0,0,0,1\n'), 'poses');
  assert.equal(detectImport('# machine: head-head-ac\nx y z a b c\n0 0 0 0 0 0\n'), 'poses');
  assert.equal(detectImport('x,y,z\n0,0,0\n1,0,0\n'), 'target');
  assert.equal(detectImport('{"points": [[0, 0, 0], [1, 0, 0]]}'), 'target');
  const angles = importToolPoses('x,y,z,a,c\n0,0,0,0,0\n1,0,0,30,90\n', undefined, { machine: 'table-table-ac' });
  assert.equal(angles.machine, 'table-table-ac');
  assert.ok(Math.abs(Math.hypot(...angles.axes.subarray(3, 6)) - 1) < 1e-15);
  assert.throws(() => importToolPoses('x,y,z,a,c\n0,0,0,0,0\n1,0,0,30,90\n'), /name the machine/);
  const inch = importToolPoses('# units: inch\n0,0,0,0,0,1\n1,0,0,0,0,1\n');
  assert.equal(inch.units, 'inch');
  assert.throws(
    () => importToolPoses('0,0,0,0,0,1\n1,0,0,0,1\n'),
    /line 2, column 10: expected 6 numbers for a pose \(tip x, y, z and tool axis i, j, k\), found 5/,
  );
  const target = importTarget('# units: mm\nx;y;z\n0;0;-1\n1,5;0;-1\n');
  assert.deepEqual(Array.from(target.points), [0, 0, -1, 1.5, 0, -1]);
  assert.equal(target.units, 'mm');
  // a ball of radius 1 whose centre runs along z = 1 over x from 0 to 3: a target line at z = −1 is
  // 2 from the centres, 1 from the ball
  const path = ToolPath.fromPoses([0, 0, 0, 0, 0, 1, 3, 0, 0, 0, 0, 1], { radius: 1, length: 5 });
  const d = path.envelopeDeviation([0.5, 0, -1, 1.5, 0, -1, 2.5, 0, -1, 1.5, 0, 0.5]);
  assert.deepEqual(
    Array.from(d.points).map((x) => Math.round(x * 1e12) / 1e12),
    [1, 1, 1, -0.5],
  );
  assert.equal(d.worst, 0);
  assert.equal(d.perPose.length, 2);
  assert.deepEqual(Array.from(d.worstPoint), [0.5, 0, -1]);
});

test('the plot’s ticks: 1, 2 or 5 times a power of ten, covering the values, written with the language’s marks', () => {
  const at = (/** @type {number} */ lo, /** @type {number} */ hi) => niceTicks(lo, hi);
  assert.deepEqual(at(-0.158, 0.141), { values: [-0.2, -0.1, 0, 0.1, 0.2], step: 0.1 });
  assert.deepEqual(at(-8.3, 170), { values: [-50, 0, 50, 100, 150, 200], step: 50 });
  assert.deepEqual(at(0, 0).values.length > 1, true, 'an empty range still has two ticks');
  for (const [lo, hi] of [
    [-3e-5, 7e-4],
    [1, 1.0001],
    [-1234, -17],
  ]) {
    const { values, step } = at(lo, hi);
    assert.ok(values[0] <= lo && values[values.length - 1] >= hi && values.length <= 7, `${lo}..${hi}`);
    assert.ok(
      [1, 2, 5].some((m) => Math.abs(step / 10 ** Math.floor(Math.log10(step)) - m) < 1e-9),
      `step ${step}`,
    );
  }
  assert.equal(tickText(-0.1, 0.1), '−0.1');
  assert.equal(tickText(0.30000000000000004, 0.1, true), '0,3');
  assert.equal(tickText(-1e-17, 0.05), '0.00');
  assert.equal(tickText(150, 50), '150');
});

test('post() measures the program as posted against a target, in the program’s units, and the header says it', () => {
  // a ball of radius 1 along x at a constant vertical axis: its centre on z = 1, so points at z = −1
  // are 1 from the swept ball (material left) and a point at z = 0.5 under the path is 0.5 inside
  // it (a gouge); the approach and retract come down and go up the axis at the ends, away from them
  const path = ToolPath.fromPoses([0, 0, 0, 0, 0, 1, 10, 0, 0, 0, 0, 1], { radius: 1, length: 5 });
  const target = [2, 0, -1, 8, 0, -1, 5, 0, 0.5];
  for (const [units, word, places] of [
    ['mm', 'mm', 4],
    ['inch', 'inch', 5],
  ]) {
    for (const [dialect, mode] of [
      ['linuxcnc', 'machine'],
      ['heidenhain', 'tcp'],
      ['sinumerik', 'tcp'],
    ]) {
      const r = path.post({ dialect, mode, units, target, clearance: 0.2, tolerance: 0.001 });
      const d = r.deviation;
      assert.ok(d, `${units} ${dialect}`);
      assert.ok(Math.abs(d.gouge + 0.5) < 1e-9 && Math.abs(d.leave - 1) < 1e-9, `${d.gouge} ${d.leave}`);
      assert.ok(Math.abs(d.rms - Math.sqrt(2.25 / 3)) < 1e-9);
      assert.deepEqual([d.worst, Array.from(d.points).map((x) => Math.round(x * 1e9) / 1e9)], [0, [1, 1, -0.5]]);
      assert.deepEqual(d.at, [2, 0, -1]);
      const g = (-0.5).toFixed(places);
      assert.ok(
        r.text.includes(
          `deviation of the program as posted from the target, 3 points: gouge ${g} ${word}, leave ${(1).toFixed(places)} ${word}`,
        ),
        r.text.slice(0, 2000),
      );
    }
  }
  // no target, no deviation; a target of no points is refused by name
  assert.equal(path.post({}).deviation, undefined);
  assert.throws(
    () => path.post({ target: [] }),
    (e) => e.details?.option === 'target' || /target/.test(e.message),
  );
});

test('inch programs default to 0.0004 in and 0.2 in; units other than mm and inch are refused with the list', () => {
  const path = ToolPath.fromPoses([0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 0, 1], { radius: 0.1, length: 1 });
  const inch = path.post({ units: 'inch' });
  assert.ok(Math.abs(inch.tolerance - 0.0004) < 1e-15, `${inch.tolerance}`);
  assert.match(inch.text, /tolerance chordal 0\.0004 inch/);
  assert.match(inch.text, /clearance 0\.2000 inch along the/);
  const mm = path.post({});
  assert.equal(mm.tolerance, 0.01);
  assert.match(mm.text, /clearance 5\.0000 mm along the/);
  for (const said of ['imperial', 'furlong']) {
    assert.throws(() => importTarget(`# units: ${said}\n0,0,0\n1,1,1\n`), /are not known: write mm or inch/);
    assert.throws(
      () => importToolPoses(`# units: ${said}\n0,0,0,0,0,1\n1,0,0,0,0,1\n`),
      /are not known: write mm or inch/,
    );
  }
  assert.throws(() => importTarget('{"units": "furlong", "points": [[0, 0, 0], [1, 1, 1]]}'), /"furlong"/);
  assert.equal(importTarget('# units: inches\n0,0,0\n1,1,1\n').units, 'inch');
});

test('optimisePoses brings poses moved off a plane back onto it, with progress, and refuses bad input by code', () => {
  // the plane y = 0, 11 vertical rulings over x ∈ [0, 10]; a flat end of radius ½ stands ½ off it
  // at y = ½: here 0.2 farther and tilted, so that the target leaves up to about 1; optimised, a
  // few thousandths
  const poses = [];
  for (let k = 0; k <= 10; k++) {
    const tilt = 0.05 + 0.02 * Math.sin(k);
    poses.push(k, 0.7 + 0.05 * Math.sin(k), 0, tilt, 0.08, 1);
  }
  const tool = { radius: 0.5, length: 12, end: /** @type {'flat'} */ ('flat') };
  const path = ToolPath.fromPoses(poses, tool);
  const targets = [];
  for (let i = 0; i < 40; i++) for (let j = 1; j <= 9; j++) targets.push(0.125 + 0.25 * i, 0, j);
  /** @type {number[]} */
  const shares = [];
  const r = optimisePoses(path, targets, { rounds: 100 }, (f) => shares.push(f));
  assert.ok(r.before.largest > 0.5, `before ${r.before.largest}`);
  // the fairness holds the uneven push back against its unevenness: 2.8·10⁻³ left (measured)
  assert.ok(Math.abs(r.after.largest) < 5e-3, `after ${r.after.largest} in ${r.rounds} rounds`);
  assert.ok(r.energy[1] < 1e-4 * r.energy[0]);
  assert.equal(r.poses.length, poses.length);
  assert.deepEqual([shares[0], shares[shares.length - 1]], [0, 1]);
  assert.ok(shares.every((f, i) => i === 0 || f >= shares[i - 1]));
  // the poses make the optimised path, whose own sweep is what `after` says
  const optimised = ToolPath.fromPoses(r.poses, tool);
  const d = optimised.envelopeDeviation(targets);
  assert.equal(d.worstDeviation, r.after.largest);
  for (const [args, code] of [
    [[path, []], 'too-small'],
    [[path, [0, 0, 0, 0, 0, Number.NaN]], 'not-finite'],
    [[path, targets, { fairness: -1 }], 'invalid-argument'],
    [[path, targets, { rounds: 1.5 }], 'invalid-argument'],
    [[path, targets, { round: 3 }], 'invalid-argument'],
  ]) {
    assert.throws(
      () => optimisePoses(.../** @type {[any, any, any?]} */ (args)),
      (e) => e instanceof Error && /** @type {any} */ (e).code === code,
      `${JSON.stringify(args.slice(2))} ${code}`,
    );
  }
  optimised.free();
  path.free();
});

test('rulingAligned: the tool along each ruling, its radius off the part along the normal, on the side asked', () => {
  // the plane y = 0: vertical rulings over x ∈ [0, 4]; a ball end of radius ½
  const rulings = [];
  for (let k = 0; k <= 4; k++) rulings.push(k, 0, 0, k, 0, 10);
  const tool = { radius: 0.5, length: 12, end: /** @type {'ball'} */ ('ball') };
  for (const side of /** @type {const} */ ([1, -1])) {
    const path = ToolPath.rulingAligned(rulings, tool, side);
    const [tips, axes] = [path.tips(), path.axes()];
    for (let k = 0; k <= 4; k++) {
      assert.deepEqual([tips[3 * k], Math.abs(tips[3 * k + 1]), tips[3 * k + 2]], [k, 0.5, 0]);
      assert.deepEqual([...axes.subarray(3 * k, 3 * k + 3)], [0, 0, 1]);
    }
    // the two sides stand opposite
    if (side === 1) assert.ok(tips[1] !== 0);
    path.free();
  }
  const a = ToolPath.rulingAligned(rulings, tool, 1);
  const b = ToolPath.rulingAligned(rulings, tool, -1);
  assert.equal(a.tips()[1], -b.tips()[1]);
  a.free();
  b.free();
  for (const [args, code] of [
    [[rulings, tool, 0], 'invalid-argument'],
    [[rulings.slice(0, 6), tool, 1], 'too-small'],
    [[[0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1], tool, 1], 'degenerate'],
    [[rulings, { radius: -1, length: 2 }, 1], 'invalid-argument'],
  ]) {
    assert.throws(
      () => ToolPath.rulingAligned(.../** @type {[any, any, any]} */ (args)),
      (e) => e instanceof Error && /** @type {any} */ (e).code === code,
      `${JSON.stringify(args.slice(1))} ${code}`,
    );
  }
});

test('a progress callback that is not a function is refused with a code; one that is hears fractions up to 1', () => {
  const path = cam.ToolPath.example(7).refine({ steps: 1 });
  try {
    assert.throws(
      () => path.post({}, /** @type {any} */ (5)),
      (e) => /** @type {any} */ (e).code === 'invalid-argument' && /onProgress must be a function/.test(String(e)),
    );
    /** @type {number[]} */
    const heard = [];
    path.post({}, (f) => heard.push(f));
    assert.ok(heard.length > 0 && heard.every((f) => f >= 0 && f <= 1));
  } finally {
    path.free();
  }
});
