// Beyond the paper: the Klein quadric. The rulings of a surface of the catalogue as points of the
// Klein quadric M in P⁵, drawn in the 3D image q = cos α x + sin α R_β y the reader steers (the
// core's klein module; the book's chapter "The Klein quadric"): the polygon of the points with
// the Klein form Ω of consecutive rulings by sign (Ω = −h sin φ: 0 where they meet), the image of
// M (the shell between two spheres), the conic of a regulus and the residual of a linear complex.
// A congruence of the catalogue is a net on M instead: its grid's edges join neighbouring lines.
// The surface or congruence itself stands beside, scaled; a surface's rulings are handles there
// (an edit moves their points on M).
import { AnalyticCongruence, AnalyticSurface, RuledSurface, linearComplex } from '../../pkg/ruledlab.js';
import { rulingSet } from '../edit/sets.js';
import { screenLeft } from '../camera.js';
import { defineScene, scoped } from '../scene.js';
import { GRID_LEGEND, KLEIN_LEGEND, kleinImage } from '../klein-image.js';
import { surfaceOptions, rangesOf, CONGRUENCE_PRESETS, congruencePreset } from '../catalogue.js';
import { KLEIN_RANGES } from '../limits.js';
import { KLEIN_PROJECTION } from '../klein-projection.js';

/** The surfaces offered: a regulus, helical surfaces, developables (torsal at every step), a conoid. */
const SOURCES = ['hyperboloid', 'helicoid', 'helical', 'cone', 'helix-tangent', 'quartic', 'hyperbolic-paraboloid'];

/** A congruence in the menu: its name after this prefix (a surface's value is its own name). */
const CONGRUENCE = 'congruence:';

/** Whether the menu's choice is a congruence. @param {import('../scene.js').Params} p */
const isCongruence = (p) => String(p.surface).startsWith(CONGRUENCE);

/**
 * Where the lines in space stand: their box's centre this far left of M's image as the scene's
 * camera first sees it (not behind it), and their radius there.
 */
const SPACE_AT = 3.2;
const SPACE_RADIUS = 1.3;
/** The scene's camera at first. */
const CAMERA = { yaw: -0.5, pitch: 0.35 };
/** Left on the screen of that camera, in space: (sin yaw, −cos yaw, 0). */
const LEFT = screenLeft(CAMERA.yaw);

/**
 * The similarity that stands `segments` beside M: scaled by s about their box's centre c, which
 * goes to SPACE_AT · LEFT (x ↦ s (x − c) + SPACE_AT · LEFT), as a column-major 4 × 4 matrix. Made
 * from the scene's own lines, not from an edit of them, so that a drag does not move the frame.
 * @param {Float64Array} segments
 */
function standBeside(segments) {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < segments.length; i++) {
    min[i % 3] = Math.min(min[i % 3], segments[i]);
    max[i % 3] = Math.max(max[i % 3], segments[i]);
  }
  const c = min.map((m, k) => (m + max[k]) / 2);
  let half = 0;
  for (let k = 0; k < 3; k++) half = Math.max(half, max[k] - c[k]);
  const s = SPACE_RADIUS / (half || 1);
  const t = LEFT.map((l, k) => SPACE_AT * l - s * c[k]);
  return new Float32Array([s, 0, 0, 0, 0, s, 0, 0, 0, 0, s, 0, t[0], t[1], t[2], 1]);
}

/** @typedef {{surface: string, n: number, side: number, mix: number, turn: number, unit: number, conic: boolean, space: boolean, mark: number}} KleinParams */

/**
 * The side × side grid of the catalogue's congruence `name` (from its formulas, as "Your
 * congruence" makes it).
 * @param {string} name
 * @param {number} side
 */
function grid(name, side) {
  const c = congruencePreset(name);
  if (!c) throw new Error(`unknown congruence "${name}"`);
  const analytic = AnalyticCongruence.fromFormulas({
    p: c.p,
    e: c.e,
    u: c.u,
    v: c.v,
    rows: side,
    cols: side,
    parameters: c.parameters,
  });
  try {
    return analytic.grid(side, side, c.reach);
  } finally {
    analytic.free();
  }
}

/**
 * Edge `k` of a side × side grid (kleinView's order: the rows' edges row by row, then the
 * columns' column by column) named by its two lines: "(row, column)–(row, column)".
 * @param {number} k
 * @param {number} side
 */
function edgeName(k, side) {
  const along = side * (side - 1);
  const [a, b] =
    k < along
      ? [Math.floor(k / (side - 1)), k % (side - 1)]
      : [(k - along) % (side - 1), Math.floor((k - along) / (side - 1))];
  return k < along ? `(${a}, ${b})–(${a}, ${b + 1})` : `(${a}, ${b})–(${a + 1}, ${b})`;
}

export const scene = defineScene({
  id: 'klein',
  title: 'klein.title',
  text: 'klein.text',
  params: [
    {
      key: 'surface',
      label: 'klein.param.source',
      type: 'select',
      value: 'hyperboloid',
      options: () => [
        ...surfaceOptions(SOURCES)(),
        ...CONGRUENCE_PRESETS.map(
          (c) => /** @type {[string, string]} */ ([CONGRUENCE + c.name, `congruence.${c.name}`]),
        ),
      ],
    },
    {
      key: 'n',
      label: 'param.rulings',
      type: 'range',
      min: 6,
      max: 80,
      step: 1,
      value: 24,
      play: true,
      unless: (p) => (isCongruence(p) ? 'klein.reason.congruence' : null),
    },
    {
      key: 'side',
      label: 'klein.param.side',
      type: 'range',
      min: 2,
      max: 12,
      step: 1,
      value: 12,
      play: true,
      unless: (p) => (isCongruence(p) ? null : 'klein.reason.surface'),
    },
    .../** @type {const} */ (['mix', 'turn', 'unit']).map((key) => ({
      key,
      label: `klein.param.${key}`,
      type: /** @type {const} */ ('range'),
      ...KLEIN_RANGES[key],
      value: KLEIN_PROJECTION[key],
      play: true,
    })),
    { key: 'conic', label: 'klein.param.conic', type: 'checkbox', value: true },
    { key: 'space', label: 'klein.param.space', type: 'checkbox', value: true },
    { key: 'mark', label: 'klein.param.mark', type: 'range', min: 0, max: 143, step: 1, value: 0, play: true },
  ],
  legend: [...KLEIN_LEGEND],
  // (an edit of the rulings holds what would replace them)
  fixed: ['surface', 'n', 'side'],
  /** @param {KleinParams} p */
  create(p, { t, input }) {
    return scoped((own) => {
      const chosen = String(p.surface);
      const congruence = chosen.startsWith(CONGRUENCE) ? chosen.slice(CONGRUENCE.length) : null;
      const name = congruence ?? chosen;
      const side = Number(p.side);
      const ranges = congruence ? null : rangesOf(name);
      const sampled = congruence
        ? own(grid(name, side))
        : own(own(AnalyticSurface.byName(name)).sample(Number(p.n), ranges ?? {}));
      // a surface's rulings as the reader moved them (their handles stand beside M)
      const edited = congruence ? null : input?.rulings;
      const lines = edited ? own(RuledSurface.fromSegments(edited)) : sampled;
      const segments = lines.segmentsF32();
      const projection = { mix: Number(p.mix), turn: Number(p.turn), unit: Number(p.unit) };
      const { k, layers, conic } = kleinImage(lines.segments(), {
        ...projection,
        grid: congruence ? { rows: side, cols: side } : null,
        closed: !!ranges?.closed,
        conic: !!p.conic,
      });
      const count = segments.length / 6;
      // the lines in space, scaled to stand beside M (the moments are taken in space itself)
      const transform = standBeside(sampled.segments());
      if (p.space) layers.push({ kind: 'segments', style: 'ruling', positions: segments, transform });
      // the marked ruling R_i (line i of the grid, row by row), bold in space and red on M
      const i = Math.min(Number(p.mark), count - 1);
      // the step from it to the next ruling, or the edge to the next line of its row (the grid's
      // edges run along the rows first): −1 where there is none
      const [row, col] = [Math.floor(i / side), i % side];
      const next = congruence ? (col < side - 1 ? row * (side - 1) + col : -1) : i < k.omega.length ? i : -1;
      if (p.space)
        layers.push({ kind: 'segments', style: 'rulingBold', positions: segments.slice(6 * i, 6 * i + 6), transform });
      layers.push({ kind: 'points', style: 'strictionPoint', positions: k.points.slice(3 * i, 3 * i + 3) });
      const [, outer] = k.radii;
      const r = Math.max(outer, SPACE_RADIUS);
      const at = LEFT.map((l) => SPACE_AT * l);
      const box = p.space
        ? {
            min: [Math.min(-outer, at[0] - SPACE_RADIUS), Math.min(-outer, at[1] - SPACE_RADIUS), -r],
            max: [Math.max(outer, at[0] + SPACE_RADIUS), Math.max(outer, at[1] + SPACE_RADIUS), r],
          }
        : { min: [-outer, -outer, -outer], max: [outer, outer, outer] };
      /** @type {import('../scene.js').Readout[]} */
      const readouts = [
        { label: 'klein.readout.residual', value: k.maxResidual, exactZero: true },
        {
          label: congruence ? 'klein.readout.gridTorsal' : 'klein.readout.torsal',
          value: `${k.torsalSteps} / ${k.omega.length}`,
        },
        { label: congruence ? 'klein.readout.gridLeast' : 'klein.readout.least', value: k.leastOmega, exactZero: true },
        {
          label: congruence ? 'klein.readout.gridMarked' : 'klein.readout.marked',
          value: next >= 0 ? k.omega[next] : congruence ? 'klein.readout.gridNoStep' : 'klein.readout.noStep',
          exactZero: true,
        },
        {
          label: congruence ? 'klein.readout.gridPlane' : 'klein.readout.plane',
          value: Number.isFinite(k.planeDistance)
            ? k.planeDistance
            : congruence
              ? 'klein.readout.gridNoPlane'
              : 'klein.readout.noPlane',
          exactZero: true,
        },
        { label: 'klein.readout.complex', value: k.complexResidual, exactZero: true },
        // a linear congruence (a 3-space section of M) lies in two independent complexes: the
        // second-best one's residual (the fit's spectrum, RMS in its own frame) is 0 too
        { label: 'klein.readout.congruence', value: linearComplex(lines.segments()).spectrum[1], exactZero: true },
      ];
      return {
        bounds: box,
        camera: CAMERA,
        layers,
        readouts,
        description: [
          t(congruence ? 'klein.describe.grid' : 'klein.describe', {
            surface: t(congruence ? `congruence.${name}` : `surface.${name}`),
            n: congruence ? side : Number(p.n),
            mix: Number(p.mix),
            turn: Number(p.turn),
            unit: Number(p.unit),
            inner: k.radii[0],
            outer,
            torsal: k.torsalSteps,
            steps: k.omega.length,
            least: congruence ? edgeName(k.leastStep, side) : k.leastStep,
            omega: k.leastOmega,
            residual: k.maxResidual,
          }),
          conic
            ? t(congruence ? 'klein.describe.gridConic' : 'klein.describe.conic', { plane: k.planeDistance })
            : p.conic
              ? t(congruence ? 'klein.describe.gridNoConic' : 'klein.describe.noConic')
              : '',
          p.space ? t('klein.describe.space') : '',
          congruence ? t('klein.describe.gridMark', { i, row, col }) : t('klein.describe.mark', { i }),
        ]
          .filter((x) => x)
          .join(' '),
        measures: { 'klein.leastStep': k.leastStep, 'klein.leastOmega': k.leastOmega },
        // a click or a tap on a point of M, or on a line in space, marks that one
        pick: { param: 'mark', points: k.points, ...(p.space ? { lines: segments, transform } : {}) },
        // the three rulings span no conic (the description says so): none in the legend either
        ...(p.conic && !conic ? { legendOff: ['klein.legend.conic'] } : {}),
        // a congruence's net: its edges join neighbouring lines of the grid
        ...(congruence ? { legendAs: GRID_LEGEND } : {}),
        data: {
          segments: lines.segments(),
          closed: !!ranges?.closed,
          // the scene's own image: the Klein view beside draws in it until the reader steers that view
          image: projection,
          // (drawn beside M, scaled: only if drawn at all)
          ...(p.space ? { transform } : {}),
          ...(congruence ? { grid: { rows: side, cols: side } } : {}),
        },
        // the handles: a surface's rulings' ends, where they are drawn beside M
        ...(p.space && !congruence
          ? {
              input: {
                sets: [rulingSet(lines.segments(), transform, !!ranges?.closed)],
                from: t('edit.from.surface', { surface: t(`surface.${name}`), n: Number(p.n) }),
              },
            }
          : {}),
      };
    });
  },
});
