// Section 3, Figs. 4–6: discrete Minding isometries. A slider bends the hinge chain from the
// surface (t = 0) to its isometric conoidal model (t = 1); "three panels" shows Fig. 6:
// surface, conoidal model and approximate development side by side.
import { AnalyticSurface } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { PointBatch } from '../gl/points.js';
import { stripMesh } from '../gl/mesh.js';
import { bounds, cross, normalize } from '../math.js';
import { dropNonFinite, lift2d, maxRelativeEdgeChange, polylineSegments, toFrame } from '../geometry.js';
import { COLORS } from '../theme.js';
import { developmentSvg } from '../exporters.js';
import { text } from './isometry-text.js';

const SURFACES = [
  ['quartic', 'Quartic surface of Example 3 (Fig. 4)'],
  ['helical', 'Ruled helical surface (Fig. 5)'],
  ['hyperboloid', 'Hyperboloid strip (Fig. 6)'],
  ['hyperbolic-paraboloid', 'Hyperbolic paraboloid'],
  ['pluecker-conoid', 'Plücker\u2019s conoid'],
  ['helix-tangent', 'Tangent surface of a helix (developable)'],
  ['cone', 'Cone (developable)'],
];

/** Open parameter ranges that make good figures. */
const RANGES = {
  hyperboloid: { uMin: 0, uMax: 2.4, closed: false },
  helical: { uMin: 0, uMax: 9, closed: false },
  'pluecker-conoid': { uMin: 0.1, uMax: 1.5, closed: false },
  cone: { uMin: 0, uMax: 4.5, closed: false },
  'helix-tangent': { uMin: 0, uMax: 5, closed: false },
};

export const scene = {
  id: 'isometry',
  title: 'Isometric bending and development (Figs. 4–6)',
  text,
  params: [
    { key: 'surface', label: 'Surface', type: 'select', value: 'quartic', options: () => SURFACES },
    { key: 'view', label: 'View', type: 'select', value: 'bend', options: () => [['bend', 'Bend to the conoidal model'], ['panels', 'Three panels: surface | conoidal | development']] },
    { key: 'n', label: 'Rulings N', type: 'range', min: 4, max: 120, step: 1, value: 24 },
    { key: 't', label: 'Bending t', type: 'range', min: 0, max: 1, step: 0.01, value: 1 },
    { key: 'play', label: 'Animate t', type: 'checkbox', value: false, animate: { key: 't', period: 4 } },
    { key: 'ghost', label: 'Original surface (faint)', type: 'checkbox', value: true },
  ],

  create(p) {
    const analytic = AnalyticSurface.byName(p.surface);
    const surface = analytic.sample(p.n, RANGES[p.surface] ?? {});
    analytic.free();
    const input = surface.segments();
    const inv = surface.invariants();
    // Frame of the conoidal model: x = e_0, z = n_{0,1}, y = z × x (Fig. 6's reference plane).
    const origin = [...input.subarray(0, 3)];
    const x = normalize([input[3] - input[0], input[4] - input[1], input[5] - input[2]]);
    const z = [...inv.centralNormal.subarray(0, 3)];
    const frame = { origin, x, y: cross(z, x), z };

    const development = surface.development();
    const bent = surface.bend(p.view === 'panels' ? 1 : p.t);
    const bentSegs = bent.segments();
    const bentInv = bent.invariants();
    const readout = {
      rulings: p.n,
      nonDevelopability: surface.nonDevelopability(),
      isometryError: Math.max(maxRelativeEdgeChange(input, bentSegs, 6, 0), maxRelativeEdgeChange(input, bentSegs, 6, 3)),
    };

    const panels = [];
    if (p.view === 'panels') {
      const dev = surface.development();
      const box = bounds(toFrame(input, frame));
      const width = (box.max[0] - box.min[0]) * 1.25 + 1e-9;
      const floor = box.min[2];
      const left = [-width, 0, 0];
      const right = [width, 0, 0];
      panels.push(panel(toFrame(input, frame, left), polylineSegments(toFrame(inv.striction, frame, left))));
      panels.push(panel(toFrame(bentSegs, frame), polylineSegments(toFrame(bentInv.striction, frame))));
      const feet = lift2d(projectFeet(bentInv.footpoints, frame), floor, right);
      panels.push(panel(lift2d(dev, floor, right), polylineSegments(feet)));
    } else {
      const normals = toFrame(bentInv.footpoints, frame);
      panels.push(panel(toFrame(bentSegs, frame), polylineSegments(toFrame(bentInv.striction, frame)), normals));
      if (p.ghost && p.t > 0) panels.push({ ghost: toFrame(input, frame) });
    }
    // the striction image in the development: the conoidal model's footpoints, projected
    const conoidal = surface.conoidal();
    const strictionImage = projectFeet(conoidal.invariants().footpoints, frame);
    conoidal.free();
    surface.free();
    bent.free();
    const all = panels.flatMap((q) => [q.segments ?? q.ghost]);
    return {
      bounds: bounds(...all),
      camera: p.view === 'panels' ? { yaw: -Math.PI / 2, pitch: 0.8 } : { yaw: -1.2, pitch: 0.45 },
      readout,
      data: { segments: bentSegs },
      actions: [{ label: 'Download development (SVG)', filename: `development-${p.surface}.svg`, content: developmentSvg(development, strictionImage), type: 'image/svg+xml' }],
      build(gl) {
        const layers = [];
        for (const q of panels) {
          if (q.ghost) {
            layers.push(new LineBatch(gl, q.ghost, { color: COLORS.ghost, width: 1 }));
            continue;
          }
          layers.push(new LineBatch(gl, q.segments, { color: COLORS.ruling, width: 1.6 }));
          if (q.normals) layers.push(new LineBatch(gl, q.normals, { color: COLORS.normal, width: 2.2 }));
          layers.push(new LineBatch(gl, q.striction, { color: COLORS.striction, width: 3 }));
          layers.push(stripMesh(gl, q.segments, COLORS.strip));
        }
        return layers;
      },
    };
  },

  legend: [
    ['ruling', 'rulings'],
    ['striction', 'striction polygon (its image in the development)'],
    ['normal', 'common perpendiculars', (p) => p.view === 'bend'],
    ['ghost', 'original surface', (p) => p.view === 'bend' && p.ghost && p.t > 0],
  ],
};

/** One drawn surface: rulings, striction polygon segments and, optionally, common normals. */
function panel(segments, striction, normals = null) {
  return { segments, striction, normals: normals && dropNonFinite(normals, 6) };
}

/** Footpoints f_{i,i+1} of the conoidal model projected onto the reference plane (x, y). */
function projectFeet(footpoints, frame) {
  const p = toFrame(footpoints, frame);
  const out = new Float64Array((p.length / 6) * 2);
  for (let i = 0; i < p.length / 6; i++) {
    out[2 * i] = p[6 * i];
    out[2 * i + 1] = p[6 * i + 1];
  }
  return out;
}
