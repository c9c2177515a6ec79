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
import { builtInTasks } from '../../www/task/builtin.js';
import { defaults } from '../../www/scene.js';
import { translator } from '../../www/i18n/index.js';
import { STYLES } from '../../www/theme.js';
import { ROUNDING, TURNING_FROM, TURNING_STEPS } from '../../www/limits.js';

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

test('Example 5: read literally, and coupled, K has no effect — each gives the same lines for every K from 3 to 1000 (not the same as each other); two-stage depends on K', () => {
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
    // each on its own: the two readings are not the same lines
    const [paper, coupled] = [lines('paper', 6), lines('coupled', 6)];
    assert.ok(
      paper.some((x, i) => Math.abs(x - coupled[i]) > 1e-4),
      `${name}: 'paper' and 'coupled' give the same lines`,
    );
    const [a, b] = [lines('two-stage', 3), lines('two-stage', 12)];
    assert.ok(
      a.some((x, i) => Math.abs(x - b[i]) > 1e-4),
      `${name}: two-stage does not depend on K`,
    );
    grid.free();
    analytic.free();
  }
});

test('milling (Example 6): refining helps; with 7 poses or more the variational schemes come closest to the profile; the midpoint rule turns in the smallest steps but least evenly, the averaged scheme most evenly (4–12 poses, 1–3 steps, every scheme shown)', () => {
  // every scheme shown (the claims compare all four whichever is chosen)
  const seen = checkClaims('milling', {
    scheme: ['variational', 'averaged', 'four-point', 'linear'],
    poses: range(4, 12),
    steps: [0, 1, 2, 3],
    tool: [false],
    envelope: [false],
    part: [false],
  });
  assert.deepEqual([...seen].sort(), ['milling.claim.refined', 'milling.claim.turns', 'milling.claim.variational']);
});

test('milling: the coupled variational scheme is not always the most even (12 poses, 3 steps: four-point turns more evenly), so the text names the averaged scheme alone', () => {
  const scene = sceneOf('milling');
  const evenness = (/** @type {string} */ scheme) => {
    const built = scene.create(
      { ...defaults(scene), scheme, poses: 12, steps: 3, tool: false, envelope: false, part: false },
      context,
    );
    return /** @type {number} */ (built.readouts?.find((r) => r.label === 'milling.readout.secondDifference')?.value);
  };
  const [coupled, averaged, fourPoint] = ['variational', 'averaged', 'four-point'].map(evenness);
  assert.deepEqual([coupled.toExponential(2), fourPoint.toExponential(2)], ['3.17e-3', '3.08e-3']);
  assert.ok(averaged < fourPoint && fourPoint < coupled);
  const said = {
    en: ['the averaged variational scheme most evenly', 'the variational schemes most evenly'],
    de: ['das gemittelte variationelle Schema am gleichmäßigsten', 'die variationellen Schemata am gleichmäßigsten'],
  };
  for (const [lang, [right, wrong]] of Object.entries(said)) {
    const text = translator(lang).t('milling.text').replace(/\s+/g, ' ');
    assert.ok(text.includes(right), `${lang}: milling.text does not say "${right}"`);
    assert.ok(!text.includes(wrong), `${lang}: milling.text says "${wrong}"`);
  }
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

test('curves: the text’s turning angles at w = 0.17 (closed) after four step counts are what the core measures, and they do not fall steadily', () => {
  const scene = sceneOf('curves');
  const steps = [TURNING_FROM - 2, TURNING_FROM, TURNING_STEPS - 2, TURNING_STEPS];
  // the scene's own polygon, as its handles hold it (f64)
  const polygon = /** @type {any} */ (scene.create({ ...defaults(scene), steps: 0 }, context)).input.sets[0].points;
  const angles = ruledlab.turningAngles(polygon, { scheme: 'four-point', steps: TURNING_STEPS, closed: true, w: 0.17 });
  const said = steps.map((k) => angles[k].toFixed(2));
  assert.deepEqual(said, ['1.15', '1.04', '1.19', '1.00']);
  assert.ok(angles[steps[2]] > angles[steps[1]], 'the angle rises from the second to the third count: it oscillates');
  for (const lang of ['en', 'de']) {
    const text = translator(lang).t('curves.text');
    const words = lang === 'en' ? said : said.map((x) => x.replace('.', ','));
    const numbers = `${words.slice(0, -1).join(', ')} ${lang === 'en' ? 'and' : 'und'} ${words.at(-1)}`;
    assert.ok(text.includes(numbers), `${lang}: curves.text does not say ${numbers}`);
  }
});

test('the four-point scheme is C¹ at w = 0.18, beyond (√5 − 1)/8, as the text says the sharp bound 0.19273 allows: the scheme of the divided differences contracts in 16 steps', () => {
  // a(z) of (8), and c(z) = 2a(z)/(1 + z)², the scheme of the differences of the divided
  // differences; S_a is C¹ when ‖S_c^k‖_∞ < 1 for some k (Dyn's criterion)
  const contraction = (/** @type {number} */ w, /** @type {number} */ k) => {
    const c = [-2 * w, 4 * w, 1 - 4 * w, 4 * w, -2 * w];
    let m = Float64Array.from(c);
    for (let level = 1; level < k; level++) {
      const s = 2 ** level;
      const next = new Float64Array(m.length + (c.length - 1) * s);
      for (let j = 0; j < c.length; j++) for (let i = 0; i < m.length; i++) next[j * s + i] += c[j] * m[i];
      m = next;
    }
    const period = 2 ** k;
    const sums = new Float64Array(period);
    for (let i = 0; i < m.length; i++) sums[i % period] += Math.abs(m[i]);
    return sums.reduce((a, b) => Math.max(a, b), 0) ** (1 / k);
  };
  assert.ok(contraction(0.18, 16) < 0.98);
  // at w = 1/16 (cubic precision) the rate tends to 1/2 from above
  const cubic = contraction(1 / 16, 16);
  assert.ok(cubic > 0.5 && cubic < 0.61, String(cubic));
});

test('the book’s catalogue: ten surfaces, each with δ(u) and all but the cylinder with an exact striction curve; Fig. 5’s preset is the surface with rulings at 45°', () => {
  const { AnalyticSurface } = ruledlab;
  const list = AnalyticSurface.list();
  assert.equal(list.length, 10);
  const none = [];
  for (const { name, uMin, uMax } of list) {
    const surface = AnalyticSurface.byName(name);
    const u = Float64Array.from([0.3, 0.5, 0.7], (f) => uMin + f * (uMax - uMin));
    assert.ok([...surface.distribution(u)].every(Number.isFinite), `${name}: δ(u)`);
    if (![...surface.striction(u)].every(Number.isFinite)) none.push(name);
    surface.free();
  }
  assert.deepEqual(none, ['cylinder']);
  const preset = (/** @type {string} */ id) => PRESETS.find((p) => p.id === id)?.params.surface;
  assert.deepEqual([preset('fig5'), preset('fig5-orthogonal')], ['helical', 'helical-orthogonal']);
  assert.match(i18n.t('surface.helical'), /45°/);
  for (const file of ['guide/ruled-surfaces.md', 'guide/computes.md']) {
    const page = readFileSync(new URL(`../../docs/src/${file}`, import.meta.url), 'utf8').replace(/\s+/g, ' ');
    assert.match(page, /all but the cylinder/, file);
    assert.match(page, /rulings at 45°, which Fig\. 5's preset shows/, file);
  }
});

test('subdivision: on Example 3 the averaged variant gains 200× over the coupled one at the middle inserted ruling, at most 3.4e-6 at the three central ones, and 3.7× over the interior column, as the book says', () => {
  const { AnalyticSurface, RuledSurface } = ruledlab;
  const quartic = AnalyticSurface.byName('quartic');
  const strip = quartic.sample(12, { uMin: -1, uMax: 1, closed: false });
  const exact = quartic.sample(23, { uMin: -1, uMax: 1, closed: false }).segments();
  // the distance of each inserted ruling alone: the others replaced by the exact rulings
  const each = (/** @type {'coupled' | 'averaged'} */ variant) => {
    const refined = strip.subdivide({ scheme: 'variational', n: 12, variant });
    const segments = refined.segments();
    refined.free();
    const out = [];
    for (let j = 1; j < 23; j += 2) {
      const alone = Float64Array.from(exact);
      alone.set(segments.subarray(6 * j, 6 * j + 6), 6 * j);
      const s = RuledSurface.fromSegments(alone);
      out.push(quartic.insertedDistance(s, 2, -1, 1));
      s.free();
    }
    return out;
  };
  const [coupled, averaged] = [each('coupled'), each('averaged')];
  const max = (/** @type {number[]} */ xs) => Math.max(...xs);
  const e = (/** @type {number} */ x, digits = 1) => x.toExponential(digits);
  // the middle one (u = 0), the three central ones, the interior (two left out at each end)
  assert.deepEqual(
    [e(coupled[5]), e(averaged[5]), Math.round(coupled[5] / averaged[5] / 100) * 100],
    ['2.1e-4', '1.0e-6', 200],
  );
  assert.deepEqual([e(max(coupled.slice(4, 7))), e(max(averaged.slice(4, 7)))], ['2.1e-4', '3.4e-6']);
  const [inner, innerAveraged] = [max(coupled.slice(2, -2)), max(averaged.slice(2, -2))];
  assert.deepEqual([e(inner), e(innerAveraged), (inner / innerAveraged).toFixed(1)], ['2.1e-4', '5.6e-5', '3.7']);
  const page = readFileSync(new URL('../../docs/src/guide/subdivision.md', import.meta.url), 'utf8').replace(
    /\s+/g,
    ' ',
  );
  for (const said of [
    "O(H²) against the fairness terms' O(H⁴)",
    'relatively larger by O(H⁻²)',
    'from 2.1e-4 to 1.0e-6 (200×)',
    'at most 3.4e-6',
    '3.7× (2.1e-4 to 5.6e-5)',
  ])
    assert.ok(page.includes(said), `subdivision.md does not say "${said}"`);
  strip.free();
  quartic.free();
});

test('the sharp C¹ bound of the four-point scheme, w* ≈ 0.19273 (the real root of 32w³ + 4w − 1), is given alike in the book and the page, which says that its slider goes past it', () => {
  let [lo, hi] = [0, 0.5];
  for (let k = 0; k < 60; k++) {
    const w = (lo + hi) / 2;
    if (32 * w ** 3 + 4 * w - 1 > 0) hi = w;
    else lo = w;
  }
  assert.equal(lo.toFixed(5), '0.19273');
  const max = /** @type {number} */ (sceneOf('curves').params.find((p) => p.key === 'w')?.max);
  assert.ok(max > lo, `the slider ends at ${max}`);
  const book = (/** @type {string} */ file) =>
    readFileSync(new URL(`../../docs/src/${file}`, import.meta.url), 'utf8').replace(/\s+/g, ' ');
  for (const file of ['guide/subdivision.md', 'conventions.md']) {
    const page = book(file);
    for (const said of ['w* ≈ 0.19273', 'real root of 32w³ + 4w − 1 = 0', 'Linear Algebra Appl. 430, 2009'])
      assert.ok(page.includes(said), `${file} does not say "${said}"`);
  }
  assert.ok(book('guide/subdivision.md').includes(`goes on to ${max}, past w*, where there is no C¹ limit`));
  const texts = {
    en: ['the real root of 32w³ + 4w − 1 = 0', `Past w* ≈ 0.193 (the slider goes on to ${max}) there is no C¹ limit`],
    de: [
      'w* ≈ 0,19273 ist die reelle Nullstelle von 32w³ + 4w − 1 = 0',
      `Jenseits von w* ≈ 0,193 (der Regler reicht bis ${String(max).replace('.', ',')}) gibt es keine C¹-Grenzkurve`,
    ],
  };
  for (const [lang, said] of Object.entries(texts)) {
    const text = translator(lang).t('curves.text').replace(/\s+/g, ' ');
    for (const s of said) assert.ok(text.includes(s), `${lang}: curves.text does not say "${s}"`);
    assert.ok(text.includes('3019–3029'), `${lang}: the citation's pages`);
  }
});

test('curves: de Casteljau keeps the end points, and degree-2 knot insertion at midpoints is Chaikin’s cuts, as the text says', () => {
  const { subdividePolygon } = ruledlab;
  const points = new Float64Array([0, 0, 0, 1, 2, 0, 3, 1, 0, 4, 3, 0, 6, 0, 0]);
  const casteljau = subdividePolygon(points, { scheme: 'bezier', steps: 1 });
  assert.deepEqual([...casteljau.slice(0, 3), ...casteljau.slice(-3)], [0, 0, 0, 6, 0, 0]);
  const chaikin = subdividePolygon(points, { scheme: 'chaikin', steps: 2 });
  const quadratic = subdividePolygon(points, { scheme: 'bspline', degree: 2, steps: 2 });
  assert.equal(chaikin.length, quadratic.length);
  assert.ok(chaikin.every((x, i) => Math.abs(x - quadratic[i]) < 1e-12));
  const said = {
    en: ['do not keep all the input points', 'except for degree 2'],
    de: ['nicht alle Eingabepunkte behalten', 'außer für Grad 2'],
  };
  for (const [lang, words] of Object.entries(said)) {
    const text = translator(lang).t('curves.text').replace(/\s+/g, ' ');
    for (const w of words) assert.ok(text.includes(w), `${lang}: "${w}"`);
  }
});

test('conventions: δ = 0 on a cylindrical ruling is a convention — at an isolated one, a = (u, 0, 0), d = (0, 1, u²), δ(u) = (1 + u⁴)/(2u) grows without bound', () => {
  const { AnalyticSurface } = ruledlab;
  const surface = AnalyticSurface.fromFormulas({ a: ['u', '0', '0'], e: ['0', '1', 'u^2'], u: [-1, 1] });
  const u = [0.5, 0.1, 0.01, -0.01];
  const delta = surface.distribution(Float64Array.from(u));
  for (const [i, x] of u.entries()) {
    const want = (1 + x ** 4) / (2 * x);
    assert.ok(Math.abs(delta[i] - want) < 1e-9 * Math.abs(want), `u = ${x}: ${delta[i]}`);
  }
  assert.equal(surface.distribution(new Float64Array([0]))[0], 0);
  assert.ok(surface.striction(new Float64Array([0])).every(Number.isNaN));
  surface.free();
  const page = readFileSync(new URL('../../docs/src/conventions.md', import.meta.url), 'utf8').replace(/\s+/g, ' ');
  assert.ok(page.includes('ruledlab returns δ = 0 by convention'));
  assert.ok(page.includes('δ(u) = (1 + u⁴)/(2u) → ±∞'));
});

test('the polygon of perpendicular midpoints is Example 1’s polygon, after the text that describes it, never what Fig. 3 (not at hand) is said to show', () => {
  const keys = [
    'legend.perpendicularMidpoints',
    'readout.perpendicularMidpointError',
    'striction.param.midpoints',
    'striction.readout.order.perpendicular',
    'isometry.legend.envelope',
    'paper.ex1.note',
  ];
  const fig3 = /Fig\. 3['’]s polygon|Fig\. 3 polygon|of Fig\. 3\b|\(Fig\. 3[,)]|aus Abb\. 3|\(Abb\. 3[,)]/;
  for (const lang of ['en', 'de']) {
    const { t } = translator(lang);
    for (const key of keys) assert.match(t(key), lang === 'en' ? /Example 1/ : /Beispiel 1/, `${lang}: ${key}`);
    for (const key of [...keys, 'isometry.text']) assert.doesNotMatch(t(key), fig3, `${lang}: ${key}`);
  }
  for (const file of ['conventions.md', 'guide/isometries.md', 'teaching/paper.md']) {
    const page = readFileSync(new URL(`../../docs/src/${file}`, import.meta.url), 'utf8').replace(/\s+/g, ' ');
    assert.doesNotMatch(page, fig3, file);
  }
});

test('the exercises as the book and their hints state them: the tolerances drawn for the striction exercise, and the variational schemes missing 10⁻³ rad by about 5·10⁻³ or more', () => {
  const tasks = builtInTasks();
  const striction = tasks.find((t) => t.id === 'striction-accuracy');
  const tolerances = /** @type {any} */ (striction?.draw)?.tol?.list;
  assert.deepEqual(tolerances, [2e-3, 1e-3, 5e-4]);
  const page = readFileSync(new URL('../../docs/src/teaching/exercises.md', import.meta.url), 'utf8').replace(
    /\s+/g,
    ' ',
  );
  assert.ok(page.includes('within a tolerance drawn from 2·10⁻³, 10⁻³ and 5·10⁻⁴ of the exact curve'));
  // the congruence exercise: one step of every variational scheme on Example 5
  const scene = sceneOf('congruence');
  const angle = (/** @type {string} */ scheme) =>
    /** @type {number} */ (
      scene
        .create({ ...defaults(scene), congruence: 'example5', scheme, steps: 1 }, context)
        .readouts?.find((r) => r.label === 'congruence.readout.angle')?.value
    );
  const misses = ['paper', 'two-stage', 'coupled'].map(angle);
  const least = Math.min(...misses);
  assert.equal(least.toExponential(2), '4.98e-3', 'the coupled scheme, just under 5·10⁻³');
  assert.ok(misses.every((x) => x > 1e-3));
  const hints = /** @type {any} */ (tasks.find((t) => t.id === 'congruence-scheme'))?.hints.at(-1);
  assert.ok(hints.en.includes('miss by about 5·10⁻³ rad or more'), hints.en);
  assert.ok(hints.de.includes('verfehlen um etwa 5·10⁻³ rad oder mehr'), hints.de);
});

test('strip: the texts give the n slider’s range as it is, 3 to 24, apart from the 5 to 24 where coupled wins', () => {
  const n = /** @type {any} */ (sceneOf('strip').params.find((p) => p.key === 'n'));
  const said = {
    en: `(the slider runs from ${n.min} to ${n.max})`,
    de: `(der Regler reicht von ${n.min} bis ${n.max})`,
  };
  for (const [lang, words] of Object.entries(said)) {
    const { t } = translator(lang);
    for (const key of ['strip.claim.coupled', 'strip.text'])
      assert.ok(t(key).replace(/\s+/g, ' ').includes(words), `${lang}: ${key} does not say "${words}"`);
  }
});

test('congruences: butterfly has the smallest angle everywhere and the smallest distance on the sphere and Example 5; on the hyperbolic paraboloid it ties at distance 0 with the bilinear average and the coupled scheme, as the book says', () => {
  const scene = sceneOf('congruence');
  /** @type {Record<string, Record<string, {distance: number, angle: number}>>} */
  const errors = {};
  for (const congruence of ['sphere', 'hyperbolic-paraboloid', 'example5']) {
    errors[congruence] = {};
    for (const scheme of ['paper', 'two-stage', 'coupled', 'butterfly']) {
      const built = scene.create({ ...defaults(scene), congruence, scheme, steps: 1 }, context);
      const value = (/** @type {string} */ l) =>
        /** @type {number} */ (built.readouts?.find((r) => r.label === l)?.value);
      errors[congruence][scheme] = {
        distance: value('congruence.readout.distance'),
        angle: value('congruence.readout.angle'),
      };
    }
  }
  for (const [congruence, by] of Object.entries(errors)) {
    const { butterfly, ...others } = by;
    for (const [scheme, e] of Object.entries(others)) {
      assert.ok(butterfly.angle < e.angle, `${congruence}: ${scheme}'s angle`);
      if (congruence !== 'hyperbolic-paraboloid')
        assert.ok(butterfly.distance < e.distance, `${congruence}: ${scheme}`);
    }
  }
  const paraboloid = errors['hyperbolic-paraboloid'];
  for (const scheme of ['paper', 'coupled', 'butterfly']) assert.ok(paraboloid[scheme].distance < 1e-15, scheme);
  assert.ok(paraboloid['two-stage'].distance > 1e-3);
  const page = readFileSync(new URL('../../docs/src/guide/congruences.md', import.meta.url), 'utf8').replace(
    /\s+/g,
    ' ',
  );
  assert.ok(!page.includes('wins everywhere'));
  assert.ok(page.includes('ties at distance 0 with the bilinear average and the coupled scheme'));
});

test('subdivision: every scheme of the book’s table is named by options the API takes, and its Example 3 column is what they give; the README’s midpoint rule is one of them', () => {
  const { AnalyticSurface } = ruledlab;
  const quartic = AnalyticSurface.byName('quartic');
  const strip = quartic.sample(12, { uMin: -1, uMax: 1, closed: false });
  const page = readFileSync(new URL('../../docs/src/guide/subdivision.md', import.meta.url), 'utf8');
  const rows = [...page.matchAll(/^\| ([^|]*?`(scheme: [^`]*)`[^|]*) \| \**([\d.e-]+)\**/gm)];
  assert.equal(rows.length, 7, 'the table names each scheme by its options');
  for (const [, name, options, said] of rows) {
    const o = /** @type {any} */ (Function(`return ({ ${options} })`)());
    if (o.scheme === 'variational') o.n = 12;
    const refined = strip.subdivide(o);
    // the inserted rulings of the interpolatory schemes (Chaikin keeps none, and the book
    // measures all its rulings, which insertedDistance does not: its options alone are checked)
    const d = o.scheme === 'chaikin' ? Number.NaN : quartic.insertedDistance(refined, 2, -1, 1);
    refined.free();
    if (o.scheme === 'chaikin') continue;
    if (Number(said) < 1e-14) assert.ok(d < 1e-14, `${name}: ${d}`);
    else assert.equal(d.toExponential(1), said, name);
  }
  const readme = readFileSync(new URL('../../README.md', import.meta.url), 'utf8');
  const literal = strip.subdivide({ scheme: 'variational', n: 12, variant: 'literal' });
  const midpoint = strip.subdivide({ scheme: 'bspline', degree: 1 });
  const coupled = strip.subdivide({ scheme: 'variational', n: 12 });
  const [l, m, c] = [literal, midpoint, coupled].map((r) => quartic.insertedDistance(r, 2, -1, 1).toExponential(1));
  assert.deepEqual([l, m, c], ['9.2e-3', '9.2e-3', '8.0e-4']);
  for (const said of [
    `${c} from`,
    `the midpoint rule's, { scheme: 'bspline', degree: 1 }`,
    "variant: 'literal'): 9.2e-3",
  ])
    assert.ok(readme.includes(said), `README: "${said}"`);
  for (const o of [literal, midpoint, coupled, strip, quartic]) o.free();
});

test('the book against what a newcomer does: no invented address, where the source comes from, the installed path of the element, its least height, the camera event, the Node.js versions', () => {
  const read = (/** @type {string} */ file) =>
    readFileSync(new URL(`../../${file}`, import.meta.url), 'utf8').replace(/\s+/g, ' ');
  const cargo = read('Cargo.toml');
  assert.ok(!/\brepository\s*=/.test(cargo), 'Cargo.toml names no repository');
  const pages = [
    'README.md',
    'Cargo.toml',
    'package.json',
    'docs/src/guide/package.md',
    'docs/src/guide/getting-started.md',
  ];
  for (const file of pages) {
    const text = read(file);
    assert.ok(!/example\.invalid|<the repository>/.test(text), `${file} invents no address`);
  }
  const pkg = read('docs/src/guide/package.md');
  assert.ok(
    !pkg.startsWith('# The npm package `npm install ruledlab` gives'),
    'package.md does not begin with npm install',
  );
  assert.ok(pkg.includes('ruledlab is not published'));
  assert.ok(pkg.includes('Its source is the repository this book belongs to'));
  // the element from an installed package, as tests/page/pack.test.mjs loads it
  const installed = '"ruledlab/view": "./node_modules/ruledlab/www/index.js"';
  for (const file of ['README.md', 'docs/src/guide/embedding.md']) {
    const text = read(file);
    assert.ok(!text.includes('src="./www/ruled-view.js"'), `${file}: a path of the repository only`);
    assert.ok(text.includes(installed), `${file}: the installed path`);
  }
  assert.ok(read('tests/page/pack.test.mjs').includes(installed));
  const element = readFileSync(new URL('../../www/ruled-view.js', import.meta.url), 'utf8');
  const least = /:host \{[^}]*min-height: (\d+)px/.exec(element)?.[1];
  const view = read('docs/src/guide/ruled-view.md');
  assert.ok(view.includes(`never less than ${least} px, the element's \`min-height\``), `ruled-view.md: ${least} px`);
  assert.ok(view.includes('the attribute itself is not changed'));
  for (const file of ['docs/src/introduction.md', 'docs/src/guide/getting-started.md', 'README.md']) {
    const text = read(file);
    assert.match(text, /16\.4/, file);
    assert.match(text, /20/, file);
  }
  assert.ok(
    read('docs/src/introduction.md').includes(
      'Node.js 16.4 runs the built package; building it from the source and its tests need Node.js 20 or later',
    ),
  );
});
