// Section 5, Figs. 11–15: line congruences between two director surfaces, refined by the
// butterfly scheme (16) or variationally (Section 5.2); given lines thin, inserted lines in
// colour, the director surface d₁ shaded (and d₂ on request).
import { AnalyticCongruence } from '../../pkg/ruledlab.js';
import { defineScene, scoped, bounds } from '../scene.js';
import { gridIndices } from '../gl/mesh.js';
import { congruenceOptions } from './common.js';

/** The schemes: menu value → subdivide options. */
/** @type {Record<string, (steps: number) => import('../../pkg/ruledlab.js').CongruenceSubdivideOptions>} */
const SCHEMES = {
  paper: (/** @type {number} */ steps) => ({ scheme: 'variational', variant: 'paper', K: 6, steps }),
  'two-stage': (/** @type {number} */ steps) => ({ scheme: 'variational', variant: 'two-stage', K: 6, steps }),
  coupled: (/** @type {number} */ steps) => ({ scheme: 'variational', variant: 'coupled', K: 6, steps }),
  butterfly: (/** @type {number} */ steps) => ({ scheme: 'butterfly', steps }),
  diagonal: () => ({ scheme: 'butterfly', diagonalOnly: true }),
};

/** Segment length as a share of the direction d: short enough to read the grid. */
const REACH = 0.35;

/**
 * The congruence figure of an analytic congruence: shared with "Your congruence".
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {import('../../pkg/ruledlab.js').AnalyticCongruence} analytic
 * @param {{scheme: string, steps: number, director: boolean, second: boolean}} p
 * @param {import('../scene.js').Context} ctx
 * @param {string} name   for the description
 * @returns {import('../scene.js').Built}
 */
export function congruenceFigure(own, analytic, p, { t }, name) {
  const grid = own(analytic.grid(undefined, undefined, REACH));
  const diagonal = p.scheme === 'diagonal';
  const steps = diagonal ? 1 : p.steps;
  const refined = own(grid.subdivide(SCHEMES[/** @type {keyof typeof SCHEMES} */ (p.scheme)](steps)));
  const given = grid.segmentsF32();
  const stride = 2 ** steps;
  const inserted = diagonal ? refined.segmentsF32() : refined.insertedF32(stride);
  const dense = diagonal ? grid : refined;
  const indices = gridIndices(dense.rows, dense.cols);
  const fine = inserted.length / 6 > 400;
  /** @type {import('../scene.js').Layer[]} */
  const layers = [
    { kind: 'segments', style: fine ? 'givenThin' : 'given', positions: given },
    { kind: 'segments', style: fine ? 'insertedFine' : 'inserted', positions: inserted },
  ];
  if (!fine) layers.push({ kind: 'points', style: 'insertedPoint', positions: diagonal ? refined.directorF32(1) : refined.insertedDirectorF32(stride, 1) });
  if (p.director) layers.push({ kind: 'mesh', style: 'director1', positions: dense.directorF32(1), indices });
  if (p.second) layers.push({ kind: 'mesh', style: 'director2', positions: dense.directorF32(2), indices });
  const lines = diagonal ? grid.rows * grid.cols + refined.rows * refined.cols : refined.rows * refined.cols;
  /** @type {import('../scene.js').Readout[]} */
  const readouts = [
    { label: 'congruence.readout.grid', value: `${grid.rows} × ${grid.cols}` },
    { label: 'congruence.readout.lines', value: lines },
  ];
  let errors = null;
  if (!diagonal && steps === 1) {
    errors = analytic.errors(refined);
    readouts.push({ label: 'congruence.readout.distance', value: errors.distance, exactZero: true }, { label: 'congruence.readout.angle', value: errors.angle, exactZero: true });
  }
  return {
    bounds: bounds(given, inserted),
    camera: { yaw: -2.1, pitch: 0.55 },
    layers,
    readouts,
    description: t('congruence.describe', {
      congruence: t(`congruence.${name}`),
      rows: grid.rows,
      cols: grid.cols,
      scheme: t(`congruence.scheme.${p.scheme}`),
      lines,
      error: errors ? t('congruence.describe.error', { distance: errors.distance, angle: errors.angle }) : '',
    }),
    data: { segments: refined.segments(), grid: { rows: refined.rows, cols: refined.cols } },
  };
}

/** The scheme parameters shared with "Your congruence". */
export const SCHEME_PARAMS = /** @type {import('../scene.js').Param[]} */ ([
  { key: 'scheme', label: 'param.scheme', type: 'select', value: 'paper', refit: false, options: () => Object.keys(SCHEMES).map((s) => [s, `congruence.scheme.${s}`]) },
  { key: 'steps', label: 'param.steps', type: 'range', min: 1, max: 3, step: 1, value: 1, play: true, unless: (p) => (p.scheme === 'diagonal' ? 'congruence.reason.diagonal' : null) },
  { key: 'director', label: 'congruence.param.director', type: 'checkbox', value: true },
  { key: 'second', label: 'congruence.param.second', type: 'checkbox', value: false },
]);

/** The legend shared with "Your congruence". */
export const LEGEND = /** @type {import('../scene.js').LegendEntry[]} */ ([
  { style: 'given', label: 'congruence.legend.given' },
  { style: 'inserted', label: 'congruence.legend.inserted' },
  { style: 'director1', label: 'congruence.legend.d1', when: (p) => !!p.director },
  { style: 'director2', label: 'congruence.legend.d2', when: (p) => !!p.second },
]);

export const scene = defineScene({
  id: 'congruence',
  title: 'congruence.title',
  text: 'congruence.text',
  paper: true,
  params: [{ key: 'congruence', label: 'congruence.param.congruence', type: 'select', value: 'example5', options: congruenceOptions }, ...SCHEME_PARAMS],
  legend: LEGEND,
  create(p, ctx) {
    return scoped((own) => {
      const name = String(p.congruence);
      const analytic = own(AnalyticCongruence.byName(name));
      return congruenceFigure(own, analytic, /** @type {any} */ (p), ctx, name);
    });
  },
});
