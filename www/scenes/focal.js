// Focal surfaces (beyond the paper): a congruence's two focal sheets where they are real, the
// torsal directions as short strokes on the director surface, its lines by kind (hyperbolic,
// elliptic, parabolic), the normality and the best-fitting linear complex. Everything comes
// from the core (LineCongruence.focal, focalSheetF32, torsalStrokesF32, linearComplex).
import { AnalyticCongruence, LineCongruence } from '../../pkg/ruledlab.js';
import { defineScene, scoped, bounds } from '../scene.js';
import { focalLayers } from '../layers/focal.js';
import { CONGRUENCE_PRESETS, congruencePreset } from '../catalogue.js';
import { lineSet } from '../edit/sets.js';

/** @typedef {{congruence: string, reach: number, n: number, sheets: boolean, torsal: boolean}} FocalParams */

export const scene = defineScene({
  id: 'focal',
  title: 'focal.title',
  text: 'focal.text',
  // an edit of the lines replaces the congruence, its grid and the lines' length
  fixed: ['congruence', 'reach', 'n'],
  params: [
    {
      key: 'congruence',
      label: 'congruence.param.congruence',
      type: 'select',
      value: 'ellipsoid-normals',
      // every congruence of the catalogue, with a line length that passes its focal points
      options: () => CONGRUENCE_PRESETS.map((c) => /** @type {[string, string]} */ ([c.name, `congruence.${c.name}`])),
      sets: (v) => ({ reach: congruencePreset(String(v))?.reach ?? 1 }),
    },
    { key: 'reach', label: 'focal.param.reach', type: 'range', min: 0.2, max: 4, step: 0.1, value: 2.2 },
    { key: 'n', label: 'focal.param.n', type: 'range', min: 4, max: 40, step: 1, value: 14 },
    { key: 'sheets', label: 'focal.param.sheets', type: 'checkbox', value: true },
    { key: 'torsal', label: 'focal.param.torsal', type: 'checkbox', value: true },
  ],
  legend: [
    { style: 'focalHyperbolic', label: 'focal.legend.hyperbolic' },
    { style: 'focalElliptic', label: 'focal.legend.elliptic' },
    { style: 'focal1', label: 'focal.legend.focal1', when: (p) => !!p.sheets },
    { style: 'focal2', label: 'focal.legend.focal2', when: (p) => !!p.sheets },
    { style: 'torsal', label: 'focal.legend.torsal', when: (p) => !!p.torsal },
  ],
  /** @param {FocalParams} p */
  create(p, ctx) {
    return scoped((own) => {
      const name = String(p.congruence);
      const analytic = own(AnalyticCongruence.byName(name));
      const n = Number(p.n);
      const edited = ctx.input?.lines;
      const grid = own(edited ? LineCongruence.fromGrid(n, n, edited) : analytic.grid(n, n, Number(p.reach)));
      const figure = focalLayers(own, grid, p, ctx);
      const congruence = ctx.t(`congruence.${name}`);
      return {
        bounds: bounds(...figure.positions),
        camera: { yaw: -2.1, pitch: 0.55 },
        layers: figure.layers,
        readouts: figure.readouts,
        measures: figure.measures,
        description: `${edited ? ctx.t('edit.edited', { what: congruence }) : congruence}: ${figure.sentence}`,
        data: { segments: grid.segments(), grid: { rows: grid.rows, cols: grid.cols } },
        // the handles: p and q of every line of the grid
        input: {
          sets: [lineSet(grid.segments(), grid.cols)],
          from: ctx.t('edit.from.congruence', { congruence, rows: n, cols: n }),
        },
      };
    });
  },
});
