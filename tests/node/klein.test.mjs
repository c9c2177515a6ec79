// The Klein quadric view through the package (beyond the paper; docs/src/guide/klein.md): the
// shapes of kleinView's buffers, exact answers (a regulus on one conic, a cone torsal at every step
// and its rulings in a plane on M holding no conic, Ω = −h sin φ against the invariants), the
// scene's legend naming a conic only where one is drawn, and coded errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import ruledlab from './load.mjs';
import { SCENES } from '../../www/scenes/index.js';
import { translator } from '../../www/i18n/index.js';
import { legendOf, defaults } from '../../www/scene.js';
import { toScreen, transformPoint } from '../../www/edit/geometry.js';
import { OrbitCamera } from '../../www/camera.js';
import { holdValue } from '../../www/klein-projection.js';

const { AnalyticCongruence, AnalyticSurface, kleinView } = ruledlab;

/** Runs `body` with the objects, freeing them after. */
function using(objects, body) {
  try {
    return body(...objects);
  } finally {
    for (const o of objects) o.free();
  }
}

test('kleinView: the hyperboloid is one conic, Ω = −h sin φ, every point on M', () => {
  using([AnalyticSurface.byName('hyperboloid')], (h) => {
    using([h.sample(24, { uMin: 0, uMax: 2 * Math.PI, closed: true })], (s) => {
      const k = kleinView(s.segments(), { closed: true });
      assert.ok(k.points instanceof Float32Array && k.points.length === 3 * 24);
      assert.equal(k.omega.length, 24);
      assert.equal((k.positive.length + k.negative.length + k.torsal.length) / 6, 24);
      assert.equal(k.torsalSteps, 0);
      assert.ok(k.maxResidual <= 1e-12, `residual ${k.maxResidual}`);
      assert.ok(k.planeDistance < 1e-12, `plane ${k.planeDistance}`);
      assert.equal(k.conic.length, 3 * 64);
      assert.ok(k.outline.length > 0 && k.outline.length % 3 === 0 && k.outline.some(Number.isNaN));
      const inv = s.invariants({ closed: true });
      for (let i = 0; i < 24; i++) {
        const want = -inv.distance[i] * Math.sin(inv.angle[i]);
        assert.ok(Math.abs(k.omega[i] - want) < 1e-14, `${i}: ${k.omega[i]} vs ${want}`);
      }
      // the image of M is the shell between the radii; at 45° the outer one is √2
      assert.ok(Math.abs(k.radii[1] - Math.SQRT2) < 1e-15 && k.radii[0] < 1e-15);
      for (let i = 0; i < k.points.length; i += 3) assert.ok(Math.hypot(...k.points.subarray(i, i + 3)) <= 1.4143);
    });
  });
});

test('kleinView: a cone is torsal at every step, a helical surface lies in a linear complex', () => {
  using([AnalyticSurface.byName('cone')], (c) => {
    using([c.sample(30, { uMin: 0, uMax: 2 * Math.PI, vMin: 0.2, vMax: 1.2, closed: true })], (s) => {
      const k = kleinView(s.segments(), { closed: true, mix: 20, turn: 30, unit: 2 });
      assert.equal(k.torsalSteps, 30);
      assert.equal(k.positive.length + k.negative.length, 0);
      assert.ok(Math.abs(k.leastOmega) < 1e-14);
    });
  });
  using([AnalyticSurface.byName('helical')], (h) => {
    using([h.sample(40)], (s) => {
      const k = kleinView(s.segments());
      assert.ok(k.complexResidual < 1e-10, `complex ${k.complexResidual}`);
      assert.ok(k.planeDistance > 1e-3, 'not a regulus');
    });
  });
});

test('the elliptic cone: its rulings lie in a plane on M, which holds no conic — none drawn, none in the legend', () => {
  using([AnalyticSurface.byName('cone')], (c) => {
    using([c.sample(24, { uMin: 0, uMax: 2 * Math.PI, vMin: 0.2, vMax: 1.2, closed: true })], (s) => {
      const k = kleinView(s.segments(), { closed: true });
      assert.ok(k.planeDistance < 1e-14, `plane ${k.planeDistance}`);
      assert.equal(k.conic.length, 0);
    });
  });
  const { t, format } = translator('en');
  const scene = SCENES.find((x) => x.id === 'klein');
  assert.ok(scene);
  const labels = (/** @type {string} */ surface) => {
    const params = { ...defaults(scene), surface, conic: true };
    const built = scene.create(params, { t, format, lang: 'en' });
    return { labels: legendOf(scene, params, built).map((e) => e.label), text: built.description };
  };
  for (const surface of ['cone', 'helicoid']) {
    const { labels: shown, text } = labels(surface);
    assert.ok(!shown.includes('klein.legend.conic'), `${surface}: ${shown}`);
    assert.match(text, /span no plane cutting M in a conic/);
  }
  assert.ok(labels('hyperboloid').labels.includes('klein.legend.conic'));
});

test('kleinView: wrong options are errors with codes', () => {
  const segments = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 1, 0, 0, 1, 1, 1];
  for (const options of [
    { mix: 91 },
    { mix: -1 },
    { unit: 0 },
    { turn: Number.NaN },
    { mixx: 3 },
    { closed: 1 },
    { rows: 3 },
    { cols: 3 },
    { rows: 1, cols: 3 },
    { rows: -3, cols: 1 },
    { rows: 1.5, cols: 2 },
    { rows: 3, cols: 1e9 },
    'x',
  ]) {
    assert.throws(
      () => kleinView(segments, /** @type {any} */ (options)),
      (e) => e instanceof Error && e.code === 'invalid-argument',
      JSON.stringify(options),
    );
  }
  assert.throws(
    () => kleinView('lines'),
    (e) => e.code === 'invalid-argument',
  );
  // a grid of the wrong shape, or closed: named for what is wrong
  const four = [...segments, 0, 0, 0, 0, 0, 1];
  for (const [lines, options, option] of [
    [four, { rows: 2, cols: 2, closed: true }, 'closed'],
    [segments, { rows: 2, cols: 2 }, null],
    [four, { rows: 2 }, 'cols'],
    [four, { cols: 2 }, 'rows'],
    [four, { rows: 2, cols: 2.5 }, 'cols'],
  ]) {
    assert.throws(
      () => kleinView(lines, /** @type {any} */ (options)),
      (e) => e instanceof Error && e.code === 'invalid-argument' && (option === null || e.details?.option === option),
      JSON.stringify(options),
    );
  }
  assert.equal(kleinView(four, { rows: 2, cols: 2 }).omega.length, 4);
  // two rulings: one step, no conic
  const k = kleinView([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1]);
  assert.equal(k.omega.length, 1);
  assert.ok(Number.isNaN(k.planeDistance) && k.conic.length === 0);
});

/** A rows × cols grid of lines: line (i, j) through (j, i, 0) along `direction(j, i)`. */
function grid(
  /** @type {number} */ rows,
  /** @type {number} */ cols,
  /** @type {(x: number, y: number) => number[]} */ direction,
) {
  const out = [];
  for (let i = 0; i < rows; i++)
    for (let j = 0; j < cols; j++) {
      const e = direction(j, i);
      out.push(j, i, 0, j + e[0], i + e[1], e[2]);
    }
  return out;
}

test('kleinView of a grid: a net on M whose edges join neighbouring lines; a bundle torsal on every edge, a screw’s lines on none', () => {
  const [rows, cols] = [3, 4];
  const edges = rows * (cols - 1) + cols * (rows - 1);
  // lines through the apex (0.3, −0.2, 2): every two meet
  const bundle = kleinView(
    grid(rows, cols, (x, y) => [0.3 - x, -0.2 - y, 2]),
    { rows, cols },
  );
  assert.equal(bundle.omega.length, edges);
  assert.equal(bundle.torsalSteps, edges);
  assert.equal(bundle.points.length, 3 * rows * cols);
  assert.equal(bundle.torsal.length, 6 * edges);
  // the paths' tangents of a screw: neighbouring lines skew, Ω = −h sin φ of each pair
  const screw = grid(rows, cols, (x, y) => [-y, x, 1]);
  const k = kleinView(screw, { rows, cols });
  assert.equal(k.torsalSteps, 0);
  assert.equal(k.positive.length + k.negative.length, 6 * edges);
  // edge 0 joins lines (0, 0) and (0, 1); edge rows·(cols − 1) joins (0, 0) and (1, 0)
  const line = (/** @type {number} */ n) => {
    const [a, b] = [screw.slice(6 * n, 6 * n + 3), screw.slice(6 * n + 3, 6 * n + 6)];
    const e = b.map((v, c) => v - a[c]);
    const len = Math.hypot(...e);
    return { a, e: e.map((v) => v / len) };
  };
  const cross = (/** @type {number[]} */ u, /** @type {number[]} */ v) => [
    u[1] * v[2] - u[2] * v[1],
    u[2] * v[0] - u[0] * v[2],
    u[0] * v[1] - u[1] * v[0],
  ];
  const dot = (/** @type {number[]} */ u, /** @type {number[]} */ v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  for (const [edge, m, n] of [
    [0, 0, 1],
    [rows * (cols - 1), 0, cols],
    [edges - 1, cols * (rows - 1) - 1, rows * cols - 1],
  ]) {
    const [p, q] = [line(m), line(n)];
    const c = cross(p.e, q.e);
    // −h sin φ = −det(a_q − a_p, e_p, e_q)
    const want = -dot(
      q.a.map((v, i) => v - p.a[i]),
      c,
    );
    assert.ok(Math.abs(k.omega[edge] - want) < 1e-14, `edge ${edge}: ${k.omega[edge]} vs ${want}`);
  }
  // the same lines as a polygon: one step fewer than lines, along the rows and across them
  assert.equal(kleinView(screw).omega.length, rows * cols - 1);
});

test('the catalogue’s congruences as nets on M: every point on M to 1e-12, and the scene draws them', () => {
  const { t, format } = translator('en');
  const scene = SCENES.find((x) => x.id === 'klein');
  assert.ok(scene);
  for (const { name } of AnalyticCongruence.list()) {
    using([AnalyticCongruence.byName(name)], (c) => {
      using([c.grid(7, 5)], (g) => {
        const k = kleinView(g.segments(), { rows: 7, cols: 5 });
        assert.ok(k.maxResidual <= 1e-12, `${name}: ${k.maxResidual}`);
        assert.equal(k.omega.length, 7 * 4 + 5 * 6);
      });
      // as the book says, on the scene's 12 × 12 grid: no torsal edge; Example 5's lines in one
      // linear complex, the others' not
      using([c.grid(12, 12)], (g) => {
        const k = kleinView(g.segments(), { rows: 12, cols: 12 });
        assert.equal(k.torsalSteps, 0, name);
        if (name === 'example5') assert.ok(k.complexResidual < 1e-12, `${name}: ${k.complexResidual}`);
        else assert.ok(k.complexResidual > 0.1, `${name}: ${k.complexResidual}`);
      });
    });
    const params = { ...defaults(scene), surface: `congruence:${name}`, side: 8, mark: 9 };
    const built = scene.create(params, { t, format, lang: 'en' });
    assert.equal(built.data?.grid?.rows, 8);
    assert.equal(built.data?.segments.length, 6 * 64);
    assert.match(built.description, /The 8 × 8 lines of the congruence/);
    assert.match(built.description, /Line 9 of the grid \(row 1, column 1\)/);
    const labels = legendOf(scene, params, built).map((e) => t(e.label));
    assert.ok(labels.includes('edge of the net with Ω > 0'), String(labels));
    const marked = built.readouts?.find((r) => r.label === 'klein.readout.gridMarked');
    // line 9 = (1, 1): the edge to (1, 2) is edge 1·7 + 1
    const k = kleinView(built.data?.segments ?? [], {
      rows: 8,
      cols: 8,
      mix: params.mix,
      turn: params.turn,
      unit: params.unit,
    });
    assert.equal(marked?.value, k.omega[8]);
  }
});

test('lines meeting two skew lines: a net on M torsal on every edge, its least |Ω| named by its two lines', () => {
  const { t, format } = translator('en');
  const scene = SCENES.find((x) => x.id === 'klein');
  assert.ok(scene);
  // every line from (u, 0, −1) to (v, a v, 1): a row's lines share their first point, a
  // column's their second, so neighbouring lines always meet
  const params = { ...defaults(scene), surface: 'congruence:two-lines', side: 5, mark: 4 };
  const built = scene.create(params, { t, format, lang: 'en' });
  const value = (/** @type {string} */ label) => built.readouts?.find((r) => r.label === label)?.value;
  assert.equal(value('klein.readout.gridTorsal'), '40 / 40');
  assert.equal(value('klein.readout.gridMarked'), 'klein.readout.gridNoStep');
  assert.match(built.description, /torsal edges \(Ω = 0: the two lines meet or are parallel\): 40 of 40/);
  assert.match(built.description, /between the lines \(\d, \d\)–\(\d, \d\) of the grid/);
  // the surfaces keep their own slider; a congruence's is the grid's side
  assert.equal(scene.params.find((q) => q.key === 'n')?.unless?.(params), 'klein.reason.congruence');
  assert.equal(
    scene.params.find((q) => q.key === 'side')?.unless?.({ ...params, surface: 'cone' }),
    'klein.reason.surface',
  );
  // the edge the description names: its two lines' Ω, from their points and directions, is the
  // least |Ω| of all neighbouring pairs of the grid
  const other = scene.create({ ...params, surface: 'congruence:example5' }, { t, format, lang: 'en' });
  const segments = other.data?.segments ?? new Float64Array();
  const omega = (/** @type {number} */ m, /** @type {number} */ n) => {
    const [a, b] = [segments.slice(6 * m, 6 * m + 6), segments.slice(6 * n, 6 * n + 6)];
    const unit = (/** @type {Float64Array} */ s) => {
      const e = [s[3] - s[0], s[4] - s[1], s[5] - s[2]];
      const l = Math.hypot(...e);
      return e.map((x) => x / l);
    };
    const [e, f] = [unit(a), unit(b)];
    const d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const cross = [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]];
    return -(d[0] * cross[0] + d[1] * cross[1] + d[2] * cross[2]);
  };
  const pairs = [];
  for (let i = 0; i < 5; i++)
    for (let j = 0; j < 5; j++) {
      if (j < 4) pairs.push(Math.abs(omega(5 * i + j, 5 * i + j + 1)));
      if (i < 4) pairs.push(Math.abs(omega(5 * i + j, 5 * (i + 1) + j)));
    }
  const named = other.description.match(/between the lines \((\d), (\d)\)–\((\d), (\d)\) of the grid/);
  assert.ok(named, other.description);
  const [r1, c1, r2, c2] = named.slice(1).map(Number);
  assert.equal(Math.abs(r2 - r1) + Math.abs(c2 - c1), 1, 'neighbours');
  assert.ok(Math.abs(Math.abs(omega(5 * r1 + c1, 5 * r2 + c2)) - Math.min(...pairs)) < 1e-15);
});

test('kleinDeparture: Chaikin’s first new line leaves M by ρ = a·a₀/|a|² of ¾ L₀ + ¼ L₁ (computed here from the points); after N, on M; the line scene’s points each joined to its line’s', () => {
  const { kleinDeparture } = ruledlab;
  using([AnalyticSurface.byName('helicoid')], (h) => {
    using([h.sample(24, h.ranges?.() ?? { uMin: -1, uMax: 1 })], (s) => {
      const seg = s.segments();
      // the lines' 6-vectors (e, p × e), e the unit direction, from the segments' points alone
      const line = (/** @type {number} */ i) => {
        const p = [seg[6 * i], seg[6 * i + 1], seg[6 * i + 2]];
        const d = [0, 1, 2].map((k) => seg[6 * i + 3 + k] - p[k]);
        const n = Math.hypot(...d);
        const e = d.map((x) => x / n);
        const m = [p[1] * e[2] - p[2] * e[1], p[2] * e[0] - p[0] * e[2], p[0] * e[1] - p[1] * e[0]];
        return [...e, ...m];
      };
      const [l0, l1] = [line(0), line(1)];
      // (the scheme orients the lines consistently: here the first two already are, e₀·e₁ > 0)
      assert.ok(l0[0] * l1[0] + l0[1] * l1[1] + l0[2] * l1[2] > 0);
      const c = l0.map((x, k) => 0.75 * x + 0.25 * l1[k]);
      const want = (c[0] * c[3] + c[1] * c[4] + c[2] * c[5]) / (c[0] ** 2 + c[1] ** 2 + c[2] ** 2);
      const d = kleinDeparture(seg, { scheme: 'chaikin', steps: 1 }, { mix: 30, turn: 90, unit: 1 });
      assert.ok(d.before[0] >= Math.abs(want) && Math.abs(want) > 1e-4, `${d.before[0]} ≥ |${want}|`);
      assert.ok(d.after[0] < 1e-15, `after N: ${d.after[0]}`);
      assert.equal(d.points.length, d.lines.length);
      // the points after N are the refined lines' points on M, as kleinView draws them
      using([s.subdivide({ scheme: 'chaikin', steps: 1, space: 'lines' })], (r) => {
        const k = kleinView(r.segments(), { mix: 30, turn: 90, unit: 1 });
        assert.equal(k.points.length, d.lines.length);
        for (let i = 0; i < k.points.length; i++) assert.ok(Math.abs(k.points[i] - d.lines[i]) < 1e-6, `${i}`);
      });
    });
  });
  // errors with codes, naming what is wrong
  const seg = new Float64Array([0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, -1, 0, 2]);
  for (const [subdivide, image, option] of [
    [{ scheme: 'bezier', steps: 1 }, undefined, 'space'],
    [{ scheme: 'chaikin', steps: 1 }, { mix: 91 }, 'mix'],
    [{ scheme: 'chaikin', steps: 1 }, { angle: 3 }, 'angle'],
    [{ scheme: 'chaikin', step: 1 }, undefined, 'step'],
  ]) {
    assert.throws(
      () => kleinDeparture(seg, /** @type {any} */ (subdivide), /** @type {any} */ (image)),
      (/** @type {any} */ e) => e instanceof Error && typeof e.code === 'string' && e.message.includes(option),
      option,
    );
  }
});

test('the line scene says how far its points leave M, and draws them beside: before N, joined to their lines’ points', () => {
  const scene = SCENES.find((s) => s.id === 'lines');
  assert.ok(scene);
  const { t } = translator('en');
  const built = scene.create(defaults(scene), { t, lang: 'en', input: null, data: null });
  const before = built.readouts?.find((r) => r.label === 'lines.readout.departure')?.value;
  const after = built.readouts?.find((r) => r.label === 'lines.readout.departureAfter')?.value;
  assert.ok(typeof before === 'number' && before > 1e-6, `before ${before}`);
  assert.ok(typeof after === 'number' && after < 1e-14, `after ${after}`);
  assert.ok(built.klein && built.data);
  // in the image the view beside draws in, whichever the reader steers: each chord ends at its
  // line's point as kleinView draws the scene's lines in that image
  for (const image of [
    { mix: 30, turn: 90, unit: 1 },
    { mix: 71, turn: 213, unit: 2.35 },
  ]) {
    const [chords, points] = built.klein(image).layers;
    const count = built.data.segments.length / 6;
    assert.equal(points.positions.length, 3 * count);
    assert.equal(chords.positions.length, 2 * points.positions.length);
    const drawn = ruledlab.kleinView(built.data.segments, image).points;
    for (let i = 0; i < count; i++)
      for (let c = 0; c < 3; c++) {
        assert.equal(chords.positions[6 * i + c], points.positions[3 * i + c]);
        assert.ok(
          Math.abs(chords.positions[6 * i + 3 + c] - drawn[3 * i + c]) < 1e-6,
          `line ${i} in ${JSON.stringify(image)}`,
        );
      }
    assert.match(built.klein(image).description, /leave it by up to ρ = /);
  }
  // two images are two pictures
  assert.notDeepEqual(
    built.klein({ mix: 30, turn: 90, unit: 1 }).layers[1].positions,
    built.klein({ mix: 71, turn: 213, unit: 2.35 }).layers[1].positions,
  );
});

test('the link keeps the Klein view’s image: klein=α,β,ℓ read and written back, a bare klein the scene’s own, a bad or held value said', async () => {
  const { readLink, writeLink } = await import('../../www/link.js');
  const read = (/** @type {string} */ hash) => readLink(hash, SCENES);
  const steered = read('#scene=striction&klein=12,200,2.35');
  assert.equal(steered.view, 'split');
  assert.deepEqual(steered.projection, { mix: 12, turn: 200, unit: 2.35 });
  assert.deepEqual(steered.notes, []);
  assert.match(writeLink(steered), /(^|&)klein=12%2C200%2C2\.35(&|$)/);
  assert.deepEqual(read(`#${writeLink(steered)}`).projection, steered.projection);
  // a bare klein: the scene's own image, written bare
  const own = read('#scene=striction&klein');
  assert.equal(own.projection, null);
  assert.match(writeLink(own), /(^|&)klein(&|$)/);
  // the 3D view alone writes no klein, whatever the image
  assert.doesNotMatch(writeLink({ ...steered, view: 'space' }), /klein/);
  // not three numbers: the scene's own image, said
  for (const bad of ['12,200', 'a,b,c', '1,2,3,4', '1,,3', 'Infinity,1,1']) {
    const link = read(`#scene=striction&klein=${encodeURIComponent(bad)}`);
    assert.equal(link.view, 'split', bad);
    assert.equal(link.projection, null, bad);
    assert.deepEqual(link.notes, [{ key: 'klein', note: 'note.badKlein' }], bad);
  }
  // outside the ranges or between steps: held, said
  const held = read('#scene=striction&klein=120,-3,0.33');
  assert.deepEqual(held.projection, { mix: 90, turn: 0, unit: 0.35 });
  assert.deepEqual(held.notes, [{ key: 'klein', note: 'note.kleinHeld' }]);
  // the notes are in both languages
  for (const lang of ['en', 'de']) {
    const { has } = translator(lang);
    for (const key of ['note.badKlein', 'note.kleinHeld', 'element.note.badKlein', 'element.note.kleinHeld'])
      assert.ok(has(key), `${lang} ${key}`);
  }
});

test('the Klein scene’s sliders α, β, ℓ take only values the Klein view beside holds as they are, and its lines carry its image', () => {
  const scene = SCENES.find((x) => x.id === 'klein');
  assert.ok(scene);
  for (const key of /** @type {const} */ (['mix', 'turn', 'unit'])) {
    const p = scene.params.find((q) => q.key === key);
    assert.ok(p && p.type === 'range' && p.min !== undefined && p.max !== undefined && p.step !== undefined);
    // every value the scene's slider takes is one the view's projection keeps (none held, none moved)
    for (let k = 0; p.min + k * p.step <= p.max + 1e-9; k++) {
      const v = Number((p.min + k * p.step).toFixed(2));
      assert.equal(holdValue(key, v), v, `${key} = ${v}`);
    }
    assert.equal(holdValue(key, p.max + p.step), p.max, `${key} beyond its slider`);
  }
  const { t } = translator('en');
  const built = scene.create(
    { ...defaults(scene), mix: 64, turn: 12, unit: 1.5 },
    { t, lang: 'en', input: null, data: null },
  );
  assert.deepEqual(built.data?.image, { mix: 64, turn: 12, unit: 1.5 });
});

test('the Klein scene’s rulings are handles where they are drawn, left of M as first seen; a ruling screwed about the helix’s axis keeps the complex, its end lifted alone leaves it; every point stays on M', () => {
  const scene = SCENES.find((x) => x.id === 'klein');
  assert.ok(scene);
  const { t } = translator('en');
  const p = { ...defaults(scene), surface: 'helix-tangent', n: 8, conic: false };
  const create = (/** @type {Float64Array | null} */ rulings) =>
    scene.create(p, { t, lang: 'en', input: rulings ? { rulings } : null, data: null });
  const built = create(null);
  const set = built.input?.sets[0];
  assert.ok(set?.transform);
  assert.equal(set.key, 'rulings');
  assert.equal(set.points.length, 6 * 8);
  // the handles stand where the rulings are drawn: the layer's similarity
  const drawn = built.layers.find((l) => l.style === 'ruling');
  assert.deepEqual(Array.from(set.transform), Array.from(drawn?.transform ?? []));
  // the centre of their box stands left of M's centre on the screen of the scene's camera, level
  // with it, about 3.2 away in space
  const lo = [0, 1, 2].map((k) => Math.min(...Array.from(set.points).filter((_, i) => i % 3 === k)));
  const hi = [0, 1, 2].map((k) => Math.max(...Array.from(set.points).filter((_, i) => i % 3 === k)));
  const centre = transformPoint(
    set.transform,
    lo.map((l, k) => (l + hi[k]) / 2),
  );
  assert.ok(Math.abs(Math.hypot(...centre) - 3.2) < 1e-5, `centre ${centre}`);
  const camera = new OrbitCamera();
  Object.assign(camera, { yaw: built.camera?.yaw, pitch: 0, target: [0, 0, 0], distance: 20 });
  const m = camera.viewProj(1.5);
  const screen = (/** @type {number[]} */ p) => toScreen(m, p, 1500, 1000);
  const [onLeft, ofM] = [screen(centre), screen([0, 0, 0])];
  assert.ok(ofM.x - onLeft.x > 150, `left of M on screen: ${onLeft.x} < ${ofM.x}`);
  assert.ok(Math.abs(onLeft.y - ofM.y) < 1, 'level with it');
  const readout = (/** @type {any} */ b, /** @type {string} */ label) =>
    Number(b.readouts.find((/** @type {any} */ r) => r.label === label)?.value);
  const base = Float64Array.from(set.points);
  assert.ok(readout(built, 'klein.readout.complex') < 1e-12, 'the tangents of a helix lie in a complex');
  // ruling 5 turned about the helix's axis z by 0.4 and moved along it by 0.25: in the complex still
  const screwed = base.slice();
  for (const o of [30, 33]) {
    const [x, y] = [screwed[o], screwed[o + 1]];
    screwed.set(
      [x * Math.cos(0.4) - y * Math.sin(0.4), x * Math.sin(0.4) + y * Math.cos(0.4), screwed[o + 2] + 0.25],
      o,
    );
  }
  const lifted = base.slice();
  lifted[35] += 0.3;
  const before = kleinView(base).points;
  for (const [edit, inComplex] of /** @type {const} */ ([
    [screwed, true],
    [lifted, false],
  ])) {
    const after = create(edit);
    assert.ok(readout(after, 'klein.readout.residual') <= 1e-12, 'every point on M');
    const residual = readout(after, 'klein.readout.complex');
    assert.ok(inComplex ? residual < 1e-12 : residual > 0.3, `complex residual ${residual}`);
    // its point moved on M; the others stayed
    const points = kleinView(edit).points;
    assert.ok(Math.hypot(...[0, 1, 2].map((c) => points[15 + c] - before[15 + c])) > 1e-3, 'R_5’s point moved');
    assert.ok(Math.hypot(...[0, 1, 2].map((c) => points[12 + c] - before[12 + c])) < 1e-12, 'R_4’s point stayed');
  }
  // a congruence's lines are not handles
  assert.equal(
    scene.create({ ...p, surface: 'congruence:two-lines' }, { t, lang: 'en', input: null, data: null }).input,
    undefined,
  );
});

test('a linear congruence is a 3-space section of M: the Klein scene’s second-best complex has residual 0 for the lines meeting two lines, the helicoid and a regulus, not for a helical surface; a closed surface is a closed polygon on M beside any scene', async () => {
  const scene = SCENES.find((x) => x.id === 'klein');
  assert.ok(scene);
  const { t } = translator('en');
  const value = (/** @type {string} */ surface) =>
    Number(
      scene
        .create({ ...defaults(scene), surface }, { t, lang: 'en', input: null, data: null })
        .readouts?.find((r) => r.label === 'klein.readout.congruence')?.value,
    );
  for (const surface of ['congruence:two-lines', 'helicoid', 'hyperboloid', 'hyperbolic-paraboloid'])
    assert.ok(value(surface) < 1e-9, `${surface}: ${value(surface)}`);
  for (const surface of ['helical', 'helix-tangent']) assert.ok(value(surface) > 1e-3, `${surface}: ${value(surface)}`);
  // the book's number for the helical surface at 24 rulings
  assert.ok(Math.abs(value('helical') - 0.3) < 0.01, `helical: ${value('helical')}`);
  // the striction scene's hyperboloid is closed: the Klein view beside joins its last ruling to its first
  const { kleinImage } = await import('../../www/klein-image.js');
  const striction = SCENES.find((x) => x.id === 'striction');
  assert.ok(striction);
  for (const [surface, closed] of /** @type {const} */ ([
    ['hyperboloid', true],
    ['helicoid', false],
  ])) {
    const built = striction.create({ ...defaults(striction), surface }, { t, lang: 'en', input: null, data: null });
    assert.equal(!!built.data?.closed, closed, surface);
    const n = (built.data?.segments.length ?? 0) / 6;
    const steps = kleinImage(/** @type {Float64Array} */ (built.data?.segments), { closed: !!built.data?.closed }).k
      .omega.length;
    assert.equal(steps, closed ? n : n - 1, surface);
  }
});

test('Share’s element snippet carries the Klein view and its image as the element reads them back', async () => {
  const { elementSnippet } = await import('../../www/page/share.js');
  const { readProjection } = await import('../../www/klein-projection.js');
  const scene = SCENES.find((x) => x.id === 'striction');
  assert.ok(scene);
  const snippet = (/** @type {any} */ edit) =>
    elementSnippet(scene, defaults(scene), 'en', { src: 'ruledlab-embed.js' }, null, null, edit);
  const steered = snippet({ klein: true, projection: { mix: 40, turn: 200, unit: 1.5 } });
  const value = /\sklein="([^"]*)"/.exec(steered)?.[1];
  assert.equal(value, '40,200,1.5');
  assert.deepEqual(readProjection(value ?? null), { projection: { mix: 40, turn: 200, unit: 1.5 }, held: false });
  // the scene's own image: a bare attribute; the 3D view alone: none
  assert.match(snippet({ klein: true, projection: null }), /\sklein\s/);
  assert.doesNotMatch(snippet({ klein: false, projection: { mix: 40, turn: 200, unit: 1.5 } }), /klein/);
});
