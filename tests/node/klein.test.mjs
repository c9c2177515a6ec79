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

const { AnalyticSurface, kleinView } = ruledlab;

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
  // two rulings: one step, no conic
  const k = kleinView([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1]);
  assert.equal(k.omega.length, 1);
  assert.ok(Number.isNaN(k.planeDistance) && k.conic.length === 0);
});
