// Small builders of MathML markup for the explanations in the language files. They compose
// the project's own fixed strings only (never text from a user or a link).

/** <mi>…</mi> for each letter-like token, <mo> for operators, <mn> for digits. */
const token = (/** @type {string} */ t) =>
  /^[0-9.]+$/.test(t) ? `<mn>${t}</mn>` : /^[+−=,()<>·×∈/|′→]$/.test(t) ? `<mo>${t}</mo>` : `<mi>${t}</mi>`;

/** A row of tokens separated by spaces: "i , i + 1". */
export const row = (/** @type {string} */ tokens) =>
  `<mrow>${tokens.split(' ').filter(Boolean).map(token).join('')}</mrow>`;

/** base with a subscript: sub('f', 'i , i + 1'). */
export const sub = (/** @type {string} */ base, /** @type {string} */ index) =>
  `<msub>${token(base)}${row(index)}</msub>`;

/** Inline math. */
export const m = (/** @type {string} */ inner) => `<math>${inner}</math>`;

/** Display math with an equation number (focusable, since a long one scrolls sideways on a phone). */
export const display = (/** @type {string} */ inner, /** @type {string} */ number = '') =>
  `<math display="block" tabindex="0">${inner}${number ? `<mspace width="1em"/><mtext>(${number})</mtext>` : ''}</math>`;

/** A fraction. */
export const frac = (/** @type {string} */ a, /** @type {string} */ b) => `<mfrac>${a}${b}</mfrac>`;

/** Plain tokens in a row, as inline math: m$('s ( u )'). */
export const mr = (/** @type {string} */ tokens) => m(row(tokens));

/** The indexed symbols the explanations of every language use: f_{i,i+1}, f_{i,i−1}, R_i. */
export const fii1 = sub('f', 'i , i + 1');
export const fiim = sub('f', 'i , i − 1');
export const Ri = sub('R', 'i');

/** 100000 → "100 000": numbers as the explanations of every language write them. */
export const grouped = (/** @type {number} */ n) => String(n).replace(/\B(?=(\d{3})+(?!\d))/g, ' ');
