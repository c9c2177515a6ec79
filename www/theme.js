// The styles every scene draws with, by meaning (a ruling, the striction polygon, an exact
// curve …), in colour and in black and white. Colours come from the Okabe–Ito palette
// (safe for the three common colour-vision deficiencies) plus ink and a dark maroon chosen
// for contrast; every pair that a scene shows together stays ≥ 15 CIEDE2000 apart under
// simulated deuteranopia, protanopia and tritanopia (tests/page/a11y.test.mjs). Where two
// things must be told apart a second cue is given as well: dashes, points, width.
// In black and white (the exports' `bw`) every pair a scene shows together differs by its dash
// pattern, a width ratio of at least 2 or a grey level ΔL* ≥ 25 (points: hollow or filled, size,
// grey; surfaces: hatching or grey) — tests/node/print.test.mjs checks every combination of
// every scene's switches.

/**
 * @typedef {object} LineStyle
 * @property {'line'} kind
 * @property {string} color     CSS hex colour
 * @property {number} width     CSS pixels
 * @property {number} [alpha]   opacity, default 1
 * @property {number[]} [dash]  on/off lengths in CSS pixels
 * @property {{gray: number, width: number, dash?: number[]}} bw   black-and-white rendition
 * @property {boolean} [halo]   drawn over surfaces with a paper-coloured halo in the exports (an
 *                              exact curve on shading)
 *
 * @typedef {object} PointStyle
 * @property {'point'} kind
 * @property {string} color
 * @property {number} size      diameter in CSS pixels
 * @property {{gray: number, size: number, hollow?: boolean}} bw
 *
 * @typedef {object} AreaStyle
 * @property {'area'} kind
 * @property {string} color     front side
 * @property {string} back      back side
 * @property {number} alpha
 * @property {{gray: number, back: number, hatch?: Hatch}} bw   black and white: light greys, and
 *   a hatching where two surfaces shown together must be told apart
 * @property {boolean} [occludes]   whether it hides the lines behind it in the exports (default
 *   true; a faint ghost does not)
 *
 * @typedef {'ne' | 'nw' | 'h' | 'cross'} Hatch   lines rising to the right, falling, level, both diagonals
 *
 * @typedef {LineStyle | PointStyle | AreaStyle} Style
 */

export const PALETTE = {
  ink: '#1f2430',
  blue: '#0072b2',
  sky: '#56b4e9',
  vermillion: '#d55e00',
  orange: '#e69f00',
  yellow: '#f0e442',
  maroon: '#771100',
  grey: '#8a8f99',
  lightGrey: '#b8bcc4',
  paper: '#fbfaf7',
};

/** @returns {LineStyle} */
const line = (
  /** @type {string} */ color,
  /** @type {number} */ width,
  /** @type {LineStyle['bw']} */ bw,
  /** @type {{alpha?: number, dash?: number[], halo?: boolean}} */ extra = {},
) => ({ kind: 'line', color, width, bw, ...extra });
/** @returns {PointStyle} */
const point = (/** @type {string} */ color, /** @type {number} */ size, /** @type {PointStyle['bw']} */ bw) => ({
  kind: 'point',
  color,
  size,
  bw,
});
/** @returns {AreaStyle} */
const area = (
  /** @type {string} */ color,
  /** @type {string} */ back,
  /** @type {number} */ alpha,
  /** @type {AreaStyle['bw']} */ bw,
  /** @type {{occludes?: boolean}} */ extra = {},
) => ({ kind: 'area', color, back, alpha, bw, ...extra });

/** @type {Record<string, Style>} */
export const STYLES = {
  ruling: line(PALETTE.ink, 1.6, { gray: 0, width: 0.6 }),
  rulingBold: line(PALETTE.ink, 2.6, { gray: 0, width: 1.2 }),
  given: line(PALETTE.ink, 2.2, { gray: 0, width: 0.6 }),
  givenPoint: point(PALETTE.ink, 8, { gray: 0, size: 3 }),
  givenThin: line(PALETTE.ink, 1.1, { gray: 0, width: 0.5 }),
  normal: line(PALETTE.blue, 2.4, { gray: 0, width: 0.6, dash: [3, 2] }),
  foot: point(PALETTE.blue, 6, { gray: 0, size: 2.5, hollow: true }),
  striction: line(PALETTE.vermillion, 3.4, { gray: 0, width: 1.6 }),
  strictionPoint: point(PALETTE.vermillion, 8, { gray: 0, size: 3.5 }),
  perpendicularMidpoints: line(PALETTE.maroon, 2.4, { gray: 0.35, width: 1.0, dash: [5, 2, 1, 2] }, { dash: [9, 5] }),
  perpendicularMidpoint: point(PALETTE.maroon, 6, { gray: 0.35, size: 2.5, hollow: true }),
  exact: line(PALETTE.sky, 6, { gray: 0.6, width: 2.4 }, { alpha: 0.85, halo: true }),
  exactPoint: point(PALETTE.sky, 11, { gray: 0.6, size: 4 }),
  tangent: line(PALETTE.maroon, 2.4, { gray: 0.35, width: 0.8, dash: [4, 2] }, { dash: [8, 5] }),
  ghost: line(PALETTE.grey, 1.2, { gray: 0.55, width: 0.4, dash: [2, 2] }, { alpha: 0.6, dash: [4, 3] }),
  helper: line(PALETTE.grey, 1.8, { gray: 0.45, width: 0.6, dash: [3, 2] }, { dash: [7, 5] }),
  level: line(PALETTE.grey, 1.2, { gray: 0.6, width: 0.5 }, { alpha: 0.7 }),
  inserted: line(PALETTE.vermillion, 2.6, { gray: 0, width: 1.4 }),
  insertedFine: line(PALETTE.vermillion, 1.2, { gray: 0.2, width: 0.5 }, { alpha: 0.85 }),
  insertedPoint: point(PALETTE.vermillion, 5, { gray: 0, size: 2 }),
  insertedAxis: line(PALETTE.blue, 1.6, { gray: 0.4, width: 0.5 }),
  optimisedAxis: line(PALETTE.maroon, 1.8, { gray: 0.5, width: 0.5, dash: [1, 1.5] }, { dash: [2, 3] }),
  result: line(PALETTE.vermillion, 3, { gray: 0, width: 1.4 }),
  resultPoint: point(PALETTE.vermillion, 6, { gray: 0, size: 2.5 }),
  pointA: point(PALETTE.sky, 13, { gray: 0.75, size: 4 }),
  pointB: point(PALETTE.blue, 13, { gray: 0.25, size: 4 }),
  triangulation: line(PALETTE.grey, 0.9, { gray: 0.55, width: 0.3 }, { alpha: 0.8 }),
  barycentre: line(PALETTE.vermillion, 2.4, { gray: 0, width: 1.0, dash: [4, 2] }, { dash: [7, 4] }),
  barycentrePoint: point(PALETTE.vermillion, 4, { gray: 0, size: 1.5 }),
  endpointScheme: line(PALETTE.orange, 1.3, { gray: 0.5, width: 0.4, dash: [3, 2] }, { alpha: 0.9, dash: [6, 4] }),
  lineScheme: line(PALETTE.blue, 1.7, { gray: 0, width: 1.4 }),
  axisLine: line(PALETTE.maroon, 2.2, { gray: 0.3, width: 0.8, dash: [6, 2, 1, 2] }, { dash: [10, 4, 2, 4] }),
  strip: area('#a9c9e8', '#f3d3a6', 0.55, { gray: 0.93, back: 0.86 }),
  stripOpaque: area('#a9c9e8', '#f3d3a6', 1, { gray: 0.93, back: 0.86 }),
  surfaceFaint: area('#b3c2d1', '#e0d5c1', 0.28, { gray: 0.96, back: 0.94 }, { occludes: false }),
  director1: area(PALETTE.sky, PALETTE.sky, 0.45, { gray: 0.9, back: 0.86 }),
  director2: area(PALETTE.yellow, PALETTE.yellow, 0.4, { gray: 0.95, back: 0.92, hatch: 'ne' }),
  envelope: area(PALETTE.yellow, PALETTE.yellow, 0.35, { gray: 0.93, back: 0.9, hatch: 'ne' }, { occludes: false }),
  part: area(PALETTE.lightGrey, PALETTE.lightGrey, 0.55, { gray: 0.9, back: 0.86 }),
  tool: area('#6e6e6e', '#6e6e6e', 0.9, { gray: 0.62, back: 0.55 }),
  endpointStrip: area(PALETTE.orange, PALETTE.orange, 0.3, { gray: 0.94, back: 0.9, hatch: 'nw' }),
  lineStrip: area(PALETTE.sky, PALETTE.sky, 0.35, { gray: 0.9, back: 0.86 }),
  focal1: area(PALETTE.blue, PALETTE.blue, 0.5, { gray: 0.86, back: 0.8, hatch: 'nw' }),
  focal2: area(PALETTE.grey, PALETTE.grey, 0.55, { gray: 0.92, back: 0.88, hatch: 'h' }),
  torsal: line(PALETTE.maroon, 2.6, { gray: 0.4, width: 1.3 }),
  conic: line(PALETTE.sky, 5, { gray: 0.6, width: 2.4, dash: [1, 1.5] }, { alpha: 0.85 }),
  cell: line(PALETTE.blue, 3.6, { gray: 0, width: 1.8 }),
  complexAxis: line(PALETTE.grey, 2.4, { gray: 0.4, width: 0.9, dash: [8, 2, 1, 2] }, { dash: [12, 4, 2, 4] }),
  focalHyperbolic: line(PALETTE.ink, 1.2, { gray: 0.3, width: 0.4 }, { alpha: 0.8 }),
  focalElliptic: line(PALETTE.orange, 1.8, { gray: 0.4, width: 0.7, dash: [3, 2] }, { dash: [6, 4] }),
  focalParabolic: line(PALETTE.vermillion, 1.8, { gray: 0.2, width: 0.7, dash: [1, 2] }, { dash: [2, 4] }),
};

/**
 * "#rrggbb" → [r, g, b] in 0–1.
 * @param {string} hex
 * @returns {number[]}
 */
export function rgb(hex) {
  return [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16) / 255);
}

/**
 * RGBA (0–1) of a style's main colour, alpha included.
 * @param {Style} style
 * @returns {number[]}
 */
export function rgba(style) {
  return [...rgb(style.color), style.kind === 'point' ? 1 : (style.alpha ?? 1)];
}
