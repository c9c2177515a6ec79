// Figures that print: in black and white every pair of legend entries a scene shows together
// can be told apart — by the dash pattern, a width ratio of at least 2 or a grey level ΔL* ≥ 25
// (dots: hollow or filled, size ratio 2, grey; surfaces: hatching or grey) — for every
// combination of every scene's switches and menus (and the ranges its legend depends on), as the
// colour-vision test checks the colours; and the TikZ export's texts are pure ASCII with symbols
// as math, in every language.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import './load.mjs';
import { SCENES } from '../../www/scenes/index.js';
import { STYLES } from '../../www/theme.js';
import { paint } from '../../www/export/projection.js';
import { texText, texLabel } from '../../www/export/tikz.js';
import { translator, LANGUAGE_CODES } from '../../www/i18n/index.js';
import { lab } from '../page/colour.mjs';

/** L* of a grey level. @param {number} g */
const lightness = (g) => lab([g, g, g])[0];

/**
 * Why two styles can be told apart in black and white, or null.
 * @param {string} a @param {string} b
 */
function printCue(a, b) {
  const [sa, sb] = [STYLES[a], STYLES[b]];
  if (sa.kind !== sb.kind) return `${sa.kind} and ${sb.kind}`;
  const [pa, pb] = [/** @type {any} */ (paint(a, true)), /** @type {any} */ (paint(b, true))];
  const dL = Math.abs(lightness(pa.color[0]) - lightness(pb.color[0]));
  if (dL >= 25) return `ΔL* ${dL.toFixed(0)}`;
  if (sa.kind === 'line') {
    if (JSON.stringify(pa.dash) !== JSON.stringify(pb.dash)) return 'dashes';
    const ratio = Math.max(pa.width, pb.width) / Math.min(pa.width, pb.width);
    return ratio >= 2 ? `widths ×${ratio.toFixed(2)}` : null;
  }
  if (sa.kind === 'point') {
    if (pa.hollow !== pb.hollow) return 'hollow and filled';
    return Math.max(pa.radius, pb.radius) / Math.min(pa.radius, pb.radius) >= 2 ? 'sizes' : null;
  }
  return pa.hatch !== pb.hatch ? 'hatching' : null;
}

/**
 * Every combination of a scene's checkboxes and menus, and of the least, default and greatest
 * values of the ranges its legend asks about.
 * @param {import('../../www/scene.js').Scene} scene
 */
function combinations(scene) {
  const asked = scene.legend.map((e) => String(e.when ?? '')).join(' ');
  /** @type {Array<Record<string, number | string | boolean>>} */
  let out = [Object.fromEntries(scene.params.map((p) => [p.key, p.value]))];
  for (const p of scene.params) {
    /** @type {Array<number | string | boolean>} */
    let values = [];
    if (p.type === 'checkbox') values = [true, false];
    else if (p.type === 'select' && p.options) values = p.options().map(([v]) => v);
    else if (p.type === 'range' && new RegExp(`\\bp\\.${p.key}\\b`).test(asked))
      values = [/** @type {number} */ (p.min), p.value, /** @type {number} */ (p.max)];
    if (values.length) out = out.flatMap((c) => values.map((v) => ({ ...c, [p.key]: v })));
  }
  return out;
}

test('black and white: every pair of legend entries shown together differs by dashes, width ×2 or ΔL* ≥ 25', () => {
  const report = [];
  for (const scene of SCENES) {
    const pairs = new Map();
    for (const params of combinations(scene)) {
      const shown = scene.legend.filter((e) => !e.when || e.when(params));
      for (let i = 0; i < shown.length; i++)
        for (let j = i + 1; j < shown.length; j++) {
          const [a, b] = [shown[i], shown[j]];
          const cue = printCue(a.style, b.style);
          assert.ok(
            cue,
            `${scene.id}: "${a.label}" (${a.style}) and "${b.label}" (${b.style}) look alike in black and white`,
          );
          pairs.set(`${a.style}/${b.style}`, cue);
        }
    }
    report.push(`${scene.id} ${pairs.size}`);
  }
  console.log(`# pairs of legend entries checked per scene: ${report.join(', ')}`);
});

test('the congruence scene’s given and inserted lines: thin and thick, as in the paper’s Fig. 13', () => {
  const given = /** @type {any} */ (paint('given', true));
  const inserted = /** @type {any} */ (paint('inserted', true));
  assert.ok(inserted.width / given.width >= 2, `${inserted.width} / ${given.width}`);
});

test('TikZ texts are pure ASCII, symbols as math: every legend, label and title in every language', () => {
  assert.equal(texText('rulings R_i'), 'rulings $R_{i}$');
  assert.equal(
    texText('common perpendiculars N_{i,i+1} and footpoints'),
    'common perpendiculars $N_{i,i+1}$ and footpoints',
  );
  assert.equal(texText('director surface d₁'), 'director surface $d_{1}$');
  assert.equal(texText('focal surface of t₂'), 'focal surface of $t_{2}$');
  assert.equal(texText('exact striction curve s(u) (wide)'), 'exact striction curve $s(u)$ (wide)');
  assert.equal(texText('central tangent s(u) + [e_3(u)] (4)'), 'central tangent $s(u)$ + [$e_{3}(u)$] (4)');
  assert.equal(
    texText('Erzeugende R_i, Kehllinie (dick) – 50 % für φ'),
    'Erzeugende $R_{i}$, Kehllinie (dick) -- 50 \\% f\\"ur $\\varphi$',
  );
  assert.equal(
    texText('the labelled cell: R, T, S and R̄ (Fig. 14)'),
    'the labelled cell: R, T, S and $\\bar{R}$ (Fig. 14)',
  );
  assert.equal(texLabel('R̄_{i,j}'), '$\\bar{R}_{i,j}$');
  assert.equal(texLabel('φ_{i,i+1}'), '$\\varphi_{i,i+1}$');
  assert.equal(texLabel('R_{i−1}'), '$R_{i-1}$');
  const ascii = /^[\x20-\x7e]*$/;
  for (const lang of LANGUAGE_CODES) {
    const { t } = translator(lang);
    for (const scene of SCENES)
      for (const key of [scene.title, ...scene.legend.map((e) => e.label)]) {
        const tex = texText(t(key));
        assert.match(tex, ascii, `${lang} ${key}: ${tex}`);
        assert.ok(!tex.includes('?') || t(key).includes('?'), `${lang} ${key}: a character without TeX: ${t(key)}`);
        assert.equal((tex.match(/\$/g) ?? []).length % 2, 0, `${lang} ${key}: ${tex}`);
      }
  }
});
