// The legend: for each thing a scene shows, a swatch drawn in its style (colour and dash, a
// dot for points, a filled square for areas: the second cue besides colour) and its name.
import { STYLES } from '../theme.js';
import { appendRich } from './richtext.js';
import { legendOf } from '../scene.js';

const SVG = 'http://www.w3.org/2000/svg';

/**
 * A small SVG swatch of a style.
 * @param {Document} doc
 * @param {string} styleKey
 */
export function swatch(doc, styleKey) {
  const style = STYLES[styleKey];
  const svg = doc.createElementNS(SVG, 'svg');
  svg.setAttribute('width', '28');
  svg.setAttribute('height', '12');
  svg.setAttribute('viewBox', '0 0 28 12');
  svg.setAttribute('aria-hidden', 'true');
  svg.classList.add('rl-swatch');
  svg.dataset.style = styleKey;
  svg.dataset.color = style.color;
  let shape;
  if (style.kind === 'line') {
    shape = doc.createElementNS(SVG, 'line');
    for (const [k, v] of Object.entries({ x1: 1, y1: 6, x2: 27, y2: 6 })) shape.setAttribute(k, String(v));
    shape.setAttribute('stroke', style.color);
    shape.setAttribute('stroke-width', String(Math.min(Math.max(style.width, 1.5), 5)));
    shape.setAttribute('stroke-opacity', String(Math.max(style.alpha ?? 1, 0.6)));
    if (style.dash) shape.setAttribute('stroke-dasharray', style.dash.join(' '));
  } else if (style.kind === 'point') {
    shape = doc.createElementNS(SVG, 'circle');
    for (const [k, v] of Object.entries({ cx: 14, cy: 6, r: Math.min(style.size / 2, 5.5) }))
      shape.setAttribute(k, String(v));
    shape.setAttribute('fill', style.color);
  } else {
    shape = doc.createElementNS(SVG, 'rect');
    for (const [k, v] of Object.entries({ x: 4, y: 0.5, width: 20, height: 11, rx: 2 }))
      shape.setAttribute(k, String(v));
    shape.setAttribute('fill', style.color);
    shape.setAttribute('fill-opacity', String(Math.max(style.alpha, 0.6)));
    shape.setAttribute('stroke', style.color);
  }
  svg.append(shape);
  return svg;
}

/**
 * Fills `list` with the scene's legend entries visible for `params` in the picture `built`.
 * @param {HTMLElement} list
 * @param {import('../scene.js').Scene} scene
 * @param {import('../scene.js').Params} params
 * @param {(key: string) => string} t
 * @param {import('../scene.js').Built | null} [built]
 */
export function showLegend(list, scene, params, t, built) {
  showEntries(list, legendOf(scene, params, built), t);
}

/**
 * Fills `list` with legend entries (a style and the i18n key of its name each).
 * @param {HTMLElement} list
 * @param {Array<{style: string, label: string}>} entries
 * @param {(key: string) => string} t
 */
export function showEntries(list, entries, t) {
  const doc = list.ownerDocument;
  list.replaceChildren(
    ...entries.map((entry) => {
      const li = doc.createElement('li');
      li.dataset.style = entry.style;
      li.append(swatch(doc, entry.style), appendRich(doc.createElement('span'), t(entry.label)));
      return li;
    }),
  );
  list.hidden = list.children.length === 0;
}
