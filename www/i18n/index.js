// Languages, every one loaded: i18n/translate.js with the German tables added, for what needs
// every language at hand without waiting (the package's ruledlab/view, <ruled-view>, the
// one-file build, Node). The page imports translate.js and loads the language it shows.
import de from './de/index.js';
import { addLanguage } from './translate.js';

addLanguage('de', de);

export {
  LANGUAGES,
  LANGUAGE_CODES,
  addLanguage,
  loadLanguage,
  pickLanguage,
  superscript,
  translator,
} from './translate.js';

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
