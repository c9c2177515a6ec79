// A figure of the current view for lecture notes, drawn like the paper's line drawings: the
// same layers the WebGL view draws, projected with the same camera. Surfaces become flat, light
// facets (back to front among themselves); every line, polygon, curve and dot is split by the
// core where a surface hides it (`hiddenLines`, src/visibility.rs), so visible pieces are drawn
// over all surfaces and hidden ones thin and dashed, or left out. The SVG and TikZ exports both
// start from here, so a figure on paper is the figure on screen.
import { hiddenLines } from '../../pkg/ruledlab.js';
import { STYLES, rgb, PALETTE } from '../theme.js';
import { FIGURE_TRIANGLES, HATCH_SPACING, PRINT_WIDTH } from '../limits.js';
import { parseRich } from '../ui/richtext.js';
import { legendOf } from '../scene.js';
import { least, greatest, append } from '../reduce.js';

/**
 * @typedef {object} Facet   a triangle of a surface, in CSS pixels (y down)
 * @property {number[]} points     x, y of its three corners
 * @property {number} depth        larger is farther
 * @property {string} style        key of STYLES (an area)
 * @property {boolean} back        its back side faces the viewer
 * @property {number} light        the view's light on it, 0 (grazing) … 1 (facing)
 *
 * @typedef {object} Run   a piece of a line of one visibility
 * @property {number[]} points     x, y pairs in CSS pixels; one pair for a dot
 * @property {boolean} visible
 *
 * @typedef {object} LineSet   the lines (or dots) of one layer, split where surfaces hide them
 * @property {'segments' | 'polyline' | 'points'} kind
 * @property {string} style        key of STYLES
 * @property {Run[]} runs
 *
 * @typedef {object} Figure
 * @property {number} width
 * @property {number} height
 * @property {Facet[]} facets       back to front
 * @property {LineSet[]} lines      in the scene's order (later ones on top)
 * @property {Array<{x: number, y: number, text: string}>} labels   top-left corner of each label box
 * @property {Array<{style: string, label: string}>} legend
 * @property {string} title
 */

const IDENTITY = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];

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
  /** @type {Facet[]} */
  const facets = [];
  /** @type {Array<{positions: Float32Array, indices: Uint32Array, transform?: Float32Array | Float64Array}>} */
  const meshes = [];
  /** @type {Array<{kind: 'segments' | 'polyline' | 'points', positions: Float32Array, closed?: boolean, transform?: Float32Array | Float64Array}>} */
  const lines = [];
  /** @type {string[]} */
  const lineStyles = [];
  for (const layer of built?.layers ?? []) {
    const style = STYLES[layer.style];
    if (layer.kind === 'mesh') {
      // a mesh of more triangles than a figure needs is drawn by its lighter stand-in
      const mesh = (layer.indices?.length ?? 0) / 3 > FIGURE_TRIANGLES && layer.moving ? layer.moving : layer;
      if (!mesh.indices || style.kind !== 'area') continue;
      append(facets, facetsOf(mesh, layer.style, m, width, height, eye));
      if (style.occludes !== false)
        meshes.push({ positions: mesh.positions, indices: mesh.indices, transform: mesh.transform });
    } else {
      lines.push({
        kind: layer.kind,
        positions: layer.positions,
        ...(layer.closed ? { closed: true } : {}),
        ...(layer.transform ? { transform: layer.transform } : {}),
      });
      lineStyles.push(layer.style);
    }
  }
  facets.sort((p, q) => q.depth - p.depth);
  // the core splits every line where a surface hides it
  const split = hiddenLines({ viewProj: m, width, height, meshes, lines });
  /** @type {LineSet[]} */
  const sets = split.lines.map((set, k) => {
    /** @type {Run[]} */
    const runs = [];
    for (let r = 0; r < set.visible.length; r++) {
      const [start, count] = [set.runs[2 * r], set.runs[2 * r + 1]];
      runs.push({ points: Array.from(set.points.subarray(2 * start, 2 * (start + count))), visible: !!set.visible[r] });
    }
    return { kind: lines[k].kind, style: lineStyles[k], runs };
  });
  const labels = [...viewer.labelLayer.children]
    .map((el, k) => ({ el: /** @type {HTMLElement} */ (el), text: built?.labels?.[k]?.text ?? '' }))
    .filter(({ el }) => !el.hidden)
    .map(({ el, text }) => {
      const match = /translate\(([-\d.e]+)px, ([-\d.e]+)px\)/.exec(el.style.transform);
      return { x: match ? Number(match[1]) : 0, y: match ? Number(match[2]) : 0, text };
    });
  const legend = (stage.scene ? legendOf(stage.scene, stage.params, built) : []).map((e) => ({
    style: e.style,
    label: stage.i18n.t(e.label),
  }));
  return {
    width,
    height,
    facets,
    lines: sets,
    labels,
    legend,
    title: stage.scene ? stage.i18n.t(stage.scene.title) : '',
  };
}

/**
 * The facets of a mesh layer in pixels, for the camera `m` (a drawing of what the view shows:
 * positions projected, each facet lit as the view's shader lights it).
 * @param {{positions: Float32Array, indices?: Uint32Array, transform?: Float32Array | Float64Array}} layer
 * @param {string} style
 * @param {ArrayLike<number>} m
 * @param {number} width
 * @param {number} height
 * @param {number[]} eye
 * @returns {Facet[]}
 */
function facetsOf(layer, style, m, width, height, eye) {
  const model = layer.transform ?? IDENTITY;
  const data = layer.positions;
  const vertex = (/** @type {number} */ k) => {
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
      ok: cw > 0 && cz >= -cw && Number.isFinite(cx / cw) && Number.isFinite(cy / cw),
    };
  };
  const idx = /** @type {Uint32Array} */ (layer.indices);
  /** @type {Facet[]} */
  const out = [];
  for (let t = 0; t + 2 < idx.length; t += 3) {
    const [a, b, c] = [vertex(idx[t]), vertex(idx[t + 1]), vertex(idx[t + 2])];
    if (!a.ok || !b.ok || !c.ok) continue;
    // front faces wind counter-clockwise in normalised device coordinates (y up), as in WebGL
    const area = (b.x - a.x) * (a.y - c.y) - (a.y - b.y) * (c.x - a.x);
    out.push({
      points: [a.x, a.y, b.x, b.y, c.x, c.y],
      depth: (a.z + b.z + c.z) / 3,
      style,
      back: area < 0,
      light: light(a.world, b.world, c.world, eye),
    });
  }
  return out;
}

/** The view's light on a flat triangle, 0 (grazing) … 1 (facing the light). */
function light(
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
  const lamp = norm([view[0] + 0.3, view[1] + 0.2, view[2] + 0.6]);
  return Math.max(0, n[0] * lamp[0] + n[1] * lamp[1] + n[2] * lamp[2]);
}

/**
 * @typedef {object} LineLook
 * @property {number[]} color    0–1
 * @property {number} width      CSS pixels
 * @property {number[] | null} dash
 * @property {number} opacity
 * @property {boolean} halo
 *
 * @typedef {object} PointLook
 * @property {number[]} color
 * @property {number} radius
 * @property {boolean} hollow
 * @property {number} opacity
 *
 * @typedef {object} AreaLook
 * @property {number[]} color    front side
 * @property {number[]} back     back side
 * @property {number} opacity
 * @property {import('../theme.js').Hatch | null} hatch
 */

/**
 * How things of `style` are painted: colour or grey, width, dash, opacity.
 * @param {string} key
 * @param {boolean} bw
 * @returns {LineLook | PointLook | AreaLook}
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
          halo: !!style.halo,
        }
      : {
          color: rgb(style.color),
          width: style.width,
          dash: style.dash ?? null,
          opacity: style.alpha ?? 1,
          halo: !!style.halo,
        };
  }
  if (style.kind === 'point') {
    return bw
      ? { color: grey(style.bw.gray), radius: style.bw.size, hollow: !!style.bw.hollow, opacity: 1 }
      : { color: rgb(style.color), radius: style.size / 2, hollow: false, opacity: 1 };
  }
  return bw
    ? { color: grey(style.bw.gray), back: grey(style.bw.back), opacity: 1, hatch: style.bw.hatch ?? null }
    : { color: rgb(style.color), back: rgb(style.back), opacity: style.alpha, hatch: null };
}

/** How hidden pieces of lines and hidden dots are drawn: thin, finely dashed, grey. */
export function hiddenLook(/** @type {LineLook} */ look, /** @type {boolean} */ bw) {
  return {
    color: bw ? [0.55, 0.55, 0.55] : look.color,
    width: Math.max(0.4, Math.min(0.8, look.width * 0.4)),
    dash: [2, 2],
    opacity: bw ? 1 : 0.55,
  };
}

/**
 * The colour of a facet: light flat shading (never dark, so lines stay legible over it), the
 * back side in its own colour.
 * @param {AreaLook} look
 * @param {Facet} facet
 * @param {boolean} bw
 */
export function facetColour(look, facet, bw) {
  const base = facet.back ? look.back : look.color;
  // black and white: the style's grey, up to 0.1 darker where the light grazes; colour: the
  // style's colour from 75 % to 100 % of its brightness
  return bw
    ? base.map((c) => c - 0.1 * (1 - facet.light))
    : base.map((c) => c * (0.75 + 0.25 * facet.light) + 0.05 * (1 - facet.light));
}

/**
 * The hatch lines of a facet (x1, y1, x2, y2 each, pixels), on a lattice fixed to the page so
 * that neighbouring facets continue each other's lines.
 * @param {number[]} points   the facet's corners
 * @param {import('../theme.js').Hatch} hatch
 * @param {number} [spacing]   distance of the lines (pixels of the figure)
 * @returns {number[][]}
 */
export function hatchLines(points, hatch, spacing = HATCH_SPACING) {
  const angles = { ne: [Math.PI / 4], nw: [-Math.PI / 4], h: [0], cross: [Math.PI / 4, -Math.PI / 4] }[hatch];
  const out = [];
  for (const angle of angles) {
    // lines n·x = k·spacing, n the normal of the direction (cos, −sin) (y down: "ne" rises)
    const n = [Math.sin(angle), Math.cos(angle)];
    const d = [0, 2, 4].map((k) => n[0] * points[k] + n[1] * points[k + 1]);
    for (let k = Math.ceil(least(d) / spacing); k * spacing <= greatest(d); k++) {
      const level = k * spacing;
      const cut = [];
      for (let e = 0; e < 3; e++) {
        const [i, j] = [e, (e + 1) % 3];
        if ((d[i] - level) * (d[j] - level) > 0 || d[i] === d[j]) continue;
        const t = (level - d[i]) / (d[j] - d[i]);
        cut.push([
          points[2 * i] + t * (points[2 * j] - points[2 * i]),
          points[2 * i + 1] + t * (points[2 * j + 1] - points[2 * i + 1]),
        ]);
      }
      // the two cuts farthest apart (a line through a corner cuts two edges there)
      let best = [0, 0];
      for (let i = 0; i < cut.length; i++)
        for (let j = i + 1; j < cut.length; j++)
          if (
            Math.hypot(cut[j][0] - cut[i][0], cut[j][1] - cut[i][1]) >
            Math.hypot(cut[best[1]][0] - cut[best[0]][0], cut[best[1]][1] - cut[best[0]][1])
          )
            best = [i, j];
      if (cut.length >= 2) out.push([...cut[best[0]], ...cut[best[1]]]);
    }
  }
  return out.filter((l) => Math.hypot(l[2] - l[0], l[3] - l[1]) > 0.05);
}

/** The grey level of hatch lines, and their width in pixels. */
export const HATCH = { grey: 0.45, width: 0.35 };

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

// ---- print: the drawing's box, and sizes that hold on paper

/**
 * One CSS pixel of the screen on paper, in mm: 1/96 inch (0.75 pt). The styles' line widths,
 * dash lengths and dot sizes are given in these pixels, and a printed figure draws them at this
 * size whatever its width: a figure shrunk to a column keeps lines and dashes that can be seen.
 */
export const PX_MM = 25.4 / 96;

/** Type sizes of a printed figure in CSS pixels (0.75 pt): labels 10 pt, legend 8 pt, title 11 pt. */
export const PRINT_TYPE = { label: 40 / 3, legend: 32 / 3, title: 44 / 3 };

/** The margin around a printed drawing (mm). */
const MARGIN_MM = 0.8;

/** The shortest dash or gap a shortened dash pattern keeps (CSS pixels: 0.6 pt, 0.2 mm). */
const LEAST_DASH = 0.8;

/** @type {CanvasRenderingContext2D | null} */
let measuring = null;

/**
 * The width of `text` (with R_{i,i+1}-style sub- and superscripts at 72 %) in `family` at `size`
 * pixels, as the browser sets it (0.5 em per character where nothing can measure).
 * @param {string} text @param {number} size @param {string} family @param {string} [style]  e.g. "italic"
 */
export function textWidth(text, size, family, style = '') {
  measuring ??= typeof document === 'object' ? document.createElement('canvas').getContext('2d') : null;
  let width = 0;
  for (const part of parseRich(text)) {
    const px = part.kind === 'text' ? size : 0.72 * size;
    if (!measuring) width += 0.5 * px * [...part.text].length;
    else {
      measuring.font = `${style} ${px}px ${family}`.trim();
      width += measuring.measureText(part.text).width;
    }
  }
  return width;
}

/** The font of a figure's labels, and of its legend and title. */
export const LABEL_FONT = 'Times New Roman, Times, serif';
export const TEXT_FONT = 'Helvetica, Arial, sans-serif';

/**
 * Where a label's text goes and what box it takes in a printed figure, its type `size` in the
 * figure's pixels: the label's box on screen has its top-left corner at (x, y).
 * @param {{x: number, y: number, text: string}} label @param {number} size
 */
export function labelBox(label, size) {
  const width = textWidth(label.text, size, LABEL_FONT, 'italic');
  return {
    x: label.x + 0.2 * size,
    baseline: label.y + 0.9 * size,
    box: [label.x, label.y, label.x + width + 0.4 * size, label.y + 1.3 * size],
  };
}

/**
 * @typedef {object} PrintFrame
 * @property {number} x        the drawing's box in the view's pixels, its margin included
 * @property {number} y
 * @property {number} w
 * @property {number} h
 * @property {number} nat      view pixels per CSS pixel on paper (0.75 pt): what a style's width,
 *   a dash, a dot's radius or a type size is multiplied by
 * @property {number} mm       mm on paper per view pixel
 */

/**
 * The box of a figure's drawing — its facets, the lines and dots drawn (hidden pieces unless
 * left out), their widths and the labels — with a small margin, for a figure `width` cm wide on
 * paper, and the size of a CSS pixel of the styles in it.
 * @param {Figure} fig
 * @param {{width?: number, bw?: boolean, labels?: boolean, hidden?: 'dashed' | 'omit'}} [options]
 * @returns {PrintFrame}
 */
export function printFrame(fig, { width = PRINT_WIDTH.default, bw = false, labels = true, hidden = 'dashed' } = {}) {
  /** @type {Array<{points: number[], r: number}>} extents in natural pixels (r: half a line's width, a dot's radius) */
  const parts = fig.facets.map((f) => ({ points: f.points, r: 0 }));
  for (const set of fig.lines) {
    const look = /** @type {any} */ (paint(set.style, bw));
    for (const run of set.runs) {
      if (!run.visible && (hidden === 'omit' || set.kind === 'points')) continue;
      const r =
        set.kind === 'points'
          ? look.radius
          : (run.visible ? look.width + (look.halo ? 3 : 0) : hiddenLook(look, bw).width) / 2;
      parts.push({ points: run.points, r });
    }
  }
  const box = (/** @type {number} */ nat) => {
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (const { points, r } of parts)
      for (let k = 0; k + 1 < points.length; k += 2) {
        x0 = Math.min(x0, points[k] - r * nat);
        x1 = Math.max(x1, points[k] + r * nat);
        y0 = Math.min(y0, points[k + 1] - r * nat);
        y1 = Math.max(y1, points[k + 1] + r * nat);
      }
    if (labels)
      for (const label of fig.labels) {
        const [a, b, c, d] = labelBox(label, PRINT_TYPE.label * nat).box;
        [x0, y0, x1, y1] = [Math.min(x0, a), Math.min(y0, b), Math.max(x1, c), Math.max(y1, d)];
      }
    // nothing drawn: the whole view
    return x1 > x0 && y1 > y0 ? [x0, y0, x1, y1] : [0, 0, fig.width, fig.height];
  };
  // type and widths are sized on paper, so the box depends on the scale and the scale on the box:
  // a few rounds settle it
  let nat = (PX_MM * fig.width) / (10 * width);
  let frame = { x: 0, y: 0, w: fig.width, h: fig.height, nat, mm: (10 * width) / fig.width };
  for (let round = 0; round < 4; round++) {
    const [x0, y0, x1, y1] = box(nat);
    const margin = (MARGIN_MM / PX_MM) * nat;
    const w = x1 - x0 + 2 * margin;
    frame = { x: x0 - margin, y: y0 - margin, w, h: y1 - y0 + 2 * margin, nat, mm: (10 * width) / w };
    nat = PX_MM / frame.mm;
  }
  return frame;
}

/**
 * The dash pattern of a dashed run `length` long (both in CSS pixels on paper): the style's
 * where the run holds two periods, shrunk until two fit on a shorter run — but no dash or gap
 * below 0.6 pt — so that a short dashed piece (a common perpendicular of a few mm) still shows
 * dashes.
 * @param {number[]} dash @param {number} length
 */
export function dashFor(dash, length) {
  const period = dash.reduce((a, b) => a + b, 0);
  if (length >= 2 * period) return dash;
  const f = Math.min(1, Math.max(length / (2 * period), LEAST_DASH / least(dash)));
  return dash.map((d) => d * f);
}

/** The length of a run (pixels of the figure). @param {number[]} points */
export function runLength(points) {
  let length = 0;
  for (let k = 2; k + 1 < points.length; k += 2)
    length += Math.hypot(points[k] - points[k - 2], points[k + 1] - points[k - 1]);
  return length;
}
