// The focal figure (beyond the paper): a grid of lines by kind (hyperbolic, elliptic,
// parabolic), its focal sheets where real, the torsal strokes, and the readouts of kinds,
// normality and the linear complex. Drawn by the focal scene, "Your congruence" and "Your data".
import { DATA_COMPLEX_TOLERANCE, ROUNDING } from '../limits.js';
import { greatest } from '../reduce.js';

/**
 * The focal figure of a grid of lines: shared with "Your congruence".
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {import('../../pkg/ruledlab.js').LineCongruence} grid
 * @param {{sheets: boolean, torsal: boolean}} p
 * @param {import('../scene.js').Context} ctx
 * @returns {{layers: import('../scene.js').Layer[], readouts: import('../scene.js').Readout[], sentence: string, positions: ArrayLike<number>[], measures: Record<string, number>}}
 */
export function focalLayers(own, grid, p, { t }) {
  // computed once by the core; every layer below is drawn from that one computation
  const geometry = own(grid.focalGeometry());
  const focal = geometry.result();
  const n = focal.kind.length;
  const [elliptic, hyperbolic, parabolic] = geometry.counts();
  const count = [elliptic, hyperbolic, parabolic];
  const real = Array.from(focal.normality).filter(Number.isFinite);
  /** @type {import('../scene.js').Layer[]} */
  const layers = [
    { kind: 'segments', style: 'focalHyperbolic', positions: geometry.linesOfKindF32(1) },
    { kind: 'segments', style: 'focalElliptic', positions: geometry.linesOfKindF32(0) },
    { kind: 'segments', style: 'focalParabolic', positions: geometry.linesOfKindF32(2) },
  ];
  /** what the view frames: the lines, and each drawn sheet's box */
  /** @type {ArrayLike<number>[]} */
  const positions = [grid.segmentsF32()];
  if (p.sheets) {
    for (const sheet of /** @type {const} */ ([1, 2])) {
      const mesh = geometry.sheetF32(sheet);
      if (mesh.indices.length === 0) continue;
      layers.push({
        kind: 'mesh',
        style: `focal${sheet}`,
        positions: mesh.positions,
        indices: mesh.indices,
        normals: mesh.normals,
      });
      positions.push([...mesh.min, ...mesh.max]);
    }
  }
  if (p.torsal) layers.push({ kind: 'segments', style: 'torsal', positions: geometry.strokesF32() });
  const complex = grid.linearComplex({ tolerance: DATA_COMPLEX_TOLERANCE });
  const normality = real.length ? greatest(real) : NaN;
  /** @type {import('../scene.js').Readout[]} */
  const readouts = [
    { label: 'focal.readout.hyperbolic', value: `${count[1]} / ${n}` },
    { label: 'focal.readout.elliptic', value: `${count[0]} / ${n}` },
    { label: 'focal.readout.parabolic', value: `${count[2]} / ${n}` },
    { label: 'focal.readout.normality', value: real.length ? normality : t('focal.none'), exactZero: true },
    { label: 'focal.readout.complex', value: t(`complex.kind.${complex.kind}`) },
  ];
  // a pitch at rounding level is 0: the lines all meet the axis (Example 5: the z-axis)
  if (complex.kind === 'complex')
    readouts.push({
      label: 'focal.readout.pitch',
      value: Math.abs(complex.pitch) < ROUNDING ? 0 : complex.pitch,
      exactZero: true,
    });
  const sentence = t('focal.describe', {
    hyperbolic: count[1],
    elliptic: count[0],
    parabolic: count[2],
    lines: n,
    normality: real.length ? t('focal.describe.normality', { normality }) : '',
    complex: t(`complex.kind.${complex.kind}`),
  });
  /** the shares of the lines by kind, for exercises ("no real focal points": every line elliptic) */
  const measures = {
    'focal.ellipticShare': n ? count[0] / n : Number.NaN,
    'focal.hyperbolicShare': n ? count[1] / n : Number.NaN,
  };
  return { layers, readouts, sentence, positions, measures };
}
