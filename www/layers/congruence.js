// The congruence figure (Section 5, Figs. 11–15): a grid of lines between two director
// surfaces refined by a scheme of Section 5, inserted lines in colour, the director surfaces
// shaded, every scheme compared at one step, the butterfly stencil, and Fig. 14's notation on
// one cell; with the scheme controls and the legend the congruence scene and "Your
// congruence" share.
import { gridIndices } from '../../pkg/ruledlab.js';
import { bounds, schemeParam } from '../scene.js';
import { butterflyStencil } from '../diagrams/butterfly.js';
import { FINE_LINES, ROUNDING } from '../limits.js';

/** The schemes: menu value → subdivide options. */
/** @type {Record<string, (steps: number) => import('../../pkg/ruledlab.js').CongruenceSubdivideOptions>} */
const SCHEMES = {
  paper: (/** @type {number} */ steps) => ({ scheme: 'variational', variant: 'paper', K: 6, steps }),
  'two-stage': (/** @type {number} */ steps) => ({ scheme: 'variational', variant: 'two-stage', K: 6, steps }),
  coupled: (/** @type {number} */ steps) => ({ scheme: 'variational', variant: 'coupled', K: 6, steps }),
  butterfly: (/** @type {number} */ steps) => ({ scheme: 'butterfly', steps }),
  diagonal: () => ({ scheme: 'butterfly', diagonalOnly: true }),
};

/** The schemes compared at one step, in the readout ("for comparison", beside the scheme shown). */
const COMPARED = /** @type {Array<keyof typeof SCHEMES>} */ (['paper', 'two-stage', 'coupled', 'butterfly']);

/** Segment length as a share of the direction d: short enough to read the grid. */
const REACH = 0.35;

/**
 * The grid of lines of an analytic congruence the figure refines (its default grid, segments
 * REACH of the direction long).
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {import('../../pkg/ruledlab.js').AnalyticCongruence} analytic
 */
export function givenGrid(own, analytic) {
  return own(analytic.grid(undefined, undefined, REACH));
}

/**
 * The congruence figure of a grid of lines — the given grid of an analytic congruence, compared
 * with it, or (`analytic` null) the reader's edit of it: shared with "Your congruence".
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {import('../../pkg/ruledlab.js').LineCongruence} grid   the given lines (givenGrid, or an edit)
 * @param {import('../../pkg/ruledlab.js').AnalyticCongruence | null} analytic   the congruence they sample; null for an edit
 * @param {{scheme: string, steps: number, director: boolean, second: boolean, labels?: boolean}} p
 * @param {import('../scene.js').Context} ctx
 * @param {string} name   for the description
 * @param {boolean} [compare]   measure every scheme at one step beside the chosen one (the
 *   built-in congruences, about which the text makes its comparisons)
 * @returns {import('../scene.js').Built}
 */
export function congruenceLayers(own, grid, analytic, p, { t, format }, name, compare = false) {
  const diagonal = p.scheme === 'diagonal';
  const steps = diagonal ? 1 : p.steps;
  const refined = own(grid.subdivide(SCHEMES[/** @type {keyof typeof SCHEMES} */ (p.scheme)](steps)));
  const given = grid.segmentsF32();
  const stride = 2 ** steps;
  const inserted = diagonal ? refined.segmentsF32() : refined.insertedF32(stride);
  const dense = diagonal ? grid : refined;
  const indices = gridIndices(dense.rows, dense.cols);
  const fine = inserted.length / 6 > FINE_LINES;
  // Fig. 14's notation: one cell in bold, every other line faint
  const cell = p.labels && fig14Applies(p) ? fig14Cell(refined) : null;
  /** @type {import('../scene.js').Layer[]} */
  const layers = [
    { kind: 'segments', style: cell ? 'ghost' : fine ? 'givenThin' : 'given', positions: given },
    { kind: 'segments', style: cell ? 'ghost' : fine ? 'insertedFine' : 'inserted', positions: inserted },
  ];
  if (!fine && !cell)
    layers.push({
      kind: 'points',
      style: 'insertedPoint',
      positions: diagonal ? refined.directorF32(1) : refined.insertedDirectorF32(stride, 1),
    });
  if (p.director) layers.push({ kind: 'mesh', style: 'director1', positions: dense.directorF32(1), indices });
  if (p.second) layers.push({ kind: 'mesh', style: 'director2', positions: dense.directorF32(2), indices });
  const lines = diagonal ? grid.rows * grid.cols + refined.rows * refined.cols : refined.rows * refined.cols;
  /** @type {import('../scene.js').Readout[]} */
  const readouts = [
    { label: 'congruence.readout.grid', value: `${grid.rows} × ${grid.cols}` },
    { label: 'congruence.readout.lines', value: lines },
  ];
  // the scheme shown, measured at one step (the diagonal lines at the cells' centres)
  let errors = null;
  if (analytic && (diagonal || steps === 1)) {
    errors = diagonal ? analytic.diagonalErrors(refined) : analytic.errors(refined);
    readouts.push(
      { label: 'congruence.readout.distance', value: errors.distance, exactZero: true },
      { label: 'congruence.readout.angle', value: errors.angle, exactZero: true },
    );
  }
  /** @type {import('../scene.js').Claim[]} */
  const claims = [];
  if (compare && analytic) {
    /** @type {Record<string, {distance: number, angle: number}>} */
    const all = {};
    for (const s of COMPARED) all[s] = analytic.errors(own(grid.subdivide(SCHEMES[s](1))));
    for (const s of COMPARED)
      readouts.push({
        label: `congruence.readout.compare.${s}`,
        value: `${format(all[s].distance)} / ${format(all[s].angle)}`,
      });
    const rivals = COMPARED.filter((s) => s !== 'butterfly').map((s) => all[s]);
    const best = all.butterfly;
    claims.push({
      text: 'congruence.claim.butterfly',
      holds: rivals.every((r) => best.angle < r.angle && best.distance <= r.distance + ROUNDING),
    });
  }
  if (cell) layers.push({ kind: 'segments', style: 'cell', positions: cell.lines });
  return {
    // the labelled cell fills the view (the rest stays around it as context)
    bounds: cell ? grown(bounds(cell.lines), 1.8) : bounds(given, inserted),
    camera: cell ? { yaw: -2.1, pitch: 0.3 } : { yaw: -2.1, pitch: 0.55 },
    layers,
    labels: cell?.labels ?? [],
    readouts,
    claims,
    ...(p.scheme === 'butterfly' || diagonal
      ? {
          diagram: () =>
            butterflyStencil(document, {
              title: t('congruence.stencil.title'),
              weights: t('congruence.stencil.weights'),
            }),
        }
      : {}),
    description: t(analytic ? 'congruence.describe' : 'congruence.describeEdited', {
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

/** `box` scaled by `factor` about its centre. */
function grown(/** @type {{min: number[], max: number[]}} */ box, /** @type {number} */ factor) {
  const c = box.min.map((m, k) => (m + box.max[k]) / 2);
  return {
    min: c.map((x, k) => x - ((box.max[k] - box.min[k]) / 2) * factor),
    max: c.map((x, k) => x + ((box.max[k] - box.min[k]) / 2) * factor),
  };
}

/** Whether Fig. 14's notation applies: one step of a variational scheme (T, S and R̄ exist). */
export const fig14Applies = (/** @type {{scheme: string, steps: number}} */ p) =>
  Number(p.steps) === 1 && ['paper', 'two-stage', 'coupled'].includes(p.scheme);

/**
 * Fig. 14's notation on one cell (i, j) of the grid refined once: the given lines R at even
 * indices of the refined grid, the edge lines T_{i,j} (between R_{i,j} and R_{i+1,j}) and
 * S_{i,j} (between R_{i,j} and R_{i,j+1}) and the face line R̄_{i,j}; points on d₁ are named at
 * their lower ends, the lines at their ends on d₂ (r′, s′, Q, q there). The cell's nine lines
 * (the core's segments) are drawn bold.
 * @param {import('../../pkg/ruledlab.js').LineCongruence} refined
 * @returns {{labels: import('../scene.js').Label[], lines: Float32Array}}
 */
function fig14Cell(refined) {
  const d1 = refined.directorF32(1),
    d2 = refined.directorF32(2),
    all = refined.segmentsF32();
  const i = Math.floor((refined.rows - 1) / 4),
    j = Math.floor((refined.cols - 1) / 4);
  const k = (/** @type {number} */ r, /** @type {number} */ c) => r * refined.cols + c;
  const at = (/** @type {Float32Array} */ d, /** @type {number} */ r, /** @type {number} */ c) =>
    Array.from(d.subarray(3 * k(r, c), 3 * k(r, c) + 3));
  const lines = new Float32Array(9 * 6);
  for (let a = 0; a < 3; a++)
    for (let b = 0; b < 3; b++)
      lines.set(all.subarray(6 * k(2 * i + a, 2 * j + b), 6 * k(2 * i + a, 2 * j + b) + 6), 6 * (3 * a + b));
  const labels = [
    { at: at(d1, 2 * i, 2 * j), text: 'p_{i,j}' },
    { at: at(d1, 2 * i + 2, 2 * j), text: 'p_{i+1,j}' },
    { at: at(d1, 2 * i, 2 * j + 2), text: 'p_{i,j+1}' },
    { at: at(d1, 2 * i + 2, 2 * j + 2), text: 'p_{i+1,j+1}' },
    { at: at(d1, 2 * i + 1, 2 * j), text: 'r_{i,j}' },
    { at: at(d1, 2 * i, 2 * j + 1), text: 's_{i,j}' },
    { at: at(d1, 2 * i + 1, 2 * j + 1), text: 'P_{i,j}' },
    { at: at(d2, 2 * i, 2 * j), text: 'R_{i,j}' },
    { at: at(d2, 2 * i + 1, 2 * j), text: 'T_{i,j}' },
    { at: at(d2, 2 * i, 2 * j + 1), text: 'S_{i,j}' },
    { at: at(d2, 2 * i + 1, 2 * j + 1), text: 'R̄_{i,j}' },
  ];
  return { labels, lines };
}

/** The scheme parameters shared with "Your congruence". */
export const SCHEME_PARAMS = /** @type {import('../scene.js').Param[]} */ ([
  schemeParam('paper', () => Object.keys(SCHEMES).map((s) => [s, `congruence.scheme.${s}`])),
  {
    key: 'steps',
    label: 'param.steps',
    type: 'range',
    min: 1,
    max: 3,
    step: 1,
    value: 1,
    play: true,
    unless: (p) => (p.scheme === 'diagonal' ? 'congruence.reason.diagonal' : null),
  },
  { key: 'director', label: 'congruence.param.director', type: 'checkbox', value: true },
  { key: 'second', label: 'congruence.param.second', type: 'checkbox', value: false },
]);

/** The legend shared with "Your congruence". */
/** Whether the parameters show Fig. 14's notation. */
const cellShown = (/** @type {import('../scene.js').Params} */ p) =>
  !!p.labels && fig14Applies({ scheme: String(p.scheme), steps: Number(p.steps) });

export const LEGEND = /** @type {import('../scene.js').LegendEntry[]} */ ([
  { style: 'given', label: 'congruence.legend.given', when: (p) => !cellShown(p) },
  { style: 'inserted', label: 'congruence.legend.inserted', when: (p) => !cellShown(p) },
  { style: 'ghost', label: 'congruence.legend.others', when: cellShown },
  { style: 'director1', label: 'congruence.legend.d1', when: (p) => !!p.director },
  { style: 'director2', label: 'congruence.legend.d2', when: (p) => !!p.second },
  { style: 'cell', label: 'congruence.legend.cell', when: cellShown },
]);
