// The isometry figure (Section 3, Figs. 4–6): the hinge chain bent towards its conoidal model,
// or the three panels of Fig. 6 (surface, conoidal model, development: there the image of the
// striction polygon, inscribed in the polygon the developed rulings envelop), in the frame of
// the conoidal model, with ρ and Fig. 5's claims. Drawn by the isometry scene and "Your surface".
import { stripIndices } from '../../pkg/ruledlab.js';
import { f32 } from '../scene.js';
import { multiply } from '../math.js';
import { developmentSvg } from '../export/development.js';
import { parallelProblems, rulingSet, rulingValues, strictionTargets } from '../edit/sets.js';

/**
 * The bending's time t (0: the surface, 1: its conoidal model), played: the control of every scene
 * that bends a surface (each adds when it does not apply).
 * @type {import('../scene.js').Param}
 */
export const BENDING_TIME = {
  key: 't',
  label: 'isometry.param.t',
  type: 'range',
  min: 0,
  max: 1,
  step: 0.01,
  value: 1,
  play: true,
};

/** A translation by (x, y, z), column-major. */
const translation = (/** @type {number} */ x, /** @type {number} */ y, /** @type {number} */ z) =>
  new Float32Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1]);

/** Bounding box of flat xyz data moved by the 4 × 4 matrix `m`. */
function boundsThrough(/** @type {ArrayLike<number>} */ m, /** @type {ArrayLike<number>[]} */ ...arrays) {
  const min = [Infinity, Infinity, Infinity],
    max = [-Infinity, -Infinity, -Infinity];
  for (const d of arrays) {
    for (let i = 0; i + 2 < d.length; i += 3) {
      for (let k = 0; k < 3; k++) {
        const v = m[k] * d[i] + m[4 + k] * d[i + 1] + m[8 + k] * d[i + 2] + m[12 + k];
        if (v < min[k]) min[k] = v;
        if (v > max[k]) max[k] = v;
      }
    }
  }
  return { min, max };
}

/** ρ (the core's envelopeRadii) at the middle interior ruling. */
export function middleRadius(/** @type {import('../../pkg/ruledlab.js').RuledSurface} */ surface) {
  const radii = surface.envelopeRadii();
  return radii.length ? radii[Math.floor(radii.length / 2)] : NaN;
}

/** Radius r + p tan β of the cylinder touched by the conoidal rulings of the helical surface at 45° (r = 1, p = 0.4). */
const HELICAL_RADIUS = 1.4;

/**
 * Fig. 5's claims, checked against ρ: at 45° the conoidal rulings touch a cylinder of radius
 * 1.4 (the caption fails); orthogonal to the striction helix ρ → 0 at second order (it holds).
 * @param {string} name @param {number} n @param {number} radius @param {{radius: number, n: number} | null} finer
 * @returns {import('../scene.js').Claim[]}
 */
function claimsOf(name, n, radius, finer) {
  if (name === 'helical' && n >= 6)
    return [{ text: 'isometry.claim.helical', holds: Math.abs(radius - HELICAL_RADIUS) < 0.1 }];
  if (name === 'helical-orthogonal' && finer) {
    const ratio = Math.abs(radius / finer.radius);
    return [
      { text: 'isometry.claim.orthogonal', holds: Math.abs(finer.radius) < Math.abs(radius) && ratio > 3 && ratio < 5 },
    ];
  }
  return [];
}

/**
 * The isometry figure of a sampled surface: shared with "Your surface".
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {import('../../pkg/ruledlab.js').RuledSurface} surface
 * @param {{layout: string, t: number, ghost: boolean, n: number}} p
 * @param {import('../scene.js').Context} ctx
 * @param {string} name
 * @param {{radius: number, n: number} | null} [finer]   ρ of the same surface with about twice the rulings
 * @param {string | null} [from]   what the surface is, for its handles (the isometry scene): its
 *   rulings' endpoints, drawn where the input surface is (the ghost, or the first panel)
 * @returns {import('../scene.js').Built}
 */
export function isometryLayers(own, surface, p, { t }, name, finer = null, from = null) {
  const frame = f32(surface.referenceFrame());
  const inv = surface.invariants();
  const input = surface.segmentsF32();
  const bent = own(surface.bend(p.layout === 'panels' ? 1 : p.t));
  const bentSeg = bent.segmentsF32();
  const n = surface.length;
  const strip = stripIndices(n);
  /** @type {import('../scene.js').Layer[]} */
  const layers = [];
  /** @param {Float32Array} seg @param {Float32Array} striction @param {Float32Array} m @param {Float32Array | null} normals */
  const panel = (seg, striction, m, normals = null) => {
    layers.push({ kind: 'segments', style: 'ruling', positions: seg, transform: m });
    if (normals) layers.push({ kind: 'segments', style: 'normal', positions: normals, transform: m });
    layers.push({ kind: 'polyline', style: 'striction', positions: striction, transform: m });
    layers.push({ kind: 'mesh', style: 'strip', positions: seg, indices: strip, transform: m });
  };
  let box;
  /** @type {Float32Array} where the input surface is drawn */
  let inputAt = frame;
  if (p.layout === 'panels') {
    const local = boundsThrough(frame, input);
    const width = (local.max[0] - local.min[0]) * 1.25 + 1e-9;
    const left = multiply(translation(-width, 0, 0), frame);
    const right = multiply(translation(width, 0, local.min[2]), frame);
    inputAt = left;
    panel(input, f32(inv.striction), left);
    panel(bentSeg, f32(bent.invariants().striction), frame);
    panel(f32(surface.developmentInSpace()), f32(surface.developmentStrictionInSpace()), right);
    // the polygon the developed rulings envelop; the striction polygon's image is inscribed in it
    const envelope = f32(surface.developmentEnvelopeInSpace());
    layers.push({ kind: 'polyline', style: 'perpendicularMidpoints', positions: envelope, transform: right });
    box = boundsThrough(frame, input);
    box.min[0] -= width;
    box.max[0] += width;
  } else {
    const bentInv = bent.invariants();
    panel(bentSeg, f32(bentInv.striction), frame, f32(bentInv.footpoints));
    if (p.ghost && p.t > 0) layers.push({ kind: 'segments', style: 'ghost', positions: input, transform: frame });
    box = boundsThrough(frame, input, bentSeg);
  }
  const nonDevelopability = surface.nonDevelopability();
  const defect = surface.maxEdgeChange(bent);
  const development = surface.development();
  const image = surface.developmentStriction();
  const envelope = surface.developmentEnvelope();
  const radius = middleRadius(surface);
  // δ of the middle pair of rulings, on the surface and on what it is bent to: a Minding
  // isometry keeps it (Section 3); of n − 1 pairs the middle one (for 24 rulings, R₁₁R₁₂)
  const middle = Math.max(0, Math.floor((n - 2) / 2));
  const delta = inv.distribution[middle];
  const deltaBent = bent.invariants().distribution[middle];
  return {
    bounds: box,
    camera: p.layout === 'panels' ? { yaw: -Math.PI / 2, pitch: 0.8 } : { yaw: -1.2, pitch: 0.45 },
    layers,
    readouts: [
      { label: 'readout.rulings', value: n },
      { label: 'isometry.readout.nonDevelopability', value: nonDevelopability, exactZero: true },
      { label: 'isometry.readout.isometry', value: defect },
      { label: 'isometry.readout.radius', value: radius },
      { label: 'isometry.readout.delta', value: delta },
      ...(finer ? [{ label: 'isometry.readout.radiusFiner', value: finer.radius }] : []),
    ],
    claims: claimsOf(name, n, radius, finer),
    measures: { 'isometry.deltaMiddle': delta, 'isometry.deltaBentMiddle': deltaBent },
    description: t(p.layout === 'panels' ? 'isometry.describePanels' : 'isometry.describe', {
      surface: t(`surface.${name}`),
      n,
      t: p.t,
      height: nonDevelopability,
    }),
    downloads: [
      {
        label: 'isometry.download.development',
        filename: `development-${name}.svg`,
        content: () => developmentSvg(development, image, envelope, t('isometry.download.title')),
        type: 'image/svg+xml',
      },
    ],
    data: { segments: bent.segments(), transform: frame },
    problems: parallelProblems(inv.parallel, n, t),
    // the handles snap onto the striction points (a cone's: its apex), with φ, h, δ beside them
    ...(from
      ? {
          input: {
            sets: [{ ...rulingSet(surface.segments(), inputAt), targets: [strictionTargets(inv.striction, n)] }],
            from,
            values: rulingValues(inv, n, t),
          },
        }
      : {}),
  };
}
