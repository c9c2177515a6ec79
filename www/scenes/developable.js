// Section 3, beyond it: paper models. A discrete developable strip (consecutive rulings
// coplanar) made from a helix by the tangent surface, a cone, a cylinder or the rectifying
// developable — or a hyperboloid's strip, which is not developable — beside its flat pattern: the
// exact unfolding (an isometry) or, for the hyperboloid, Section 3's approximate development with
// the gaps it leaves. Dragging a ruling edits the strip; the core makes it developable again (or,
// with "keep neighbours coplanar" off, the reader does: snapping an end onto the next ruling).
// The pattern is split where it overlaps itself, and downloads as SVG (1:1 in mm, tiled pages)
// and DXF. The strips and patterns are the CAM module's (the module for making things).
import { AnalyticSurface, stripIndices } from '../../pkg/ruledlab.js';
import { cam } from '../cam.js';
import { defineScene, scoped, bounds } from '../scene.js';
import { rulingSet } from '../edit/sets.js';

/** @typedef {{kind: string, n: number, turns: number, width: number, repair: boolean}} DevelopableParams */

/** A translation by (x, y, z), column-major. */
const translation = (/** @type {number} */ x, /** @type {number} */ y, /** @type {number} */ z) =>
  new Float32Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1]);

/**
 * `m` points of the helix (cos u, sin u, 0.4 u) over `turns` turns: the directrix a(u) of the
 * catalogue's helical surface (Fig. 5), sampled by the core (the ends a_i of its rulings).
 * @param {<O extends {free(): void}>(o: O) => O} own @param {number} m @param {number} turns
 */
function helix(own, m, turns) {
  const helical = own(AnalyticSurface.byName('helical'));
  const seg = own(helical.sample(m, { uMin: 0, uMax: 2 * Math.PI * turns })).segments();
  const out = new Float64Array(3 * m);
  for (let i = 0; i < m; i++) out.set(seg.subarray(6 * i, 6 * i + 3), 3 * i);
  return out;
}

/**
 * The segments (6 numbers per ruling) of the strip of the chosen construction, N rulings.
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {DevelopableParams} p
 * @returns {Float64Array}
 */
function strip(own, p) {
  const n = Number(p.n);
  const w = Number(p.width);
  const turns = Number(p.turns);
  const c = cam();
  switch (p.kind) {
    case 'tangent':
      return c.tangentSurface(helix(own, n + 1, turns), 0, w);
    case 'cone':
      return c.coneSurface(helix(own, n, turns), [0, 0, 0.4 * Math.PI * turns + 2], 1 - w / 2, 1);
    case 'cylinder':
      return c.cylinderSurface(helix(own, n, turns), [0, 0, 1], 0, w);
    case 'rectifying':
      return c.rectifyingDevelopable(helix(own, n, turns), -w / 2, w / 2);
    default: {
      const hyperboloid = own(AnalyticSurface.byName('hyperboloid'));
      // one side of the waist (a strip across it develops into crossing faces)
      const s = own(
        hyperboloid.sample(n, { uMin: 0, uMax: 2 * Math.PI * Math.min(turns, 1), vMin: -0.3 - w, vMax: -0.3 }),
      );
      return s.segments();
    }
  }
}

/**
 * The flat pattern of a strip: its exact unfolding where the core finds every pair of rulings
 * coplanar, else Section 3's approximate development (the core refuses to unfold a pair that is
 * not: `not-developable`).
 * @param {<O extends {free(): void}>(o: O) => O} own @param {Float64Array} segments
 */
function patternOf(own, segments) {
  const { FlatPattern } = cam();
  try {
    return { pattern: own(FlatPattern.unfold(segments)), developable: true };
  } catch (e) {
    if (/** @type {any} */ (e)?.details?.reason !== 'not-developable') throw e;
    return { pattern: own(FlatPattern.approximate(segments)), developable: false };
  }
}

/**
 * The flat pattern of the strip with these segments as a file for cutting (made when asked for:
 * the scene's objects are freed by then): one sheet as SVG or DXF.
 * @param {Float64Array} segments @param {'svg' | 'dxf'} format
 */
function exported(segments, format) {
  return scoped((own) => {
    const { pattern } = patternOf(own, segments);
    return format === 'svg' ? pattern.svg() : pattern.dxf();
  });
}

/**
 * The sheet tiled on A4 or Letter pages with registration marks: a zip of one SVG a page (the
 * zip's library loaded when first asked for, not with the scene).
 * @param {Float64Array} segments @param {'a4' | 'letter'} paper
 * @returns {Promise<Blob>}
 */
async function tiled(segments, paper) {
  const pages = /** @type {string[]} */ (scoped((own) => patternOf(own, segments).pattern.pages({ paper })));
  const { makeZip } = await import('../course/zip.js');
  /** @type {Record<string, string>} */
  const files = {};
  pages.forEach((page, k) => {
    files[`page-${String(k + 1).padStart(2, '0')}.svg`] = page;
  });
  return new Blob([makeZip(files)], { type: 'application/zip' });
}

export const scene = defineScene({
  id: 'developable',
  title: 'developable.title',
  text: 'developable.text',
  needs: ['cam'],
  // an edit of the rulings replaces the construction
  fixed: ['kind', 'n', 'turns', 'width'],
  params: [
    {
      key: 'kind',
      label: 'developable.param.kind',
      type: 'select',
      value: 'tangent',
      options: () => [
        ['tangent', 'developable.kind.tangent'],
        ['cone', 'developable.kind.cone'],
        ['cylinder', 'developable.kind.cylinder'],
        ['rectifying', 'developable.kind.rectifying'],
        ['hyperboloid', 'developable.kind.hyperboloid'],
      ],
    },
    { key: 'n', label: 'param.rulings', type: 'range', min: 4, max: 200, step: 1, value: 48, play: true },
    { key: 'turns', label: 'developable.param.turns', type: 'range', min: 0.25, max: 2, step: 0.05, value: 1 },
    { key: 'width', label: 'developable.param.width', type: 'range', min: 0.1, max: 1.5, step: 0.05, value: 0.8 },
    // off: a dragged strip stays as dragged (the exercise: make it developable by hand)
    { key: 'repair', label: 'developable.param.repair', type: 'checkbox', value: true },
  ],
  legend: [
    { style: 'ruling', label: 'legend.rulings' },
    { style: 'lineScheme', label: 'developable.legend.pattern' },
    { style: 'tangent', label: 'developable.legend.overlap' },
  ],
  /** @param {DevelopableParams} p */
  create(p, { t, input }) {
    return scoped((own) => {
      const edited = input?.rulings;
      const { makeDevelopable, maxAbsDelta } = cam();
      // an edited strip is made developable again by the core (the dragged ruling kept), unless
      // the reader keeps it as dragged
      const segments = edited ? (p.repair === false ? edited : makeDevelopable(edited)) : strip(own, p);
      const { pattern, developable } = patternOf(own, segments);
      const seg = new Float32Array(segments);
      const rulings = segments.length / 6;
      const box = bounds(seg);
      // the pattern in the plane z = 0, placed beside the strip
      const flat = pattern.segments(false);
      const flatBox = bounds(flat);
      const dx = box.max[0] - flatBox.min[0] + 0.5;
      const dz = box.min[2] - flatBox.min[2];
      const place = translation(dx, 0, dz);
      const overlap = pattern.segments(true);
      /** @type {import('../scene.js').Layer[]} */
      const layers = [
        { kind: 'mesh', style: 'strip', positions: seg, indices: stripIndices(rulings) },
        { kind: 'segments', style: 'ruling', positions: seg },
        { kind: 'segments', style: 'lineScheme', positions: flat, transform: place },
      ];
      if (overlap.length) layers.push({ kind: 'segments', style: 'tangent', positions: overlap, transform: place });
      const pieces = pattern.pieces().length / 2;
      const delta = maxAbsDelta(segments);
      const gaps = pattern.gaps();
      const largestGap = gaps.reduce((m, g) => Math.max(m, Math.abs(g)), 0);
      const all = bounds(
        new Float32Array([
          ...box.min,
          ...box.max,
          flatBox.min[0] + dx,
          flatBox.min[1],
          dz,
          flatBox.max[0] + dx,
          flatBox.max[1],
          dz,
        ]),
      );
      const name = p.kind;
      return {
        bounds: all,
        camera: { yaw: -1.6, pitch: 0.9 },
        layers,
        readouts: [
          { label: 'readout.rulings', value: rulings },
          { label: 'developable.readout.delta', value: delta, exactZero: true },
          { label: 'developable.readout.isometry', value: pattern.isometryLength, exactZero: true },
          { label: 'developable.readout.pieces', value: pieces },
          ...(edited ? [] : [{ label: 'developable.readout.turns', value: Number(p.turns) }]),
          ...(developable
            ? []
            : [
                { label: 'developable.readout.gap', value: largestGap },
                { label: 'developable.readout.climb', value: pattern.climb },
              ]),
        ],
        measures: { 'developable.maxAbsDelta': delta, 'developable.pieces': pieces },
        description: t(developable ? 'developable.describe' : 'developable.describeApproximate', {
          kind: t(`developable.kind.${name}`),
          n: rulings,
          pieces,
        }),
        downloads: [
          {
            label: 'developable.download.svg',
            filename: `pattern-${name}.svg`,
            content: () => exported(segments, 'svg'),
            type: 'image/svg+xml',
          },
          {
            label: 'developable.download.dxf',
            filename: `pattern-${name}.dxf`,
            content: () => exported(segments, 'dxf'),
            type: 'application/dxf',
          },
          .../** @type {const} */ (['a4', 'letter']).map((paper) => ({
            label: `developable.download.${paper}`,
            filename: `pattern-${name}-${paper}.zip`,
            content: () => tiled(segments, paper),
            type: 'application/zip',
          })),
        ],
        data: { segments },
        input: { sets: [rulingSet(segments)], from: t('developable.from', { kind: t(`developable.kind.${name}`) }) },
      };
    });
  },
});
