// A figure of the current view for lecture notes: the same layers the WebGL view draws,
// projected with the same camera into flat primitives (segments, dots, shaded triangles),
// ordered back to front, with the labels where the view placed them and the legend. The SVG,
// TikZ and PNG exports all start from here, so a figure on paper is the figure on screen.
import { STYLES, rgb, PALETTE } from '../theme.js';
import { polylineSegments } from '../gl/lines.js';

/**
 * @typedef {object} Primitive
 * @property {'segment' | 'dot' | 'triangle'} kind
 * @property {number[]} points     x, y pairs in CSS pixels (y down)
 * @property {number} depth        larger is farther
 * @property {string} style        key of STYLES
 * @property {number[]} [fill]     triangle: shaded colour (0–1) or grey level
 * @property {boolean} [back]      triangle: its back side faces the viewer
 */

/**
 * @typedef {object} Figure
 * @property {number} width
 * @property {number} height
 * @property {Primitive[]} primitives   back to front
 * @property {Array<{x: number, y: number, text: string}>} labels   top-left corner of each label box
 * @property {Array<{style: string, label: string}>} legend
 * @property {string} title
 */

/** Lines and dots are drawn just in front of the surfaces they lie on, as in the view. */
const LINE_BIAS = 2e-4;
const DOT_BIAS = 4e-4;

/**
 * The figure of a stage's current view.
 * @param {import('../stage.js').Stage} stage
 * @returns {Figure}
 */
export function figureOf(stage) {
  const { viewer } = stage;
  const built = viewer.built;
  const width = Math.max(1, viewer.canvas.clientWidth);
  const height = Math.max(1, viewer.canvas.clientHeight);
  const m = viewer.camera.viewProj(width / height);
  const eye = viewer.camera.eye;
  /** @type {Primitive[]} */
  const primitives = [];
  for (const layer of built?.layers ?? []) {
    const style = STYLES[layer.style];
    const model = layer.transform ?? [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
    /** World and screen position of vertex k of `data` (3 floats each). */
    const vertex = (/** @type {ArrayLike<number>} */ data, /** @type {number} */ k) => {
      const [x, y, z] = [data[3 * k], data[3 * k + 1], data[3 * k + 2]];
      const wx = model[0] * x + model[4] * y + model[8] * z + model[12];
      const wy = model[1] * x + model[5] * y + model[9] * z + model[13];
      const wz = model[2] * x + model[6] * y + model[10] * z + model[14];
      const cw = m[3] * wx + m[7] * wy + m[11] * wz + m[15];
      const cx = m[0] * wx + m[4] * wy + m[8] * wz + m[12];
      const cy = m[1] * wx + m[5] * wy + m[9] * wz + m[13];
      const cz = m[2] * wx + m[6] * wy + m[10] * wz + m[14];
      return {
        world: [wx, wy, wz],
        x: ((cx / cw + 1) / 2) * width,
        y: ((1 - cy / cw) / 2) * height,
        z: cz / cw,
        w: cw,
      };
    };
    const ok = (/** @type {{x: number, y: number, w: number}} */ v) =>
      v.w > 0 && Number.isFinite(v.x) && Number.isFinite(v.y);
    if (layer.kind === 'segments' || layer.kind === 'polyline') {
      const segments = layer.kind === 'polyline' ? polylineSegments(layer.positions, layer.closed) : layer.positions;
      for (let k = 0; 6 * k + 5 < segments.length; k++) {
        const [a, b] = [vertex(segments, 2 * k), vertex(segments, 2 * k + 1)];
        if (!ok(a) || !ok(b)) continue;
        primitives.push({
          kind: 'segment',
          points: [a.x, a.y, b.x, b.y],
          depth: (a.z + b.z) / 2 - LINE_BIAS,
          style: layer.style,
        });
      }
    } else if (layer.kind === 'points') {
      for (let k = 0; 3 * k + 2 < layer.positions.length; k++) {
        const p = vertex(layer.positions, k);
        if (ok(p)) primitives.push({ kind: 'dot', points: [p.x, p.y], depth: p.z - DOT_BIAS, style: layer.style });
      }
    } else if (layer.kind === 'mesh' && layer.indices && style.kind === 'area') {
      const idx = layer.indices;
      for (let t = 0; t + 2 < idx.length; t += 3) {
        const [a, b, c] = [
          vertex(layer.positions, idx[t]),
          vertex(layer.positions, idx[t + 1]),
          vertex(layer.positions, idx[t + 2]),
        ];
        if (!ok(a) || !ok(b) || !ok(c)) continue;
        // front faces wind counter-clockwise in normalised device coordinates (y up), as in WebGL
        const area = (b.x - a.x) * (a.y - c.y) - (a.y - b.y) * (c.x - a.x);
        const back = area < 0;
        primitives.push({
          kind: 'triangle',
          points: [a.x, a.y, b.x, b.y, c.x, c.y],
          depth: (a.z + b.z + c.z) / 3,
          style: layer.style,
          back,
          fill: [shade(a.world, b.world, c.world, eye)],
        });
      }
    }
  }
  primitives.sort((p, q) => q.depth - p.depth);
  const labels = [...viewer.labelLayer.children]
    .map((el, k) => ({ el: /** @type {HTMLElement} */ (el), text: built?.labels?.[k]?.text ?? '' }))
    .filter(({ el }) => !el.hidden)
    .map(({ el, text }) => {
      const match = /translate\(([-\d.e]+)px, ([-\d.e]+)px\)/.exec(el.style.transform);
      return { x: match ? Number(match[1]) : 0, y: match ? Number(match[2]) : 0, text };
    });
  const legend = (stage.scene?.legend ?? [])
    .filter((e) => !e.when || e.when(stage.params))
    .map((e) => ({ style: e.style, label: stage.i18n.t(e.label) }));
  return { width, height, primitives, labels, legend, title: stage.scene ? stage.i18n.t(stage.scene.title) : '' };
}

/** The light the view's mesh shader uses, as one factor (0.45 … 1) for a flat triangle. */
function shade(
  /** @type {number[]} */ a,
  /** @type {number[]} */ b,
  /** @type {number[]} */ c,
  /** @type {number[]} */ eye,
) {
  const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  const centre = [0, 1, 2].map((k) => (a[k] + b[k] + c[k]) / 3);
  let view = [0, 1, 2].map((k) => eye[k] - centre[k]);
  const norm = (/** @type {number[]} */ x) => {
    const l = Math.hypot(...x) || 1;
    return x.map((y) => y / l);
  };
  n = norm(n);
  view = norm(view);
  if (n[0] * view[0] + n[1] * view[1] + n[2] * view[2] < 0) n = n.map((x) => -x);
  const light = norm([view[0] + 0.3, view[1] + 0.2, view[2] + 0.6]);
  return 0.45 + 0.55 * Math.max(0, n[0] * light[0] + n[1] * light[1] + n[2] * light[2]);
}

/**
 * How a primitive of `style` is painted: colour or grey, width, dash, opacity.
 * @param {string} key
 * @param {boolean} bw
 */
export function paint(key, bw) {
  const style = STYLES[key];
  const grey = (/** @type {number} */ g) => [g, g, g];
  if (style.kind === 'line') {
    return bw
      ? {
          color: grey(style.bw.gray),
          width: Math.max(style.bw.width * 1.6, 0.5),
          dash: style.bw.dash ?? null,
          opacity: 1,
        }
      : { color: rgb(style.color), width: style.width, dash: style.dash ?? null, opacity: style.alpha ?? 1 };
  }
  if (style.kind === 'point') {
    return bw
      ? { color: grey(style.bw.gray), radius: style.bw.size, hollow: !!style.bw.hollow, opacity: 1 }
      : { color: rgb(style.color), radius: style.size / 2, hollow: false, opacity: 1 };
  }
  return bw
    ? { color: grey(style.bw.gray), back: grey(style.bw.back), opacity: 1 }
    : { color: rgb(style.color), back: rgb(style.back), opacity: style.alpha };
}

/** A colour (0–1) as "#rrggbb". */
export function hex(/** @type {number[]} */ c) {
  return `#${c
    .map((x) =>
      Math.round(Math.min(1, Math.max(0, x)) * 255)
        .toString(16)
        .padStart(2, '0'),
    )
    .join('')}`;
}

/** The page background. */
export const PAPER = rgb(PALETTE.paper);
