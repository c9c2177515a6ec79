// Section 2, Figs. 1–3: a discrete ruled surface with its common perpendiculars and the
// striction polygon of footpoint midpoints, against the exact striction curve.
import { AnalyticSurface, RuledSurface } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { PointBatch } from '../gl/points.js';
import { stripMesh } from '../gl/mesh.js';
import { bounds } from '../math.js';
import { dropNonFinite, maxDistance, parameters, polylineSegments, wrapClosed } from '../geometry.js';
import { COLORS } from '../theme.js';
import { text } from './striction-text.js';

export const scene = {
  id: 'striction',
  title: 'Striction polygon (Figs. 1–3)',
  text,
  params: [
    {
      key: 'surface', label: 'Surface', type: 'select', value: 'hyperboloid',
      options: () => AnalyticSurface.list().map((s) => [s.name, s.title]),
    },
    { key: 'n', label: 'Rulings N', type: 'range', min: 6, max: 160, step: 1, value: 36 },
    { key: 'strip', label: 'Surface strip', type: 'checkbox', value: true },
    { key: 'normals', label: 'Common perpendiculars Nᵢ,ᵢ₊₁', type: 'checkbox', value: true },
    { key: 'polygon', label: 'Striction polygon mᵢ', type: 'checkbox', value: true },
    { key: 'exact', label: 'Exact striction curve s(u)', type: 'checkbox', value: false },
  ],

  /** Computes the scene for `params`; returns its layers, bounds and a live readout. */
  create(p) {
    const analytic = AnalyticSurface.byName(p.surface);
    const info = AnalyticSurface.list().find((s) => s.name === p.surface);
    const surface = analytic.sample(p.n);
    const segments = surface.segments();
    const segmentsF32 = surface.segmentsF32();
    // Closed surfaces: wrap so every ruling is interior and the polygon closes.
    const model = info.closed ? RuledSurface.fromSegments(wrapClosed(segments)) : surface;
    const inv = model.invariants();
    if (model !== surface) model.free();

    const feet = inv.footpoints.subarray(info.closed ? 6 : 0);
    const u = parameters(p.n, info.uMin, info.uMax, info.closed);
    const interior = info.closed ? u : u.subarray(1, p.n - 1);
    const exactAtRulings = analytic.striction(interior);
    const exactCurve = analytic.striction(parameters(400, info.uMin, info.uMax, info.closed));
    // f_{i,i+1} of each interior ruling: pair i of the (wrapped) model.
    const firstPair = info.closed ? 0 : 1;
    const forwardFeet = new Float64Array(interior.length * 3);
    for (let k = 0; k < interior.length; k++) {
      const at = 6 * (k + firstPair);
      forwardFeet.set(feet.subarray(at, at + 3), 3 * k);
    }
    const readout = {
      rulings: p.n,
      parallelPairs: inv.parallel.reduce((a, b) => a + b, 0),
      midpointError: maxDistance(inv.striction, exactAtRulings),
      footpointError: maxDistance(forwardFeet, exactAtRulings),
      meanDelta: inv.distributionMean.length ? inv.distributionMean[Math.floor(inv.distributionMean.length / 2)] : NaN,
    };
    surface.free();
    analytic.free();

    const polygon = polylineSegments(inv.striction, info.closed);
    const normals = dropNonFinite(info.closed ? inv.footpoints.subarray(6) : inv.footpoints, 6);
    const exact = polylineSegments(exactCurve, info.closed);
    return {
      bounds: bounds(segments),
      readout,
      data: { segments },
      build(gl) {
        const layers = [new LineBatch(gl, segmentsF32, { color: COLORS.ruling, width: 1.6 })];
        if (p.normals) {
          layers.push(new LineBatch(gl, normals, { color: COLORS.normal, width: 2.6 }));
          layers.push(new PointBatch(gl, dropNonFinite(normals, 3), { color: COLORS.foot, size: 5 }));
        }
        if (p.exact) layers.push(new LineBatch(gl, exact, { color: COLORS.exact, width: 5 }));
        if (p.polygon) {
          layers.push(new LineBatch(gl, polygon, { color: COLORS.striction, width: 3.2 }));
          layers.push(new PointBatch(gl, dropNonFinite(inv.striction, 3), { color: COLORS.striction, size: 7 }));
        }
        if (p.strip) {
          layers.push(stripMesh(gl, segmentsF32, { ...COLORS.strip, closed: info.closed }));
        }
        return layers;
      },
    };
  },

  legend: [
    ['ruling', 'rulings R<sub>i</sub>'],
    ['normal', 'common perpendiculars N<sub>i,i+1</sub>, footpoints', 'normals'],
    ['striction', 'striction polygon m<sub>i</sub>', 'polygon'],
    ['exact', 'exact striction curve s(u)', 'exact'],
  ],
};
