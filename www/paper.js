// The paper's figures and examples as presets of the scenes (Odehnal & Pottmann, Figs. 1–18,
// Examples 1–6): which scene shows each, with which parameters, what the paper's caption says,
// what ruledlab shows, whose data it is, and where ruledlab goes beyond or corrects the paper.
// Shared by the page (the "Paper" menu and `#paper=fig3` links), <ruled-view paper="fig3">, the
// one-file build and the book's page of figures (docs/src/teaching/paper.md, written by scripts/paper-table.mjs); tests/node/claims.test.mjs
// computes every preset, tests/page/paper.test.mjs opens each.
import { defaults } from './scene.js';

/**
 * One figure or example of the paper.
 * @typedef {object} PaperPreset
 * @property {string} id          its name in links: fig1 … fig18, ex1 … ex6 (fig5-orthogonal and
 *                                fig13-right for the second case of a figure)
 * @property {string} label       i18n key of its name in the menu ("Fig. 3", "Example 1")
 * @property {string} scene       the scene that shows it
 * @property {import('./scene.js').Params} params   the preset's values (others: the scene's defaults)
 * @property {string} caption     i18n key of the paper's caption (or the example's statement)
 * @property {string} note        i18n key: what ruledlab shows, and whose data it is (where the
 *                                paper gives none: "the paper gives no data; ruledlab uses …")
 * @property {string} [beyond]    i18n key: where ruledlab differs from or goes beyond the paper,
 *                                and the measured consequence
 * @property {'paper' | 'partly' | 'none'} data   whether the numbers are the paper's
 */

/** Figs. 2 and 3: Example 1's hyperboloid, 36 rulings, its strip and common perpendiculars. */
const EXAMPLE_1 = {
  surface: 'hyperboloid',
  n: 36,
  strip: true,
  normals: true,
  exact: false,
  axis: false,
};

/** @type {PaperPreset[]} */
export const PRESETS = [
  {
    id: 'fig1',
    label: 'paper.fig1',
    scene: 'notation',
    params: {},
    caption: 'paper.fig1.caption',
    note: 'paper.fig1.note',
    data: 'none',
  },
  {
    id: 'fig2',
    label: 'paper.fig2',
    scene: 'striction',
    params: { ...EXAMPLE_1, polygon: true, midpoints: false },
    caption: 'paper.fig2.caption',
    note: 'paper.fig2.note',
    data: 'partly',
  },
  {
    id: 'fig3',
    label: 'paper.fig3',
    scene: 'striction',
    params: { ...EXAMPLE_1, polygon: false, midpoints: true },
    caption: 'paper.fig3.caption',
    note: 'paper.fig3.note',
    beyond: 'paper.fig3.beyond',
    data: 'partly',
  },
  {
    id: 'fig4',
    label: 'paper.fig4',
    scene: 'isometry',
    params: { surface: 'quartic', layout: 'bend', n: 24, t: 1, ghost: true },
    caption: 'paper.fig4.caption',
    note: 'paper.fig4.note',
    data: 'none',
  },
  {
    id: 'fig5',
    label: 'paper.fig5',
    scene: 'isometry',
    params: { surface: 'helical', layout: 'bend', n: 24, t: 1, ghost: true },
    caption: 'paper.fig5.caption',
    note: 'paper.fig5.note',
    beyond: 'paper.fig5.beyond',
    data: 'none',
  },
  {
    id: 'fig5-orthogonal',
    label: 'paper.fig5-orthogonal',
    scene: 'isometry',
    params: { surface: 'helical-orthogonal', layout: 'bend', n: 24, t: 1, ghost: true },
    caption: 'paper.fig5.caption',
    note: 'paper.fig5-orthogonal.note',
    beyond: 'paper.fig5.beyond',
    data: 'none',
  },
  {
    id: 'fig6',
    label: 'paper.fig6',
    scene: 'isometry',
    params: { surface: 'hyperboloid', layout: 'panels', n: 24 },
    caption: 'paper.fig6.caption',
    note: 'paper.fig6.note',
    data: 'none',
  },
  {
    id: 'fig7',
    label: 'paper.fig7',
    scene: 'curves',
    params: { scheme: 'chaikin', steps: 4, closed: false, levels: true },
    caption: 'paper.fig7.caption',
    note: 'paper.fig7.note',
    data: 'none',
  },
  {
    id: 'fig8',
    label: 'paper.fig8',
    scene: 'curves',
    params: { scheme: 'four-point', steps: 4, w: 1 / 13, closed: false, levels: true },
    caption: 'paper.fig8.caption',
    note: 'paper.fig8.note',
    data: 'partly',
  },
  {
    id: 'fig9',
    label: 'paper.fig9',
    scene: 'strip',
    params: { scheme: 'literal', n: 6, triangulation: '1', labels: true, exact: false },
    caption: 'paper.fig9.caption',
    note: 'paper.fig9.note',
    data: 'partly',
  },
  {
    id: 'fig10',
    label: 'paper.fig10',
    scene: 'strip',
    params: { scheme: 'literal', n: 12, triangulation: 'none', labels: false, exact: false },
    caption: 'paper.fig10.caption',
    note: 'paper.fig10.note',
    beyond: 'paper.strip.beyond',
    data: 'partly',
  },
  {
    id: 'fig11',
    label: 'paper.fig11',
    scene: 'congruence',
    params: { congruence: 'example5', scheme: 'paper', steps: 1, director: true, second: true, labels: false },
    caption: 'paper.fig11.caption',
    note: 'paper.fig11.note',
    data: 'partly',
  },
  {
    id: 'fig12',
    label: 'paper.fig12',
    scene: 'congruence',
    params: { congruence: 'example5', scheme: 'diagonal', steps: 1, director: true, second: false, labels: false },
    caption: 'paper.fig12.caption',
    note: 'paper.fig12.note',
    data: 'partly',
  },
  {
    id: 'fig13',
    label: 'paper.fig13',
    scene: 'congruence',
    params: { congruence: 'sphere', scheme: 'diagonal', steps: 1, director: true, second: false, labels: false },
    caption: 'paper.fig13.caption',
    note: 'paper.fig13.note',
    data: 'none',
  },
  {
    id: 'fig13-right',
    label: 'paper.fig13-right',
    scene: 'congruence',
    params: {
      congruence: 'hyperbolic-paraboloid',
      scheme: 'diagonal',
      steps: 1,
      director: true,
      second: false,
      labels: false,
    },
    caption: 'paper.fig13.caption',
    note: 'paper.fig13-right.note',
    data: 'none',
  },
  {
    id: 'fig14',
    label: 'paper.fig14',
    scene: 'congruence',
    params: { congruence: 'example5', scheme: 'paper', steps: 1, director: false, second: false, labels: true },
    caption: 'paper.fig14.caption',
    note: 'paper.fig14.note',
    data: 'partly',
  },
  {
    id: 'fig15',
    label: 'paper.fig15',
    scene: 'congruence',
    params: { congruence: 'example5', scheme: 'paper', steps: 1, director: true, second: false, labels: false },
    caption: 'paper.fig15.caption',
    note: 'paper.fig15.note',
    beyond: 'paper.congruence.beyond',
    data: 'partly',
  },
  {
    id: 'fig16',
    label: 'paper.fig16',
    scene: 'milling',
    params: { poses: 7, steps: 1, scheme: 'variational', tool: true, at: 0.35, envelope: true, part: true },
    caption: 'paper.fig16.caption',
    note: 'paper.fig16.note',
    beyond: 'paper.milling.beyond',
    data: 'none',
  },
  {
    id: 'fig17',
    label: 'paper.fig17',
    scene: 'milling',
    params: { poses: 7, steps: 2, scheme: 'variational', tool: true, at: 0.35, envelope: true, part: true },
    caption: 'paper.fig17.caption',
    note: 'paper.fig17.note',
    beyond: 'paper.milling.beyond',
    data: 'none',
  },
  {
    id: 'fig18',
    label: 'paper.fig18',
    scene: 'milling',
    params: { poses: 7, steps: 3, scheme: 'variational', tool: true, at: 0.35, envelope: true, part: true },
    caption: 'paper.fig18.caption',
    note: 'paper.fig18.note',
    beyond: 'paper.milling.beyond',
    data: 'none',
  },
  {
    id: 'ex1',
    label: 'paper.ex1',
    scene: 'striction',
    params: {
      surface: 'hyperboloid',
      n: 36,
      strip: true,
      normals: false,
      polygon: true,
      midpoints: true,
      exact: true,
      axis: false,
    },
    caption: 'paper.ex1.caption',
    note: 'paper.ex1.note',
    data: 'partly',
  },
  {
    id: 'ex2',
    label: 'paper.ex2',
    scene: 'isometry',
    params: { surface: 'quartic', layout: 'bend', n: 24, t: 0.5, ghost: true },
    caption: 'paper.ex2.caption',
    note: 'paper.ex2.note',
    data: 'none',
  },
  {
    id: 'ex3',
    label: 'paper.ex3',
    scene: 'strip',
    params: { scheme: 'literal', n: 12, triangulation: '1', labels: false, exact: true },
    caption: 'paper.ex3.caption',
    note: 'paper.ex3.note',
    beyond: 'paper.strip.beyond',
    data: 'partly',
  },
  {
    id: 'ex4',
    label: 'paper.ex4',
    scene: 'congruence',
    params: { congruence: 'sphere', scheme: 'diagonal', steps: 1, director: true, second: true, labels: false },
    caption: 'paper.ex4.caption',
    note: 'paper.ex4.note',
    beyond: 'paper.congruence.beyond',
    data: 'none',
  },
  {
    id: 'ex5',
    label: 'paper.ex5',
    scene: 'congruence',
    params: { congruence: 'example5', scheme: 'paper', steps: 1, director: true, second: true, labels: false },
    caption: 'paper.ex5.caption',
    note: 'paper.ex5.note',
    beyond: 'paper.congruence.beyond',
    data: 'partly',
  },
  {
    id: 'ex6',
    label: 'paper.ex6',
    scene: 'milling',
    params: { poses: 7, steps: 2, scheme: 'variational', tool: true, at: 0.6, envelope: true, part: true },
    caption: 'paper.ex6.caption',
    note: 'paper.ex6.note',
    beyond: 'paper.milling.beyond',
    data: 'none',
  },
];

/** The preset named `id`, or undefined. */
export function findPreset(/** @type {string | null | undefined} */ id) {
  return id ? PRESETS.find((p) => p.id === id) : undefined;
}

/**
 * A link query with the preset's values filled in where the query gives none (so a link
 * `#paper=fig3` opens the figure, and `#paper=fig3&n=72` the figure with 72 rulings).
 * @param {PaperPreset} preset
 * @param {import('./scene.js').Scene} scene   the preset's scene
 * @param {URLSearchParams} query
 */
export function withPreset(preset, scene, query) {
  const merged = new URLSearchParams(query);
  for (const p of scene.params) {
    if (!merged.has(p.key) && p.key in preset.params)
      merged.set(p.key, p.type === 'checkbox' ? (preset.params[p.key] ? '1' : '0') : String(preset.params[p.key]));
  }
  return merged;
}

/**
 * Whether `params` are the preset's (parameters that do nothing for these values are ignored).
 * @param {PaperPreset} preset
 * @param {import('./scene.js').Scene} scene
 * @param {import('./scene.js').Params} params
 */
export function atPreset(preset, scene, params) {
  const full = { ...defaults(scene), ...preset.params };
  return scene.params.every((p) => p.unless?.(params) || full[p.key] === params[p.key]);
}
