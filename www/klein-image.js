// Beyond the paper: the Klein image of lines (the book's chapter "The Klein quadric"). Lines as
// points of the Klein quadric M in P⁵, drawn in the 3D image q = cos α x + sin α R_β y of the
// core's kleinView: the points, the polygon of consecutive lines (or a congruence's net) by the
// sign of the Klein form Ω (= −h sin φ: 0 where they meet), the torsal steps, the outline of M's
// image and the conic of the first, middle and last line. The Klein scene draws its catalogue
// with it, and the Klein view beside the 3D view (stage/klein-pane.js) the lines of any scene.
import { kleinView } from '../pkg/ruledlab.js';
import { KLEIN_PROJECTION } from './klein-projection.js';

export { KLEIN_PROJECTION };

/** What a Klein image draws, in its legend (the conic where it is asked for). */
export const KLEIN_LEGEND = Object.freeze([
  { style: 'givenPoint', label: 'klein.legend.points' },
  { style: 'lineScheme', label: 'klein.legend.positive' },
  { style: 'endpointScheme', label: 'klein.legend.negative' },
  { style: 'torsal', label: 'klein.legend.torsal' },
  { style: 'level', label: 'klein.legend.outline' },
  { style: 'conic', label: 'klein.legend.conic', when: (/** @type {{conic?: unknown}} */ p) => !!p.conic },
]);

/** The legend of a congruence's net: edges, not steps. */
export const GRID_LEGEND = Object.freeze({
  'klein.legend.points': 'klein.legend.gridPoints',
  'klein.legend.positive': 'klein.legend.gridPositive',
  'klein.legend.negative': 'klein.legend.gridNegative',
  'klein.legend.torsal': 'klein.legend.gridTorsal',
  'klein.legend.conic': 'klein.legend.gridConic',
});

/**
 * The Klein image of `segments` (6 numbers a line: two of its points): the core's numbers (`k`,
 * kleinView's) and the layers that draw them; `conic` whether the conic is among them (the three
 * lines may span no plane that cuts M in one).
 * @param {Float64Array | Float32Array} segments
 * @param {{mix?: number, turn?: number, unit?: number, closed?: boolean,
 *   grid?: {rows: number, cols: number} | null, conic?: boolean}} [options]   grid: the lines are
 *   a congruence's grid, row by row (a net on M); closed: the last line and the first are a step
 */
export function kleinImage(segments, { grid = null, closed = false, conic = true, ...projection } = {}) {
  const k = kleinView(
    segments,
    grid
      ? { ...KLEIN_PROJECTION, ...projection, rows: grid.rows, cols: grid.cols }
      : { ...KLEIN_PROJECTION, ...projection, closed },
  );
  /** @type {import('./scene.js').Layer[]} */
  const layers = [
    { kind: 'polyline', style: 'level', positions: k.outline },
    { kind: 'segments', style: 'lineScheme', positions: k.positive },
    { kind: 'segments', style: 'endpointScheme', positions: k.negative },
    { kind: 'segments', style: 'torsal', positions: k.torsal },
    { kind: 'points', style: 'givenPoint', positions: k.points },
  ];
  const drawn = conic && k.conic.length > 0;
  if (drawn) layers.push({ kind: 'polyline', style: 'conic', positions: k.conic, closed: true });
  return { k, layers, conic: drawn };
}
