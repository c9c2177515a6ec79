// Section 2, Fig. 1: the notation of a discrete ruled surface on three consecutive rulings of
// the hyperboloid of Example 1: angle, common perpendicular, footpoints, distance, and the
// midpoint m_i of the two footpoints on R_i.
import { AnalyticSurface, RuledSurface } from '../../pkg/ruledlab.js';
import { defineScene, scoped, bounds, f32 } from '../scene.js';
import { footpointTargets, parallelProblems, rulingSet, rulingValues } from '../edit/sets.js';

/** The point t of the way along segment i of flat segments `s`. */
const along = (/** @type {Float64Array} */ s, /** @type {number} */ i, /** @type {number} */ t) =>
  [0, 1, 2].map((c) => s[6 * i + c] + t * (s[6 * i + 3 + c] - s[6 * i + c]));

export const scene = defineScene({
  id: 'notation',
  title: 'notation.title',
  text: 'notation.text',
  paper: true,
  // an edit of the three rulings replaces where they are sampled
  fixed: ['spacing', 'u'],
  params: [
    {
      key: 'spacing',
      label: 'notation.param.spacing',
      type: 'range',
      min: 0.15,
      max: 0.9,
      step: 0.01,
      value: 0.55,
      play: true,
    },
    { key: 'u', label: 'notation.param.u', type: 'range', min: 0, max: 6.28, step: 0.01, value: 0.7, play: true },
  ],
  legend: [
    { style: 'rulingBold', label: 'legend.rulings3' },
    { style: 'normal', label: 'legend.normals' },
    { style: 'helper', label: 'notation.legend.parallel' },
    { style: 'strictionPoint', label: 'notation.legend.midpoint' },
  ],
  create(p, ctx) {
    const { t } = ctx;
    return scoped((own) => {
      const u = Number(p.u),
        spacing = Number(p.spacing);
      const hyp = own(AnalyticSurface.byName('hyperboloid'));
      const sampled = own(hyp.sample(3, { uMin: u - spacing, uMax: u + spacing, closed: false }));
      // segments of one length centred on the striction points keep the picture on what matters
      // (the reader's edit of them, if any)
      const edited = ctx.input?.rulings;
      const s = own(edited ? RuledSurface.fromSegments(edited) : sampled.recut(1.6));
      const seg = s.segments();
      const inv = s.invariants();
      const e = s.directions();
      const f = inv.footpoints; // f_{0,1}, f_{1,0}, f_{1,2}, f_{2,1}
      const foot = (/** @type {number} */ k) => [f[3 * k], f[3 * k + 1], f[3 * k + 2]];
      const fi = foot(2); // f_{i,i+1}, on the middle ruling
      const e2 = [e[6], e[7], e[8]];
      const parallel = new Float32Array([...fi.map((x, c) => x - 0.9 * e2[c]), ...fi.map((x, c) => x + 0.9 * e2[c])]);
      const m = [...inv.striction.subarray(0, 3)];
      const angleAt = fi.map((x, c) => x + 0.35 * (e[3 + c] + e2[c]));
      const perpendicular = foot(2).map((x, c) => 0.35 * x + 0.65 * foot(3)[c]);
      return {
        bounds: bounds(seg),
        camera: { yaw: -0.9, pitch: 0.25 },
        layers: [
          { kind: 'segments', style: 'rulingBold', positions: f32(seg) },
          { kind: 'segments', style: 'normal', positions: f32(f) },
          { kind: 'segments', style: 'helper', positions: parallel },
          { kind: 'points', style: 'foot', positions: f32(f) },
          { kind: 'points', style: 'strictionPoint', positions: f32(m) },
        ],
        labels: [
          { at: along(seg, 0, 0.95), text: 'R_{i−1}' },
          { at: along(seg, 1, 0.95), text: 'R_i' },
          { at: along(seg, 2, 0.95), text: 'R_{i+1}' },
          { at: foot(2), text: 'f_{i,i+1}' },
          { at: foot(3), text: 'f_{i+1,i}' },
          { at: foot(1), text: 'f_{i,i−1}' },
          { at: perpendicular, text: 'N_{i,i+1}, h_{i,i+1}' },
          { at: angleAt, text: 'φ_{i,i+1}' },
          { at: m, text: 'm_i' },
        ],
        keepClear: new Float32Array([...foot(2), ...foot(3), ...foot(0), ...foot(1)]),
        readouts: [
          { label: 'notation.readout.angle', value: inv.angle[1] },
          { label: 'notation.readout.distance', value: inv.distance[1] },
          { label: 'notation.readout.delta', value: inv.distribution[1] },
        ],
        problems: parallelProblems(inv.parallel, 3, t),
        description: t(edited ? 'notation.describeEdited' : 'notation.describe', {
          angle: inv.angle[1],
          distance: inv.distance[1],
          delta: inv.distribution[1],
          spacing,
        }),
        // the handles: the endpoints of the three rulings
        input: {
          sets: [{ ...rulingSet(seg), targets: [footpointTargets(inv.footpoints, 3)] }],
          from: t('edit.from.notation', { u, spacing }),
          values: rulingValues(inv, 3, t),
        },
      };
    });
  },
});
