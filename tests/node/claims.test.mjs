// Every comparative sentence of the page is a claim a scene checks against the numbers of its
// readout (Built.claims). Here each scene is computed over the whole range its claims state
// (every value of the parameters the comparisons depend on), and every claim must hold there;
// a claim that never appears in the sweep fails too, so none can silently drop out.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import ruledlab from './load.mjs';
import { SCENES } from '../../www/scenes/index.js';
import { PRESETS } from '../../www/paper.js';
import { defaults } from '../../www/scene.js';
import { translator } from '../../www/i18n/index.js';
import { STYLES } from '../../www/theme.js';
import { ROUNDING } from '../../www/limits.js';

const i18n = translator('en');
const context = { t: i18n.t, format: i18n.format };
const sceneOf = (/** @type {string} */ id) =>
  /** @type {import('../../www/scene.js').Scene} */ (SCENES.find((s) => s.id === id));
const range = (/** @type {number} */ a, /** @type {number} */ b) => Array.from({ length: b - a + 1 }, (_, i) => a + i);

/** Every combination of the listed values; the other parameters keep their defaults. */
function* sweep(/** @type {Record<string, Array<number | string | boolean>>} */ axes) {
  const keys = Object.keys(axes);
  const at = (/** @type {number} */ k, /** @type {Record<string, any>} */ partial) => {
    if (k === keys.length) return [partial];
    return axes[keys[k]].flatMap((v) => at(k + 1, { ...partial, [keys[k]]: v }));
  };
  yield* at(0, {});
}

/** Computes `id` at each combination; returns the claims seen, failing on any that does not hold. */
function checkClaims(/** @type {string} */ id, /** @type {Record<string, any[]>} */ axes) {
  const scene = sceneOf(id);
  const seen = new Set();
  for (const params of sweep(axes)) {
    const built = scene.create({ ...defaults(scene), ...params }, context);
    for (const claim of built.claims ?? []) {
      seen.add(claim.text);
      assert.ok(
        claim.holds,
        `${id} ${JSON.stringify(params)}: "${i18n.t(claim.text)}" does not hold (readout: ${JSON.stringify(built.readouts?.map((r) => [r.label, r.value]))})`,
      );
    }
  }
  return seen;
}

test('striction (Props. 1–2, Example 1): orders 1, 2, 2 on the hyperboloid and the quartic from 20 rulings on', () => {
  const seen = checkClaims('striction', {
    surface: ['hyperboloid', 'quartic', 'helical', 'cone'],
    n: range(6, 160),
    strip: [false],
  });
  assert.deepEqual([...seen], ['striction.claim.orders']);
});

test('curves (Figs. 7–8): on the zigzag the four-point angle falls from 8 to 12 steps up to w = 0.17 closed, 0.126 open; from 0.171, 0.127 to 0.2 a turn above 1 rad remains', () => {
  // every w of the slider from its step 0.001 to its end 0.2 (w ≤ 0 states nothing)
  const seen = checkClaims('curves', {
    scheme: ['four-point'],
    closed: [true, false],
    w: range(1, 200).map((k) => k / 1000),
    steps: [4],
  });
  assert.deepEqual([...seen].sort(), ['curves.claim.falls', 'curves.claim.sharp']);
});

test('strip (Example 3): the literal energy is the midpoint rule, coupled beats it for 5 ≤ n ≤ 24 and not for n = 3, 4, four-point is exact', () => {
  const seen = checkClaims('strip', { scheme: ['literal', 'coupled', 'averaged', 'four-point'], n: range(3, 24) });
  assert.deepEqual([...seen].sort(), ['strip.claim.coupled', 'strip.claim.fourPoint', 'strip.claim.literal']);
});

test('the conventions page states, with its n, how much the coupled strip energy gains over the midpoint rule on Example 3', () => {
  // the table of docs/src/conventions.md ("How much the coupled reading gains"), recomputed row by
  // row with the measure of the strip scene's readout, in the digits it shows
  const page = readFileSync(new URL('../../docs/src/conventions.md', import.meta.url), 'utf8');
  const header = '| n | midpoint rule | coupled | midpoint / coupled |';
  const at = page.indexOf(header);
  assert.ok(at >= 0, `docs/src/conventions.md has no table "${header}"`);
  const rows = [...page.slice(at).matchAll(/^\| (\d+) \| ([\d.e-]+) \| ([\d.e-]+) \| ([\d.]+) \|$/gm)];
  assert.ok(rows.length >= 5, `only ${rows.length} rows in the table`);
  const { AnalyticSurface } = ruledlab;
  const quartic = AnalyticSurface.byName('quartic');
  const strip = quartic.sample(12, { uMin: -1, uMax: 1, closed: false });
  const distance = (/** @type {import('../../pkg/ruledlab.js').SubdivideOptions} */ options) => {
    const refined = strip.subdivide(options);
    const d = quartic.insertedDistance(refined, 2, -1, 1);
    refined.free();
    return d;
  };
  const midpoint = distance({ scheme: 'bspline', degree: 1 });
  for (const [, n, mid, coupledText, ratio] of rows) {
    const coupled = distance({ scheme: 'variational', n: Number(n), variant: 'coupled' });
    assert.deepEqual(
      [midpoint.toExponential(1), coupled.toExponential(1), (midpoint / coupled).toFixed(1)],
      [mid, coupledText, ratio],
      `n = ${n}`,
    );
  }
  strip.free();
  quartic.free();
});

test('congruences (Examples 4–5): at one step the butterfly scheme is the most accurate on every built-in congruence', () => {
  const congruence =
    sceneOf('congruence')
      .params[0].options?.()
      .map(([v]) => v) ?? [];
  assert.ok(congruence.length >= 3);
  const seen = checkClaims('congruence', { congruence, scheme: ['paper', 'butterfly'], steps: [1, 2] });
  assert.deepEqual([...seen], ['congruence.claim.butterfly']);
});

test('Example 5: read literally (and coupled), K has no effect — every K from 3 to 1000 gives the same lines; two-stage depends on K', () => {
  const { AnalyticCongruence } = ruledlab;
  const congruence =
    sceneOf('congruence')
      .params[0].options?.()
      .map(([v]) => v) ?? [];
  const Ks = [...range(3, 24), 50, 100, 500, 1000];
  for (const name of congruence) {
    const analytic = AnalyticCongruence.byName(name);
    const grid = analytic.grid(undefined, undefined, 0.35);
    const lines = (/** @type {'paper' | 'coupled' | 'two-stage'} */ variant, /** @type {number} */ K) => {
      const refined = grid.subdivide({ scheme: 'variational', variant, K });
      const segments = refined.segments();
      refined.free();
      return segments;
    };
    for (const variant of /** @type {const} */ (['paper', 'coupled'])) {
      const at6 = lines(variant, 6);
      for (const K of Ks) {
        const other = lines(variant, K);
        const worst = other.reduce((m, x, i) => Math.max(m, Math.abs(x - at6[i])), 0);
        assert.ok(worst <= ROUNDING, `${name}, ${variant}: K = ${K} moves a line by ${worst}`);
      }
    }
    const [a, b] = [lines('two-stage', 3), lines('two-stage', 12)];
    assert.ok(
      a.some((x, i) => Math.abs(x - b[i]) > 1e-4),
      `${name}: two-stage does not depend on K`,
    );
    grid.free();
    analytic.free();
  }
});

test('milling (Example 6): refining helps; with 7 poses or more the variational schemes come closest to the profile', () => {
  const seen = checkClaims('milling', {
    poses: range(4, 12),
    steps: [0, 1, 2, 3],
    tool: [false],
    envelope: [false],
    part: [false],
  });
  assert.deepEqual([...seen].sort(), ['milling.claim.refined', 'milling.claim.variational']);
});

test('Fig. 5: the caption fails at 45° (ρ = r + p tan β = 1.4) and holds in the limit orthogonal to the striction helix (ρ → 0 as H²)', () => {
  const seen = checkClaims('isometry', {
    surface: ['helical', 'helical-orthogonal'],
    n: [4, 5, 6, 8, 12, 16, 24, 36, 60, 90, 120],
  });
  assert.deepEqual([...seen].sort(), ['isometry.claim.helical', 'isometry.claim.orthogonal']);
});

test('every paper preset computes, and its claims hold', () => {
  for (const preset of PRESETS) {
    const scene = sceneOf(preset.scene);
    const built = scene.create({ ...defaults(scene), ...preset.params }, context);
    assert.ok(built.layers.length > 0, preset.id);
    for (const claim of built.claims ?? []) assert.ok(claim.holds, `${preset.id}: ${claim.text}`);
  }
});

test('every legend entry that says “dashed” or “dash-dot” is drawn dashed, in colour as in black and white', () => {
  let checked = 0;
  for (const scene of SCENES) {
    for (const entry of scene.legend) {
      const label = i18n.t(entry.label);
      if (!/dash/.test(label)) continue;
      const style = STYLES[entry.style];
      assert.ok(
        style.kind === 'line' && style.dash && style.bw.dash,
        `${scene.id}: "${label}" (${entry.style}) is solid`,
      );
      checked++;
    }
  }
  assert.ok(checked >= 8, `only ${checked} dashed legend entries`);
});
