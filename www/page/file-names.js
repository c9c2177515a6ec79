// The names of the page's downloads: what the figure is, so that a lecturer's folder of exports
// reads like a list of figures and no two different figures overwrite each other —
// `fig13-congruence-bw.svg` (the paper's Fig. 13 as shown), `striction-n36-bw.tikz` (a scene, with
// the counts it is made of), `striction-n36-exact-de.svg` (a switch turned on, German words).
import { defaults } from '../scene.js';

/** A name's longest stem before the tokens are replaced by a hash (file systems allow 255 bytes). */
const LONGEST = 80;

/** A short hash of `text` (FNV-1a, 6 hex digits): tells edited inputs and formulas apart. */
export function shortHash(/** @type {string} */ text) {
  let h = 0x811c9dc5;
  for (let k = 0; k < text.length; k++) {
    h ^= text.charCodeAt(k);
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h.toString(16).padStart(8, '0').slice(0, 6);
}

/** A number as a file name writes it: up to 4 significant digits, no trailing zeros. */
const number = (/** @type {number} */ x) => String(Number(x.toPrecision(4)));

/** Letters, digits, '.', '_', '-' only. */
const safe = (/** @type {string} */ s) =>
  s
    .normalize('NFKD')
    .replace(/[^\w.-]+/g, '-')
    .replace(/-+/g, '-')
    .replace(/^-|-$/g, '');

/**
 * Whether a parameter counts what the figure is made of (rulings, steps, levels, poses, rows):
 * an integer range. Its value is named even where it is the default.
 * @param {import('../scene.js').Param} p
 */
const counts = (p) => p.type === 'range' && Number.isInteger(p.step ?? 1) && Number.isInteger(p.min ?? 0);

/**
 * The stem of a download's name: the paper's figure shown (and the scene), else the scene and its
 * counts; then every parameter that differs from the figure's settings or the scene's defaults
 * (a number as key and value, a menu as its choice, a switch as its key or no-key, typed formulas
 * as one hash), an edited input and imported data (each with a hash of its numbers).
 * @param {{scene: import('../scene.js').Scene, params: import('../scene.js').Params,
 *   paper?: import('../paper.js').PaperPreset | null, input?: import('../scene.js').Input | null,
 *   data?: import('../scene.js').ImportedData | null}} shown
 */
export function fileStem({ scene, params, paper = null, input = null, data = null }) {
  const base = { ...defaults(scene), ...(paper?.params ?? {}) };
  /** @type {string[]} */
  const tokens = [];
  /** @type {string[]} */
  const formulas = [];
  for (const p of scene.params) {
    const value = params[p.key] ?? base[p.key];
    const changed = value !== base[p.key];
    if (p.type === 'text') {
      if (changed) formulas.push(`${p.key}=${value}`);
    } else if (p.type === 'checkbox') {
      if (changed) tokens.push(value ? p.key : `no-${p.key}`);
    } else if (p.type === 'select') {
      if (changed) tokens.push(String(value));
    } else if (changed || (!paper && counts(p)))
      // (a key that ends in a digit is kept apart from its value: h0_0.45)
      tokens.push(`${p.key}${/\d$/.test(p.key) ? '_' : ''}${number(Number(value))}`);
  }
  if (formulas.length) tokens.push(`formulas-${shortHash(formulas.join('&'))}`);
  if (input)
    tokens.push(
      `edited-${shortHash(
        Object.entries(input)
          .map(([key, points]) => `${key}:${Array.from(points, number).join(',')}`)
          .join(';'),
      )}`,
    );
  if (data) tokens.push(`data-${shortHash(Array.from(data.segments, number).join(','))}`);
  const head = paper ? `${paper.id}-${scene.id}` : scene.id;
  const stem = safe([head, ...tokens].join('-'));
  return stem.length <= LONGEST ? stem : `${safe(head)}-${shortHash(stem)}`;
}

/**
 * The name of an export of what `stage` shows.
 * @param {import('../stage.js').Stage} stage
 * @param {'svg' | 'tikz' | 'png' | 'plot' | 'data'} kind   a figure (words in the page's language),
 *   or a data file (numbers only)
 * @param {{bw?: boolean, scale?: number, suffix?: string}} [options]   suffix: of a data file ('.csv', '-invariants.json')
 */
export function exportName(stage, kind, { bw = false, scale = 1, suffix = '' } = {}) {
  const stem = fileStem({
    scene: /** @type {import('../scene.js').Scene} */ (stage.scene),
    params: stage.params,
    paper: stage.paper,
    input: stage.input,
    data: stage.data,
  });
  if (kind === 'data') return `${stem}${suffix}`;
  // a figure's legend, labels and axes speak the page's language: English is the default
  const lang = stage.i18n.lang === 'en' ? '' : `-${stage.i18n.lang}`;
  if (kind === 'png') return `${stem}${lang}${scale === 1 ? '' : `-${scale}x`}.png`;
  if (kind === 'plot') return `${stem}-plot${lang}.svg`;
  return `${stem}${bw ? '-bw' : ''}${lang}.${kind}`;
}
