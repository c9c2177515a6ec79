// Languages: every visible text comes from a per-language table (en/, de/) by key, and
// numbers are formatted for the language (decimal comma in German). A translator is made
// per view, so two <ruled-view> elements in different languages can share a page. English is
// always here; another language is loaded on demand (loadLanguage): the page loads only the
// language it shows. i18n/index.js is this module with every language loaded.
import en from './en/index.js';
import notation from './notation.js';

/** The tables of the languages loaded so far. @type {Record<string, Record<string, string>>} */
export const LANGUAGES = { en };

/**
 * The languages besides English and how to load each (its module is fetched when first needed,
 * so a page in English never loads the German tables).
 * @type {Record<string, () => Promise<{default: Record<string, string>}>>}
 */
const LOADERS = { de: () => import('./de/index.js') };

/** Codes of the languages offered. */
export const LANGUAGE_CODES = ['en', ...Object.keys(LOADERS)];

/**
 * Loads the texts of language `code` (a code of LANGUAGE_CODES; nothing to do for English or a
 * language loaded already); resolves to whether they are there. Call it before making a
 * translator for a language other than English.
 * @param {string} code
 * @returns {Promise<boolean>}
 */
export async function loadLanguage(code) {
  if (LANGUAGES[code]) return true;
  const load = LOADERS[code];
  if (!load) return false;
  LANGUAGES[code] = (await load()).default;
  return true;
}

/** Makes `table` the texts of language `code` (a module that has them at hand: i18n/index.js). */
export function addLanguage(/** @type {string} */ code, /** @type {Record<string, string>} */ table) {
  LANGUAGES[code] = table;
}

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

/** @typedef {import('./index.js').Translator} Translator */

/**
 * The separators (grouping, decimal) of the languages offered: their numbers are written here,
 * exactly as Intl.NumberFormat writes them (tests/node/messages.test.mjs), without making one
 * (which takes milliseconds, on the way to the first picture).
 */
const SEPARATORS = /** @type {Record<string, [string, string]>} */ ({ en: [',', '.'], de: ['.', ','] });

/** The number formats of each language used so far. */
/** @type {Map<string, {decimal: {format: (x: number) => string}, integer: {format: (x: number) => string}}>} */
const NUMBER_FORMATS = new Map();

/**
 * The number formats of `lang`: an integer with grouping, a decimal with three places (rounded
 * half away from zero from its shortest decimal form, as Intl does).
 * @param {string} lang
 * @returns {{decimal: {format: (x: number) => string}, integer: {format: (x: number) => string}}}
 */
function numberFormats(lang) {
  const made = NUMBER_FORMATS.get(lang);
  if (made) return made;
  const separators = SEPARATORS[lang];
  if (separators) {
    const [group, point] = separators;
    const grouped = (/** @type {string} */ digits) => digits.replace(/\B(?=(\d{3})+(?!\d))/g, group);
    const formats = {
      integer: {
        format: (/** @type {number} */ x) => `${x < 0 || Object.is(x, -0) ? '-' : ''}${grouped(String(Math.abs(x)))}`,
      },
      decimal: {
        format: (/** @type {number} */ x) => {
          const [whole, fraction = ''] = String(Math.abs(x)).split('.');
          const thousandths =
            Number(whole) * 1000 + Number(fraction.slice(0, 3).padEnd(3, '0')) + (fraction[3] >= '5' ? 1 : 0);
          const places = String(thousandths % 1000).padStart(3, '0');
          return `${x < 0 ? '-' : ''}${grouped(String(Math.floor(thousandths / 1000)))}${point}${places}`;
        },
      },
    };
    NUMBER_FORMATS.set(lang, formats);
    return formats;
  }
  const formats = {
    decimal: new Intl.NumberFormat(lang, { minimumFractionDigits: 3, maximumFractionDigits: 3 }),
    integer: new Intl.NumberFormat(lang, { maximumFractionDigits: 0, useGrouping: true }),
  };
  NUMBER_FORMATS.set(lang, formats);
  return formats;
}

/**
 * A translator for `lang`; a language not loaded yet (loadLanguage) reads in English.
 * @param {string} lang
 * @returns {Translator}
 */
export function translator(lang) {
  const table = LANGUAGES[lang] ?? en;
  const comma = lang === 'de';
  /** @param {number | string | boolean | null | undefined} x */
  const format = (x) => {
    if (typeof x !== 'number') return x === null || x === undefined ? '—' : String(x);
    if (Number.isNaN(x)) return '—';
    if (!Number.isFinite(x)) return x > 0 ? '∞' : '−∞';
    if (Number.isInteger(x) && Math.abs(x) < 1e15) return numberFormats(lang).integer.format(x).replace('-', '−');
    const a = Math.abs(x);
    if (a >= 0.1 && a < 1000) return numberFormats(lang).decimal.format(x).replace('-', '−');
    const [m, e] = x.toExponential(2).split('e');
    const mantissa = comma ? m.replace('.', ',') : m;
    return `${mantissa.replace('-', '−')}·10${superscript(Number(e))}`;
  };
  /** @param {string} key @param {Record<string, string | number>} [vars] */
  const t = (key, vars) => {
    const text =
      table[key] ??
      /** @type {Record<string, string>} */ (en)[key] ??
      /** @type {Record<string, string>} */ (notation)[key] ??
      key;
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
  return { lang, t, format, has: (/** @type {string} */ key) => key in table || key in notation };
}

const SUPERSCRIPT = { '-': '⁻', 0: '⁰', 1: '¹', 2: '²', 3: '³', 4: '⁴', 5: '⁵', 6: '⁶', 7: '⁷', 8: '⁸', 9: '⁹' };

/** 12 → "¹²", −3 → "⁻³". @param {number} n */
export function superscript(n) {
  return String(n).replace(/./g, (c) => SUPERSCRIPT[/** @type {keyof typeof SUPERSCRIPT} */ (c)] ?? c);
}
