// The built package's JS API, in Node: values, shapes, and every bad-input case.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import ruledlab from './load.mjs';

const { RuledSurface, AnalyticSurface, AnalyticCongruence } = ruledlab;
const GOOD = new Float64Array([0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 1, 1, 2]);
const near = (a, b, tol = 1e-12) => Math.abs(a - b) <= tol * Math.max(1, Math.abs(a), Math.abs(b));

test('fromSegments, length, segments and segmentsF32 round-trip', () => {
  const s = RuledSurface.fromSegments(GOOD);
  assert.equal(s.length, 3);
  assert.deepEqual(s.segments(), GOOD);
  assert.ok(s.segmentsF32() instanceof Float32Array);
  assert.deepEqual([...s.segmentsF32()], [...GOOD]);
  s.free();
});

test('coordinates come as Float64Array, Float32Array or a plain array of numbers', () => {
  for (const input of [[...GOOD], new Float32Array(GOOD)]) {
    const s = RuledSurface.fromSegments(input);
    try {
      assert.deepEqual(s.segments(), GOOD);
    } finally {
      s.free();
    }
  }
  // the f32 buffers the core hands out go back in as they are (f32 → f64 is exact)
  const a = RuledSurface.fromSegments(new Float64Array([0, 0, 0, 1, 0, 0, 0.1, 0, 1, 0.1, 1, 1, 0, 0, 2, 1, 1, 2.3]));
  const b = RuledSurface.fromSegments(a.segmentsF32());
  try {
    assert.deepEqual(b.segments(), Float64Array.from(a.segmentsF32()));
  } finally {
    a.free();
    b.free();
  }
});

test('invariants: typed arrays of the documented lengths and the right values', () => {
  // rulings along x, then along y one unit higher: φ = π/2, h = 1, footpoints on the z-axis
  const s = RuledSurface.fromSegments(GOOD);
  const inv = s.invariants();
  const lengths = {
    angle: 2,
    distance: 2,
    distribution: 2,
    footpoints: 12,
    centralNormal: 6,
    striction: 3,
    distributionMean: 1,
    perpendicularMidpoints: 6,
    parallel: 2,
  };
  for (const [k, n] of Object.entries(lengths)) {
    assert.equal(inv[k].length, n, k);
    assert.ok(k === 'parallel' ? inv[k] instanceof Uint8Array : inv[k] instanceof Float64Array, k);
  }
  assert.ok(near(inv.angle[0], Math.PI / 2));
  assert.ok(near(inv.distance[0], 1));
  assert.ok(near(inv.distribution[0], 2 / Math.PI));
  assert.deepEqual(
    [...inv.footpoints.subarray(0, 6)].map((x) => Math.round(x * 1e12) / 1e12),
    [0, 0, 0, 0, 0, 1],
  );
  assert.deepEqual([...inv.parallel], [0, 0]);
  s.free();
});

test('parallel pairs are flagged and NaN, not plausible numbers', () => {
  const s = RuledSurface.fromSegments(new Float64Array([0, 0, 0, 0, 0, 1, 3, 4, 0, 3, 4, 2]));
  const inv = s.invariants();
  assert.equal(inv.parallel[0], 1);
  assert.ok(near(inv.distance[0], 5));
  assert.ok(Number.isNaN(inv.distribution[0]) && Number.isNaN(inv.footpoints[0]) && Number.isNaN(inv.centralNormal[0]));
  s.free();
});

test('wasm computes the same invariants as the native build (1e-12)', () => {
  // npm test writes the native numbers in its native step (cargo would wait here for the build
  // directory while the wasm lane holds it); run alone, the test asks cargo itself
  const written = process.env.RULEDLAB_NATIVE_INVARIANTS;
  const native = JSON.parse(
    written
      ? readFileSync(written, 'utf8')
      : execFileSync('cargo', ['run', '-q', '--example', 'dump_invariants'], { encoding: 'utf8' }),
  );
  const q = AnalyticSurface.byName('quartic');
  const s = q.sample(50);
  const inv = s.invariants();
  for (const [k, values] of Object.entries(native)) {
    assert.equal(inv[k].length, values.length, k);
    values.forEach((v, i) => {
      assert.ok(near(inv[k][i], v), `${k}[${i}]: wasm ${inv[k][i]} vs native ${v}`);
    });
  }
  s.free();
  q.free();
});

test('analytic surfaces: list, exact values, sampling and the convergence study', () => {
  const list = AnalyticSurface.list();
  assert.deepEqual(
    list.map((s) => s.name),
    [
      'hyperboloid',
      'quartic',
      'helicoid',
      'helical',
      'helical-orthogonal',
      'pluecker-conoid',
      'hyperbolic-paraboloid',
      'cone',
      'cylinder',
      'helix-tangent',
    ],
  );
  // each entry is one plain object with exactly the fields of AnalyticSurfaceInfo (a
  // CatalogueEntry and `closed`), in the order the declaration gives them
  for (const entry of list) {
    assert.deepEqual(Object.keys(entry), ['name', 'title', 'uMin', 'uMax', 'vMin', 'vMax', 'closed']);
    assert.equal(Object.getPrototypeOf(entry), Object.prototype);
    assert.equal(typeof entry.closed, 'boolean');
    assert.ok(entry.uMin < entry.uMax && entry.vMin < entry.vMax, entry.name);
  }
  assert.deepEqual(
    list.filter((s) => s.closed).map((s) => s.name),
    ['hyperboloid', 'pluecker-conoid', 'cone', 'cylinder'],
  );
  const congruences = AnalyticCongruence.list();
  for (const entry of congruences) {
    const keys = ['name', 'title', 'uMin', 'uMax', 'vMin', 'vMax', 'rows', 'cols'];
    assert.deepEqual(Object.keys(entry), keys);
    assert.ok(Number.isInteger(entry.rows) && Number.isInteger(entry.cols), entry.name);
  }
  const helicoid = AnalyticSurface.byName('helicoid');
  assert.equal(helicoid.name, 'helicoid');
  const s = helicoid.sample(20, { uMin: 0, uMax: 2 });
  for (const d of s.invariants().distribution) assert.ok(near(d, 0.5), `δ = ${d}`);
  assert.deepEqual([...helicoid.distribution(new Float64Array([0.3, 1]))], [0.5, 0.5]);
  const conoid = AnalyticSurface.byName('pluecker-conoid');
  const st = conoid.striction(new Float64Array([0.25]));
  assert.ok(near(st[2], Math.sin(0.5)) && st[0] === 0 && st[1] === 0);
  assert.ok(
    AnalyticSurface.byName('cylinder')
      .striction(new Float64Array([0.1]))
      .every(Number.isNaN),
  );
  const study = AnalyticSurface.byName('hyperboloid').convergence({ u: 0.7, h0: 0.1, levels: 7 });
  const order = (name) => study.series.find((x) => x.name === name).orders.at(-1);
  assert.ok(Math.abs(order('footpoint') - 1) < 0.1, `footpoint order ${order('footpoint')}`);
  assert.ok(Math.abs(order('midpoint') - 2) < 0.1, `midpoint order ${order('midpoint')}`);
  assert.ok(Math.abs(order('distribution') - 1) < 0.1);
  assert.ok(Math.abs(order('distributionMean') - 2) < 0.1);
  assert.equal(study.steps.length, 7);
});

test('every bad input throws an Error that says what is wrong, and the module keeps working', () => {
  const cases = [
    [
      () => RuledSurface.fromSegments([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, {}]),
      /coords\[11\] must be a number, got an object/,
    ],
    [
      () => RuledSurface.fromSegments('0,0,0'),
      /must be a Float64Array, Float32Array or array of numbers, got a string/,
    ],
    [() => RuledSurface.fromSegments(new Uint8Array(12)), /got a Uint8Array/],
    [() => RuledSurface.fromSegments(), /got undefined/],
    [() => RuledSurface.fromSegments(null), /got null/],
    [() => RuledSurface.fromSegments(new Float32Array(12)), /ruling 0 has zero length/],
    [() => RuledSurface.fromSegments(new Float64Array(13)), /length 13 is not a multiple of 6/],
    [() => RuledSurface.fromSegments(new Float64Array(6)), /rulings: got 1, need at least 2/],
    [() => RuledSurface.fromSegments(new Float64Array(0)), /rulings: got 0, need at least 2/],
    [() => RuledSurface.fromSegments(GOOD.map((x, i) => (i === 7 ? NaN : x))), /coordinate 7 \(ruling 1, a.y\) is NaN/],
    [
      () => RuledSurface.fromSegments(GOOD.map((x, i) => (i === 3 ? Infinity : x))),
      /coordinate 3 \(ruling 0, b.x\) is inf/,
    ],
    [() => RuledSurface.fromSegments(GOOD.map((x, i) => (i === 3 ? -Infinity : x))), /is -inf/],
    [() => RuledSurface.fromSegments(GOOD.map((x, i) => (i === 4 ? 1e300 : x))), /magnitudes above 1e150/],
    [() => RuledSurface.fromSegments(new Float64Array(12)), /ruling 0 has zero length/],
    [
      () => RuledSurface.fromSegments(new Float64Array((1 << 22) * 6 + 6)),
      /rulings: 4194305 exceeds the limit of 4194304/,
    ],
    [() => AnalyticSurface.byName('torus'), /unknown surface "torus"; known: hyperboloid/],
    [() => AnalyticSurface.byName(7), /name must be a string, got a number/],
    [() => AnalyticSurface.byName('cone').sample(1), /count must be an integer from 2/],
    [() => AnalyticSurface.byName('cone').sample('ten'), /count must be an integer from 2 to \d+, got a string/],
    [() => AnalyticSurface.byName('cone').sample(1e9), /got 1000000000/],
    [() => AnalyticSurface.byName('cone').sample(5, { vMin: 1, vMax: 1 }), /vMax: must differ from vMin/],
    [() => AnalyticSurface.byName('cone').sample(5, { uMin: NaN }), /options.uMin must be a finite number, got NaN/],
    [() => AnalyticSurface.byName('cone').sample(5, { steps: 3 }), /unknown option "steps"/],
    [
      () => AnalyticSurface.byName('cone').sample(5, [1, 2]),
      /options must be an object \{ uMin, uMax, vMin, vMax, closed \}, got an array/,
    ],
    [() => AnalyticSurface.byName('cone').striction([0.5, 'a']), /u\[1\] must be a number, got a string/],
    [() => AnalyticSurface.byName('cone').distribution(new Float64Array([Infinity])), /every u must be finite/],
    [() => AnalyticSurface.byName('cylinder').convergence(), /no striction point/],
    [
      () => AnalyticSurface.byName('cone').convergence({ levels: 99 }),
      /options.levels must be an integer from 2 to 20, got 99/,
    ],
    [() => AnalyticSurface.byName('cone').convergence({ h0: 0 }), /h0: must be in \(0, 1\], got 0/],
  ];
  for (const [call, message] of cases) {
    assert.throws(call, (e) => e instanceof Error && message.test(e.message), String(message));
    // the module is still fine after every error
    const s = RuledSurface.fromSegments(GOOD);
    assert.equal(s.invariants().angle.length, 2);
    s.free();
  }
});

test('using a freed object throws an Error instead of trapping', () => {
  const s = RuledSurface.fromSegments(GOOD);
  s.free();
  assert.throws(() => s.invariants(), Error);
  assert.equal(RuledSurface.fromSegments(GOOD).length, 3);
});

test('the TypeScript declarations type the results', () => {
  const dts = readFileSync(new URL('../../pkg/ruledlab.d.ts', import.meta.url), 'utf8');
  assert.match(dts, /export interface Invariants \{/);
  assert.match(dts, /invariants\(options\?: InvariantsOptions( \| null)?\): Invariants;/);
  assert.match(dts, /static fromSegments\(coords: Float64Array \| Float32Array \| number\[\]\): RuledSurface;/);
  // trailing options are optional (tsc --strict accepts calls without them)
  for (const signature of [
    'convergence(opts?: ConvergenceOptions): ConvergenceStudy;',
    'sample(count: number, opts?: SampleOptions): RuledSurface;',
    'importSegments(text: string, format?: "csv" | "json"): ImportedSegments;',
    'grid(rows?: number, cols?: number, reach?: number): LineCongruence;',
  ])
    assert.ok(dts.includes(signature), signature);
  // the CAM module's (ruledlab/cam)
  const camDts = readFileSync(new URL('../../pkg/cam/ruledlab_cam.d.ts', import.meta.url), 'utf8');
  for (const signature of [
    'refine(options?: Partial<SubdivideOptions>): ToolPath;',
    'export(format: "json" | "csv" | "gcode", options?: GcodeOptions): string;',
  ])
    assert.ok(camDts.includes(signature), signature);
  // the teaching module declares nothing of CAM
  assert.doesNotMatch(dts, /class ToolPath|GcodeOptions|importToolPoses/);
  // the public API (before wasm-bindgen's internal InitOutput table) has no `any` type
  for (const text of [dts, camDts]) {
    const api = text.slice(0, text.indexOf('export type InitInput'));
    assert.doesNotMatch(api, /[:<,|(]\s*any\b|\bany\[\]/);
  }
});

test('invariantsInPlace: views of wasm memory with the numbers of invariants(), reused in place, detached (never wrong) once memory grows', () => {
  const a = ruledlab.AnalyticSurface.byName('quartic');
  const s1 = a.sample(40);
  const s2 = a.sample(40, { vMin: -2, vMax: 0.5 });
  const buffer = new ruledlab.InvariantsBuffer();
  try {
    assert.equal(buffer.angle.length, 0);
    s1.invariantsInPlace(buffer);
    const fresh = s1.invariants();
    for (const [k, v] of Object.entries(fresh)) assert.deepEqual(buffer[k], v, k);
    const first = buffer.footpoints;
    // the next computation of the same size writes to the same place
    s2.invariantsInPlace(buffer);
    assert.equal(buffer.footpoints.byteOffset, first.byteOffset);
    assert.deepEqual(first, s2.invariants().footpoints, 'an old view shows the new numbers');
    // closed surfaces too
    const ring = a.sample(12, { uMin: 0, uMax: 2 * Math.PI, closed: true });
    ring.invariantsInPlace(buffer, { closed: true });
    assert.deepEqual(buffer.striction, ring.invariants({ closed: true }).striction);
    ring.free();
    // memory growth detaches every view: it then reads as empty, never as other numbers
    const view = buffer.striction;
    assert.ok(view.length > 0);
    const rulings = Math.ceil(view.buffer.byteLength / 48) + 1000;
    const big = a.sample(Math.min(rulings, 4_000_000));
    assert.equal(view.length, 0, 'detached by the growth');
    assert.equal(buffer.striction.length, 3 * 12, 'a fresh view reads the numbers again');
    big.free();
    assert.throws(
      () => s1.invariantsInPlace(buffer, { open: true }),
      /invariantsInPlace: unknown option "open"; known options: closed/,
    );
    assert.throws(
      () => s1.invariantsInPlace(/** @type {any} */ ({})),
      (e) => e.code === 'invalid-argument',
    );
  } finally {
    buffer.free();
    s1.free();
    s2.free();
    a.free();
  }
});

test('invariants() and invariantsInto, filled a block of pairs at a time, equal the zero-copy views', () => {
  // 10 001 rulings: three blocks and a part, open and closed
  const a = ruledlab.AnalyticSurface.byName('hyperboloid');
  const s = a.sample(10001, { uMin: 0, uMax: 40, closed: false });
  const buffer = new ruledlab.InvariantsBuffer();
  try {
    for (const closed of [false, true]) {
      const fresh = s.invariants({ closed });
      const into = s.invariants({ closed });
      for (const v of Object.values(into)) v.fill(0);
      s.invariantsInto(into, { closed });
      s.invariantsInPlace(buffer, { closed });
      for (const [k, v] of Object.entries(fresh)) {
        const view = /** @type {any} */ (buffer)[k];
        assert.equal(v.length, view.length, k);
        assert.deepEqual(v, view.slice(), `invariants().${k}, closed: ${closed}`);
        assert.deepEqual(/** @type {any} */ (into)[k], v, `invariantsInto: ${k}, closed: ${closed}`);
      }
    }
  } finally {
    buffer.free();
    s.free();
    a.free();
  }
});

test('invariantsInto called again from inside its own copy (an array whose set calls ruledlab) does not panic', () => {
  const a = ruledlab.AnalyticSurface.byName('quartic');
  const s = a.sample(30);
  try {
    const inner = s.invariants();
    let calls = 0;
    class Sneaky extends Float64Array {
      /** @param {ArrayLike<number>} src @param {number} [at] */
      set(src, at) {
        if (calls++ === 0) s.invariantsInto(inner);
        super.set(src, at);
      }
    }
    const out = s.invariants();
    out.angle = new Sneaky(out.angle.length);
    s.invariantsInto(out);
    assert.ok(calls >= 1);
    assert.deepEqual(Array.from(out.angle), Array.from(s.invariants().angle));
    assert.deepEqual(inner.striction, s.invariants().striction);
  } finally {
    s.free();
    a.free();
  }
});

test('invariantsInto refills the arrays of an earlier result without allocating new ones', () => {
  const a = ruledlab.AnalyticSurface.byName('quartic');
  const s1 = a.sample(40);
  const s2 = a.sample(40, { vMin: -2, vMax: 0.5 });
  const out = s1.invariants();
  const arrays = Object.values(out);
  s2.invariantsInto(out);
  const fresh = s2.invariants();
  for (const [k, v] of Object.entries(fresh)) assert.deepEqual(out[k], v, k);
  Object.values(out).forEach((v, i) => {
    assert.equal(v, arrays[i], 'same array objects');
  });
  const small = a.sample(10);
  assert.throws(
    () => small.invariantsInto(out),
    /out.angle must be a typed array of length 9 \(this surface has 10 rulings\)/,
  );
  assert.throws(() => small.invariantsInto(null), /out must be an Invariants object, got null/);
  assert.throws(() => s2.invariantsInto({ ...out, angle: new Float32Array(39) }), /out.angle must be a Float64Array/);
});
