// Your congruence: lines p(u, v) + t·e(u, v) typed as formulas, refined by the schemes of
// Section 5 like the paper's examples.
import { AnalyticCongruence } from '../../pkg/ruledlab.js';
import { defineScene, scoped } from '../scene.js';
import { congruenceFigure, SCHEME_PARAMS, LEGEND } from './congruence.js';
import { focalFigure } from './focal.js';

/** Congruences as formulas: p, e, u and v ranges, grid, a, b, c. */
export const PRESETS = {
  example5: { p: ['u', 'v', 'sin(2*u + 1.5*v)/2'], e: ['u', 'v', 'sin(u) + 1.3*cos(v)'], u: ['-1.1', '1.1'], v: ['-1.1', '1.1'], grid: [8, 7], abc: [1, 1, 1] },
  sphere: { p: ['cos(v)*cos(u)', 'cos(v)*sin(u)', 'sin(v)'], e: ['cos(v)*cos(u) + 0.3*sin(2*v)', 'cos(v)*sin(u) + 0.3*cos(3*u)', 'sin(v) + 0.3*u*v'], u: ['-0.8', '0.8'], v: ['-0.6', '0.6'], grid: [6, 6], abc: [1, 1, 1] },
  'hyperbolic-paraboloid': { p: ['u', 'v', 'u*v'], e: ['-v + 0.3*cos(2*v)', '-u + 0.3*sin(u)', '1'], u: ['-1', '1'], v: ['-1', '1'], grid: [6, 6], abc: [1, 1, 1] },
  'ellipsoid-normals': { p: ['a*cos(v)*cos(u)', 'b*cos(v)*sin(u)', 'c*sin(v)'], e: ['-cos(v)*cos(u)/a', '-cos(v)*sin(u)/b', '-sin(v)/c'], u: ['-1', '1'], v: ['-0.7', '0.7'], grid: [8, 8], abc: [1.6, 1.2, 0.8] },
  'two-lines': { p: ['u', '0', '-1'], e: ['v - u', 'a*v', '2'], u: ['-1', '1'], v: ['-1', '1'], grid: [7, 7], abc: [1, 1, 1] },
};

/** @returns {import('../scene.js').Params} */
function presetParams(/** @type {string} */ name) {
  const c = PRESETS[/** @type {keyof typeof PRESETS} */ (name)];
  if (!c) return {};
  return { px: c.p[0], py: c.p[1], pz: c.p[2], ex: c.e[0], ey: c.e[1], ez: c.e[2], umin: c.u[0], umax: c.u[1], vmin: c.v[0], vmax: c.v[1], rows: c.grid[0], cols: c.grid[1], a: c.abc[0], b: c.abc[1], c: c.abc[2] };
}

const START = presetParams('example5');
const formula = (/** @type {string} */ key) => ({ key, label: `formulaCongruence.param.${key}`, type: /** @type {const} */ ('text'), value: String(START[/** @type {keyof typeof START} */ (key)]) });

/** @type {Record<string, string>} */
const FIELDS = { 'p[0]': 'px', 'p[1]': 'py', 'p[2]': 'pz', 'e[0]': 'ex', 'e[1]': 'ey', 'e[2]': 'ez', 'u[0]': 'umin', 'u[1]': 'umax', 'v[0]': 'vmin', 'v[1]': 'vmax', u: 'umin', v: 'vmin', e: 'ex', rows: 'rows', cols: 'cols' };

export const scene = defineScene({
  id: 'formula-congruence',
  title: 'formulaCongruence.title',
  text: 'formulaCongruence.text',
  params: [
    { key: 'preset', label: 'formula.param.preset', type: 'select', value: 'example5', options: () => Object.keys(PRESETS).map((k) => [k, `congruence.${k}`]), sets: (v) => presetParams(String(v)) },
    formula('px'), formula('py'), formula('pz'), formula('ex'), formula('ey'), formula('ez'),
    formula('umin'), formula('umax'), formula('vmin'), formula('vmax'),
    { key: 'rows', label: 'formulaCongruence.param.rows', type: 'range', min: 2, max: 30, step: 1, value: 8 },
    { key: 'cols', label: 'formulaCongruence.param.cols', type: 'range', min: 2, max: 30, step: 1, value: 7 },
    { key: 'a', label: 'formula.param.a', type: 'range', min: -3, max: 3, step: 0.01, value: 1, exact: true, play: true },
    { key: 'b', label: 'formula.param.b', type: 'range', min: -3, max: 3, step: 0.01, value: 1, exact: true, play: true },
    { key: 'c', label: 'formula.param.c', type: 'range', min: -3, max: 3, step: 0.01, value: 1, exact: true, play: true },
    ...SCHEME_PARAMS,
    { key: 'focal', label: 'formulaCongruence.param.focal', type: 'checkbox', value: false },
  ],
  legend: [
    ...LEGEND,
    { style: 'focal1', label: 'focal.legend.focal1', when: (p) => !!p.focal },
    { style: 'focal2', label: 'focal.legend.focal2', when: (p) => !!p.focal },
    { style: 'torsal', label: 'focal.legend.torsal', when: (p) => !!p.focal },
  ],
  fieldOf: (option) => FIELDS[option] ?? null,
  create(p, ctx) {
    return scoped((own) => {
      const analytic = own(
        AnalyticCongruence.fromFormulas({
          p: [String(p.px), String(p.py), String(p.pz)],
          e: [String(p.ex), String(p.ey), String(p.ez)],
          u: [String(p.umin), String(p.umax)],
          v: [String(p.vmin), String(p.vmax)],
          rows: Number(p.rows),
          cols: Number(p.cols),
          parameters: { a: Number(p.a), b: Number(p.b), c: Number(p.c) },
          // German readers write 0,5: a comma between digits is a decimal comma (not in atan2's arguments)
          decimalComma: ctx.lang === 'de',
        }),
      );
      const built = congruenceFigure(own, analytic, /** @type {any} */ (p), ctx, 'formula');
      if (p.focal) {
        // beyond the paper: the focal sheets and torsal directions of the given grid (scene "Focal surfaces")
        const focal = focalFigure(own, own(analytic.grid()), { sheets: true, torsal: true }, ctx);
        built.layers.push(...focal.layers.filter((l) => l.kind === 'mesh' || l.style === 'torsal'));
        built.readouts?.push(...focal.readouts);
        built.description = `${built.description} ${focal.sentence}`;
      }
      return built;
    });
  },
});
