// The arrangement of a stage: its panel beside the view when there is room, under it otherwise
// (narrow: under NARROW px, or a box taller than wide under PORTRAIT px); the labels above the
// controls when tiny; the legend under the heading in the panel of a narrow box. The box is the element's, or
// for the page the screen. Also the share of a narrow view the legend and the toolbar cover, so
// that a fitted figure is framed between them.
import { NARROW, PORTRAIT, TINY, SMALL_VIEW } from '../limits.js';

/**
 * What arranging a stage needs besides its elements.
 * @typedef {object} LayoutPorts
 * @property {HTMLElement} host      the element the stage fills
 * @property {boolean} page          the page's stage (its box is the screen)
 * @property {() => boolean} controls   the panel shows the controls (the state's)
 * @property {() => void} fitControls   the controls measure themselves for the new width
 * @property {() => void} redraw     the view is drawn again (it moved)
 */

/**
 * Arranges the stage for the size of its box; redraws when the arrangement changed.
 * @param {import('./elements.js').StageElements} els
 * @param {LayoutPorts} ports
 */
export function arrange(els, ports) {
  const { root, panel, legend, view, bar } = els;
  const before = root.className;
  const box = root.getBoundingClientRect();
  const host = () => ports.host.getBoundingClientRect();
  const width = box.width || host().width;
  const height = ports.page ? window.innerHeight : box.height || host().height;
  const narrow = width > 0 && (width < NARROW || (height > width && width < PORTRAIT));
  root.classList.toggle('rl-narrow', narrow);
  // in a narrow box with a panel the legend goes into the panel, under the scene's heading: the
  // view keeps its whole height for the figure, and the heading, painted first (the page's shell),
  // stays where it is when the legend comes
  const legendInPanel = narrow && !panel.hidden && ports.controls();
  if (legendInPanel && legend.parentElement !== panel) els.heading.after(legend);
  if (!legendInPanel && legend.parentElement !== view) view.insertBefore(legend, bar);
  legend.classList.toggle('rl-legend-panel', legendInPanel);
  // the Klein view's legend with it, under it
  const { klein, kleinLegend } = els;
  if (legendInPanel && kleinLegend.previousElementSibling !== legend) legend.after(kleinLegend);
  if (!legendInPanel && kleinLegend.parentElement !== klein) klein.insertBefore(kleinLegend, els.kleinNote);
  kleinLegend.classList.toggle('rl-legend-panel', legendInPanel);
  // and its sliders under its legend
  const { kleinSteer } = els;
  if (legendInPanel && kleinSteer.previousElementSibling !== kleinLegend) kleinLegend.after(kleinSteer);
  if (!legendInPanel && kleinSteer.parentElement !== klein) klein.insertBefore(kleinSteer, els.kleinNote);
  kleinSteer.classList.toggle('rl-klein-steer-panel', legendInPanel);
  // in a narrow box without a panel the sliders fold under their summary (the Klein view's half
  // is small); they unfold again where there is room — the reader's own opening kept meanwhile
  const folded = narrow && !legendInPanel;
  if (folded !== kleinSteer.classList.contains('rl-klein-steer-folded')) kleinSteer.open = !folded;
  kleinSteer.classList.toggle('rl-klein-steer-folded', folded);
  root.classList.toggle('rl-tiny', width > 0 && width < TINY);
  // the hint under the view only where it fits beside the toolbar on one line
  root.classList.toggle('rl-view-small', view.getBoundingClientRect().width < SMALL_VIEW);
  ports.fitControls();
  // a new arrangement moves the view (a view resized alone is redrawn by the viewer itself)
  if (root.className !== before) ports.redraw();
}

/**
 * The shares of a canvas's height (the 3D view's, or `canvas`: the Klein view's) that the legend
 * (top) and the toolbar (bottom) cover in a narrow box; none beside a panel. (Split, the 3D view
 * has the upper half: the toolbar lies over the Klein view.)
 * @param {import('./elements.js').StageElements} els
 * @param {HTMLElement} [canvas]
 */
export function covered({ root, view, legend, toolbar, canvas: space }, canvas = space) {
  if (!root.classList.contains('rl-narrow')) return { top: 0, bottom: 0 };
  const box = canvas.getBoundingClientRect();
  if (!box.height) return { top: 0, bottom: 0 };
  const top = legend.hidden || !view.contains(legend) ? null : legend.getBoundingClientRect();
  const bar = toolbar.getBoundingClientRect();
  return {
    top: top ? Math.max(0, top.bottom - box.top) / box.height : 0,
    bottom: Math.max(0, box.bottom - bar.top) / box.height,
  };
}
