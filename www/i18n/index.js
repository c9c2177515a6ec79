// Languages: every visible text comes from a per-language table (en.js, de.js) by key, and
// numbers are formatted for the language (decimal comma in German). A translator is made
// per view, so two <ruled-view> elements in different languages can share a page.
import en from './en.js';
import de from './de.js';

/** @type {Record<string, Record<string, string>>} */
export const LANGUAGES = { en, de };

/** Codes of the languages offered. */
export const LANGUAGE_CODES = Object.keys(LANGUAGES);

/**
 * The language to use: `wanted` if offered (e.g. "de", "de-AT"), else the browser's first
 * offered language, else English.
 * @param {string | null | undefined} wanted
 * @returns {string}
 */
export function pickLanguage(wanted) {
  const offered = (/** @type {string | null | undefined} */ code) => {
    const base = String(code ?? '')
      .toLowerCase()
      .split('-')[0];
    return LANGUAGE_CODES.includes(base) ? base : null;
  };
  if (wanted && offered(wanted)) return /** @type {string} */ (offered(wanted));
  const browser = typeof navigator === 'undefined' ? [] : (navigator.languages ?? [navigator.language]);
  for (const code of browser) if (offered(code)) return /** @type {string} */ (offered(code));
  return 'en';
}

/**
 * @typedef {object} Translator
 * @property {string} lang
 * @property {(key: string, vars?: Record<string, string | number>) => string} t
 *   the text of `key`, with `{name}` replaced by `vars.name` (numbers formatted); the English
 *   text when the language lacks the key, the key itself when English lacks it too
 * @property {(key: string) => boolean} has
 * @property {(x: number | string | boolean | null | undefined) => string} format
 *   a readout number: integers as they are, others with 3 decimals between 0.1 and 1000 and in
 *   scientific notation otherwise; "exact" for 0 where exactness is claimed by the caller
 */

/**
 * A translator for `lang`.
 * @param {string} lang
 * @returns {Translator}
 */
export function translator(lang) {
  const table = LANGUAGES[lang] ?? en;
  const decimal = new Intl.NumberFormat(lang, { minimumFractionDigits: 3, maximumFractionDigits: 3 });
  const integer = new Intl.NumberFormat(lang, { maximumFractionDigits: 0, useGrouping: true });
  const comma = lang === 'de';
  /** @param {number | string | boolean | null | undefined} x */
  const format = (x) => {
    if (typeof x !== 'number') return x === null || x === undefined ? '—' : String(x);
    if (Number.isNaN(x)) return '—';
    if (!Number.isFinite(x)) return x > 0 ? '∞' : '−∞';
    if (Number.isInteger(x) && Math.abs(x) < 1e15) return integer.format(x).replace('-', '−');
    const a = Math.abs(x);
    if (a >= 0.1 && a < 1000) return decimal.format(x).replace('-', '−');
    const [m, e] = x.toExponential(2).split('e');
    const mantissa = comma ? m.replace('.', ',') : m;
    return `${mantissa.replace('-', '−')}·10${superscript(Number(e))}`;
  };
  /** @param {string} key @param {Record<string, string | number>} [vars] */
  const t = (key, vars) => {
    const text = table[key] ?? /** @type {Record<string, string>} */ (en)[key] ?? key;
    if (!vars) return text;
    // {n:rule:rules}: the number and the word in the singular or the plural
    return text
      .replace(/\{(\w+):([^:}]*):([^}]*)\}/g, (m, name, one, many) =>
        name in vars ? `${format(vars[name])} ${vars[name] === 1 ? one : many}` : m,
      )
      .replace(/\{(\w+)\}/g, (m, name) =>
        name in vars ? (typeof vars[name] === 'number' ? format(vars[name]) : String(vars[name])) : m,
      );
  };
  return { lang, t, format, has: (/** @type {string} */ key) => key in table };
}

const SUPERSCRIPT = { '-': '⁻', 0: '⁰', 1: '¹', 2: '²', 3: '³', 4: '⁴', 5: '⁵', 6: '⁶', 7: '⁷', 8: '⁸', 9: '⁹' };

/** 12 → "¹²", −3 → "⁻³". @param {number} n */
export function superscript(n) {
  return String(n).replace(/./g, (c) => SUPERSCRIPT[/** @type {keyof typeof SUPERSCRIPT} */ (c)] ?? c);
}
