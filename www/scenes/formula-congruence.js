// Your congruence: lines p(u, v) + t·e(u, v) typed as formulas, refined by the schemes of
// Section 5 like the paper's examples.
import { AnalyticCongruence } from '../../pkg/ruledlab.js';
import { defineScene, scoped } from '../scene.js';
import { congruenceLayers, givenGrid, SCHEME_PARAMS, LEGEND } from '../layers/congruence.js';
import { focalLayers } from '../layers/focal.js';
import { CONGRUENCE_PRESETS, formulaFieldOf, formulaParameter, congruenceFields } from '../catalogue.js';
import { append } from '../reduce.js';

const START = congruenceFields('example5');
const formula = (/** @type {string} */ key) => ({
  key,
  label: `formulaCongruence.param.${key}`,
  type: /** @type {const} */ ('text'),
  value: String(START[/** @type {keyof typeof START} */ (key)]),
});

/** @typedef {{preset: string, px: string, py: string, pz: string, ex: string, ey: string, ez: string, umin: string, umax: string, vmin: string, vmax: string, rows: number, cols: number, a: number, b: number, c: number, scheme: string, steps: number, director: boolean, second: boolean, focal: boolean}} FormulaCongruenceParams */

export const scene = defineScene({
  id: 'formula-congruence',
  title: 'formulaCongruence.title',
  text: 'formulaCongruence.text',
  editAsData: true,
  params: [
    {
      key: 'preset',
      label: 'formula.param.preset',
      type: 'select',
      value: 'example5',
      options: () => CONGRUENCE_PRESETS.map((k) => [k.name, `congruence.${k.name}`]),
      sets: (v) => congruenceFields(String(v)),
    },
    formula('px'),
    formula('py'),
    formula('pz'),
    formula('ex'),
    formula('ey'),
    formula('ez'),
    formula('umin'),
    formula('umax'),
    formula('vmin'),
    formula('vmax'),
    { key: 'rows', label: 'formulaCongruence.param.rows', type: 'range', min: 2, max: 30, step: 1, value: 8 },
    { key: 'cols', label: 'formulaCongruence.param.cols', type: 'range', min: 2, max: 30, step: 1, value: 7 },
    formulaParameter('a', 1),
    formulaParameter('b', 1),
    formulaParameter('c', 1),
    ...SCHEME_PARAMS,
    { key: 'focal', label: 'formulaCongruence.param.focal', type: 'checkbox', value: false },
  ],
  legend: [
    ...LEGEND,
    { style: 'focal1', label: 'focal.legend.focal1', when: (p) => !!p.focal },
    { style: 'focal2', label: 'focal.legend.focal2', when: (p) => !!p.focal },
    { style: 'torsal', label: 'focal.legend.torsal', when: (p) => !!p.focal },
  ],
  fieldOf: formulaFieldOf('p'),
  /** @param {FormulaCongruenceParams} p */
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
          // 0,5 is a number in every language (a German link opened in English); only a German
          // reader's atan2(1,5) is ambiguous (an English reader's has two arguments)
          decimalComma: ctx.lang === 'de' ? true : 'unambiguous',
        }),
      );
      const built = congruenceLayers(own, givenGrid(own, analytic), analytic, p, ctx, 'formula');
      if (p.focal) {
        // beyond the paper: the focal sheets and torsal directions of the given grid (scene "Focal surfaces")
        const focal = focalLayers(own, own(analytic.grid()), { sheets: true, torsal: true }, ctx);
        append(
          built.layers,
          focal.layers.filter((l) => l.kind === 'mesh' || l.style === 'torsal'),
        );
        if (built.readouts) append(built.readouts, focal.readouts);
        built.measures = { ...built.measures, ...focal.measures };
        built.description = `${built.description} ${focal.sentence}`;
      }
      return built;
    });
  },
});
